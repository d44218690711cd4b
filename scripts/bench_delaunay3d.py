#!/usr/bin/env python3
"""Time and peak memory of every 3D Delaunay variant beside CGAL, TetGen and Gmsh's HXT, one
process per run.

For each size n and distribution D (verify/generators/points3d.hpp), runs on the same points:
    build/dtlab delaunay --dim 3 --random N --distribution D --seed S --algo A --stats [--threads T]
    build/bench/cgal_delaunay3d_run_bench --random N --distribution D --seed S       (CGAL DT3)
    tetgen -NEFIB points.node    (TetGen 1.5, Debian's binary; the points written once per case by
                                  cgal_delaunay3d_run_bench --write-node; no output files)
    Delaunay_CLI -i points.msh -t T -s -v 1   (Gmsh's HXT, Marot-Pellerin-Remacle 2019, when
                                  --hxt PATH is given, once per --threads value as hxt-tT; the
                                  points written once per case by --write-msh; no output file)
RUNS times each (interleaved: round 1 of every program, then round 2, ...), and prints a Markdown
table row per (n, distribution, program): seconds (the program's own timing of the
tetrahedralization: dtlab's and CGAL's JSON: wall clock; TetGen's "Delaunay seconds" line: its
clock(), CPU time; HXT's "Init + BRIO + Delaunay took" line: wall clock, to 10 ms) as the median
over the runs with the spread (min-max), the process's CPU time (user + system, point generation
or reading included: median and spread), million tetrahedra per minute, peak resident MB of the
process (maximum over the runs), bytes of peak RSS per tetrahedron, time / CGAL, time / HXT on as
many threads (a sequential variant: HXT on 1), time / TetGen and time / the same program on
uniform points of the same n (ratios of this invocation's medians), and nanoseconds per point.
Then, per program and distribution, how flat the time per point stays from 10^4 to the largest n
(issue 23 asks for +-20 % from 10^4 to 10^7). A machine, compiler, commit and load line comes
first. The raw measurements go to a JSON file.

A variant that is registered but not written yet (dtlab says "not built yet") is left out; a
variant with "parallel" in its name runs once per --threads value, as "parallel-t1", ...; when
the dtlab binary has no --threads option, those rows are left out.

Peers' peak RSS is taken with GNU time (/usr/bin/time, Debian's `time` package): Linux carries
a process's peak RSS across exec, so a program started from Python would report Python's resident
size as its floor, and TetGen and HXT cannot report their own. Without /usr/bin/time that column
is "-". HXT counts its ghost tetrahedra in "Mesh contains N tetrahedra": its rows give that count
as printed, and the check that all programs made as many tetrahedra leaves HXT out.

  scripts/bench_delaunay3d.py --build build                 # uniform 10^4..10^6, the others at 10^5, 5 runs
  scripts/bench_delaunay3d.py --build build --large         # and 10^7 uniform
  scripts/bench_delaunay3d.py --sizes 1000000 --distributions grid,clustered --distribution-sizes 1000000
  scripts/bench_delaunay3d.py --sizes 1000000 --distributions '' --hxt /tmp/peers/hxt/build/Delaunay_CLI
  scripts/bench_delaunay3d.py --from-json build/bench_delaunay3d.json --update-readme

--update-readme writes the table between <!-- perf-delaunay3d:begin --> and
<!-- perf-delaunay3d:end --> in docs/performance.md (scripts/readme_tables.py; --readme PATH:
another file), inside the perf-table block.
"""
import argparse
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile

import readme_tables
from bench_delaunay2d import (children_cpu, fmt, fmt_spread, load_text, machine, progress, run_once, run_peer,
                              size_label)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CGAL = "cgal"
TETGEN = "tetgen"
HXT = "hxt"  # programs hxt-t1, hxt-t2, ...
PEERS = (CGAL, TETGEN)
# TetGen times its phases with clock(), the process's CPU time; dtlab and CGAL report wall time.
TETGEN_NOTE = ("‡ TetGen's own timing is CPU time (clock()), the others' wall time: equal on an idle "
               "machine; on a busy one the ratios to TetGen favour TetGen (compare the process CPU column)")
