#!/usr/bin/env python3
"""The 3D mesher's field point insertion on several threads (algorithms/mesh3d/field_point_regions.hpp):
`dtlab mesh` on the cube minus a ball (the surface of scripts/bench_mesh3d.py, `gmsh -2 -clmax H`)
with `--insertion-regions R --threads T` for each R and T given, and optionally a baseline dtlab
binary (an older commit) with its defaults. Runs are interleaved (round 1 of every configuration,
then round 2, ...); times are dtlab's own `--stats` seconds (the meshing call, no file output):
field points (candidates and insertion) and the whole call, median [min - max], never a minimum.
Each configuration's tetrahedron count is checked to be the same in every round, and the meshes of
one region count are checked to be the same bytes for every thread count.

  scripts/bench_mesh3d_threads.py --dtlab build/dtlab --size 0.02 --runs 5 --regions 1,16,64 \
      --threads 1,2 [--baseline /path/to/old/dtlab] [--optimize]
"""
import argparse
import hashlib
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_mesh3d  # noqa: E402  (its GEO: the same domain)


def run(exe, surface, out, h, extra, optimize):
    cmd = [exe, "mesh", surface, "-o", out, "--size", str(h), "--remove-cavities", "--stats"] + extra
    if not optimize:
        cmd.append("--no-optimize")
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"bench_mesh3d_threads: {' '.join(cmd)} failed: {p.stderr.strip()}")
    return json.loads(p.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", default="build/dtlab")
    ap.add_argument("--baseline", help="another dtlab binary, run with its defaults")
    ap.add_argument("--size", type=float, default=0.02)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--regions", default="1,16,64")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--optimize", action="store_true", help="keep the optimization (default: --no-optimize)")
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="dtlab-threads-")
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "cube_ball.geo"), "w") as f:
        f.write(bench_mesh3d.GEO)
    subprocess.run(["gmsh", "-2", "cube_ball.geo", "-clmax", str(args.size), "-format", "mesh", "-o", "surface.mesh"],
                   cwd=work, check=True, capture_output=True)
    surface = os.path.join(work, "surface.mesh")
    configs = []
    if args.baseline:
        configs.append(("baseline (its defaults)", args.baseline, [], None))
    for s in [int(x) for x in args.regions.split(",")]:
        for t in [int(x) for x in args.threads.split(",")]:
            configs.append((f"{s} region(s), {t} thread(s)", args.dtlab,
                            ["--insertion-regions", str(s), "--threads", str(t)], s))
    times = {c[0]: [] for c in configs}
    tets, digest = {}, {}
    for r in range(args.runs):
        for name, exe, extra, streams in configs:
            out = os.path.join(work, "out.mesh")
            d = run(exe, surface, out, args.size, extra, args.optimize)
            times[name].append((d["seconds_field_points"], d["seconds"]))
            if tets.setdefault(name, d["tetrahedra"]) != d["tetrahedra"]:
                sys.exit(f"bench_mesh3d_threads: {name}: {d['tetrahedra']} tetrahedra, {tets[name]} in round 1")
            with open(out, "rb") as f:
                h = hashlib.sha256(f.read()).hexdigest()
            key = streams if streams is not None else name
            if digest.setdefault(key, h) != h:
                sys.exit(f"bench_mesh3d_threads: {name}: not the same mesh as the other runs of {key} region(s)")
        print(f"round {r + 1} of {args.runs} done", file=sys.stderr)
    print(f"h = {args.size}, {'with' if args.optimize else 'without'} the optimization, {args.runs} interleaved "
          f"rounds, dtlab's --stats seconds, median [min - max]\n")
    print("| configuration | tetrahedra | field points s | whole call s |")
    print("|---|---|---|---|")
    for name, _, _, _ in configs:
        f = [x[0] for x in times[name]]
        w = [x[1] for x in times[name]]
        print(f"| {name} | {tets[name]:,} | {statistics.median(f):.3f} [{min(f):.3f} - {max(f):.3f}] | "
              f"{statistics.median(w):.3f} [{min(w):.3f} - {max(w):.3f}] |")


if __name__ == "__main__":
    main()
