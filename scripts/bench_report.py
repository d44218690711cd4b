#!/usr/bin/env python3
"""One command, one performance report: predicates, 2D and 3D Delaunay, beside their peers.

Runs, with fixed seeds and named distributions, REPEATS times each, in this one session:
  1. bench/predicates_bench (Google Benchmark: dtlab's predicates, each stage alone, the plain
     double determinant and CGAL Epick in the same binary);
  2. 2D Delaunay, one process per run (scripts/bench_delaunay2d.py's runner): every variant
     through `dtlab delaunay --stats`, CGAL's Delaunay_triangulation_2 through
     bench/cgal_delaunay2d_run_bench, same points;
  3. 3D Delaunay, one process per run (scripts/bench_delaunay3d.py's runner): every built variant
     (a parallel one at 1 and 2 threads), CGAL's Delaunay_triangulation_3, and TetGen's Debian
     binary, same points;
  4. bench/delaunay2d_bench and bench/delaunay3d_bench (Google Benchmark, CGAL in the same
     process): heap bytes per element of each call;
and writes OUT/ (default BUILD/bench-report):
  report.md    tables: elements per minute, bytes per element, ratio to each peer, min / median /
               max over the repeats and the noise they imply, predicate stage counts of every
               Delaunay run (its --stats JSON), ns per predicate call; every row says which
               machine, compiler, flags and commit produced it
  *.png        elements per minute against n (log axes, one line per variant and peer), bytes per
               element against n, ns per predicate call (matplotlib, Debian's python3-matplotlib)
  report.json  every measurement, from which --from-report rebuilds report.md, the plots and the
               tables of docs/performance.md
Progress goes to stderr. Missing binaries are built first (cmake, Release, benchmarks on), so
the command runs from a fresh clone.

  scripts/bench_report.py                              # default size: a few minutes of runs
  scripts/bench_report.py --size ci --out /tmp/r       # ~1-2 minutes (the CTest bench_report_ci)
  scripts/bench_report.py --size large                 # adds 10^7 points
  scripts/bench_report.py --from-report build/bench-report --update-readme

--update-readme writes the predicate, 2D and 3D tables of the report into docs/performance.md (--readme
PATH: another file), each between
its own markers inside the perf-table block (scripts/readme_tables.py), and nothing else.
Why a script under scripts/ and not bench/: it drives the other benchmark scripts of this folder
(bench_predicates_table.py, bench_delaunay2d.py, bench_delaunay3d.py) as modules, and bench/
holds what CMake builds.
"""
import argparse
import datetime
import json
import os
import re
import statistics
import subprocess
import sys

import bench_delaunay2d as d2
import bench_delaunay3d as d3
import bench_predicates_table as pt
import readme_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED = 1

# What each size runs. Predicates: Google Benchmark filter, seconds per repetition. 2D: (n,
# distribution) cases. 3D: the same. gbench: the n of the in-process suites.
SIZES = {
    "ci": {"repeats": 2, "pred_filter": "/random/", "pred_min_time": 0.01,
           "cases2d": [(1_000, "uniform"), (10_000, "uniform"), (10_000, "grid")],
           "cases3d": [(1_000, "uniform"), (10_000, "uniform"), (10_000, "grid")], "gbench": [1_000, 10_000], "gbench_min_time": 0.01},
    "default": {"repeats": 3, "pred_filter": "", "pred_min_time": 0.1,
                "cases2d": [(10_000, "uniform"), (100_000, "uniform"), (1_000_000, "uniform")]
                + [(100_000, d) for d in ("normal", "grid", "circle", "clustered")],
                "cases3d": [(n, "uniform") for n in (1_000, 10_000, 100_000, 1_000_000)]
                + [(100_000, d) for d in ("normal", "grid", "sphere", "clustered")], "gbench": [1_000, 10_000, 100_000],
                "gbench_min_time": 0.2},
}
SIZES["large"] = dict(SIZES["default"], cases2d=SIZES["default"]["cases2d"] + [(10_000_000, "uniform")],
                      cases3d=SIZES["default"]["cases3d"] + [(10_000_000, "uniform")])
