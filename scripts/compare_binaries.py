#!/usr/bin/env python3
"""Speed of two `dtlab` binaries on the Delaunay, constrained and meshing jobs, for a refactor that
must keep it (issue 41): each job run by A then B (the order swapped every round), --runs rounds,
reported as the median [min - max] of each binary's own `--stats` seconds (the algorithm's time,
no file output) and of the process's wall time, with the ratio B / A of the medians.

Jobs (inputs made once in --work, as scripts/output_hashes.py makes them; needs gmsh and tetgen):
  delaunay 2D   10^6 uniform points, incremental
  delaunay 3D   10^6 uniform points, incremental; parallel on 2 threads
  constrain 3D  the cube minus a ball (Gmsh's surface at h = 0.02), recover and cdt
  mesh 2D       the square minus a disc at h = 0.002, edge and front
  mesh 3D       the cube minus a ball at h = 0.04 (Gmsh's surface), --remove-cavities
  optimize 3D   TetGen's -pq1.414 mesh of that surface at h = 0.06

  scripts/compare_binaries.py --a /tmp/old/dtlab --b build/dtlab --work /tmp/h --runs 5
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "data"))
import make_mesh2d_examples as examples  # noqa: E402
from bench_mesh3d import GEO  # noqa: E402
from output_hashes import prepare  # noqa: E402


def inputs(work):
    base = prepare(work, 0.06)  # TetGen's mesh at 0.06, as output_hashes.py
    for h in ("0.02", "0.04"):
        surface = os.path.join(base, f"surface_{h}.mesh")
        if not os.path.exists(surface):
            subprocess.run(["gmsh", "-2", "cube_ball.geo", "-clmax", h, "-format", "mesh", "-o", surface], cwd=base,
                           check=True, capture_output=True)
    poly = os.path.join(base, "square_disc_0.002.poly")
    if not os.path.exists(poly):
        outer, circle = examples.square_disc(0.002)
        examples.write_poly(poly, [(outer, 1), (circle, 2)], [(0.5, 0.5)], "square minus disc, spacing 0.002")
    return base


def jobs(base):
    s02, s04 = os.path.join(base, "surface_0.02.mesh"), os.path.join(base, "surface_0.04.mesh")
    return {
        "delaunay 2D 1e6 incremental": ["delaunay", "--random", "1000000", "--stats"],
        "delaunay 3D 1e6 incremental": ["delaunay", "--dim", "3", "--random", "1000000", "--stats"],
        "delaunay 3D 1e6 parallel x2": ["delaunay", "--dim", "3", "--random", "1000000", "--algo", "parallel",
                                        "--threads", "2", "--stats"],
        "constrain 3D recover (h 0.02)": ["constrain", s02, "--method", "recover", "--stats"],
        "constrain 3D cdt (h 0.02)": ["constrain", s02, "--method", "cdt", "--stats"],
        "mesh 2D edge (h 0.002)": ["mesh", os.path.join(base, "square_disc_0.002.poly"), "--size", "0.002",
                                   "--method", "edge", "--stats"],
        "mesh 2D front (h 0.002)": ["mesh", os.path.join(base, "square_disc_0.002.poly"), "--size", "0.002",
                                    "--method", "front", "--stats"],
        "mesh 3D (h 0.04)": ["mesh", s04, "--size", "0.04", "--remove-cavities", "--stats"],
        "optimize 3D TetGen (h 0.06)": ["optimize", os.path.join(base, "tg", "surface.1.ele"), "-o",
                                        os.path.join(base, "optimized.mesh"),
                                        "--size", "0.06", "--stats"],
    }


def own_seconds(stdout):
    """The `seconds` of the last JSON line: a number, or an object with its total."""
    for line in reversed(stdout.splitlines()):
        if line.startswith("{"):
            s = json.loads(line).get("seconds")
            if isinstance(s, dict):
                s = s.get("total")
            return float(s) if s is not None else float("nan")
    return float("nan")


def run(binary, cmd):
    t0 = time.perf_counter()
    p = subprocess.run([binary] + cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit(f"compare_binaries: {binary} {' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-1500:]}")
    return own_seconds(p.stdout), wall


def fmt(values):
    return f"{statistics.median(values):.3f} [{min(values):.3f} - {max(values):.3f}]"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--a", required=True, help="the binary before")
    ap.add_argument("--b", required=True, help="the binary after")
    ap.add_argument("--work", required=True)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--jobs", default="", help="comma-separated substrings of job names to keep (default: all)")
    args = ap.parse_args()
    base = inputs(os.path.abspath(args.work))
    todo = jobs(base)
    if args.jobs:
        keep = args.jobs.split(",")
        todo = {k: v for k, v in todo.items() if any(s in k for s in keep)}
    binaries = {"A": os.path.abspath(args.a), "B": os.path.abspath(args.b)}
    times = {(j, b): ([], []) for j in todo for b in binaries}
    for r in range(args.runs):
        order = ["A", "B"] if r % 2 == 0 else ["B", "A"]
        for j, cmd in todo.items():
            for b in order:
                own, wall = run(binaries[b], cmd)
                times[(j, b)][0].append(own)
                times[(j, b)][1].append(wall)
        print(f"round {r + 1}/{args.runs} done", file=sys.stderr)
    print(f"A = {binaries['A']}\nB = {binaries['B']}\n{args.runs} interleaved runs each, median [min - max] seconds\n")
    print("| job | A own | B own | B/A own | A wall | B wall | B/A wall |")
    print("|---|---|---|---|---|---|---|")
    for j in todo:
        (ao, aw), (bo, bw) = times[(j, "A")], times[(j, "B")]
        print(f"| {j} | {fmt(ao)} | {fmt(bo)} | {statistics.median(bo) / statistics.median(ao):.3f} | {fmt(aw)} | "
              f"{fmt(bw)} | {statistics.median(bw) / statistics.median(aw):.3f} |")


if __name__ == "__main__":
    main()
