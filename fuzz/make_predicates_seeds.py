#!/usr/bin/env python3
"""Writes the seed corpus of predicates_fuzz (fuzz/corpus/predicates/): exactly degenerate
configurations in each input mode of fuzz/predicates_fuzz.cpp (see the layout there).
Header: mode byte, transform byte (bit 0: scale by 2^e, e = -142 + (t >> 2) * 268 // 63;
bit 1: translate by 1e9), transposition byte. Run from the repository root."""
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "predicates")


def header(mode, transform=0, swap=0x21):
    return bytes([mode, transform, swap])


def raw(coords):  # mode 0: little-endian doubles
    return header(0) + b"".join(struct.pack("<d", c) for c in coords)


def small(coords, transform=0):  # mode 1: signed bytes
    return header(1, transform) + bytes((c + 256) % 256 for c in coords)


def lattice(coords, transform=0):  # mode 2: signed 16-bit
    return header(2, transform) + b"".join(struct.pack("<h", c) for c in coords)


def ulps(halves, steps):  # mode 3: per coordinate, k (value k / 2) and a signed step count
    return header(3) + b"".join(bytes([(k + 256) % 256, (s + 256) % 256]) for k, s in zip(halves, steps))


def pad(coords, n=15):
    return list(coords) + [0] * (n - len(coords))


SCALE_LARGE = 1 | (63 << 2)  # e = 126
SCALE_SMALL = 1 | (0 << 2)   # e = -142
FAR = 2

seeds = {
    # Kettner et al.'s orientation example: p = (0.5, 0.5) on the line through (12, 12), (24, 24).
    "kettner_collinear": raw(pad([0.5, 0.5, 12, 12, 24, 24, 0.5 + 2**-53, 0.5])),
    # Corners of a square: exactly cocircular (incircle zero), then perturbed.
    "square_cocircular": raw(pad([23.5, 0.5, 23.5, 23.5, 0.5, 23.5, 0.5, 0.5])),
    "collinear_small": small(pad([0, 0, 1, 1, 2, 2, 3, 3])),
    "cocircular_small": small(pad([1, 0, 0, 1, -1, 0, 0, -1])),
    "duplicates_small": small(pad([1, 2, 1, 2, 3, 4, 3, 4])),
    "cospherical_small": small([1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, 0, -1]),
    "coplanar_small": small([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0]),
    "cocircular_lattice_large": lattice(pad([5, 0, 3, 4, -4, 3, 0, -5]), SCALE_LARGE),
    "cocircular_lattice_small": lattice(pad([5, 0, 3, 4, -4, 3, 0, -5]), SCALE_SMALL),
    "cospherical_lattice_far": lattice([2, 3, 6, 6, 2, 3, 3, 6, 2, -7, 0, 0, 0, 0, 7], FAR),
    "collinear_far": small(pad([0, 0, 1, 1, 2, 2, 3, 3]), FAR),
    # Kettner's example in mode 3: p = (0.5 + 1 ulp, 0.5 - 2 ulps), q = (12, 12), r = (24, 24).
    "kettner_ulps": ulps(pad([1, 1, 24, 24, 48, 48, 1, 47]), pad([1, -2, 0, 0, 0, 0, 3, 0])),
    # The square's corners, the last one moved off the circle by ulps.
    "square_ulps": ulps(pad([47, 1, 47, 47, 1, 47, 1, 1]), pad([0, 0, 0, 0, 0, 0, -5, 3])),
    # Found by verify/tests/predicate_properties_test on a work-in-progress stage 2 (the
    # double-word estimate for rounded differences), which gave the wrong sign on these:
    # the in-circle Kettner grid point (0, 192), outside the circle;
    "incircle_adaptive_rounded_grid": raw(pad([23.5, 0.5, 23.5, 23.5, 0.5, 23.5,
                                               float.fromhex("0x1.fffffffffffp-2"),
                                               float.fromhex("0x1.000000000004p-1")])),
    # a near-cocircular quadruple scaled by 2^-120;
    "incircle_adaptive_rounded_small": raw(pad([float.fromhex(h) for h in (
        "-0x1.99f84c72c3fc9p-121", "0x1.256ced763f8f4p-120", "0x1.98903f6d7aa57p-120",
        "-0x1.7fcf243e1b972p-121", "-0x1.bca7d9f17638ep-122", "-0x1.2ef501326cda5p-120",
        "0x1.4142654a8a915p-121", "0x1.a313585237df9p-120")])),
    # a near-cospherical quintuple scaled by 2^-120.
    "insphere_adaptive_rounded_small": raw([float.fromhex(h) for h in (
        "-0x1.33aa816d98ce9p-121", "-0x1.7a580d80e3bedp-122", "-0x1.afed1a4efe8ecp-121",
        "-0x1.9bfd97738a73dp-122", "-0x1.467e4978007c5p-122", "-0x1.84349236d287p-121",
        "-0x1.63115bc9ac0f9p-122", "-0x1.72f159168bb93p-122", "-0x1.8ba5836586239p-121",
        "-0x1.7ff6aa4ad7b46p-122", "-0x1.195c57a23084cp-121", "-0x1.de99d737ccfafp-121",
        "-0x1.dbc4074095176p-122", "-0x1.03c1a4cd693b4p-123", "-0x1.1607cbc9bcaa6p-120")]),
}

os.makedirs(OUT, exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)
print(f"wrote {len(seeds)} seeds to {OUT}")