HXT_NOTE = ("§ HXT's own timing is its \"Init + BRIO + Delaunay took\" line (wall clock, printed to 10 ms: "
            "its sort and insertion, not the reading of the points); its tetrahedron count holds its ghost "
            "tetrahedra, so its Mtets/min and bytes/tet are on that count")
PRODUCER = ("Produced by `scripts/bench_delaunay3d.py --update-readme` (dtlab's variants through "
            "`dtlab delaunay --dim 3 --stats`, CGAL's Delaunay_triangulation_3 through "
            "`bench/cgal_delaunay3d_run_bench`, TetGen 1.5 through its Debian binary, Gmsh's HXT through "
            "its `Delaunay_CLI`, same points).")


def dtlab_variants(dtlab, threads):
    """Program names of every 3D variant that runs: a parallel one once per thread count."""
    out = subprocess.run([dtlab, "delaunay", "--dim", "3", "--list-algos"], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    has_threads = "--threads" in subprocess.run([dtlab, "delaunay", "--help"], stdout=subprocess.PIPE,
                                                stderr=subprocess.STDOUT, text=True).stdout
    programs = []
    for name in (line.split("\t", 1)[0] for line in out.splitlines() if line.strip()):
        probe = subprocess.run([dtlab, "delaunay", "--dim", "3", "--random", "200", "--algo", name],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if "not built yet" in probe.stderr:
            progress(f"{name}: not built yet, left out")
            continue
        if "parallel" not in name:
            programs.append(name)
        elif has_threads:
            programs += [f"{name}-t{t}" for t in threads]
        else:
            progress(f"{name}: this dtlab has no --threads option, left out")
    return programs


def split_threads(program):
    """("parallel", 2) for "parallel-t2", ("hxt", 1) for "hxt-t1"; (program, None) otherwise."""
    m = re.fullmatch(r"(.*parallel.*|hxt)-t(\d+)", program)
    return (m.group(1), int(m.group(2))) if m else (program, None)


def is_hxt(program):
    return split_threads(program)[0] == HXT


def is_peer(program):
    return program in PEERS or is_hxt(program)


def parse_hxt(text, n):
    """HXT's Delaunay_CLI -s prints "Mesh contains T tetrahedra and V vertices" (T with ghosts)
    and "Init + BRIO + Delaunay took S seconds"."""
    seconds = re.search(r"Init \+ BRIO \+ Delaunay took ([0-9.]+) seconds", text)
    tets = re.search(r"Mesh contains (\d+) tetrahedra", text)
    if not seconds or not tets:
        return "no 'Init + BRIO + Delaunay took' / 'Mesh contains' line in HXT's output"
    return {"points": n, "elements": int(tets.group(1)), "seconds": float(seconds.group(1))}


def tetgen_once(args, node_file, n, timeout):
    """TetGen's record (elements, seconds, peak_rss_mb or None) or (None, error text)."""
    cmd = [args.tetgen, "-NEFIB", node_file]
    measured = os.access(args.gnu_time, os.X_OK)
    if measured:
        cmd = [args.gnu_time, "-f", "dtlab-peak-rss-kb %M"] + cmd
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
    seconds = re.search(r"^Delaunay seconds:\s*([0-9.eE+-]+)", out, re.M)
    tets = re.search(r"^\s*Mesh tetrahedra:\s*(\d+)", out, re.M)
    if not seconds or not tets:
        return None, "no 'Delaunay seconds' / 'Mesh tetrahedra' line in TetGen's output"
    rss = re.search(r"dtlab-peak-rss-kb (\d+)", err) if measured else None
    result = {"points": n, "elements": int(tets.group(1)), "seconds": float(seconds.group(1)),
              "peak_rss_mb": int(rss.group(1)) / 1024.0 if rss else None}
    result["elements_per_minute"] = result["elements"] * 60.0 / result["seconds"] if result["seconds"] else None
    return result, None


def command(args, program, n, distribution):
    common = ["--random", str(n), "--distribution", distribution, "--seed", str(args.seed)]
    if program == CGAL:
        return [args.cgal] + common
    variant, threads = split_threads(program)
    cmd = [args.dtlab, "delaunay", "--dim", "3"] + common + ["--algo", variant, "--stats"]
    return cmd + (["--threads", str(threads)] if threads else [])


def measure(args, programs, cases, save):
    """Raw records: one per (n, distribution, program, run). A program that failed, timed out or
    took more than --slow seconds on a case is not run again on it."""
    records = []
    scratch = tempfile.mkdtemp(prefix="dtlab-bench3d-")
    try:
        for n, distribution in cases:
            done = set()
            node_file = os.path.join(scratch, f"{distribution}-{n}.node")
            msh_file = os.path.join(scratch, f"{distribution}-{n}.msh")
            writes = (["--write-node", node_file] if TETGEN in programs else []) + \
                (["--write-msh", msh_file] if any(is_hxt(p) for p in programs) else [])
            if writes:
                subprocess.run([args.cgal, "--random", str(n), "--distribution", distribution, "--seed",
                                str(args.seed)] + writes, check=True)
            for run in range(args.runs):
                for program in programs:
                    if program in done:
                        continue
                    timeout = args.timeout * max(1.0, n / 1e6)
                    cpu_before = children_cpu()
                    if program == TETGEN:
                        cmd = [args.tetgen, "-NEFIB", node_file]
                        result, error = tetgen_once(args, node_file, n, timeout)
                    elif is_hxt(program):
                        cmd = [args.hxt, "-i", msh_file, "-t", str(split_threads(program)[1]), "-s", "-v", "1"]
                        result, error = run_peer(cmd, timeout, args.gnu_time, lambda text: parse_hxt(text, n))
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
                        rec.update({k: result[k] for k in ("points", "elements", "seconds", "elements_per_minute",
                                                           "peak_rss_mb", "cgal_version", "predicates",
                                                           "threads") if k in result})
                        if result["seconds"] > args.slow:
                            done.add(program)
                        mb = result.get("peak_rss_mb")
                        progress(f"  n={n} {distribution} {program} run {run + 1}/{args.runs}: "
                                 f"{result['seconds']:.3f} s, cpu {cpu:.3f} s, "
                                 + (f"{mb:.0f} MB" if mb is not None else "peak MB not measured"))
                    records.append(rec)
            for f in (node_file, msh_file):
                if os.path.exists(f):
                    os.remove(f)
            save(records)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return records


def summarise(records):
    """{(n, distribution, program): {"seconds", "cpu", "mb", "times", "cpus", "elements", "errors",
    "runs"}}: seconds and cpu are the medians of the runs' lists times and cpus, mb the maximum."""
    out = {}
    for r in records:
        s = out.setdefault((r["n"], r["distribution"], r["program"]),
                           {"seconds": None, "cpu": None, "mb": None, "times": [], "cpus": [], "elements": set(),
                            "errors": [], "runs": 0})
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


def ratio(s, peer):
    return s["seconds"] / peer["seconds"] if peer.get("seconds") and s["seconds"] else None


def hxt_peer(program, programs):
    """The HXT program on as many threads as `program` (a sequential variant: 1), if it ran."""
    threads = split_threads(program)[1] or 1
    name = f"{HXT}-t{threads}"
    return name if name in programs else None


def table(summary, programs, cases, runs):
    head = ["n", "distribution", "program", "seconds: median (min–max)", "process CPU s: median (min–max)",
            "Mtets/min", "peak MB", "bytes/tet", "time / CGAL", "time / HXT same threads", "time / TetGen",
            "time / uniform", "ns/point"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    notes = []
    for n, distribution in cases:
        cgal = summary.get((n, distribution, CGAL), {})
        tetgen = summary.get((n, distribution, TETGEN), {})
        counts = set()
        for program in programs:
            s = summary.get((n, distribution, program))
            if s is None:
                continue
            if not is_hxt(program):  # HXT's count holds its ghosts
                counts |= s["elements"]
            if s["runs"] == 0:
                lines.append(f"| {size_label(n)} | {distribution} | {program} | error: {s['errors'][0]} |"
                             + " |" * (len(head) - 4))
                continue
            uniform = summary.get((n, "uniform", program), {})
            hxt_name = hxt_peer(program, programs)
            hxt = summary.get((n, distribution, hxt_name), {}) if hxt_name and not is_peer(program) else {}
            tets = min(s["elements"])
            per_minute = tets * 60.0 / s["seconds"] / 1e6 if s["seconds"] else None
            per_tet = s["mb"] * 1024 * 1024 / tets if s["mb"] is not None and tets else None
            name = f"**{program}**" if is_peer(program) else program
            mark = (" †" if s["runs"] < runs else "") + (" ‡" if program == TETGEN else "") + \
                (" §" if is_hxt(program) else "")
            lines.append("| " + " | ".join([
                size_label(n), distribution, name, fmt_spread(s["times"]) + mark, fmt_spread(s["cpus"]),
                fmt(per_minute), fmt(s["mb"]), fmt(per_tet), fmt(ratio(s, cgal), 2), fmt(ratio(s, hxt), 2),
                fmt(ratio(s, tetgen), 2), fmt(ratio(s, uniform), 2), fmt(s["seconds"] * 1e9 / n)]) + " |")
            if s["errors"]:
                notes.append(f"{program} on {distribution} n={n}: {len(s['errors'])} failed run(s): "
                             f"{s['errors'][0]}")
        if any(0 < summary.get((n, distribution, p), {}).get("runs", runs) < runs for p in programs) and \
                not any(note.startswith("†") for note in notes):
            notes.append(f"† fewer runs than {runs}: a run longer than the --slow limit is not repeated")
        if TETGEN in programs and not any(note.startswith("‡") for note in notes):
            notes.append(TETGEN_NOTE)
        if any(is_hxt(p) for p in programs) and not any(note.startswith("§") for note in notes):
            notes.append(HXT_NOTE)
        if len(counts) > 1:
            notes.append(f"n={n} {distribution}: the programs disagree on the number of tetrahedra "
                         f"({sorted(counts)}): different points, duplicates or degeneracies handled "
                         f"differently, or a wrong result")
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


def machine_line(m, runs, seed):
    return (f"Machine: {m['cpu']}, {m['cpus']} CPUs (1-minute load average {load_text(m)}); "
            f"compiler {m['compiler']}; `{m.get('dtlab_version', 'dtlab')}` (tree at {m['commit']}); "
            f"CGAL {m.get('cgal', 'unknown')}; TetGen {m.get('tetgen', 'unknown')}; HXT {m.get('hxt', 'not run')}. "
            f"One process per run, points of verify/generators/points3d.hpp, seed {seed}, {runs} interleaved runs; "
            f"seconds: each program's own timing of the tetrahedralization, median (min–max) of the runs; "
            f"process CPU likewise; peak MB: maximum; bytes/tet: peak RSS per finite tetrahedron; ratios of "
            f"medians from this one invocation.")


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


def update_readme(path, text, producer=PRODUCER):
    readme_tables.write_block(path, "delaunay3d", "3D Delaunay", producer, text)


def tetgen_version(tetgen):
    """TetGen prints no version; Debian's package does."""
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "tetgen"], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True).stdout.strip()
    except OSError:
        out = ""
    return f"{out} (Debian package)" if out else os.path.basename(tetgen)


def programs_for(args):
    """The programs to run, dtlab's variants first, the peers last."""
    if args.variants:
        # A parallel variant named without its thread count runs once per --threads value.
        programs = []
        for name in args.variants.split(","):
            if "parallel" in name and split_threads(name)[1] is None:
                programs += [f"{name}-t{t}" for t in args.threads]
            else:
                programs.append(name)
    else:
        programs = dtlab_variants(args.dtlab, args.threads)
    if not args.no_cgal:
        if not os.access(args.cgal, os.X_OK):
            raise SystemExit(f"{args.cgal} not found (build it with CGAL, or pass --no-cgal)")
        programs.append(CGAL)
    if not args.no_tetgen:
        if shutil.which(args.tetgen) is None:
            progress(f"{args.tetgen} not found: TetGen left out (Debian package `tetgen`)")
        elif not os.access(args.cgal, os.X_OK):
            progress("TetGen needs the CGAL runner to write its points: left out")
        else:
            programs.append(TETGEN)
    if args.hxt:
        if not os.access(args.hxt, os.X_OK):
            raise SystemExit(f"{args.hxt} is not an executable (--hxt)")
        if not os.access(args.cgal, os.X_OK):
            raise SystemExit("--hxt needs the CGAL runner, which writes HXT's points")
        programs += [f"{HXT}-t{t}" for t in args.threads]
    return programs


def add_arguments(ap):
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory")
    ap.add_argument("--dtlab", help="the dtlab binary (default BUILD/dtlab)")
    ap.add_argument("--cgal", help="the CGAL runner (default BUILD/bench/cgal_delaunay3d_run_bench)")
    ap.add_argument("--tetgen", default="tetgen", help="the TetGen binary")
    ap.add_argument("--gnu-time", default="/usr/bin/time", help="GNU time, for TetGen's and HXT's peak RSS")
    ap.add_argument("--variants", help="comma-separated programs (default: every built variant; a parallel "
                    "variant without -tN runs once per --threads value)")
    ap.add_argument("--threads", default="1,2", help="thread counts of a parallel variant")
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--no-tetgen", action="store_true")
    ap.add_argument("--hxt", help="Gmsh HXT's Delaunay_CLI: run it beside dtlab, once per --threads value")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=600,
                    help="seconds per run of 10^6 points (scaled up with n); a run past it is killed")
    ap.add_argument("--slow", type=float, default=60, help="a run longer than this (seconds) is not repeated")


