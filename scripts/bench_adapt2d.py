#!/usr/bin/env python3
"""2D anisotropic adaptation beside BAMG: dtlab adapt, FreeFem++'s adaptmesh and Gmsh's BAMG
(Mesh.Algorithm 7) on the same metric fields, measured by the same `dtlab quality --metric`.

The fields are the 2D analogues of the UGAWG benchmark's (github UGAWG/adapt-benchmarks, README),
h0 = 0.001 / SCALE, on the 2D sections of their domains:
  linear   on the unit square: h_x = 0.1 / SCALE, h_y = h0 + 2 (0.1 / SCALE - h0) |y - 0.5|
  polar-1  on the square minus the quarter disc r < 0.5 (the section of the cube-cylinder; in
           polar coordinates (r, t) about the origin): h_r = h0 + 2 (0.1 / SCALE - h0) |r - 0.5|,
           h_t = 0.1 / SCALE: a layer along the curved wall
  polar-2  h_r as polar-1, h_t = 0.1 / SCALE for r > 0.6, else d / 40 + (1 - d) 0.1 (over SCALE),
           d = 10 (0.6 - r) (in [0, 1] on the domain, r >= 0.5: the formula has no meaning below)
As in the UGAWG runs, every code starts from the same mesh (200 triangles: the square's 10 x 10
grid, or the quarter domain's polar 10 x 10 grid with the arc cut into 10 chords) and makes
CYCLES cycles; before each the field is evaluated analytically at the current vertices (dtlab
and Gmsh: a .sol / .pos this script writes; FreeFem++: the same formulas interpolated in P1 on
its mesh, which is the value at the vertices). Each code adapts its own previous mesh: dtlab by
local modification (dtlab adapt, boundary points on its smooth support of the polygonal arc) and
by complete reconstruction (dtlab adapt --method reconstruct: the boundary cut anew on the
previous mesh's chords, the domain generated anew),
FreeFem++ by BAMG's adaptmesh (no metric smoothing, ratio=0, since the field is given; its
geometry is the start mesh's boundary), Gmsh by BAMG remeshing the domain's exact geometry (a
true circular arc) with the current mesh as the background. The last mesh of each is measured
with the field at its vertices: the share of edges of metric length in [1/sqrt2, sqrt2], the
length extremes, and the worst and mean metric mean ratio as the UGAWG MEASURES define them
(dtlab quality --metric).

Times: each code's own time for its cycles (dtlab adapt's "seconds", FreeFem++'s clock() around
adaptmesh, Gmsh's "Done meshing 2D (Wall ...)"), summed over the cycles; the median of RUNS
interleaved runs (round 1 of every code on a field, then round 2, ...) with the spread min-max,
and the ratio of medians to dtlab. The process times (start-up and file output included) are
reported too. The meshes are the same in every run (checked for dtlab: the same bytes).

  scripts/bench_adapt2d.py [--dtlab build/dtlab] [--freefem FreeFem++-nw] [--gmsh gmsh]
                           [--fields linear,polar-1,polar-2] [--cycles 5] [--runs 5] [--scale 1]
                           [--work DIR] [--markdown FILE]
A peer that is not found is skipped with a note."""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def field_sizes(field, x, y, scale):
    """(h1 along e1, h2 along e2, e1) of the field at (x, y)."""
    h0, hmax = 0.001 / scale, 0.1 / scale
    if field == "linear":
        return hmax, h0 + 2.0 * (hmax - h0) * abs(y - 0.5), (1.0, 0.0)
    r = math.hypot(x, y)
    t = math.atan2(y, x)
    hr = h0 + 2.0 * (hmax - h0) * abs(r - 0.5)
    ht = hmax
    if field == "polar-2":
        d = (0.6 - r) * 10.0
        ht = hmax if d < 0 else (d / 40.0 + (1.0 - d) * 0.1) / scale
    return ht, hr, (-math.sin(t), math.cos(t))


def metric(field, x, y, scale):
    """m11, m12, m22 of R diag(h1^-2, h2^-2) R^T, R = [e1, e2]."""
    h1, h2, (c, s) = field_sizes(field, x, y, scale)
    l1, l2 = h1 ** -2, h2 ** -2
    return c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2


