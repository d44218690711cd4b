#!/usr/bin/env python3
"""Markdown tables of the predicate benchmark (bench/predicates_bench.cpp).

Runs build/bench/predicates_bench with --benchmark_format=json and repetitions (or reads a JSON
file it wrote before), and prints ns per call (CPU time: the machine may be shared) as
"median (min–max)" over the repetitions, interleaved in random order
(--benchmark_enable_random_interleaving), with ratios of the medians:
  1. the predicates as callers use them: plain double determinant, dtlab filtered, dtlab
     uncounted, CGAL Epick, filtered/plain and filtered/CGAL, per input distribution;
     one table per consumer of the sign (sum: the predicate's own cost; branch: what a caller
     that branches on the sign pays);
  2. each stage alone, with the share of cases the filter stages leave undecided;
plus the machine, compiler and commit the figures come from.

  scripts/bench_predicates_table.py                       # runs build/bench/predicates_bench
  scripts/bench_predicates_table.py --binary build-bench/bench/predicates_bench --min-time 0.5
  scripts/bench_predicates_table.py --json run.json       # tables of an earlier run
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys

import readme_tables

PREDICATES = ["orient2d", "incircle", "orient3d", "insphere"]
CALLER_IMPLS = [("plain", "plain det"), ("filtered", "filtered"), ("uncounted", "uncounted"),
                ("cgal_epick", "CGAL Epick")]
STAGES = ["semistatic", "adaptive", "expansion", "exact"]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_benchmark(binary, repetitions, min_time, bench_filter):
    cmd = [binary, "--benchmark_format=json", f"--benchmark_repetitions={repetitions}",
           f"--benchmark_min_time={min_time}", "--benchmark_enable_random_interleaving=true"]
    if bench_filter:
        cmd.append(f"--benchmark_filter={bench_filter}")
    print("running: " + " ".join(cmd), file=sys.stderr)
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out)


def collect(data):
    """{(predicate, impl, dist, consumer): {"ns": [per repetition], "undecided": x, "error": msg}}"""
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        parts = b["run_name"].split("/")
        if len(parts) != 4:
            continue
        entry = runs.setdefault(tuple(parts), {"ns": [], "undecided": None, "error": None})
        if b.get("error_occurred"):
            entry["error"] = b.get("error_message", "error")
            continue
        entry["ns"].append(b["time_per_call"] * 1e9)
        entry["undecided"] = b.get("undecided")
    return runs


def fmt_ns(v):
    return f"{v:.3g}" if v < 100 else f"{v:.0f}"


def cell(runs, key):
    e = runs.get(key)
    if e is None:
        return "–", None
    if e["error"]:
        return "error", None
    med, lo, hi = statistics.median(e["ns"]), min(e["ns"]), max(e["ns"])
    return f"{fmt_ns(med)} ({fmt_ns(lo)}–{fmt_ns(hi)})", med


def ratio(a, b):
    return f"{a / b:.2f}" if a is not None and b is not None else "–"


def caller_table(runs, dists, consumer):
    head = ["predicate", "input"] + [name for _, name in CALLER_IMPLS] + ["filtered/plain",
                                                                         "filtered/CGAL"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for p in PREDICATES:
        for d in dists:
            row, medians = [p, d], {}
            for impl, _ in CALLER_IMPLS:
                text, medians[impl] = cell(runs, (p, impl, d, consumer))
                row.append(text)
            row += [ratio(medians["filtered"], medians["plain"]), ratio(medians["filtered"], medians["cgal_epick"])]
            if any(key[0] == p and key[2] == d for key in runs):
                lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def stage_table(runs, dists):
    head = ["predicate", "input"] + [f"{s}" for s in STAGES] + ["undecided by semistatic",
                                                                 "undecided by adaptive"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for p in PREDICATES:
        for d in dists:
            row = [p, d] + [cell(runs, (p, s, d, "sum"))[0] for s in STAGES]
            for s in ("semistatic", "adaptive"):
                e = runs.get((p, s, d, "sum"))
                row.append(f"{100 * e['undecided']:.1f}%" if e and e["undecided"] is not None else "–")
            if any(key[0] == p and key[2] == d for key in runs):
                lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def machine_line(data, repetitions):
    c = data["context"]
    return (f"Machine: {cpu_model()}, {c.get('num_cpus')} CPUs at {c.get('mhz_per_cpu')} MHz "
            f"(load average {', '.join(f'{x:.1f}' for x in c.get('load_avg', []))}); "
            f"compiler {c.get('compiler')} ({c.get('build_type')}, flags `{c.get('flags')}`); "
            f"dtlab {c.get('dtlab_commit')}; CGAL {c.get('cgal', 'not built')}; "
            f"{c.get('cases_per_iteration')} cases per distribution; "
            f"ns per call, CPU time, median (min–max) of {repetitions} repetitions in random interleaved "
            f"order; ratios of medians.")


PRODUCER = "Produced by `scripts/bench_predicates_table.py --update-readme` (bench/predicates_bench)."


def update_readme(path, text, producer=PRODUCER):
    readme_tables.write_block(path, "predicates", "Predicates", producer, text)


def markdown(data, dists):
    """The tables of one predicates_bench JSON output, machine line first."""
    runs = collect(data)
    repetitions = max((len(e["ns"]) for e in runs.values()), default=0)
    out = [machine_line(data, repetitions) + "\n"]
    for consumer, what in (("sum", "sign summed, no branch on it: the predicate's own cost"),
                           ("branch", "caller branches on the sign, as a walk or cavity search does")):
        out.append(f"**Predicates as called** ({what}); ns per call, median (min–max):\n")
        out.append(caller_table(runs, dists, consumer) + "\n")
    all_dists = ["random", "near", "degenerate"]
    out.append("**Stages alone** (sign summed); ns per call, median (min–max), and the share of cases each "
               "filter stage leaves undecided:\n")
    out.append(stage_table(runs, all_dists))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "bench", "predicates_bench"))
    ap.add_argument("--json", help="read this JSON output of predicates_bench instead of running it")
    ap.add_argument("--save-json", help="also write the raw JSON here")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--min-time", type=float, default=0.2, help="seconds per repetition")
    ap.add_argument("--filter", default="", help="--benchmark_filter for the run")
    ap.add_argument("--dists", default="random,near,degenerate", help="distributions shown in the caller tables")
    ap.add_argument("--update-readme", action="store_true",
                    help="also write the tables between <!-- perf-predicates:begin/end --> in docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()

    if args.json:
        with open(args.json) as f:
            data = json.load(f)
    else:
        data = run_benchmark(args.binary, args.repetitions, args.min_time, args.filter)
    if args.save_json:
        with open(args.save_json, "w") as f:
            json.dump(data, f, indent=1)

    text = markdown(data, [d for d in args.dists.split(",") if d])
    print(text)
    if args.update_readme:
        update_readme(args.readme, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