def resolve(args):
    args.dtlab = args.dtlab or os.path.join(args.build, "dtlab")
    args.cgal = args.cgal or os.path.join(args.build, "bench", "cgal_delaunay3d_run_bench")
    args.threads = [int(t) for t in str(args.threads).split(",") if t]


def run(args, cases, path):
    """Measures, writes the JSON to `path` after each size, returns the data."""
    programs = programs_for(args)
    m = machine(args.dtlab)
    m["tetgen"] = tetgen_version(args.tetgen) if TETGEN in programs else "not run"
    m["hxt"] = f"Gmsh contrib/hxt ({args.hxt})" if args.hxt else "not run"
    progress(f"3D: {len(cases)} cases x {len(programs)} programs x {args.runs} runs: {', '.join(programs)}")
    data = {"machine": m, "programs": programs, "cases": cases, "runs": args.runs, "seed": args.seed,
            "records": []}

    def save(records):
        data["records"] = records
        data["machine"]["load_average_end"] = list(os.getloadavg())
        data["machine"]["cgal"] = next((r["cgal_version"] for r in records if "cgal_version" in r), "not run")
        with open(path, "w") as f:
            json.dump(data, f, indent=1)

    measure(args, programs, cases, save)
    progress(f"wrote {path}")
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_arguments(ap)
    ap.add_argument("--sizes", default="10000,100000,1000000", help="sizes of the uniform runs")
    ap.add_argument("--distributions", default="normal,grid,sphere,clustered",
                    help="other distributions (points3d.hpp names), at --distribution-sizes")
    ap.add_argument("--distribution-sizes", default="100000")
    ap.add_argument("--large", action="store_true", help="also 10^7 uniform points")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--json", help="write the measurements here (default BUILD/bench_delaunay3d.json)")
    ap.add_argument("--from-json", help="print the table of an earlier run instead of measuring")
    ap.add_argument("--update-readme", action="store_true", help="write the table into docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()
    resolve(args)

    if args.from_json:
        with open(args.from_json) as f:
            data = json.load(f)
    else:
        cases = [(int(n), "uniform") for n in args.sizes.split(",") if n]
        if args.large and (10_000_000, "uniform") not in cases:
            cases.append((10_000_000, "uniform"))
        cases += [(int(n), d) for n in args.distribution_sizes.split(",") if n
                  for d in args.distributions.split(",") if d and d != "uniform"]
        data = run(args, cases, args.json or os.path.join(args.build, "bench_delaunay3d.json"))

    text = markdown(data)
    print(text)
    if args.update_readme:
        update_readme(args.readme, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