def freefem_metric(field, scale):
    """The same field in FreeFem++'s language (m11, m12, m22 as P1 functions)."""
    h0, hmax = 0.001 / scale, 0.1 / scale
    if field == "linear":
        return (f"Vh hh2 = {h0!r} + 2.0 * ({hmax!r} - {h0!r}) * abs(y - 0.5);\n"
                f"Vh m11 = 1.0 / ({hmax!r} * {hmax!r}), m12 = 0, m22 = 1.0 / (hh2 * hh2);\n")
    ht = f"{hmax!r}"
    if field == "polar-2":
        ht = f"((0.6 - rr) * 10.0 < 0 ? {hmax!r} : (((0.6 - rr) * 10.0) / 40.0 + (1.0 - (0.6 - rr) * 10.0) * 0.1) / {scale!r})"
    return ("func rr = sqrt(x * x + y * y);\nfunc tt = atan2(y, x);\n"
            f"func hr = {h0!r} + 2.0 * ({hmax!r} - {h0!r}) * abs(rr - 0.5);\nfunc ht = {ht};\n"
            "func l1 = 1.0 / (ht * ht);\nfunc l2 = 1.0 / (hr * hr);\n"
            "Vh m11 = sin(tt)^2 * l1 + cos(tt)^2 * l2, m12 = -sin(tt) * cos(tt) * (l1 - l2), "
            "m22 = cos(tt)^2 * l1 + sin(tt)^2 * l2;\n")


# --- Medit 2D meshes ----------------------------------------------------------------------------
def read_medit(path):
    """(vertices [(x, y)], edges [(a, b, ref)], triangles [(a, b, c, ref)]), 0-based; Gmsh's
    Dimension 3 files are read with z dropped (it is 0 for a planar mesh)."""
    words = open(path).read().split()
    dim = int(words[words.index("Dimension") + 1])
    out = {"Vertices": [], "Edges": [], "Triangles": []}
    i = 0
    while i < len(words):
        w = words[i]
        if w in out:
            n = int(words[i + 1])
            i += 2
            width = {"Vertices": dim + 1, "Edges": 3, "Triangles": 4}[w]
            for k in range(n):
                rec = words[i + k * width: i + (k + 1) * width]
                if w == "Vertices":
                    out[w].append((float(rec[0]), float(rec[1])))
                else:
                    out[w].append(tuple(int(v) - 1 for v in rec[:-1]) + (int(rec[-1]),))
            i += n * width
        else:
            i += 1
    return out["Vertices"], out["Edges"], out["Triangles"]


def write_medit(path, vertices, edges, triangles):
    with open(path, "w") as f:
        f.write(f"MeshVersionFormatted 2\nDimension 2\nVertices\n{len(vertices)}\n")
        f.writelines(f"{x!r} {y!r} 0\n" for x, y in vertices)
        f.write(f"Edges\n{len(edges)}\n")
        f.writelines(f"{a + 1} {b + 1} {r}\n" for a, b, r in edges)
        f.write(f"Triangles\n{len(triangles)}\n")
        f.writelines(f"{a + 1} {b + 1} {c + 1} {r}\n" for a, b, c, r in triangles)
        f.write("End\n")


def start_mesh(path, domain, n=10):
    """The square's n x n grid, or the quarter domain's: the arc r = 0.5 and the square's sides
    x = 1, y = 1 joined along rays, n cells each way; each cell two counter-clockwise triangles.
    Edge references: square 1; quarter domain 1 (y = 0), 2 (outer sides), 3 (x = 0), 4 (arc)."""
    def point(i, j):
        if domain == "square":
            return i / n, j / n
        a = 0.5 * math.pi * i / n
        inner = (0.5 * math.cos(a), 0.5 * math.sin(a))
        outer = (1.0, math.tan(a)) if 2 * i <= n else (1.0 / math.tan(a), 1.0)
        if 2 * i == n:
            outer = (1.0, 1.0)
        t = j / n
        return (1 - t) * inner[0] + t * outer[0], (1 - t) * inner[1] + t * outer[1]
    vertices = [point(i, j) for j in range(n + 1) for i in range(n + 1)]
    triangles, edges = [], []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            for tri in ((a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)):
                (ax, ay), (bx, by), (cx, cy) = (vertices[v] for v in tri)
                ccw = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0
                triangles.append(tri + (1,) if ccw else (tri[0], tri[2], tri[1], 1))
    quarter = domain != "square"
    for i in range(n):
        top, left, right = n * (n + 1), i * (n + 1), i * (n + 1) + n
        edges += [(i, i + 1, 4 if quarter else 1), (top + i + 1, top + i, 2 if quarter else 1),
                  (right, right + n + 1, 1 if quarter else 1), (left + n + 1, left, 3 if quarter else 1)]
    write_medit(path, vertices, edges, triangles)


def write_sol(path, field, vertices, scale):
    with open(path, "w") as f:
        f.write(f"MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n{len(vertices)}\n1 3\n")
        for x, y in vertices:
            f.write("%.17g %.17g %.17g\n" % metric(field, x, y, scale))
        f.write("End\n")


