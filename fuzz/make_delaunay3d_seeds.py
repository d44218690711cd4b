#!/usr/bin/env python3
"""Writes the seed corpus of fuzz/delaunay3d_fuzz.cpp into fuzz/corpus/delaunay3d/.

Layout (see the fuzzer's header): byte 0 = mode, byte 1 = parameter (modes 1-3: scale 2^(p&127 - 64),
top bit: translate by 1e9), then the payload. Deterministic: run once, commit the files.
"""
import math
import os
import random
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "delaunay3d")
UNIT = 64  # parameter for scale 2^0, no translation


def raw(points):  # mode 0: little-endian doubles
    return bytes([0, 0]) + b"".join(struct.pack("<ddd", x, y, z) for x, y, z in points)


def grid4(points, parameter=UNIT):  # mode 1: one byte per coordinate, 0..3
    return bytes([1, parameter]) + bytes(v & 3 for p in points for v in p)


def lattice16(points, parameter=UNIT):  # mode 2: one byte per coordinate, 0..15
    return bytes([2, parameter]) + bytes(v & 15 for p in points for v in p)


def int16(points, parameter=UNIT):  # mode 3: signed 16-bit integers
    return bytes([3, parameter]) + b"".join(struct.pack("<hhh", x, y, z) for x, y, z in points)


def sphere(r):  # every integer point of x^2 + y^2 + z^2 = r^2
    return [(x, y, z) for x in range(-r, r + 1) for y in range(-r, r + 1) for z in range(-r, r + 1)
            if x * x + y * y + z * z == r * r]


def main():
    rng = random.Random(20240612)
    cube = [(i, j, k) for i in range(4) for j in range(4) for k in range(4)]
    seeds = {
        # the whole 4 x 4 x 4 grid, shuffled: cospherical and coplanar everywhere
        "grid4_full": grid4(rng.sample(cube, 64)),
        # random subsets of it, one scaled by 2^-60, one translated by 1e9 (which rounds it)
        "grid4_subset": grid4(rng.sample(cube, 20)),
        "grid4_tiny": grid4(rng.sample(cube, 30), 4),
        "grid4_far": grid4(rng.sample(cube, 30), 128 + 40),
        # cube corners (8 cospherical points), a square pyramid (flat hull face), one tetrahedron
        "cube_corners": grid4([(x, y, z) for x in (0, 3) for y in (0, 3) for z in (0, 3)]),
        "pyramid": grid4([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (1, 1, 1)]),
        "tetrahedron": grid4([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]),
        # degenerate outcomes: all collinear, all coplanar, all equal, fewer than four
        "collinear": grid4([(t, t, t) for t in [0, 3, 1, 2, 1]]),
        "coplanar": lattice16([(x, y, (x + y) % 16) for x in range(4) for y in range(4) if x + y < 16]),
        "all_equal": grid4([(1, 2, 3)] * 9),
        "three": grid4([(0, 0, 0), (1, 0, 0), (0, 1, 0)]),
        # a lattice with two coplanar layers and a point between; a 16^3 lattice sample
        "layers": lattice16([(x, y, z) for x in range(5) for y in range(5) for z in (0, 8)] + [(2, 2, 4)]),
        "lattice16": lattice16([(rng.randrange(16), rng.randrange(16), rng.randrange(16)) for _ in range(150)]),
        # integer points on spheres of radius 9 and 21, with the centre; collinear runs with off-line points
        "exact_sphere9": int16(sphere(9) + [(0, 0, 0)]),
        "exact_sphere21": int16(sphere(21)),
        "collinear_runs": int16([(3 * t, 2 * t - 50, -t) for t in range(-20, 20, 3)]
                                + [(-t, 7 * t, 2 * t) for t in range(-10, 11, 2)] + [(13, -17, 5), (-31, 5, 9)]),
        # uniform doubles, points near a sphere, and a raw mix with NaN, infinities, huge and tiny values
        "raw_uniform": raw([(rng.random(), rng.random(), rng.random()) for _ in range(120)]),
        "raw_near_sphere": raw([(math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t))
                                for t, p in ((math.acos(rng.uniform(-1, 1)), rng.uniform(0, 2 * math.pi))
                                             for _ in range(80))]),
        "raw_specials": raw([(float("nan"), 1.0, 0.0), (float("inf"), -2.0, 1.0), (1e300, -1e-300, 2.0),
                             (-float("inf"), 5e-324, 3.0), (0.0, -0.0, 0.0), (1.0, 1.0, 1.0), (2.0, 3.0, 5.0),
                             (1e9, 1e9 + 0.5, 7.0)]),
    }
    os.makedirs(OUT, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
    print(f"wrote {len(seeds)} seeds to {OUT}")


if __name__ == "__main__":
    main()
