#!/usr/bin/env python3
"""Writes the seed corpus of fuzz/delaunay2d_fuzz.cpp into fuzz/corpus/delaunay2d/.

Layout (see the fuzzer's header): byte 0 = mode, byte 1 = parameter (modes 1-3: scale 2^(p&127 - 64),
top bit: translate by 1e9), then the payload. Deterministic: run once, commit the files.
"""
import math
import os
import random
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "delaunay2d")
UNIT = 64  # parameter for scale 2^0, no translation


def raw(points):  # mode 0: little-endian doubles
    return bytes([0, 0]) + b"".join(struct.pack("<dd", x, y) for x, y in points)


def lattice16(points, parameter=UNIT):  # mode 1: one byte per coordinate, 0..15
    return bytes([1, parameter]) + bytes(v & 15 for p in points for v in p)


def int16(points, parameter=UNIT):  # mode 2: signed 16-bit integers
    return bytes([2, parameter]) + b"".join(struct.pack("<hh", x, y) for x, y in points)


def nudged(points, parameter=UNIT):  # mode 3: (k, s) per coordinate: k/2 moved by s%4 ulps
    return bytes([3, parameter]) + bytes(b & 255 for p in points for c in p for b in c)


def main():
    rng = random.Random(20240611)
    seeds = {
        # the whole 16 x 16 lattice, shuffled: cocircular everywhere, collinear hull sides
        "lattice_full": lattice16(rng.sample([(i, j) for i in range(16) for j in range(16)], 256)),
        # a lattice scaled by 2^-60 and one translated by 1e9 (which rounds it)
        "lattice_tiny": lattice16([(rng.randrange(16), rng.randrange(16)) for _ in range(60)], 4),
        "lattice_far": lattice16([(rng.randrange(16), rng.randrange(16)) for _ in range(60)], 128 + 40),
        # all collinear, with repeats; then every point equal
        "collinear": lattice16([(t, t) for t in [0, 3, 1, 15, 7, 3, 9]]),
        "all_equal": lattice16([(5, 5)] * 12),
        "tiny": lattice16([(0, 0), (1, 0), (0, 1)]),
        # integer points on x^2 + y^2 = 65^2 (Pythagorean), plus the centre
        "exact_circle": int16([(x, y) for x in range(-65, 66) for y in range(-65, 66) if x * x + y * y == 65 * 65]
                              + [(0, 0)]),
        # several collinear runs and off-line points
        "collinear_runs": int16([(3 * t, 2 * t - 50) for t in range(-20, 20, 3)]
                                + [(-t, 7 * t) for t in range(-10, 11, 2)] + [(13, -17), (-31, 5)]),
        # a half-integer square lattice moved by a few ulps
        "nudged_lattice": nudged([((2 * i, rng.randrange(4)), (2 * j, rng.randrange(4))) for i in range(6)
                                  for j in range(6)]),
        # uniform doubles, points near a circle, and a raw mix with NaN, infinities, huge and tiny values
        "raw_uniform": raw([(rng.random(), rng.random()) for _ in range(100)]),
        "raw_near_circle": raw([(math.cos(a), math.sin(a)) for a in (rng.uniform(0, 2 * math.pi) for _ in range(60))]),
        "raw_specials": raw([(float("nan"), 1.0), (float("inf"), -2.0), (1e300, -1e-300), (-float("inf"), 5e-324),
                             (0.0, -0.0), (1.0, 1.0), (2.0, 3.0), (1e9, 1e9 + 0.5)]),
    }
    os.makedirs(OUT, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
    print(f"wrote {len(seeds)} seeds to {OUT}")


if __name__ == "__main__":
    main()