def write_pos(path, field, vertices, triangles, scale):
    """The field as a Gmsh tensor view on the mesh's triangles (the background of BAMG)."""
    tensors = [metric(field, x, y, scale) for x, y in vertices]
    with open(path, "w") as f:
        f.write('View "metric" {\n')
        for a, b, c, _ in triangles:
            coords = ",".join(f"{vertices[v][0]!r},{vertices[v][1]!r},0" for v in (a, b, c))
            vals = ",".join(f"{m[0]!r},{m[1]!r},0,{m[1]!r},{m[2]!r},0,0,0,1" for m in (tensors[v] for v in (a, b, c)))
            f.write(f"TT({coords}){{{vals}}};\n")
        f.write("};\n")


GEO = {"square": """Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Curve(1) = {1, 2, 3, 4}; Physical Surface(1) = {1};
""", "quarter": """Point(1) = {0.5, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {0, 0.5, 0, 0.1}; Point(6) = {0, 0, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Circle(5) = {5, 6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5}; Plane Surface(1) = {1};
Physical Curve(1) = {1}; Physical Curve(2) = {2, 3}; Physical Curve(3) = {4}; Physical Curve(4) = {5};
Physical Surface(1) = {1};
"""}


def domain_of(field):
    return "square" if field == "linear" else "quarter"


# --- one cycle of each code ---------------------------------------------------------------------
def run(cmd, cwd):
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
    return p.stdout + p.stderr, wall


def cycle_dtlab(args, work, field, current, nxt):
    vertices, _, _ = read_medit(os.path.join(work, current))
    write_sol(os.path.join(work, "metric.sol"), field, vertices, args.scale)
    out, wall = run([args.dtlab, "adapt", current, "--metric", "metric.sol", "-o", nxt, "--stats"], work)
    return json.loads(out.strip().splitlines()[-1])["seconds"], wall


def cycle_dtlab_reconstruct(args, work, field, current, nxt):
    vertices, _, _ = read_medit(os.path.join(work, current))
    write_sol(os.path.join(work, "metric.sol"), field, vertices, args.scale)
    out, wall = run([args.dtlab, "adapt", current, "--metric", "metric.sol", "--method", "reconstruct", "-o", nxt,
                     "--stats"], work)
    return json.loads(out.strip().splitlines()[-1])["seconds"], wall


def cycle_freefem(args, work, field, current, nxt):
    script = (f'mesh Th = readmesh("{current}");\nfespace Vh(Th, P1);\n' + freefem_metric(field, args.scale) +
              "real t0 = clock();\n"
              "Th = adaptmesh(Th, m11, m12, m22, IsMetric = 1, ratio = 0, nbvx = 10000000, hmin = 1e-9, hmax = 10);\n"
              'real t1 = clock();\ncout << "adaptmesh_seconds " << (t1 - t0) << endl;\n'
              f'savemesh(Th, "{nxt}");\n')
    with open(os.path.join(work, "cycle.edp"), "w") as f:
        f.write(script)
    out, wall = run([args.freefem, "-v", "0", "cycle.edp"], work)
    return float(re.search(r"adaptmesh_seconds\s+(\S+)", out).group(1)), wall


def cycle_gmsh(args, work, field, current, nxt):
    vertices, _, triangles = read_medit(os.path.join(work, current))
    write_pos(os.path.join(work, "metric.pos"), field, vertices, triangles, args.scale)
    with open(os.path.join(work, "domain.geo"), "w") as f:
        f.write(GEO[domain_of(field)])
    out, wall = run([args.gmsh, "domain.geo", "-2", "-algo", "bamg", "-bgm", "metric.pos", "-o", "gmsh_out.mesh"], work)
    seconds = float(re.search(r"Done meshing 2D \(Wall ([0-9.eE+-]+)s", out).group(1))
    v, e, t = read_medit(os.path.join(work, "gmsh_out.mesh"))
    # Gmsh lists its triangles' orientation as the surface's normal gives it: made counter-clockwise.
    fixed = []
    for a, b, c, r in t:
        (ax, ay), (bx, by), (cx, cy) = v[a], v[b], v[c]
        fixed.append((a, b, c, r) if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0 else (a, c, b, r))
    write_medit(os.path.join(work, nxt), v, e, fixed)
    return seconds, wall


CODES = {"dtlab": cycle_dtlab, "dtlab reconstruct": cycle_dtlab_reconstruct, "FreeFem++ adaptmesh": cycle_freefem,
         "Gmsh BAMG": cycle_gmsh}


