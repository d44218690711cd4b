#!/usr/bin/env python3
"""Inputs for the book's §7.13 sphere (George & Borouchaki 1998, Table 7.3, Figures 7.5-7.7).

  sphere.py surface --frequency N -o S.off
      The unit sphere's uniform boundary mesh: the geodesic sphere of frequency N, each face of the
      icosahedron cut into N^2 triangles on a barycentric grid and the vertices projected onto the
      sphere (10 N^2 + 2 vertices, 20 N^2 triangles, oriented outwards). Exact integer keys merge the
      vertices shared by two faces, so the surface is closed by construction.

  sphere.py sizes --background B.mesh --centre-ratio C -o S.sol
      A size map for `dtlab mesh --size-map S.sol --background B.mesh`: at each vertex of B (a Medit
      mesh of the unit ball with its boundary Triangles), h(r) = HC + (HB - HC) r with r the distance
      to the centre, HB the mean edge length of B's boundary triangles and HC = C HB, so the sizes
      vary linearly from the centroid to the boundary (the book's cases 2 and 3: C > 1 pushes the
      points away from the centroid, "repulsion"; C < 1 draws them to it, "attraction"). Prints
      "HB HC" on stdout.
"""
import argparse
import math
import sys


def icosahedron():
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return v, f


def geodesic_sphere(n):
    corners, faces = icosahedron()
    index = {}  # key: the sorted (corner, weight) pairs of non-zero weight -> vertex number
    points = []

    def vertex(weights):
        key = tuple(sorted((c, w) for c, w in weights if w))
        if key not in index:
            x = [sum(w * corners[c][d] for c, w in key) for d in range(3)]
            r = math.sqrt(sum(xi * xi for xi in x))
            index[key] = len(points)
            points.append(tuple(xi / r for xi in x))
        return index[key]

    triangles = []
    for a, b, c in faces:
        grid = {}
        for i in range(n + 1):
            for j in range(n + 1 - i):
                grid[i, j] = vertex(((a, n - i - j), (b, i), (c, j)))
        for i in range(n):
            for j in range(n - i):
                triangles.append((grid[i, j], grid[i + 1, j], grid[i, j + 1]))
                if i + j < n - 1:
                    triangles.append((grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]))
    return points, triangles


def signed_volume(points, triangles):
    v = 0.0
    for a, b, c in triangles:
        p, q, r = points[a], points[b], points[c]
        v += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
              + p[2] * (q[0] * r[1] - q[1] * r[0])) / 6.0
    return v


def write_surface(args):
    points, triangles = geodesic_sphere(args.frequency)
    n = args.frequency
    if len(points) != 10 * n * n + 2 or len(triangles) != 20 * n * n:
        sys.exit(f"sphere.py: {len(points)} vertices, {len(triangles)} triangles for frequency {n}")
    if signed_volume(points, triangles) <= 0:
        sys.exit("sphere.py: the triangles are not oriented outwards")
    with open(args.output, "w") as out:
        out.write(f"OFF\n{len(points)} {len(triangles)} 0\n")
        for p in points:
            out.write(f"{p[0]!r} {p[1]!r} {p[2]!r}\n")
        for t in triangles:
            out.write(f"3 {t[0]} {t[1]} {t[2]}\n")


def read_medit(path):
    """The Vertices and the Triangles (0-based) of a Medit .mesh."""
    with open(path) as f:
        tokens = f.read().split()
    k = tokens.index("Vertices")
    count = int(tokens[k + 1])
    vertices = [tuple(float(tokens[k + 2 + 4 * i + d]) for d in range(3)) for i in range(count)]
    triangles = []
    if "Triangles" in tokens:
        k = tokens.index("Triangles")
        count = int(tokens[k + 1])
        triangles = [tuple(int(tokens[k + 2 + 4 * i + d]) - 1 for d in range(3)) for i in range(count)]
    return vertices, triangles


def write_sizes(args):
    vertices, triangles = read_medit(args.background)
    if not triangles:
        sys.exit(f"sphere.py: {args.background} has no boundary Triangles")
    hb = sum(math.dist(vertices[t[i]], vertices[t[(i + 1) % 3]]) for t in triangles for i in range(3)) / (3 * len(triangles))
    hc = args.centre_ratio * hb
    with open(args.output, "w") as out:
        out.write(f"MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n{len(vertices)}\n1 1\n")
        for p in vertices:
            r = min(1.0, math.sqrt(sum(x * x for x in p)))
            out.write(f"{hc + (hb - hc) * r!r}\n")
        out.write("End\n")
    print(f"{hb:.6g} {hc:.6g}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("surface")
    s.add_argument("--frequency", type=int, required=True)
    s.add_argument("-o", "--output", required=True)
    z = sub.add_parser("sizes")
    z.add_argument("--background", required=True)
    z.add_argument("--centre-ratio", type=float, required=True)
    z.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    {"surface": write_surface, "sizes": write_sizes}[args.command](args)


if __name__ == "__main__":
    main()
