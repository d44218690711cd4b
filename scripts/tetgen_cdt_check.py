#!/usr/bin/env python3
"""Is a TetGen output constrained Delaunay? An exact check in rationals, for the comparison of
Steiner point counts in docs/performance.md (a count means something only beside a CDT).

    scripts/tetgen_cdt_check.py OUT.1        # reads OUT.1.node, OUT.1.ele, OUT.1.face

For every facet shared by two tetrahedra of OUT.1.ele that is not one of the triangles of
OUT.1.face (TetGen's boundary and constraint faces), the vertex across must not lie strictly inside
the circumsphere of the tetrahedron on this side: the local condition that, by the constrained
Delaunay lemma (Shewchuk 2008), makes the tetrahedra a CDT of what they cover. Also counts the
tetrahedra that are not positively oriented. Coordinates are read as doubles and turned into
exact fractions; orient3d and insphere are the plain determinants, no tolerance. Prints one line:
points, tetrahedra, non-positive tetrahedra, unconstrained interior facets, facets not locally
Delaunay; exit status 1 when either count is not zero. Pure Python: a few seconds per thousand
tetrahedra.
"""
import sys
from fractions import Fraction


def rows(path):
    out = []
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if words:
                out.append(words)
    return out


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def det3(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
            a[2] * (b[0] * c[1] - b[1] * c[0]))


def orient3d(a, b, c, d):
    """Positive when d lies on the side of plane abc that (b - a) x (c - a) points to."""
    return det3(sub(b, a), sub(c, a), sub(d, a))


def det4(m):
    total = 0
    for j in range(4):
        minor = [[m[i][k] for k in range(4) if k != j] for i in (1, 2, 3)]
        total += (-1) ** j * m[0][j] * det3(*minor)
    return total


def insphere(a, b, c, d, e):
    """Sign convention fixed by calibration below: the lifted 4x4 determinant."""
    lifted = []
    for p in (a, b, c, d):
        q = sub(p, e)
        lifted.append([q[0], q[1], q[2], q[0] * q[0] + q[1] * q[1] + q[2] * q[2]])
    return det4(lifted)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    base = sys.argv[1]
    nodes = rows(base + ".node")
    count, first = int(nodes[0][0]), None
    points = {}
    for r in nodes[1:1 + count]:
        points[int(r[0])] = tuple(Fraction(float(x)) for x in r[1:4])
    ele = rows(base + ".ele")
    tets = [tuple(int(x) for x in r[1:5]) for r in ele[1:1 + int(ele[0][0])]]
    face = rows(base + ".face")
    constrained = {frozenset(int(x) for x in r[1:4]) for r in face[1:1 + int(face[0][0])]}

    # The sign insphere takes for a point inside a positively oriented tetrahedron's sphere.
    unit = [(Fraction(0),) * 3, (Fraction(1), Fraction(0), Fraction(0)), (Fraction(0), Fraction(1), Fraction(0)),
            (Fraction(0), Fraction(0), Fraction(1))]
    centre = (Fraction(1, 4),) * 3
    inside = (insphere(*unit, centre) > 0) == (orient3d(*unit) > 0)

    nonpositive = sum(1 for t in tets if orient3d(*[points[i] for i in t]) <= 0)
    facets = {}
    for k, t in enumerate(tets):
        for i in range(4):
            facets.setdefault(frozenset(t[:i] + t[i + 1:]), []).append((k, t[i]))
    interior = not_delaunay = 0
    for f, sides in facets.items():
        if len(sides) != 2 or f in constrained:
            continue
        interior += 1
        (k, _), (_, across) = sides
        t = [points[i] for i in tets[k]]
        o = orient3d(*t)
        s = insphere(*t, points[across])
        if s != 0 and ((s > 0) == (o > 0)) == inside:
            not_delaunay += 1
    print(f"{base}: {len(points)} points, {len(tets)} tetrahedra, {nonpositive} not positive, "
          f"{interior} unconstrained interior facets, {not_delaunay} not locally Delaunay")
    sys.exit(1 if nonpositive or not_delaunay else 0)


if __name__ == "__main__":
    main()