def chain(args, code, field, work):
    """The CYCLES cycles of one code from the start mesh; (own seconds, process seconds, last mesh)."""
    os.makedirs(work, exist_ok=True)
    shutil.copy(os.path.join(args.work, f"start_{domain_of(field)}.mesh"), os.path.join(work, "mesh0.mesh"))
    own = wall = 0.0
    for c in range(args.cycles):
        s, w = CODES[code](args, work, field, f"mesh{c}.mesh", f"mesh{c + 1}.mesh")
        own += s
        wall += w
    return own, wall, os.path.join(work, f"mesh{args.cycles}.mesh")


def measure(args, field, mesh):
    # Rewritten with Vertices, Edges and Triangles only: FreeFem++ adds BAMG's own sections
    # (SubDomainFromMesh, ...), which dtlab's reader refuses by name.
    vertices, edges, triangles = read_medit(mesh)
    mesh = mesh[:-5] + "_measured.mesh"
    write_medit(mesh, vertices, edges, triangles)
    sol = mesh[:-5] + ".sol"
    write_sol(sol, field, vertices, args.scale)
    out, _ = run([args.dtlab, "quality", mesh, "--metric", sol, "--json"], os.path.dirname(mesh))
    return json.loads(out.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", default="build/dtlab")
    ap.add_argument("--freefem", default="FreeFem++-nw")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--fields", default="linear,polar-1,polar-2")
    ap.add_argument("--cycles", type=int, default=5)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--scale", type=float, default=1.0, help="divide every size of the fields by this (larger meshes)")
    ap.add_argument("--work", default=None, help="keep the meshes here (default: a temporary folder)")
    ap.add_argument("--markdown", default=None, help="also write the table to this file")
    args = ap.parse_args()
    if not (1 <= args.cycles <= 100 and 1 <= args.runs <= 100 and args.scale > 0):
        ap.error("--cycles and --runs in [1, 100], --scale > 0")
    args.dtlab = os.path.abspath(args.dtlab)
    if not os.access(args.dtlab, os.X_OK):
        ap.error(f"no dtlab at {args.dtlab} (build it, or give --dtlab)")
    codes = ["dtlab", "dtlab reconstruct"]
    for code, exe in (("FreeFem++ adaptmesh", args.freefem), ("Gmsh BAMG", args.gmsh)):
        if shutil.which(exe):
            codes.append(code)
        else:
            print(f"note: {exe} not found, {code} skipped", file=sys.stderr)
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="bench_adapt2d_"))
    os.makedirs(args.work, exist_ok=True)
    for domain in ("square", "quarter"):
        start_mesh(os.path.join(args.work, f"start_{domain}.mesh"), domain)

    lines = [f"2D adaptation, {args.cycles} cycles from the same 200-triangle mesh, fields at scale {args.scale:g}; "
             f"time: median (min-max) of {args.runs} interleaved runs of each code's own time over the cycles; "
             "quality of the last mesh by dtlab quality --metric (UGAWG measures)", "",
             "| field | code | vertices | triangles | edges in [1/√2, √2] | min L | max L | worst mean ratio | mean mean ratio "
             "| time s | time / dtlab | process s |", "|" + "---|" * 12]
    for field in args.fields.split(","):
        if field not in ("linear", "polar-1", "polar-2"):
            ap.error(f"unknown field '{field}' (linear, polar-1, polar-2)")
        times = {c: [] for c in codes}
        walls = {c: [] for c in codes}
        last = {}
        for r in range(args.runs):
            for code in codes:
                work = os.path.join(args.work, field, code.replace(" ", "_") + f"_run{r}")
                own, wall, mesh = chain(args, code, field, work)
                times[code].append(own)
                walls[code].append(wall)
                if code == "dtlab" and "dtlab" in last and open(mesh, "rb").read() != open(last["dtlab"], "rb").read():
                    print(f"WARNING: dtlab's mesh of run {r + 1} differs from run 1 ({field})", file=sys.stderr)
                last.setdefault(code, mesh)
        base = statistics.median(times["dtlab"])
        for code in codes:
            q = measure(args, field, last[code])
            med = statistics.median(times[code])
            lines.append(f"| {field} | {code} | {q['vertices']} | {q['elements']} | {100 * q['unit_edge_share']:.1f} % "
                         f"| {q['metric_length_min']:.3f} | {q['metric_length_max']:.3f} | {q['mean_ratio_worst']:.3f} "
                         f"| {q['mean_ratio_mean']:.3f} | {med:.3f} ({min(times[code]):.3f}-{max(times[code]):.3f}) "
                         f"| {med / base:.2f} | {statistics.median(walls[code]):.2f} |")
            print(lines[-1], flush=True)
    print("\n".join(lines[:4]))
    print("\n".join(lines[4:]))
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
