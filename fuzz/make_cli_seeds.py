#!/usr/bin/env python3
"""Writes the seed corpus of cli_fuzz (fuzz/corpus/cli/): small valid inputs for each subcommand,
in the layout of fuzz/cli_fuzz.cpp's header: subcommand, extension, option bits, 8 value bytes,
the first file's length, then the file(s)."""
import os
import struct

SUBS = ["delaunay", "verify", "constrain", "mesh", "optimize", "quality", "convert", "plot", "adapt",
        "metric", "transfer"]
EXTS = ["node", "poly", "mesh", "ele", "msh", "off", "obj", "stl", "smesh", "txt", "meshb", "sol", "xyz", "vtu"]
NUMBERS = ["0", "-1", "nan", "inf", "1e300", "abc", "0.5", "1", "2", "3", "1e100", "-inf", "", "1e12", "100", "7"]

NODE2 = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
POLY2 = NODE2 + "4 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n0\n"
MESH2 = ("MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
         "Edges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nTriangles\n2\n1 2 4 1\n2 3 4 1\nEnd\n")
MESH3 = ("MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0.3 0.3 0.3 0\n"
         "Tetrahedra\n4\n1 2 3 5 1\n1 2 5 4 1\n2 3 5 4 1\n1 5 3 4 1\nEnd\n")
OFF = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
SOL2 = "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 1\n0.1\n0.2\n0.3\n0.4\nEnd\n"
SOL2_METRIC = "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 3\n" + "4 0 4\n" * 4 + "End\n"


def seed(sub, ext, options=(), values=(), first="", second=""):
    bits = sum(1 << i for i in options)
    vals = [NUMBERS.index(v) for v in values] + [0] * (8 - len(values))
    head = bytes([SUBS.index(sub), EXTS.index(ext)]) + struct.pack("<H", bits) + bytes(vals)
    return head + struct.pack("<H", len(first.encode())) + first.encode() + second.encode()


SEEDS = {
    "delaunay_node": seed("delaunay", "node", [0, 2], first=NODE2),
    "delaunay_random3": seed("delaunay", "txt", [7, 10], ["7"]),
    "verify_node_mesh": seed("verify", "node", first=NODE2, second=MESH2),
    "constrain_poly": seed("constrain", "poly", [0, 4], first=POLY2),
    "constrain_off": seed("constrain", "off", [0], first=OFF),
    "mesh_poly_size": seed("mesh", "poly", [0, 1], ["0.5"], first=POLY2),
    "mesh_off": seed("mesh", "off", [0, 1], ["1"], first=OFF),
    "optimize_mesh2": seed("optimize", "mesh", [0, 1], ["0.5"], first=MESH2),
    "optimize_mesh3": seed("optimize", "mesh", [0, 2], ["2"], first=MESH3),
    "quality_metric": seed("quality", "mesh", [2], first=MESH2, second=SOL2_METRIC),
    "convert_msh": seed("convert", "mesh", [1], first=MESH3),
    "convert_vtu_sol": seed("convert", "mesh", [2, 9], first=MESH2, second=SOL2),
    "plot_mesh2": seed("plot", "mesh", [1], first=MESH2),
    "adapt_mesh2": seed("adapt", "mesh", [0, 1], ["2"], first=MESH2),
    "metric_sol": seed("metric", "mesh", [0], ["100"], first=MESH2, second=SOL2),
    "transfer_sol": seed("transfer", "mesh", [1], first=MESH2, second=SOL2),
}

if __name__ == "__main__":
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "cli")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
    print(f"{len(SEEDS)} seeds in {out}")
