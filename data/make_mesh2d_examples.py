#!/usr/bin/env python3
"""Writes the bundled 2D meshing examples (dtlab mesh) and their size and metric files.

  square_disc.poly     the unit square minus a disc of radius 0.2 at its centre, boundary cut at
                       spacing H (default 0.02; the benchmark uses 0.01 and 0.0015): markers 1
                       outer, 2 circle, the disc a hole
  unit_square.poly     the unit square, sides cut into 10 (for the anisotropic fields)
  unit_square_bg.mesh  a 50 x 50 background grid of the unit square (Medit, two triangles a cell)
  linear_layer.sol     UGAWG's 2D "linear" field on it: h_x = 0.1, h_y = h0 + 2 (0.1 - h0)|y - 0.5|
  polar_layer.sol      UGAWG's 2D "polar-1" field: h_r = h0 + 2 (0.1 - h0)|r - 0.5|, h_t = 0.1
  size_map.sol         a scalar size field: h = 0.02 + 0.08 |x - 0.5|
Usage: make_mesh2d_examples.py [OUT_DIR] [--spacing H] [--h0 H0] [--grid N]
"""
import argparse
import math
import os


def square_disc(h):
    n = max(1, round(1.0 / h))
    pts = []
    for side in range(4):
        for i in range(n):
            t = i / n
            pts.append([(t, 0.0), (1.0, t), (1.0 - t, 1.0), (0.0, 1.0 - t)][side])
    m = max(3, round(2 * math.pi * 0.2 / h))
    circle = [(0.5 + 0.2 * math.cos(2 * math.pi * i / m), 0.5 + 0.2 * math.sin(2 * math.pi * i / m)) for i in range(m)]
    return pts, circle


def write_poly(path, loops, holes, comment):
    points = [p for loop, _ in loops for p in loop]
    with open(path, "w") as f:
        f.write(f"# {comment}\n{len(points)} 2 0 0\n")
        for i, (x, y) in enumerate(points, 1):
            f.write(f"{i} {x!r} {y!r}\n")
        f.write(f"{len(points)} 1\n")
        k, first = 1, 1
        for loop, marker in loops:
            for i in range(len(loop)):
                a = first + i
                b = first + (i + 1) % len(loop)
                f.write(f"{k} {a} {b} {marker}\n")
                k += 1
            first += len(loop)
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes, 1):
            f.write(f"{i} {x!r} {y!r}\n")
        f.write("0\n")


def grid(n):
    verts = [(i / n, j / n) for j in range(n + 1) for i in range(n + 1)]
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            tris += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    return verts, tris


def write_mesh(path, verts, tris):
    with open(path, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 2\n")
        f.write(f"Vertices\n{len(verts)}\n")
        for x, y in verts:
            f.write(f"{x!r} {y!r} 0\n")
        f.write(f"Triangles\n{len(tris)}\n")
        for a, b, c in tris:
            f.write(f"{a + 1} {b + 1} {c + 1} 0\n")
        f.write("End\n")


def tensor(e1, h1, h2):
    # M = R diag(h1^-2, h2^-2) R^T with R's first column e1.
    c, s = e1
    l1, l2 = h1 ** -2, h2 ** -2
    return (c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2)


def write_sol(path, values, kind):
    with open(path, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 2\n")
        f.write(f"SolAtVertices\n{len(values)}\n1 {1 if kind == 'scalar' else 3}\n")
        for v in values:
            f.write((f"{v!r}" if kind == "scalar" else " ".join(repr(x) for x in v)) + "\n")
        f.write("End\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="?", default=os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--spacing", type=float, default=0.02)
    ap.add_argument("--h0", type=float, default=0.001)
    ap.add_argument("--grid", type=int, default=50,
                    help="background grid cells per side (bundled: 50; the layers' benchmark: 200)")
    ap.add_argument("--only-square-disc", action="store_true", help="write square_disc.poly only")
    a = ap.parse_args()
    outer, circle = square_disc(a.spacing)
    write_poly(os.path.join(a.out, "square_disc.poly"), [(outer, 1), (circle, 2)], [(0.5, 0.5)],
               f"unit square minus the disc r = 0.2 at (0.5, 0.5), boundary spacing {a.spacing}")
    if a.only_square_disc:
        return
    side, _ = square_disc(0.1)
    write_poly(os.path.join(a.out, "unit_square.poly"), [(side, 1)], [], "unit square, sides cut into 10")
    verts, tris = grid(a.grid)
    write_mesh(os.path.join(a.out, "unit_square_bg.mesh"), verts, tris)
    h0 = a.h0
    write_sol(os.path.join(a.out, "linear_layer.sol"),
              [tensor((1.0, 0.0), 0.1, h0 + 2 * (0.1 - h0) * abs(y - 0.5)) for x, y in verts], "tensor")
    polar = []
    for x, y in verts:
        r = math.hypot(x, y)
        e = (x / r, y / r) if r > 0 else (1.0, 0.0)
        polar.append(tensor(e, h0 + 2 * (0.1 - h0) * abs(r - 0.5), 0.1))
    write_sol(os.path.join(a.out, "polar_layer.sol"), polar, "tensor")
    write_sol(os.path.join(a.out, "size_map.sol"), [0.02 + 0.08 * abs(x - 0.5) for x, y in verts], "scalar")


if __name__ == "__main__":
    main()
