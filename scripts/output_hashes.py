#!/usr/bin/env python3
"""The bytes a refactor must keep (issue 41, "Behaviour unchanged"): runs one `dtlab` binary on a
fixed set of jobs and prints the SHA-256 of every output file, one line each, sorted by name, so
that two binaries (before and after) compare with `diff`:

  main job    every 2D Delaunay variant on data/default.node; every 3D variant on a 20,000-point
              grid (2 threads); every constrained method on every data/*.poly and on
              data/schonhardt.off and data/quad_cube.off (scripts/run-main.sh's runs and more);
              the classical 2D mesh (no size) of two of the .poly
  mesh2d      the benchmark's square minus a disc at h = 0.01 (scripts/bench_mesh2d.py's domain),
              edge and front, with and without optimization; the anisotropic cases (UGAWG linear
              and polar layers on data/unit_square_bg.mesh, boundary cut in the metric), edge and front
  mesh3d      the benchmark's cube minus a ball (Gmsh's surface at H, scripts/bench_mesh3d.py's
              geometry): `mesh --size H --remove-cavities`, with --optimize thorough, and
              classical (no size: the control space from the surface's own edge lengths)
  optimize    `dtlab optimize` on TetGen's `-pq1.414 -a` mesh of that surface (its .ele), and on
              dtlab's own 2D mesh without optimization
  adapt       2D adaptation to the linear layer (local and reconstruct), 3D adaptation of the
              mesh3d output to a size field; `dtlab transfer` of that field in 2D and 3D

Gmsh and TetGen make the inputs once per work folder (--work): reuse the folder so that both
binaries see the same surface and the same TetGen mesh. Needs gmsh and tetgen (Debian packages).

  scripts/output_hashes.py --dtlab /path/old/dtlab --work /tmp/h > before.txt
  scripts/output_hashes.py --dtlab build/dtlab --work /tmp/h > after.txt && diff before.txt after.txt
"""
import argparse
import hashlib
import math
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "data"))
import make_mesh2d_examples as examples  # noqa: E402
from bench_mesh3d import GEO, medit_sections, write_smesh  # noqa: E402

DATA = os.path.join(ROOT, "data")


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"output_hashes: {' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-2000:]}")


def prepare(work, h3):
    """The inputs that peers make, once: Gmsh's surface, TetGen's mesh, the 2D domain, the fields."""
    inputs = os.path.join(work, "inputs")
    if os.path.exists(os.path.join(inputs, "done")):
        return inputs
    os.makedirs(inputs, exist_ok=True)
    with open(os.path.join(inputs, "cube_ball.geo"), "w") as f:
        f.write(GEO)
    run(["gmsh", "-2", "cube_ball.geo", "-clmax", str(h3), "-format", "mesh", "-o", "surface.mesh"], inputs)
    os.makedirs(os.path.join(inputs, "tg"), exist_ok=True)
    write_smesh(os.path.join(inputs, "surface.mesh"), os.path.join(inputs, "tg", "surface.smesh"))
    v = h3 ** 3 / (6.0 * math.sqrt(2.0))
    run(["tetgen", f"-pq1.414a{v:.6g}Q", "tg/surface.smesh"], inputs)
    outer, circle = examples.square_disc(0.01)
    examples.write_poly(os.path.join(inputs, "square_disc.poly"), [(outer, 1), (circle, 2)], [(0.5, 0.5)],
                        "unit square minus the disc r = 0.2 at (0.5, 0.5), boundary spacing 0.01")
    open(os.path.join(inputs, "done"), "w").close()
    return inputs


def size_field(mesh, path, dimension):
    """A scalar size at each vertex of `mesh`: 0.02 + 0.1 |x - 0.5| (a layer across the domain)."""
    verts = medit_sections(mesh)["Vertices"]
    with open(path, "w") as f:
        f.write(f"MeshVersionFormatted 2\nDimension {dimension}\nSolAtVertices\n{len(verts)}\n1 1\n")
        for v in verts:
            f.write(f"{0.02 + 0.1 * abs(float(v[0]) - 0.5)!r}\n")
        f.write("End\n")


