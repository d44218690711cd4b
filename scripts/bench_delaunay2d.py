#!/usr/bin/env python3
"""Time and peak memory of every 2D Delaunay variant beside CGAL and Triangle, one process per run.

For each size n and distribution, runs
    build/dtlab delaunay --random N --distribution D --seed S --algo A --stats   (every variant)
    build/bench/cgal_delaunay2d_run_bench --random N --distribution D --seed S   (CGAL, same points)
    triangle -NEI points.node    (Shewchuk's Triangle 1.6, its default divide-and-conquer, when
                                  --triangle PATH is given; the points written once per case by
                                  cgal_delaunay2d_run_bench --write-node; no output files)
RUNS times each (interleaved: round 1 of every program, then round 2, ...), so that each peak
resident memory is that run's alone and a burst of load on the machine falls on every program
alike, and prints a Markdown table per (n, distribution, program): seconds (the program's own
timing of the triangulation, input copy included; Triangle's "Delaunay milliseconds" line:
median over the runs, with the spread min-max), the process's CPU time (user + system, whole
process, point generation included: median and spread), million triangles per minute (from the
median), peak resident MB of the process (maximum over the runs), time / CGAL's time, time /
Triangle's and time / the same program's time on uniform points of the same n (ratios of this
invocation's medians). A machine, compiler and commit line comes first. The raw measurements go
to a JSON file.

  scripts/bench_delaunay2d.py                                  # 10^5 and 10^6, all distributions, 5 runs
  scripts/bench_delaunay2d.py --triangle /tmp/peers/triangle/triangle --large   # and 10^7 uniform
  scripts/bench_delaunay2d.py --sizes 100000 --distributions uniform,grid --runs 7
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
import re
import resource
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile

import readme_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DISTRIBUTIONS = ["uniform", "normal", "grid", "circle", "clustered"]
CGAL = "cgal"
TRIANGLE = "triangle"


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


def run_peer(cmd, timeout, gnu_time, parse):
    """A peer that prints its own timing as text: (record, None) or (None, error text). The
    record is parse(stdout + stderr) (a dict, or an error string) with peak_rss_mb from GNU time
    (/usr/bin/time: Linux carries a process's peak RSS across exec, so a peer started from Python
    would report Python's resident size as its floor) or None without it."""
    measured = gnu_time is not None and os.access(gnu_time, os.X_OK)
    if measured:
        cmd = [gnu_time, "-f", "dtlab-peak-rss-kb %M"] + cmd
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, f"timed out after {timeout:g} s"
    if proc.returncode != 0:
        return None, f"exit {proc.returncode}: {(out + err).strip()[-300:]}"
    result = parse(out + err)
    if isinstance(result, str):
        return None, result
    rss = re.search(r"dtlab-peak-rss-kb (\d+)", err) if measured else None
    result["peak_rss_mb"] = int(rss.group(1)) / 1024.0 if rss else None
    if result.get("seconds"):
        result["elements_per_minute"] = result["elements"] * 60.0 / result["seconds"]
    return result, None


def parse_triangle(text, n):
    """Triangle 1.6 prints "Delaunay milliseconds:  T" (its sort and triangulation, not the reading) and "Mesh triangles: N"."""
    ms = re.search(r"^Delaunay milliseconds:\s*(\d+)", text, re.M)
    tris = re.search(r"^\s*Mesh triangles:\s*(\d+)", text, re.M)
    if not ms or not tris:
        return "no 'Delaunay milliseconds' / 'Mesh triangles' line in Triangle's output"
    return {"points": n, "elements": int(tris.group(1)), "seconds": int(ms.group(1)) / 1000.0}


def spread(values):
    """(median, min, max) of a non-empty list."""
    return statistics.median(values), min(values), max(values)


def fmt_spread(values, digits=3):
    """'median (min–max)', or '–' for no value."""
    if not values:
        return "–"
    med, lo, hi = spread(values)
    return f"{fmt(med, digits)} ({fmt(lo, digits)}–{fmt(hi, digits)})"


def command(args, program, n, distribution):
    common = ["--random", str(n), "--distribution", distribution, "--seed", str(args.seed)]
    if program == CGAL:
        return [args.cgal] + common
    return [args.dtlab, "delaunay"] + common + ["--algo", program, "--stats"]


def measure(args, programs, cases, save):
    """Raw records: one per (n, distribution, program, run). A program that timed out or took
    more than --slow seconds on a case is not run again on it."""
    records = []
    scratch = tempfile.mkdtemp(prefix="dtlab-bench2d-")
    try:
        for n, distribution in cases:
            done = set()
            node_file = os.path.join(scratch, f"{distribution}-{n}.node")
            if TRIANGLE in programs:
                subprocess.run([args.cgal, "--random", str(n), "--distribution", distribution, "--seed",
                                str(args.seed), "--write-node", node_file], check=True)
            for run in range(args.runs):
                for program in programs:
                    if program in done:
                        continue
                    timeout = args.timeout * max(1.0, n / 1e6)
                    # communicate() reaps the child, whose rusage then joins RUSAGE_CHILDREN.
                    cpu_before = children_cpu()
                    if program == TRIANGLE:
                        cmd = [args.triangle, "-NEI", node_file]
                        result, error = run_peer(cmd, timeout, getattr(args, "gnu_time", "/usr/bin/time"),
                                                 lambda text: parse_triangle(text, n))
                    else:
                        cmd = command(args, program, n, distribution)
                        result, error = run_once(cmd, timeout)
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
                        mb = result.get("peak_rss_mb")
                        progress(f"  n={n} {distribution} {program} run {run + 1}/{args.runs}: "
                                 f"{result['seconds']:.3f} s, cpu {cpu:.3f} s, "
                                 + (f"{mb:.0f} MB" if mb is not None else "peak MB not measured"))
                    records.append(rec)
            if os.path.exists(node_file):
                os.remove(node_file)
            save(records)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return records


def summarise(records):
    """{(n, distribution, program): {"seconds", "cpu", "mb", "times", "cpus", "elements", "errors",
    "runs"}}: seconds and cpu are the medians of the runs' lists times and cpus, mb the maximum."""
    out = {}
    for r in records:
        key = (r["n"], r["distribution"], r["program"])
        s = out.setdefault(key, {"seconds": None, "cpu": None, "mb": None, "times": [], "cpus": [],
                                 "elements": set(), "errors": [], "runs": 0})
        if "error" in r:
            s["errors"].append(r["error"])
            continue
        s["runs"] += 1
        s["times"].append(r["seconds"])
        s["cpus"].append(r["process_cpu_seconds"])
        s["seconds"] = statistics.median(s["times"])
        s["cpu"] = statistics.median(s["cpus"])
        if r.get("peak_rss_mb") is not None:
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
    head = ["n", "distribution", "program", "seconds: median (min–max)", "process CPU s: median (min–max)",
            "Mtriangles/min", "peak MB", "time / CGAL", "time / Triangle", "time / uniform"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    notes = []
    for n, distribution in cases:
        cgal = summary.get((n, distribution, CGAL), {})
        triangle = summary.get((n, distribution, TRIANGLE), {})
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

            def ratio(peer):
                return s["seconds"] / peer["seconds"] if peer.get("seconds") else None

            name = f"**{program}**" if program in (CGAL, TRIANGLE) else program
            lines.append("| " + " | ".join([
                size_label(n), distribution, name,
                fmt_spread(s["times"]) + (" †" if s["runs"] < runs else ""), fmt_spread(s["cpus"]),
                fmt(per_minute), fmt(s["mb"]), fmt(ratio(cgal), 2), fmt(ratio(triangle), 2),
                fmt(ratio(uniform), 2)]) + " |")
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


def flatness(summary, programs, cases):
    """One line per (program, distribution) measured at two sizes >= 10^4 or more: ns per point
    (median seconds / n) at each n and the half-width of the band around their middle that holds
    them all, (max - min) / (max + min)."""
    lines = []
    for distribution in dict.fromkeys(d for _, d in cases):
        sizes = sorted(n for n, d in cases if d == distribution and n >= 10_000)
        for program in programs:
            per_point = [(n, summary[(n, distribution, program)]["seconds"] * 1e9 / n) for n in sizes
                         if summary.get((n, distribution, program), {}).get("seconds")]
            if len(per_point) < 2:
                continue
            values = [v for _, v in per_point]
            band = 100.0 * (max(values) - min(values)) / (max(values) + min(values))
            series = ", ".join(f"{fmt(v)} at {size_label(n)}" for n, v in per_point)
            lines.append(f"{program}, {distribution}: ns per point {series}: flat within ±{band:.0f} %")
    return lines


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
            "system": platform.platform(), "load_average_during": []}


def load_text(m):
    """The 1-minute load averages at the start and the end of the measurements."""
    start = m.get("load_average", [None])[0]
    end = m.get("load_average_end", [None])[0]
    parts = [f"{start:.1f} at the start" if start is not None else None,
             f"{end:.1f} at the end" if end is not None else None]
    return ", ".join(p for p in parts if p) or "unknown"


def machine_line(m, runs, seed):
    return (f"Machine: {m['cpu']}, {m['cpus']} CPUs (1-minute load average {load_text(m)}); "
            f"compiler {m['compiler']}; `{m.get('dtlab_version', 'dtlab')}` (tree at {m['commit']}); CGAL {m.get('cgal', 'unknown')}"
            f"{'; Triangle ' + m['triangle'] if m.get('triangle') else ''}. "
            f"One process per run, points seed {seed}, {runs} interleaved runs; seconds and CPU: median "
            f"(min–max) of the runs; peak MB: maximum; ratios of medians from this one invocation.")


def markdown(data):
    programs = data["programs"]
    cases = [tuple(c) for c in data["cases"]]
    summary = summarise(data["records"])
    body, notes = table(summary, programs, cases, data["runs"])
    text = machine_line(data["machine"], data["runs"], data["seed"]) + "\n\n" + body + "\n"
    flat = flatness(summary, programs, cases)
    if flat:
        text += "\nTime per point from 10^4 up (medians):\n\n" + "\n".join(f"- {line}" for line in flat) + "\n"
    if notes:
        text += "\n" + "\n".join(f"- {note}" for note in notes) + "\n"
    return text


PRODUCER = ("Produced by `scripts/bench_delaunay2d.py --update-readme` (dtlab's variants through "
            "`dtlab delaunay --stats`, CGAL's Delaunay_triangulation_2 through "
            "`bench/cgal_delaunay2d_run_bench`, Shewchuk's Triangle 1.6 (divide-and-conquer) through its "
            "own binary, same points).")


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
    ap.add_argument("--triangle", help="Triangle 1.6's binary: run it beside dtlab and CGAL (needs the CGAL "
                    "runner, which writes its points)")
    ap.add_argument("--gnu-time", default="/usr/bin/time", help="GNU time, for Triangle's peak RSS")
    ap.add_argument("--runs", type=int, default=5)
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
        if args.triangle:
            if not os.access(args.triangle, os.X_OK):
                raise SystemExit(f"{args.triangle} is not an executable (--triangle)")
            if not os.access(args.cgal, os.X_OK):
                raise SystemExit("--triangle needs the CGAL runner, which writes Triangle's points")
            programs.append(TRIANGLE)
        cases = [(int(n), d) for n in args.sizes.split(",") if n
                 for d in args.distributions.split(",") if d]
        if args.large:
            cases.append((10_000_000, "uniform"))
        m = machine(args.dtlab)
        if args.triangle:
            m["triangle"] = "1.6 (" + args.triangle + ")"
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
