#!/usr/bin/env python3
"""Writes the seed corpus of fuzz/constrained2d_fuzz.cpp into fuzz/corpus/constrained2d/.

Layout (see the fuzzer's header): byte 0 = mode (0 lattice byte per point, 1 raw doubles,
2 nudged half-integers), byte 1 = point count, byte 2 = flags (bit 0 keep exterior, bit 1 hole
at the centroid of the first three points), the points, then segment index pairs.
Deterministic: run once, commit the files.
"""
import os
import random
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "constrained2d")


def lattice(points, segments, flags=0):  # mode 0: x in the low nibble, y in the high one
    return bytes([0, len(points), flags]) + bytes((x & 15) | ((y & 15) << 4) for x, y in points) + \
        bytes(i for s in segments for i in s)


def raw(points, segments, flags=0):  # mode 1: little-endian doubles
    return bytes([1, len(points), flags]) + b"".join(struct.pack("<dd", x, y) for x, y in points) + \
        bytes(i for s in segments for i in s)


def nudged(points, segments, flags=0):  # mode 2: (k, s) per coordinate, k/2 moved by s%4 ulps
    return bytes([2, len(points), flags]) + bytes(b & 255 for p in points for c in p for b in c) + \
        bytes(i for s in segments for i in s)


def ring(first, count):
    return [(first + i, first + (i + 1) % count) for i in range(count)]


def main():
    rng = random.Random(20240612)
    square = [(0, 0), (15, 0), (15, 15), (0, 15), (6, 6), (9, 6), (9, 9), (6, 9), (3, 0), (3, 15)]
    seeds = {
        # a square with a square hole (the hole point is the centroid of points 4, 5, 6: inside)
        # and a wall, as data/square_with_hole.poly
        "square_with_hole": lattice([square[4], square[5], square[6]] + square[:4] + square[7:],
                                    ring(3, 4) + [(0, 1), (1, 2), (2, 7), (7, 0), (8, 9)], flags=2),
        "square_keep_exterior": lattice(square, ring(0, 4) + ring(4, 4) + [(8, 9)], flags=1),
        # crossing diagonals, a segment through a vertex, collinear overlaps, duplicates
        "crossings_overlaps": lattice([(0, 0), (8, 8), (0, 8), (8, 0), (4, 4), (2, 0), (6, 0), (12, 0)],
                                      [(0, 1), (2, 3), (0, 7), (5, 6), (5, 7), (1, 0), (3, 3)]),
        # many segments through one non-vertex point, at non-double crossings
        "star_of_segments": lattice([(0, 1), (15, 14), (1, 15), (14, 0), (0, 7), (15, 8), (7, 0), (8, 15)],
                                    [(0, 1), (2, 3), (4, 5), (6, 7)]),
        # a random soup on the lattice
        "soup": lattice([(rng.randrange(16), rng.randrange(16)) for _ in range(30)],
                        [(rng.randrange(30), rng.randrange(30)) for _ in range(25)]),
        # random doubles with random segments (crossings at rounded points)
        "raw_random": raw([(rng.random(), rng.random()) for _ in range(20)],
                          [(rng.randrange(20), rng.randrange(20)) for _ in range(8)]),
        # a nudged lattice: a few ulps off the degenerate configurations
        "nudged_grid": nudged([((rng.randrange(-8, 8), rng.randrange(4)), (rng.randrange(-8, 8), rng.randrange(4)))
                               for _ in range(24)], [(rng.randrange(24), rng.randrange(24)) for _ in range(12)]),
        # a small angle at a shared vertex: conforming's concentric shells
        "small_angle": raw([(0, 0), (100, 1), (100, -1), (50, 3), (50, -3), (30, 0)], [(0, 1), (0, 2)]),
    }
    os.makedirs(OUT, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
    print(f"wrote {len(seeds)} seeds to {OUT}")


if __name__ == "__main__":
    main()
