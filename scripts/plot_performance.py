#!/usr/bin/env python3
"""The performance report as a picture: million elements per minute of each program on each
point distribution, from the JSON that scripts/bench_delaunay2d.py or bench_delaunay3d.py write.

  scripts/plot_performance.py build/bench_delaunay2d.json -o docs/img/performance.svg
  scripts/plot_performance.py build/bench_delaunay2d.json build/bench_delaunay3d.json -o perf.svg

One panel per (JSON file, n): grouped bars, one group per distribution, one bar per program (CGAL
hatched when the run had it), each from the minimum time over the runs, as the tables of
scripts/bench_report.py / readme_tables.py take it; a failed run leaves its bar out. The machine
line of the run is the caption. SVG (text kept as text) or PNG from the extension; no date in
the file, so the same JSON gives the same bytes. Needs matplotlib (Debian: python3-matplotlib;
where `python3` is another interpreter, run it as /usr/bin/python3 scripts/plot_performance.py).
"""
import argparse
import json
import os
import sys
import textwrap

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:
    sys.exit(f"plot_performance.py: {e} (Debian: apt-get install python3-matplotlib)")

COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"]


def size_label(n):
    digits = str(n)
    return f"$10^{len(digits) - 1}$" if digits[0] == "1" and set(digits[1:]) <= {"0"} else digits


def best(records):
    """{(n, distribution, program): (elements, minimum seconds)} over the runs that succeeded."""
    out = {}
    for r in records:
        if "error" in r or not r.get("seconds"):
            continue
        key = (r["n"], r["distribution"], r["program"])
        if key not in out or r["seconds"] < out[key][1]:
            out[key] = (r["elements"], r["seconds"])
    return out


def dimension(data):
    return "3D" if any("--dim 3" in r.get("command", "") for r in data["records"]) else "2D"


def panels(runs):
    """[(title, data, n, distributions)] in file order, then n order."""
    out = []
    for path, data in runs:
        sizes = []
        for n, _ in data["cases"]:
            if n not in sizes:
                sizes.append(n)
        for n in sizes:
            distributions = [d for m, d in data["cases"] if m == n]
            out.append((f"{dimension(data)} Delaunay, n = {size_label(n)}", data, n, distributions))
    return out


def draw(runs, out):
    plt.rcParams.update({"svg.hashsalt": "dtlab", "svg.fonttype": "none", "font.size": 9})
    ps = panels(runs)
    fig, axes = plt.subplots(len(ps), 1, figsize=(8.0, 2.9 * len(ps) + 0.6), squeeze=False)
    for ax, (title, data, n, distributions) in zip(axes[:, 0], ps):
        table = best(data["records"])
        programs = data["programs"]
        width = 0.8 / len(programs)
        for i, program in enumerate(programs):
            xs, ys = [], []
            for j, d in enumerate(distributions):
                if (n, d, program) in table:
                    elements, seconds = table[(n, d, program)]
                    xs.append(j - 0.4 + (i + 0.5) * width)
                    ys.append(elements * 60.0 / seconds / 1e6)
            cgal = program == "cgal"
            ax.bar(xs, ys, width * 0.92, label="CGAL" if cgal else program,
                   color="#bbbbbb" if cgal else COLOURS[i % len(COLOURS)],
                   hatch="//" if cgal else None, edgecolor="#333333", linewidth=0.4)
        ax.set_xticks(range(len(distributions)), distributions)
        ax.set_ylabel("million elements / minute")
        ax.set_title(title, fontsize=10, fontweight="bold", loc="left")
        ax.grid(axis="y", color="#dddddd", linewidth=0.6)
        ax.set_axisbelow(True)
        ax.spines[["top", "right"]].set_visible(False)
        ax.legend(ncol=len(programs), fontsize=8, frameon=False, loc="upper right")
        ax.margins(y=0.18)
    captions = []
    for path, data in runs:
        m = data.get("machine", {})
        captions.append(f"{os.path.basename(path)}: {m.get('cpu', 'unknown CPU')}, {m.get('cpus', '?')} CPUs, "
                        f"load average {m.get('load_average', [float('nan')])[0]:.1f} at the start; "
                        f"{m.get('compiler', '')}; tree {m.get('commit', '?')}; minimum of {data.get('runs', '?')} "
                        f"run(s), seed {data.get('seed', '?')}; CGAL {m.get('cgal', 'not run')}")
    lines = [line for c in captions for line in textwrap.wrap(c, 150)]
    fig.text(0.01, 0.005, "\n".join(lines), fontsize=6.5, color="#444444", va="bottom")
    fig.tight_layout(rect=(0, 0.016 * len(lines) + 0.01, 1, 1))
    fig.savefig(out, metadata={"Date": None} if out.endswith(".svg") else {"Software": None})
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json", nargs="+", help="the JSON of bench_delaunay2d.py / bench_delaunay3d.py")
    ap.add_argument("-o", "--output", required=True, help="the picture: .svg or .png")
    args = ap.parse_args()
    if not args.output.endswith((".svg", ".png")):
        sys.exit(f"plot_performance.py: -o {args.output}: give an .svg or .png output")
    runs = []
    for path in args.json:
        try:
            with open(path) as f:
                data = json.load(f)
            if not isinstance(data, dict) or not {"programs", "cases", "records"} <= set(data):
                sys.exit(f"plot_performance.py: {path}: not the JSON of a bench_delaunay script "
                         "(no programs, cases, records)")
        except (OSError, json.JSONDecodeError) as e:
            sys.exit(f"plot_performance.py: {path}: {e}")
        runs.append((path, data))
    draw(runs, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