TARGETS = ["dtlab_cli", "predicates_bench", "delaunay2d_bench", "delaunay3d_bench",
           "cgal_delaunay2d_run_bench", "cgal_delaunay3d_run_bench"]
PLOTS = ["delaunay2d_rate.png", "delaunay2d_memory.png", "delaunay3d_rate.png", "delaunay3d_memory.png",
         "predicates.png"]


def progress(msg):
    print(f"[{datetime.datetime.now():%H:%M:%S}] {msg}", file=sys.stderr, flush=True)


# --- Build and provenance ---------------------------------------------------------------------

def binaries(build):
    return {"dtlab": os.path.join(build, "dtlab"),
            "predicates_bench": os.path.join(build, "bench", "predicates_bench"),
            "delaunay2d_bench": os.path.join(build, "bench", "delaunay2d_bench"),
            "delaunay3d_bench": os.path.join(build, "bench", "delaunay3d_bench"),
            "cgal2d": os.path.join(build, "bench", "cgal_delaunay2d_run_bench"),
            "cgal3d": os.path.join(build, "bench", "cgal_delaunay3d_run_bench")}


def ensure_built(build, jobs):
    """Configures BUILD (Release, benchmarks on) if it has no cache, and builds the targets
    whose binaries are missing. CGAL's targets exist only when CGAL is found: not an error."""
    bins = binaries(build)
    if all(os.access(p, os.X_OK) for p in bins.values()):
        return
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        progress(f"configuring {build}")
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                        "-DDTLAB_BUILD_BENCH=ON"], check=True, stdout=sys.stderr)
    progress(f"building {', '.join(TARGETS)} in {build} (-j{jobs})")
    for target in TARGETS:
        r = subprocess.run(["cmake", "--build", build, "-j", str(jobs), "--target", target],
                           stdout=sys.stderr, stderr=sys.stderr)
        if r.returncode != 0 and "cgal" not in target:
            raise SystemExit(f"building {target} failed")


def cmake_cache(build):
    cache = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            for line in f:
                m = re.match(r"^([A-Za-z_0-9]+):[A-Z]+=(.*)$", line.rstrip("\n"))
                if m:
                    cache[m.group(1)] = m.group(2)
    except OSError:
        pass
    return cache


