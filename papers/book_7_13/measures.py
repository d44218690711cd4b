#!/usr/bin/env python3
"""Measures that run.sh takes from outside dtlab, so that they check dtlab instead of repeating it.

  measures.py target SURFACE
      The book's "target" (§7.13 and §8.7): the Q_K of the best tetrahedron that can be built on the
      worst boundary face, i.e. the largest over the faces of the smallest Q_K of a tetrahedron on the
      face (the apex on the normal through the face's centroid, golden-section search on its height).
      SURFACE: an .off, a TetGen .face (its .node beside it) or a Medit .mesh (its Triangles).
      Prints "TARGET FACES".

  measures.py same-domain BEFORE.ele AFTER.mesh
      Whether AFTER (dtlab optimize's output) is a conforming tetrahedral mesh of the domain of BEFORE
      (TetGen's .ele, with its .node and .face): no tetrahedron of zero volume and all of one
      orientation, each triangle in at most two tetrahedra, the triangles in one tetrahedron the same
      (as coordinate triples) as TetGen's boundary faces and as AFTER's Triangles, and the same
      volume (relative difference below 1e-9). Prints "ok ..." or a reason and exits 1.
"""
import math
import sys

FRACTION = (math.sqrt(5.0) - 1.0) / 2.0


def read_off(path):
    with open(path) as f:
        tokens = f.read().split()
    nv, nf = int(tokens[1]), int(tokens[2])
    points = [tuple(float(t) for t in tokens[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
    k = 4 + 3 * nv
    triangles = []
    for _ in range(nf):
        if int(tokens[k]) != 3:
            sys.exit(f"measures.py: {path}: a face with {tokens[k]} vertices")
        triangles.append(tuple(int(t) for t in tokens[k + 1:k + 4]))
        k += 4
    return points, triangles


def tetgen_rows(path):
    with open(path) as f:
        rows = [line.split("#")[0].split() for line in f]
    rows = [r for r in rows if r]
    return rows[1:]


def read_tetgen(base):
    """Vertices (by TetGen's numbers), tetrahedra and boundary faces of BASE.node/.ele/.face."""
    points = {int(r[0]): tuple(float(x) for x in r[1:4]) for r in tetgen_rows(base + ".node")}
    tets = [tuple(int(x) for x in r[1:5]) for r in tetgen_rows(base + ".ele")]
    faces = [tuple(int(x) for x in r[1:4]) for r in tetgen_rows(base + ".face")]
    return points, tets, faces


def read_medit(path):
    """Vertices (numbered from 1), Tetrahedra and Triangles of a Medit .mesh."""
    with open(path) as f:
        tokens = f.read().split()

    def section(name, width):
        if name not in tokens:
            return []
        k = tokens.index(name)
        count = int(tokens[k + 1])
        return [tokens[k + 2 + (width + 1) * i:k + 2 + (width + 1) * i + width] for i in range(count)]

    points = {i + 1: tuple(float(x) for x in r) for i, r in enumerate(section("Vertices", 3))}
    tets = [tuple(int(x) for x in r) for r in section("Tetrahedra", 4)]
    faces = [tuple(int(x) for x in r) for r in section("Triangles", 3)]
    return points, tets, faces


def shape_quality(a, b, c, d):
    """Q_K = alpha h_max / rho (book (1.13)), alpha = sqrt(6) / 12: 1 for the regular tetrahedron."""
    ab, ac, ad = sub(b, a), sub(c, a), sub(d, a)
    n = cross(ab, ac)
    volume = abs(dot(n, ad)) / 6.0
    if volume == 0.0:
        return math.inf
    area = (norm(n) + norm(cross(ab, ad)) + norm(cross(ac, ad)) + norm(cross(sub(c, b), sub(d, b)))) / 2.0
    h_max = max(norm(ab), norm(ac), norm(ad), norm(sub(c, b)), norm(sub(d, b)), norm(sub(d, c)))
    return math.sqrt(6.0) / 12.0 * h_max * area / (3.0 * volume)


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def norm(u):
    return math.sqrt(dot(u, u))


def best_quality_on(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    nn = norm(n)
    g = tuple((a[d] + b[d] + c[d]) / 3.0 for d in range(3))
    length = max(math.dist(a, b), math.dist(b, c), math.dist(c, a))

    def q(t):
        return shape_quality(a, b, c, tuple(g[d] + t * length * n[d] / nn for d in range(3)))

    lo, hi = 0.01, 3.0
    x1, x2 = hi - FRACTION * (hi - lo), lo + FRACTION * (hi - lo)
    f1, f2 = q(x1), q(x2)
    for _ in range(45):  # the bracket shrinks to 3 * 0.618^45, below 1e-9 of the face's size
        if f1 < f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - FRACTION * (hi - lo)
            f1 = q(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + FRACTION * (hi - lo)
            f2 = q(x2)
    return min(f1, f2)


def target(path):
    if path.endswith(".off"):
        points, faces = read_off(path)
    elif path.endswith(".face"):
        points, _, faces = read_tetgen(path[:-len(".face")])
    else:
        points, _, faces = read_medit(path)
    worst = max(best_quality_on(points[a], points[b], points[c]) for a, b, c in faces)
    print(f"{worst:.6f} {len(faces)}")


def signed_volume(points, t):
    a, b, c, d = (points[i] for i in t)
    return dot(cross(sub(b, a), sub(c, a)), sub(d, a)) / 6.0


def once_faces(points, tets, name):
    """The triangles of exactly one tetrahedron, as sets of coordinate triples; fails on a triangle in
    three or more, a flat tetrahedron or two orientations."""
    count = {}
    signs = set()
    volume = 0.0
    for t in tets:
        v = signed_volume(points, t)
        if v == 0.0:
            fail(f"{name}: a flat tetrahedron {t}")
        signs.add(v > 0)
        volume += abs(v)
        for k in range(4):
            key = frozenset(points[t[j]] for j in range(4) if j != k)
            count[key] = count.get(key, 0) + 1
    if len(signs) != 1:
        fail(f"{name}: tetrahedra of both orientations")
    if max(count.values()) > 2:
        fail(f"{name}: a triangle in {max(count.values())} tetrahedra")
    return {f for f, c in count.items() if c == 1}, volume


def same_domain(before, after):
    p0, t0, f0 = read_tetgen(before[:-len(".ele")])
    p1, t1, f1 = read_medit(after)
    boundary0 = {frozenset(p0[i] for i in f) for f in f0}
    boundary1 = {frozenset(p1[i] for i in f) for f in f1}
    once0, volume0 = once_faces(p0, t0, before)
    once1, volume1 = once_faces(p1, t1, after)
    if once0 != boundary0:
        fail(f"{before}: its .face is not the boundary of its tetrahedra")
    if once1 != boundary0:
        fail(f"{after}: the boundary of its tetrahedra is not {before}'s ({len(once1)} against {len(boundary0)} triangles)")
    if boundary1 != boundary0:
        fail(f"{after}: its Triangles are not {before}'s boundary faces")
    if abs(volume1 - volume0) > 1e-9 * volume0:
        fail(f"{after}: volume {volume1!r} against {volume0!r}")
    print(f"ok boundary_triangles={len(boundary0)} tetrahedra={len(t0)}->{len(t1)} volume={volume1:.12g}")


def fail(message):
    print(message)
    sys.exit(1)


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "target":
        target(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "same-domain":
        same_domain(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
