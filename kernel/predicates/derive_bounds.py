#!/usr/bin/env python3
"""Derives the semi-static filter constants of dtlab's predicates.

Forward error analysis in exact rational arithmetic, mirroring the evaluation trees of
semistatic.hpp operation for operation. Every value is homogeneous in the maxima m of the
computed coordinate differences; a node carries
    B: bound on |computed value| / m^deg
    E: bound on |computed value - exact value on the exact inputs| / m^deg
with u = 2^-53 (round to nearest, no underflow: guaranteed by the supported coordinate range).

    leaf  d~ = fl(p - q):   B = 1, E = u          (|d - d~| <= u |d~| <= u m)
    fl(x * y):             B = Bx By (1+u),      E = Bx Ey + By Ex + Ex Ey + u Bx By
    fl(x +- y):            B = (Bx + By)(1+u),   E = Ex + Ey + u (Bx + By)

The filter certifies sign(det~) when |det~| > C * prod(m), with C = E_root padded for the
rounding of the product C * prod(m) itself (deg + 1 roundings, each a factor 1 + u), and
rounded up to a double. Run it to print the constants; semistatic.hpp holds the results.
"""
from fractions import Fraction
import math

U = Fraction(1, 2**53)


class Node:
    def __init__(self, b, e):
        self.b, self.e = b, e

    def __mul__(self, o):
        return Node(self.b * o.b * (1 + U), self.b * o.e + o.b * self.e + self.e * o.e + U * self.b * o.b)

    def __add__(self, o):
        return Node((self.b + o.b) * (1 + U), self.e + o.e + U * (self.b + o.b))

    __sub__ = __add__


def leaf():
    return Node(Fraction(1), U)


def det2(a, b, c, d):  # a*d - b*c
    return a * d - b * c


def det3(r0, r1, r2):
    # r0[0]*(r1[1]*r2[2] - r1[2]*r2[1]) - r1[0]*(r0[1]*r2[2] - r0[2]*r2[1]) + r2[0]*(r0[1]*r1[2] - r0[2]*r1[1])
    return (r0[0] * det2(r1[1], r1[2], r2[1], r2[2]) - r1[0] * det2(r0[1], r0[2], r2[1], r2[2])) + r2[0] * det2(
        r0[1], r0[2], r1[1], r1[2])


def orient2d():
    return det2(leaf(), leaf(), leaf(), leaf())


def orient3d():
    return det3([leaf()] * 3, [leaf()] * 3, [leaf()] * 3)


def lift2():
    x, y = leaf(), leaf()
    return x * x + y * y


def lift3():
    x, y, z = leaf(), leaf(), leaf()
    return (x * x + y * y) + z * z


def incircle():
    # la*(bx*cy - by*cx) - lb*(ax*cy - ay*cx) + lc*(ax*by - ay*bx)
    m = det2(leaf(), leaf(), leaf(), leaf())
    return (lift2() * m - lift2() * m) + lift2() * m


def insphere():
    # la*M(b,c,d) - lb*M(a,c,d) + lc*M(a,b,d) - ld*M(a,b,c), M a 3x3 minor
    m = orient3d()
    return ((lift3() * m - lift3() * m) + lift3() * m) - lift3() * m


def constant(node, degree):
    c = node.e * (1 + U) ** (degree + 1)
    f = float(c)
    while Fraction(f) < c:
        f = math.nextafter(f, math.inf)
    return f


if __name__ == "__main__":
    for name, fn, deg in (("orient2d", orient2d, 2), ("orient3d", orient3d, 3), ("incircle", incircle, 4),
                          ("insphere", insphere, 5)):
        print(f"{name}: {constant(fn(), deg)!r}")
