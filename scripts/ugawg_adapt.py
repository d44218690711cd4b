#!/usr/bin/env python3
"""UGAWG adaptation benchmarks (github.com/UGAWG/adapt-benchmarks; data/ugawg/README.md says
where to get the initial meshes, which are not in this repository: --meshes DIR).

For each case and cycle: the analytic metric (linear, polar-1, polar-2 of the benchmark's README
files) is evaluated at the current mesh's vertices and written as a Medit .sol, the mesh is
adapted by `build/dtlab adapt MESH --metric SOL -o OUT --rounds R`, and the result is measured by
`build/dtlab quality --metric --json` against the field at its own vertices. Prints the table
min Q / mean Q / % edges in [1/sqrt2, sqrt2] / max L, and for the cube-cylinder how far the wall's
vertices are from r = 0.5 (the input facets' sagitta is 2.5e-3; the wall is the reference whose
input triangles lie on the cylinder), beside the best published rows.

  scripts/ugawg_adapt.py [--cases cube-linear,cube-cylinder-polar-1,cube-cylinder-polar-2]
                         [--cycles N] [--rounds R] [--work DIR] --meshes DIR
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CASES = {
    "cube-linear": ("cube-linear-00.mesh", "linear"),
    "cube-cylinder-polar-1": ("cube-cylinder.mesh", "polar-1"),
    "cube-cylinder-polar-2": ("cube-cylinder.mesh", "polar-2"),
}
# The best published rows (min Q, mean Q, % in band, max L; None: not given) and targets.
PUBLISHED = {
    "cube-linear": "Feflo.a 0.48 / 0.80 / 98.8 % / 1.80; target min Q >= 0.50, >= 99 %, max L <= 1.6",
    "cube-cylinder-polar-1": "Omega_h min Q 0.13, 70 %; Feflo.a 92.1 %, min Q 0.006; target min Q >= 0.15, >= 93 %",
    "cube-cylinder-polar-2": "Omega_h 0.24 / 0.70 / 92.3 %; Feflo.a 95.3 %; target min Q >= 0.25, >= 96 %, max L <= 1.7",
}


def metric(field, x, y, z):
    """The symmetric tensor in Medit's order m11 m12 m22 m13 m23 m33."""
    h0 = 0.001
    if field == "linear":
        hz = h0 + 2.0 * (0.1 - h0) * abs(z - 0.5)
        return (0.1 ** -2, 0.0, 0.1 ** -2, 0.0, 0.0, hz ** -2)
    r = math.hypot(x, y)
    t = math.atan2(y, x)
    hz, ht = 0.1, 0.1
    hr = h0 + 2.0 * (0.1 - h0) * abs(r - 0.5)
    if field == "polar-2":
        d = (0.6 - r) * 10.0
        ht = 0.1 if d < 0 else d * (1.0 / 40.0) + (1.0 - d) * 0.1
    c, s = math.cos(t), math.sin(t)
    lr, lt, lz = hr ** -2, ht ** -2, hz ** -2
    # R diag(lr, lt) R^T with R = [[c, -s], [s, c]].
    m11 = c * c * lr + s * s * lt
    m12 = c * s * (lr - lt)
    m22 = s * s * lr + c * c * lt
    return (m11, m12, m22, 0.0, 0.0, lz)


def read_vertices(path):
    with open(path) as f:
        tokens = f.read().split()
    i = tokens.index("Vertices")
    n = int(tokens[i + 1])
    return [tuple(float(tokens[i + 2 + 4 * k + j]) for j in range(3)) for k in range(n)]


def boundary_triangles(path):
    """The boundary triangles of a Medit file: (three vertices, reference)."""
    with open(path) as f:
        tokens = f.read().split()
    vertices = read_vertices(path)
    i = tokens.index("Triangles")
    return [([vertices[int(tokens[i + 2 + 4 * k + j]) - 1] for j in range(3)], tokens[i + 2 + 4 * k + 3])
            for k in range(int(tokens[i + 1]))]


