#!/usr/bin/env python3
"""Writes data/default.node, the bundled default input of `scripts/run-main.sh`.

A deliberately hostile 2D point set (Triangle .node format, numbered from 1), deterministic:
  - 12,000 uniform points in the unit square (integer multiples of 2^-20: exact in decimal),
  - a 60 x 60 integer-step grid scaled by 1/64 (thousands of exactly cocircular 4-tuples),
  - two exactly cocircular sets: the integer points on x^2 + y^2 = 25 (scaled by 1/64) and on
    x^2 + y^2 = 8125 (scaled by 1/1024), both centred at (0.5, 0.5),
  - a collinear run of 500 points on the diagonal y = x,
  - 40 exact duplicates of earlier points (reported, kept unreferenced).
Every coordinate is a short exact decimal, so the file reads back bit for bit.
"""
import random

rng = random.Random(20261123)
pts = []
for _ in range(12000):
    pts.append((rng.randrange(0, 2**20) / 2**20, rng.randrange(0, 2**20) / 2**20))
for i in range(60):
    for j in range(60):
        pts.append((1.25 + i / 64.0, j / 64.0))
for r2, scale, cx in ((25, 1 / 64.0, 0.5), (8125, 1 / 1024.0, 0.5)):
    r = int(r2 ** 0.5) + 1
    for x in range(-r, r + 1):
        for y in range(-r, r + 1):
            if x * x + y * y == r2:
                pts.append((cx + x * scale, 0.5 + y * scale))
for k in range(500):
    t = -0.5 + k / 512.0
    pts.append((t, t))
for _ in range(40):
    pts.append(pts[rng.randrange(0, len(pts))])

with open(__file__.replace("make_default_input.py", "default.node"), "w") as f:
    f.write("# dtlab's bundled default input: written by data/make_default_input.py\n")
    f.write(f"{len(pts)} 2 0 0\n")
    for i, (x, y) in enumerate(pts, 1):
        f.write(f"{i} {x!r} {y!r}\n")