def provenance(build, bins):
    """Machine, compiler, flags and commit: what every row of the report carries."""
    m = d2.machine(bins["dtlab"])
    cache = cmake_cache(build)
    build_type = cache.get("CMAKE_BUILD_TYPE", "")
    dtlab_flags = ""
    try:
        with open(os.path.join(build, "generated", "dtlab", "build_info.hpp")) as f:
            found = re.search(r'kFlags = "([^"]*)"', f.read())
            dtlab_flags = found.group(1) if found else ""
    except OSError:
        pass
    flags = " ".join(x for x in (cache.get("CMAKE_CXX_FLAGS", ""),
                                 cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", ""), dtlab_flags) if x)
    version = m.get("dtlab_version", "")
    found = re.search(r"commit ([0-9a-f]+(?:-dirty)?)", version)
    m.update({"build_type": build_type, "flags": flags.strip(),
              "binary_commit": found.group(1) if found else "unknown",
              "date": datetime.datetime.now().isoformat(timespec="seconds")})
    return m


def provenance_cell(m):
    cpu = m["cpu"].replace("AMD ", "").replace("Intel(R) ", "")
    return (f"{cpu} ×{m['cpus']}; {m['compiler'].split(' (')[0]} {m['compiler'].split()[-1]} "
            f"{m['build_type']} `{m['flags']}`; `{m['binary_commit']}`")


# --- Measurements -----------------------------------------------------------------------------

def run_gbench(binary, out_json, repetitions, min_time, bench_filter, extra=()):
    """Google Benchmark with its console output on stderr (progress) and JSON into out_json."""
    cmd = [binary, f"--benchmark_out={out_json}", "--benchmark_out_format=json",
           f"--benchmark_repetitions={repetitions}", f"--benchmark_min_time={min_time}"] + list(extra)
    if bench_filter:
        cmd.append(f"--benchmark_filter={bench_filter}")
    progress("running " + " ".join(cmd))
    subprocess.run(cmd, check=True, stdout=sys.stderr)
    with open(out_json) as f:
        return json.load(f)


def runner_args(module, bins, repeats, timeout, **overrides):
    """The argparse namespace the 2D / 3D script's measure() expects, with its defaults and the
    report's time limit per run (seconds at 10^6 points, scaled up with n, never below it)."""
    ap = argparse.ArgumentParser()
    if module is d3:
        d3.add_arguments(ap)
        args = ap.parse_args([])
        args.dtlab, args.cgal = bins["dtlab"], bins["cgal3d"]
        d3.resolve(args)
    else:
        args = argparse.Namespace(seed=SEED, slow=60, dtlab=bins["dtlab"], cgal=bins["cgal2d"])
    args.runs = repeats
    args.timeout = timeout
    args.seed = SEED
    for k, v in overrides.items():
        setattr(args, k, v)
    return args


def measure_2d(bins, plan, repeats, timeout, out):
    programs = d2.list_variants(bins["dtlab"])
    if os.access(bins["cgal2d"], os.X_OK):
        programs.append(d2.CGAL)
    else:
        progress("2D: CGAL runner not built, CGAL left out")
    cases = plan["cases2d"]
    progress(f"2D: {len(cases)} cases x {len(programs)} programs x {repeats} runs: {', '.join(programs)}")
    data = {"machine": d2.machine(bins["dtlab"]), "programs": programs, "cases": cases, "runs": repeats,
            "seed": SEED, "records": []}

    def save(records):
        data["records"] = records
        data["machine"]["cgal"] = next((r["cgal_version"] for r in records if "cgal_version" in r), "not run")
        with open(os.path.join(out, "delaunay2d.json"), "w") as f:
            json.dump(data, f, indent=1)

    d2.measure(runner_args(d2, bins, repeats, timeout), programs, cases, save)
    return data


def measure_3d(bins, plan, repeats, timeout, out):
    args = runner_args(d3, bins, repeats, timeout)
    if not os.access(bins["cgal3d"], os.X_OK):
        progress("3D: CGAL runner not built, CGAL (and TetGen, whose points it writes) left out")
        args.no_cgal = args.no_tetgen = True
    return d3.run(args, plan["cases3d"], os.path.join(out, "delaunay3d.json"))


def measure(args, bins, out):
    plan = SIZES[args.size]
    repeats = args.repeats or plan["repeats"]
    report = {"size": args.size, "repeats": repeats, "seed": SEED,
              "provenance": provenance(args.build, bins)}
    sizes_re = "|".join(str(n) for n in plan["gbench"])

    progress("predicates (1/4)")
    report["predicates"] = run_gbench(bins["predicates_bench"], os.path.join(out, "predicates_bench.json"),
                                      repeats, plan["pred_min_time"], plan["pred_filter"])
    progress("2D Delaunay, one process per run (2/4)")
    report["delaunay2d"] = measure_2d(bins, plan, repeats, args.run_limit, out)
    progress("3D Delaunay, one process per run (3/4)")
    report["delaunay3d"] = measure_3d(bins, plan, repeats, args.run_limit, out)
    progress("2D and 3D Delaunay in-process, heap per element (4/4)")
    for suite in ("delaunay2d", "delaunay3d"):
        report[f"{suite}_gbench"] = run_gbench(bins[f"{suite}_bench"], os.path.join(out, f"{suite}_bench.json"),
                                               repeats, plan["gbench_min_time"], f"/uniform/({sizes_re})(/|$)")
    report["load_average_end"] = list(os.getloadavg())
    return report


# --- Summaries --------------------------------------------------------------------------------

def spread(values):
    """(min, median, max, noise in % of the minimum)."""
    lo, hi = min(values), max(values)
    return lo, statistics.median(values), hi, 100.0 * (hi - lo) / lo if lo > 0 else 0.0


def process_rows(data, peers):
    """One dict per (n, distribution, program) of a 2D or 3D process suite."""
    by_key = {}
    for r in data["records"]:
        key = (r["n"], r.get("distribution", "uniform"), r["program"])
        by_key.setdefault(key, []).append(r)
    rows = []
    for (n, dist, program), recs in by_key.items():
        ok = [r for r in recs if "error" not in r]
        row = {"n": n, "distribution": dist, "program": program, "runs": len(ok),
               "error": next((r["error"] for r in recs if "error" in r), None)}
        if ok:
            seconds = [r["seconds"] for r in ok]
            row["seconds"] = spread(seconds)
            row["elements"] = min(r["elements"] for r in ok)
            mbs = [r["peak_rss_mb"] for r in ok if r.get("peak_rss_mb") is not None]
            row["mb"] = max(mbs) if mbs else None
            row["predicates"] = ok[0].get("predicates")
        rows.append(row)
    index = {(r["n"], r["distribution"], r["program"]): r for r in rows}
    for r in rows:
        for peer in peers:
            p = index.get((r["n"], r["distribution"], peer))
            if "seconds" in r and p and "seconds" in p:
                r[f"ratio_{peer}"] = (r["seconds"][0] / p["seconds"][0], r["seconds"][1] / p["seconds"][1])
    order = {p: i for i, p in enumerate(data["programs"])}
    rows.sort(key=lambda r: (r["distribution"] != "uniform", r["distribution"], r["n"], order.get(r["program"], 99)))
    return rows


GBENCH_COUNTERS = {"triangle": ("triangles", "triangles_per_minute", "heap_bytes_per_triangle"),
                   "tetrahedron": ("tetrahedra", "tetrahedra_per_minute", "heap_bytes_per_tetrahedron")}


def gbench_rows(data, element):
    """One dict per in-process benchmark: heap bytes per element and elements per minute."""
    count, rate, per_element = GBENCH_COUNTERS[element]
    by_name = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        by_name.setdefault(b["run_name"], []).append(b)
    rows = []
    for name, bs in by_name.items():
        parts = name.split("/")  # delaunay3d/<program>/<distribution>/<n>[/real_time]
        rows.append({"program": parts[1], "distribution": parts[2], "n": int(parts[3]),
                     "per_minute": spread([b[rate] for b in bs]), "heap_mb": bs[0]["peak_heap_mb"],
                     "bytes_per_element": bs[0][per_element], "elements": bs[0][count]})
    index = {(r["n"], r["program"]): r for r in rows}
    for r in rows:
        c = index.get((r["n"], "cgal"))
        if c and r["program"] != "cgal":
            r["rate_over_cgal"] = r["per_minute"][2] / c["per_minute"][2] if c["per_minute"][2] else None
    return rows


# --- Markdown ---------------------------------------------------------------------------------

def fmt(v, digits=3):
    return d2.fmt(v, digits)


def md_table(head, rows):
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def process_table(rows, peers, element, prov):
    head = ["n", "distribution", "program", f"M{element}/min", "seconds min / median / max", "noise",
            "peak MB", f"bytes/{element[:-1] if element.endswith('s') else element}"]
    head += [f"time / {p} (min; median)" for p in peers] + ["machine, compiler, flags, commit"]
    out = []
    for r in rows:
        name = f"**{r['program']}**" if r["program"] in peers else r["program"]
        if "seconds" not in r:
            out.append([d2.size_label(r["n"]), r["distribution"], name, f"error: {r['error']}"]
                       + [""] * (len(head) - 5) + [prov])
            continue
        lo, med, hi, noise = r["seconds"]
        per_tet = r["mb"] * 1024 * 1024 / r["elements"] if r["mb"] is not None and r["elements"] else None
        cells = [d2.size_label(r["n"]), r["distribution"], name, fmt(r["elements"] * 60.0 / lo / 1e6),
                 f"{fmt(lo)} / {fmt(med)} / {fmt(hi)}" + ("" if r["runs"] > 1 else " (1 run)")
                 + (" ‡" if r["program"] == d3.TETGEN else ""),
                 f"{noise:.0f} %", fmt(r["mb"]), fmt(per_tet)]
        for p in peers:
            ratio = r.get(f"ratio_{p}")
            cells.append(f"{ratio[0]:.2f}; {ratio[1]:.2f}" if ratio else "–")
        out.append(cells + [prov])
    return md_table(head, out)


def gbench_table(rows, element, prov, time_kind):
    short = {"tetrahedron": "tets", "triangle": "triangles"}[element]
    head = ["n", "program", f"M{short}/min ({time_kind}) best / median / worst", "noise", "heap MB",
            f"heap bytes/{element}", "best rate / CGAL's", "machine, compiler, flags, commit"]
    out = []
    for r in sorted(rows, key=lambda r: (r["n"], r["program"] == "cgal", r["program"])):
        lo, med, hi, noise = r["per_minute"]
        out.append([d2.size_label(r["n"]), f"**{r['program']}**" if r["program"] == "cgal" else r["program"],
                    f"{fmt(hi / 1e6)} / {fmt(med / 1e6)} / {fmt(lo / 1e6)}", f"{noise:.0f} %",
                    fmt(r["heap_mb"]), fmt(r["bytes_per_element"]),
                    f"{r['rate_over_cgal']:.2f}" if r.get("rate_over_cgal") else "–", prov])
    return md_table(head, out)


def stage_table(rows, prov):
    head = ["n", "distribution", "program", "predicate", "calls", "calls/element", "semi-static", "adaptive",
            "exact (expansions or GMP)", "of which GMP", "perturbed", "machine, compiler, flags, commit"]
    out = []
    for r in rows:
        for predicate, c in (r.get("predicates") or {}).items():
            calls = c["semistatic"] + c["adaptive"] + c["exact"]
            if calls == 0:
                continue
            share = [f"{100.0 * c[k] / calls:.3g} %" for k in ("semistatic", "adaptive", "exact")]
            out.append([d2.size_label(r["n"]), r["distribution"], r["program"], predicate, calls,
                        fmt(calls / r["elements"]) if r.get("elements") else "–"] + share
                       + [c.get("gmp", "–"), c["perturbed"], prov])
    return md_table(head, out)


def predicate_rows(data):
    """(predicate, impl, input, consumer) -> spread of ns per call."""
    runs = pt.collect(data)
    return {k: spread(e["ns"]) for k, e in runs.items() if e["ns"]}


def predicate_table(data, prov):
    rows = predicate_rows(data)
    head = ["predicate", "input", "consumer", "implementation", "ns/call min / median / max", "noise",
            "/ plain", "/ CGAL Epick", "machine, compiler, flags, commit"]
    out = []
    for (p, impl, dist, consumer), (lo, med, hi, noise) in sorted(rows.items()):
        plain = rows.get((p, "plain", dist, consumer))
        cgal = rows.get((p, "cgal_epick", dist, consumer))
        out.append([p, dist, consumer, impl, f"{pt.fmt_ns(lo)} / {pt.fmt_ns(med)} / {pt.fmt_ns(hi)}",
                    f"{noise:.0f} %", f"{lo / plain[0]:.2f}" if plain else "–",
                    f"{lo / cgal[0]:.2f}" if cgal else "–", prov])
    return md_table(head, out)


def flat_lines(data3d):
    summary = d3.summarise(data3d["records"])
    return d3.flatness(summary, data3d["programs"], [tuple(c) for c in data3d["cases"]])


def busy_warning(m, load_end):
    """A paragraph when the load average exceeded the CPU count at the start or the end."""
    loads = list(m.get("load_average", []))[:1] + list(load_end)[:1]
    if not loads or max(loads) <= m["cpus"]:
        return ""
    return (f"**The machine was busy** (1-minute load average up to {max(loads):.1f} on {m['cpus']} CPUs): "
            "wall-clock times include waiting for a core, so absolute figures are pessimistic, the noise "
            "is high, and only ratios between neighbouring rows mean much. Rerun on an idle machine "
            "for figures to publish.\n")


def report_markdown(report, plots):
    m = report["provenance"]
    prov = provenance_cell(m)
    repeats = report["repeats"]
    load = ", ".join(f"{x:.1f}" for x in m.get("load_average", []))
    load_end = ", ".join(f"{x:.1f}" for x in report.get("load_average_end", []))
    peers3 = [p for p in (d3.CGAL, d3.TETGEN) if p in report["delaunay3d"]["programs"]]
    peers2 = [p for p in (d2.CGAL,) if p in report["delaunay2d"]["programs"]]
    rows2 = process_rows(report["delaunay2d"], peers2)
    rows3 = process_rows(report["delaunay3d"], peers3)
    parts = [
        "# dtlab performance report",
        "",
        f"Produced by `scripts/bench_report.py --size {report['size']}` on {m['date']}.",
        "",
        "| | |",
        "|---|---|",
        f"| machine | {m['cpu']}, {m['cpus']} CPUs, {m['system']}; load average {load} at the start, {load_end} at the end |",
        f"| compiler | {m['compiler']} |",
        f"| build | {m['build_type']}, flags `{m['flags']}` |",
        f"| commit | binary `{m['binary_commit']}` (`{m['dtlab_version']}`), tree `{m['commit']}` |",
        f"| peers | CGAL {report['delaunay3d']['machine'].get('cgal', 'not run')}, "
        f"TetGen {report['delaunay3d']['machine'].get('tetgen', 'not run')} |",
        f"| repeats | {repeats} of everything, interleaved across programs; seeds fixed ({SEED}) |",
        "",
        busy_warning(m, report.get("load_average_end", [])),
        "How to read it: a ratio is taken from this one run (the minima, then the medians); the "
        "noise column is (max − min) / min of the repeats, so a second run on the same machine "
        "should reproduce a ratio within the two programs' noise added. Times of the Delaunay "
        "processes are each program's own timing of the triangulation (wall clock: on a shared "
        "machine it includes time other processes held the core); peak MB is the process's peak "
        "resident memory, so bytes per element include the points and the process itself.",
        "",
        "## 3D Delaunay (one process per run)",
        "",
        "![tetrahedra per minute](delaunay3d_rate.png) ![bytes per tetrahedron](delaunay3d_memory.png)"
        if "delaunay3d_rate.png" in plots else "(plots: matplotlib not available)",
        "",
        process_table(rows3, peers3, "tets", prov),
        "",
        d3.TETGEN_NOTE if d3.TETGEN in peers3 else "",
        "",
        "Time per point from 10^4 up (issue 5: flat within ±20 % from 10^4 to 10^7):",
        "",
        "\n".join(f"- {line}" for line in flat_lines(report["delaunay3d"]))
        or "- (needs two sizes of 10^4 or more: not at this size)",
        "",
        "## 2D Delaunay (one process per run)",
        "",
        "![triangles per minute](delaunay2d_rate.png) ![bytes per triangle](delaunay2d_memory.png)"
        if "delaunay2d_rate.png" in plots else "",
        "",
        process_table(rows2, peers2, "triangles", prov),
        "",
        "## Heap per element, in-process (Google Benchmark, CGAL in the same binary)",
        "",
        "Peak heap of one call above what was allocated before it (the benchmark binary counts its "
        "own operator new/delete), per finite element: the working memory, result and input copy "
        "included. Rates: 3D wall clock, 2D CPU time of the calling thread.",
        "",
        "### 3D",
        "",
        gbench_table(gbench_rows(report["delaunay3d_gbench"], "tetrahedron"), "tetrahedron", prov, "wall"),
        "",
        "### 2D",
        "",
        gbench_table(gbench_rows(report["delaunay2d_gbench"], "triangle"), "triangle", prov, "CPU"),
        "",
        "## Predicate stages in the Delaunay runs",
        "",
        "From each run's `--stats` JSON (the first repeat; sequential variants count the same every "
        "time): how many calls each stage decided, and how many exact zeros the symbolic "
        "perturbation resolved.",
        "",
        "### 3D",
        "",
        stage_table(rows3, prov),
        "",
        "### 2D",
        "",
        stage_table(rows2, prov),
        "",
        "## Predicates (bench/predicates_bench)",
        "",
        "![ns per call](predicates.png)" if "predicates.png" in plots else "",
        "",
        "ns per call (CPU time) over 65536 fixed cases per input; `sum`: the sign summed without a "
        "branch (the predicate's own cost), `branch`: the caller branches on it. Ratios from minima.",
        "",
        predicate_table(report["predicates"], prov),
        "",
    ]
    return "\n".join(parts)


# --- Plots ------------------------------------------------------------------------------------

def make_plots(report, out):
    """The PNGs; returns the names written ([] without matplotlib)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        progress("matplotlib not found (Debian: python3-matplotlib): no plots")
        return []
    written = []
    for suite, peers, element in (("delaunay3d", (d3.CGAL, d3.TETGEN), "tetrahedra"),
                                  ("delaunay2d", (d2.CGAL,), "triangles")):
        rows = [r for r in process_rows(report[suite], peers) if r["distribution"] == "uniform" and "seconds" in r]
        programs = [p for p in report[suite]["programs"] if any(r["program"] == p for r in rows)]
        for kind in ("rate", "memory"):
            fig, ax = plt.subplots(figsize=(7, 4.5))
            for p in programs:
                mine = sorted((r for r in rows if r["program"] == p), key=lambda r: r["n"])
                ns = [r["n"] for r in mine]
                style = {"linestyle": "--", "marker": "s"} if p in peers else {"marker": "o"}
                if kind == "rate":
                    best = [r["elements"] * 60.0 / r["seconds"][0] for r in mine]
                    worst = [r["elements"] * 60.0 / r["seconds"][2] for r in mine]
                    ax.errorbar(ns, best, yerr=[[b - w for b, w in zip(best, worst)], [0] * len(best)],
                                label=p, capsize=3, **style)
                else:
                    pts = [(r["n"], r["mb"] * 1024 * 1024 / r["elements"]) for r in mine if r["mb"] is not None]
                    if pts:
                        ax.plot([a for a, _ in pts], [b for _, b in pts], label=p, **style)
            ax.set_xscale("log")
            ax.set_xlabel("points")
            if kind == "rate":
                ax.set_yscale("log")
                ax.set_ylabel(f"{element} per minute (fastest repeat; bar to slowest)")
            else:
                # Log too: at small n the process's own few MB dominate the figure.
                ax.set_yscale("log")
                ax.set_ylabel(f"peak RSS bytes per {element[:-1] if element != 'tetrahedra' else 'tetrahedron'}")
            ax.set_title(f"{suite}, uniform points ({report['provenance']['cpu']}, 1 process per run)")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize="small")
            name = f"{suite}_{kind}.png"
            fig.tight_layout()
            fig.savefig(os.path.join(out, name), dpi=110)
            plt.close(fig)
            written.append(name)
    rows = predicate_rows(report["predicates"])
    impls = ["plain", "filtered", "cgal_epick"]
    groups = [(p, d) for p in pt.PREDICATES for d in ("random", "near", "degenerate")
              if any((p, i, d, "branch") in rows for i in impls)]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    width = 0.8 / len(impls)
    for k, impl in enumerate(impls):
        xs = [i + k * width for i in range(len(groups))]
        ys = [rows.get((p, impl, d, "branch"), (float("nan"),))[0] for p, d in groups]
        ax.bar(xs, ys, width, label=impl)
    ax.set_xticks([i + 0.4 - width / 2 for i in range(len(groups))])
    ax.set_xticklabels([f"{p}\n{d}" for p, d in groups], fontsize="x-small")
    ax.set_yscale("log")
    ax.set_ylabel("ns per call (min), caller branches on the sign")
    ax.legend(fontsize="small")
    ax.grid(True, axis="y", which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "predicates.png"), dpi=110)
    plt.close(fig)
    written.append("predicates.png")
    return written


# --- README -----------------------------------------------------------------------------------

def update_readme(report, path, out):
    """The three README tables, each from the report's data by its own script's formatter."""
    producer = (f"Produced by `scripts/bench_report.py --update-readme` from the report in "
                f"`{os.path.basename(os.path.abspath(out))}` (size {report['size']}, {report['provenance']['date']})")
    pt.update_readme(path, pt.markdown(report["predicates"], ["random", "near", "degenerate"]),
                     producer + ": bench/predicates_bench.")
    d2.update_readme(path, d2.markdown(report["delaunay2d"]),
                     producer + ": the runs of `scripts/bench_delaunay2d.py`.")
    d3.update_readme(path, d3.markdown(report["delaunay3d"]),
                     producer + ": the runs of `scripts/bench_delaunay3d.py`.")


def use_python_with_matplotlib():
    """Debian's matplotlib lives in /usr/bin/python3's path; a python3 earlier in PATH (pyenv, a
    venv) may lack it. Then the whole script is run again by /usr/bin/python3, once."""
    try:
        import matplotlib  # noqa: F401
        return
    except ImportError:
        pass
    system = "/usr/bin/python3"
    if os.environ.get("DTLAB_REPORT_REEXEC") or not os.access(system, os.X_OK) or \
            os.path.realpath(system) == os.path.realpath(sys.executable):
        return
    if subprocess.run([system, "-c", "import matplotlib"], stderr=subprocess.DEVNULL).returncode == 0:
        progress(f"{sys.executable} has no matplotlib: running under {system}")
        os.environ["DTLAB_REPORT_REEXEC"] = "1"
        os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])


def main():
    use_python_with_matplotlib()
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (built if needed)")
    ap.add_argument("--out", help="report directory (default BUILD/bench-report)")
    ap.add_argument("--size", choices=sorted(SIZES), default="default")
    ap.add_argument("--repeats", type=int, help="repeats of everything (default: 2 for ci, 3 otherwise)")
    ap.add_argument("--run-limit", type=float, default=120,
                    help="seconds a Delaunay run of up to 10^6 points may take (scaled up with n); a "
                         "run past it is killed and reported as timed out, and not repeated")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="build jobs when building")
    ap.add_argument("--no-build", action="store_true", help="fail instead of building missing binaries")
    ap.add_argument("--from-report", help="rebuild report.md and plots of an earlier report directory")
    ap.add_argument("--update-readme", action="store_true", help="write the report's tables into docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()
    args.build = os.path.abspath(args.build)

    if args.from_report:
        out = args.from_report
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
    else:
        out = os.path.abspath(args.out or os.path.join(args.build, "bench-report"))
        os.makedirs(out, exist_ok=True)
        bins = binaries(args.build)
        if not args.no_build:
            ensure_built(args.build, args.jobs)
        for key in ("dtlab", "predicates_bench", "delaunay2d_bench", "delaunay3d_bench"):
            if not os.access(bins[key], os.X_OK):
                raise SystemExit(f"{bins[key]} not found (build it, or leave out --no-build)")
        started = datetime.datetime.now()
        report = measure(args, bins, out)
        report["wall_seconds"] = (datetime.datetime.now() - started).total_seconds()
        with open(os.path.join(out, "report.json"), "w") as f:
            json.dump(report, f, indent=1)
    plots = make_plots(report, out)
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write(report_markdown(report, plots))
    progress(f"wrote {os.path.join(out, 'report.md')} and {len(plots)} plots"
             + (f" after {report['wall_seconds']:.0f} s of measurement" if "wall_seconds" in report else ""))
    if args.update_readme:
        update_readme(report, args.readme, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