def wall_error(initial, final):
    """Largest distance from the cylinder r = 0.5 (about the z axis) of the final mesh's vertices
    on the wall: the boundary triangles of the reference whose initial triangles lie on it."""
    on = lambda t: all(abs(math.hypot(x, y) - 0.5) < 1e-9 for x, y, z in t)
    walls = {ref for t, ref in boundary_triangles(initial) if on(t)}
    off = [abs(math.hypot(x, y) - 0.5) for t, ref in boundary_triangles(final) if ref in walls for x, y, z in t]
    return max(off) if off else None


def write_sol(path, field, vertices):
    with open(path, "w") as f:
        f.write("MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n%d\n1 3\n" % len(vertices))
        for x, y, z in vertices:
            f.write(" ".join(repr(v) for v in metric(field, x, y, z)) + "\n")
        f.write("\nEnd\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--cycles", type=int, default=2)
    ap.add_argument("--rounds", type=int, default=12)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "ugawg"))
    ap.add_argument("--meshes", required=True,
                    help="folder with cube-linear-00.mesh and cube-cylinder.mesh (data/ugawg/README.md)")
    ap.add_argument("--dtlab", default=os.path.join(ROOT, "build", "dtlab"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = []
    for case in args.cases.split(","):
        if case not in CASES:
            sys.exit("unknown case %s (known: %s)" % (case, ", ".join(CASES)))
        mesh_name, field = CASES[case]
        mesh = os.path.join(args.meshes, mesh_name)
        if not os.path.exists(mesh):
            sys.exit("ugawg_adapt.py: %s not found (data/ugawg/README.md says where to get it)" % mesh)
        seconds = 0.0
        stats = {}
        for cycle in range(args.cycles):
            sol = os.path.join(args.work, "%s-%02d.sol" % (case, cycle))
            out = os.path.join(args.work, "%s-%02d.mesh" % (case, cycle + 1))
            write_sol(sol, field, read_vertices(mesh))
            start = time.perf_counter()
            run = subprocess.run([args.dtlab, "adapt", mesh, "--metric", sol, "-o", out, "--rounds", str(args.rounds), "--stats"],
                                 capture_output=True, text=True)
            seconds += time.perf_counter() - start
            if run.returncode != 0:
                sys.exit("%s cycle %d: %s%s" % (case, cycle + 1, run.stdout[-2000:], run.stderr))
            stats = json.loads(run.stdout.strip().splitlines()[-1])
            mesh = out
        sol = os.path.join(args.work, "%s-final.sol" % case)
        write_sol(sol, field, read_vertices(mesh))
        q = subprocess.run([args.dtlab, "quality", mesh, "--metric", sol, "--json"], capture_output=True, text=True)
        if q.returncode != 0:
            sys.exit("%s: dtlab quality: %s" % (case, q.stderr))
        report = json.loads(q.stdout.strip().splitlines()[-1])
        wall = wall_error(os.path.join(args.meshes, mesh_name), mesh) if "cylinder" in case else None
        rows.append((case, report, stats, seconds, wall))
    print("| case | cycles | tets | min Q | mean Q | % in [1/sqrt2, sqrt2] | max L | wall off r = 0.5 | s (adapt) |"
          " best published / target |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for case, r, s, sec, wall in rows:
        def g(k):
            v = r.get(k)
            return "-" if v is None else "%.3g" % v
        share = r.get("unit_edge_share")
        print("| %s | %d | %d | %s | %s | %s | %s | %s | %.1f | %s |" % (
            case, args.cycles, r.get("elements", 0), g("mean_ratio_worst"), g("mean_ratio_mean"),
            "-" if share is None else "%.1f" % (100 * share), g("metric_length_max"),
            "-" if wall is None else "%.1e" % wall, sec, PUBLISHED[case]))


if __name__ == "__main__":
    main()
