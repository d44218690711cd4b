#!/usr/bin/env python3
"""Time and peak memory of every 2D Delaunay variant beside CGAL, one process per run.

For each size n and distribution, runs
    build/dtlab delaunay --random N --distribution D --seed S --algo A --stats   (every variant)
    build/bench/cgal_delaunay2d_run_bench --random N --distribution D --seed S   (CGAL, same points)
RUNS times each (interleaved: round 1 of every program, then round 2, ...), so that each peak
resident memory is that run's alone, and prints a Markdown table per (n, distribution, program):
seconds (the program's own timing of the triangulation, input copy included: minimum over the
runs), million triangles per minute (from that minimum), peak resident MB of the process
(maximum over the runs; point generation included, as for every program), time / CGAL's time and
time / the same program's time on uniform points of the same n (both from this invocation's
minima), and the process's CPU time (user + system, whole process, minimum). A machine, compiler
and commit line comes first. The raw measurements go to a JSON file.

  scripts/bench_delaunay2d.py                                  # 10^5 and 10^6, all distributions
  scripts/bench_delaunay2d.py --build build-bench2 --large     # and 10^7 uniform
  scripts/bench_delaunay2d.py --sizes 100000 --distributions uniform,grid --runs 5
  scripts/bench_delaunay2d.py --from-json run.json --update-readme   # table of an earlier run into docs/performance.md

--update-readme writes the table between <!-- perf-delaunay2d:begin --> and
<!-- perf-delaunay2d:end --> in docs/performance.md (--readme PATH: another file), which sit
inside the <!-- perf-table:begin/end --> block (inserted at its end if absent); nothing else in
the file changes.
"""
import argparse
import json
import os
import platform
import resource
import signal
import subprocess
import sys

import readme_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DISTRIBUTIONS = ["uniform", "normal", "grid", "circle", "clustered"]
CGAL = "cgal"


def progress(msg):
    print(msg, file=sys.stderr, flush=True)


def list_variants(dtlab):
    out = subprocess.run([dtlab, "delaunay", "--list-algos"], check=True, stdout=subprocess.PIPE,
                         text=True).stdout
    return [line.split("\t", 1)[0] for line in out.splitlines() if line.strip()]


