#!/usr/bin/env python3
"""Writes data/schonhardt.stl: data/schonhardt.off (Schönhardt's twisted prism) as binary STL.

Binary STL stores 32-bit floats, so its corners are the OFF file's rounded to float: another
prism a few 1e-8 away, still twisted. Facet normals are the cross products of the rounded
corners (readers ignore them; dtlab orients shells by itself). The CLI tests read it.
"""
import pathlib
import struct

here = pathlib.Path(__file__).parent
rows = [r for r in (here / "schonhardt.off").read_text().splitlines() if r.strip() and not r.startswith("#")]
nv, nf, _ = map(int, rows[1].split())
points = [tuple(struct.unpack("<3f", struct.pack("<3f", *map(float, r.split())))) for r in rows[2:2 + nv]]
faces = [tuple(map(int, r.split()[1:4])) for r in rows[2 + nv:2 + nv + nf]]


def normal(face):
    a, b, c = (points[i] for i in face)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


with open(here / "schonhardt.stl", "wb") as out:
    out.write(b"dtlab: Schonhardt's twisted prism (data/schonhardt.off), binary STL".ljust(80, b" "))
    out.write(struct.pack("<I", len(faces)))
    for face in faces:
        out.write(struct.pack("<3f", *normal(face)))
        for i in face:
            out.write(struct.pack("<3f", *points[i]))
        out.write(struct.pack("<H", 0))