def jobs(dtlab, inputs, h3):
    """(output file, command) pairs, in the order they run (later ones read earlier outputs)."""
    out = []
    for algo in subprocess.run([dtlab, "delaunay", "--list-algos"], capture_output=True, text=True,
                               check=True).stdout.split("\n"):
        if algo.strip():
            name = algo.split("\t")[0]
            out.append((f"delaunay2d-{name}.mesh", ["delaunay", f"{DATA}/default.node", "--algo", name]))
    for algo in subprocess.run([dtlab, "delaunay", "--list-algos", "--dim", "3"], capture_output=True, text=True,
                               check=True).stdout.split("\n"):
        if algo.strip():
            name = algo.split("\t")[0]
            out.append((f"delaunay3d-{name}.mesh", ["delaunay", "--dim", "3", "--random", "20000", "--distribution",
                                                    "grid", "--algo", name, "--threads", "2"]))
    for m in ("cdt", "swap", "conforming"):
        out.append((f"constrain2d-{m}.mesh", ["constrain", f"{DATA}/square_with_hole.poly", "--method", m]))
        for poly in ("square_disc", "unit_square"):
            out.append((f"constrain2d-{m}-{poly}.mesh", ["constrain", f"{DATA}/{poly}.poly", "--method", m]))
    for m in ("conforming", "recover", "cdt"):
        out.append((f"constrain3d-{m}.mesh", ["constrain", f"{DATA}/schonhardt.off", "--method", m]))
        out.append((f"constrain3d-{m}-quad_cube.mesh", ["constrain", f"{DATA}/quad_cube.off", "--method", m]))
        out.append((f"constrain3d-{m}-box_with_window.mesh", ["constrain", f"{DATA}/box_with_window.poly", "--method",
                                                              m]))
    for poly in ("square_disc", "square_with_hole"):
        out.append((f"mesh2d-classical-{poly}.mesh", ["mesh", f"{DATA}/{poly}.poly"]))
    poly = os.path.join(inputs, "square_disc.poly")
    for m in ("edge", "front"):
        out.append((f"mesh2d-{m}.mesh", ["mesh", poly, "--size", "0.01", "--method", m]))
        out.append((f"mesh2d-{m}-raw.mesh", ["mesh", poly, "--size", "0.01", "--method", m, "--no-optimize"]))
        for layer in ("linear", "polar"):
            out.append((f"mesh2d-{m}-{layer}.mesh",
                        ["mesh", f"{DATA}/unit_square.poly", "--metric", f"{DATA}/{layer}_layer.sol", "--background",
                         f"{DATA}/unit_square_bg.mesh", "--method", m]))
    surface = os.path.join(inputs, "surface.mesh")
    out.append(("mesh3d.mesh", ["mesh", surface, "--size", str(h3), "--remove-cavities"]))
    out.append(("mesh3d-classical.mesh", ["mesh", surface, "--remove-cavities"]))
    out.append(("mesh3d-thorough.mesh", ["mesh", surface, "--size", str(h3), "--remove-cavities", "--optimize",
                                         "thorough"]))
    out.append(("optimize3d-tetgen.mesh", ["optimize", os.path.join(inputs, "tg", "surface.1.ele"), "--size",
                                           str(h3)]))
    out.append(("optimize2d.mesh", ["optimize", "@mesh2d-edge-raw.mesh", "--size", "0.01"]))
    for m in ("local", "reconstruct"):
        out.append((f"adapt2d-{m}.mesh", ["adapt", f"{DATA}/unit_square_bg.mesh", "--metric",
                                          f"{DATA}/linear_layer.sol", "--method", m]))
    out.append(("adapt3d.mesh", ["adapt", "@mesh3d.mesh", "--metric", "@size3d.sol"]))
    out.append(("transfer2d.sol", ["transfer", f"{DATA}/unit_square_bg.mesh", f"{DATA}/linear_layer.sol",
                                   "@adapt2d-local.mesh"]))
    out.append(("transfer3d.sol", ["transfer", "@mesh3d.mesh", "@size3d.sol", "@adapt3d.mesh"]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", required=True)
    ap.add_argument("--work", required=True, help="folder for inputs (kept and reused) and outputs")
    ap.add_argument("--size3d", type=float, default=0.06, help="H of the 3D cases (default 0.06)")
    args = ap.parse_args()
    for tool in ("gmsh", "tetgen"):
        if shutil.which(tool) is None:
            sys.exit(f"output_hashes: {tool} not installed (apt-get install gmsh tetgen)")
    dtlab = os.path.abspath(args.dtlab)
    work = os.path.abspath(args.work)
    inputs = prepare(work, args.size3d)
    outputs = os.path.join(work, "outputs")
    shutil.rmtree(outputs, ignore_errors=True)
    os.makedirs(outputs)
    for name, cmd in jobs(dtlab, inputs, args.size3d):
        cmd = [os.path.join(outputs, c[1:]) if c.startswith("@") else c for c in cmd]
        run([dtlab] + cmd + ["-o", os.path.join(outputs, name)], outputs)
        if name == "mesh3d.mesh":
            size_field(os.path.join(outputs, name), os.path.join(outputs, "size3d.sol"), 3)
    for name in sorted(os.listdir(outputs)):
        with open(os.path.join(outputs, name), "rb") as f:
            print(f"{hashlib.sha256(f.read()).hexdigest()}  {name}")


if __name__ == "__main__":
    main()