def run_once(cmd, timeout):
    """(JSON record of the last '{' line of stdout, None) or (None, error text)."""
    # Through a shell that forks the program: Linux carries a process's peak RSS across exec,
    # so a program forked from this Python process would report Python's resident size as its
    # floor (about 14 MB); forked from the shell, its floor is the shell's (about 1 MB). A
    # session of its own, so that a timeout kills the program and not only the shell.
    proc = subprocess.Popen(["sh", "-c", '"$@"; exit $?', "sh"] + cmd, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, f"timed out after {timeout:g} s"
    if proc.returncode != 0:
        return None, f"exit {proc.returncode}: {err.strip()[-300:]}"
    lines = [line for line in out.splitlines() if line.startswith("{")]
    if not lines:
        return None, "no JSON line in the output"
    return json.loads(lines[-1]), None


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def command(args, program, n, distribution):
    common = ["--random", str(n), "--distribution", distribution, "--seed", str(args.seed)]
    if program == CGAL:
        return [args.cgal] + common
    return [args.dtlab, "delaunay"] + common + ["--algo", program, "--stats"]


def measure(args, programs, cases, save):
    """Raw records: one per (n, distribution, program, run). A program that timed out or took
    more than --slow seconds on a case is not run again on it."""
    records = []
    for n, distribution in cases:
        done = set()
        for run in range(args.runs):
            for program in programs:
                if program in done:
                    continue
                cmd = command(args, program, n, distribution)
                # communicate() reaps the child, whose rusage then joins RUSAGE_CHILDREN.
                cpu_before = children_cpu()
                result, error = run_once(cmd, args.timeout * max(1.0, n / 1e6))
                cpu = children_cpu() - cpu_before
                rec = {"n": n, "distribution": distribution, "program": program, "run": run,
                       "command": " ".join(cmd), "process_cpu_seconds": cpu}
                if error:
                    rec["error"] = error
                    done.add(program)
                    progress(f"  n={n} {distribution} {program} run {run + 1}: ERROR {error}")
                else:
                    rec.update({k: result[k] for k in ("points", "elements", "seconds",
                                                       "elements_per_minute", "peak_rss_mb",
                                                       "cgal_version", "predicates") if k in result})
                    if result["seconds"] > args.slow:
                        done.add(program)
                    progress(f"  n={n} {distribution} {program} run {run + 1}/{args.runs}: "
                             f"{result['seconds']:.3f} s, {result['peak_rss_mb']:.0f} MB")
                records.append(rec)
        save(records)
    return records


def summarise(records):
    """{(n, distribution, program): {"seconds", "cpu", "mb", "elements", "errors", "runs"}}"""
    out = {}
    for r in records:
        key = (r["n"], r["distribution"], r["program"])
        s = out.setdefault(key, {"seconds": None, "cpu": None, "mb": None, "elements": set(),
                                 "errors": [], "runs": 0})
        if "error" in r:
            s["errors"].append(r["error"])
            continue
        s["runs"] += 1
        s["seconds"] = r["seconds"] if s["seconds"] is None else min(s["seconds"], r["seconds"])
        s["cpu"] = (r["process_cpu_seconds"] if s["cpu"] is None
                    else min(s["cpu"], r["process_cpu_seconds"]))
        s["mb"] = r["peak_rss_mb"] if s["mb"] is None else max(s["mb"], r["peak_rss_mb"])
        s["elements"].add(r["elements"])
    return out


def fmt(v, digits=3):
    if v is None:
        return "–"
    return f"{v:.{digits}g}" if abs(v) < 10 ** digits else f"{v:.0f}"


def size_label(n):
    digits = str(n)
    return f"10^{len(digits) - 1}" if digits[0] == "1" and set(digits[1:]) <= {"0"} else digits


def table(summary, programs, cases, runs):
    head = ["n", "distribution", "program", "seconds", "Mtriangles/min", "peak MB", "time / CGAL",
            "time / uniform", "process CPU s"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    notes = []
    for n, distribution in cases:
        cgal = summary.get((n, distribution, CGAL), {})
        counts = set()
        for program in programs:
            s = summary.get((n, distribution, program))
            if s is None:
                continue
            counts |= s["elements"]
            if s["runs"] == 0:
                lines.append(f"| {size_label(n)} | {distribution} | {program} | error: {s['errors'][0]} |"
                             + " |" * (len(head) - 4))
                continue
            uniform = summary.get((n, "uniform", program), {})
            per_minute = min(s["elements"]) * 60.0 / s["seconds"] / 1e6 if s["seconds"] else None
            ratio_cgal = (s["seconds"] / cgal["seconds"]) if cgal.get("seconds") else None
            ratio_uniform = (s["seconds"] / uniform["seconds"]) if uniform.get("seconds") else None
            name = f"**{program}**" if program == CGAL else program
            lines.append("| " + " | ".join([
                size_label(n),
                distribution, name, fmt(s["seconds"]) + (" †" if s["runs"] < runs else ""), fmt(per_minute), fmt(s["mb"]),
                fmt(ratio_cgal, 2), fmt(ratio_uniform, 2), fmt(s["cpu"])]) + " |")
            if s["errors"]:
                notes.append(f"{program} on {distribution} n={n}: {len(s['errors'])} failed run(s): "
                             f"{s['errors'][0]}")
        short = [p for p in programs if 0 < summary.get((n, distribution, p), {}).get("runs", runs) < runs]
        if short and not any(note.startswith("†") for note in notes):
            notes.append(f"† fewer runs than {runs}: a run longer than the --slow limit is not repeated")
        if len(counts) > 1:
            notes.append(f"n={n} {distribution}: the programs disagree on the number of triangles "
                         f"({sorted(counts)})")
    return "\n".join(lines), notes


def shell(cmd, cwd=None):
    try:
        return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def machine(dtlab):
    model = "unknown CPU"
    for line in shell(["lscpu"]).splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    return {"cpu": model, "cpus": os.cpu_count(), "load_average": list(os.getloadavg()),
            "compiler": shell(["g++", "--version"]).splitlines()[0] if shell(["g++", "--version"]) else "unknown",
            "commit": shell(["git", "describe", "--always", "--dirty", "--abbrev=12"], cwd=ROOT),
            "dtlab_version": shell([dtlab, "--version"]),
            "system": platform.platform()}


def machine_line(m, runs, seed):
    load = ", ".join(f"{x:.1f}" for x in m.get("load_average", []))
    return (f"Machine: {m['cpu']}, {m['cpus']} CPUs (load average {load} at the start); "
            f"compiler {m['compiler']}; `{m.get('dtlab_version', 'dtlab')}` (tree at {m['commit']}); CGAL {m.get('cgal', 'unknown')}. "
            f"One process per run, points seed {seed}; seconds: minimum of {runs} runs, "
            f"peak MB: maximum; ratios of minima from this one invocation.")


def markdown(data):
    programs = data["programs"]
    cases = [tuple(c) for c in data["cases"]]
    summary = summarise(data["records"])
    body, notes = table(summary, programs, cases, data["runs"])
    text = machine_line(data["machine"], data["runs"], data["seed"]) + "\n\n" + body + "\n"
    if notes:
        text += "\n" + "\n".join(f"- {note}" for note in notes) + "\n"
    return text


PRODUCER = ("Produced by `scripts/bench_delaunay2d.py --update-readme` (dtlab's variants through "
            "`dtlab delaunay --stats`, CGAL's Delaunay_triangulation_2 through "
            "`bench/cgal_delaunay2d_run_bench`, same points).")


def update_readme(path, text, producer=PRODUCER):
    readme_tables.write_block(path, "delaunay2d", "2D Delaunay", producer, text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory")
    ap.add_argument("--dtlab", help="the dtlab binary (default BUILD/dtlab)")
    ap.add_argument("--cgal", help="the CGAL runner (default BUILD/bench/cgal_delaunay2d_run_bench)")
    ap.add_argument("--sizes", default="100000,1000000")
    ap.add_argument("--distributions", default=",".join(DISTRIBUTIONS))
    ap.add_argument("--large", action="store_true", help="also 10^7 uniform points")
    ap.add_argument("--variants", help="comma-separated (default: every registered variant)")
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=600,
                    help="seconds per run of 10^6 points (scaled up with n); a run past it is killed")
    ap.add_argument("--slow", type=float, default=60,
                    help="a run longer than this (seconds) is not repeated")
    ap.add_argument("--json", help="write the measurements here (default BUILD/bench_delaunay2d.json)")
    ap.add_argument("--from-json", help="print the table of an earlier run instead of measuring")
    ap.add_argument("--update-readme", action="store_true", help="write the table into docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()
    args.dtlab = args.dtlab or os.path.join(args.build, "dtlab")
    args.cgal = args.cgal or os.path.join(args.build, "bench", "cgal_delaunay2d_run_bench")

    if args.from_json:
        with open(args.from_json) as f:
            data = json.load(f)
    else:
        programs = args.variants.split(",") if args.variants else list_variants(args.dtlab)
        if not args.no_cgal:
            if not os.access(args.cgal, os.X_OK):
                raise SystemExit(f"{args.cgal} not found (build it with CGAL, or pass --no-cgal)")
            programs.append(CGAL)
        cases = [(int(n), d) for n in args.sizes.split(",") if n
                 for d in args.distributions.split(",") if d]
        if args.large:
            cases.append((10_000_000, "uniform"))
        m = machine(args.dtlab)
        progress(f"{len(cases)} cases x {len(programs)} programs x {args.runs} runs: {', '.join(programs)}")
        path = args.json or os.path.join(args.build, "bench_delaunay2d.json")
        data = {"machine": m, "programs": programs, "cases": cases, "runs": args.runs,
                "seed": args.seed, "records": []}

        def save(records):
            data["records"] = records
            data["machine"]["load_average_end"] = list(os.getloadavg())
            data["machine"]["cgal"] = next((r["cgal_version"] for r in records if "cgal_version" in r),
                                           "not run")
            with open(path, "w") as f:
                json.dump(data, f, indent=1)

        measure(args, programs, cases, save)
        progress(f"wrote {path}")

    text = markdown(data)
    print(text)
    if args.update_readme:
        update_readme(args.readme, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
