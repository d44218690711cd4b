#!/usr/bin/python3
"""Files written by `dtlab convert` read back by independent readers (cli_convert.cmake):

  convert_external_check.py meshio|gmsh DTLAB DATA_DIR WORK_DIR

meshio (Debian's python3-meshio, run by /usr/bin/python3): the .msh (ASCII and binary), .vtu,
.mesh and .meshb that dtlab writes from Gmsh's own files (data/gmsh) hold the same points (bit for
bit), the same cells of each type and the same reference on each cell and vertex, and the .msh
files the same physical names (field_data) as Gmsh's originals.
gmsh (Debian's gmsh): `gmsh -check` accepts dtlab's .msh files; Gmsh reads them and writes them
again (-save_all, binary MSH 4.1), and dtlab reads that back into the same mesh, references and
physical names as it wrote.
Exits 77 (CTest's skip) when the tool is not installed.
"""
import os
import re
import shutil
import subprocess
import sys

tool, dtlab, data, work = sys.argv[1:5]
dtlab, data, work = (os.path.abspath(p) for p in (dtlab, data, work))
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def skip(why):
    print("skipped: " + why)
    sys.exit(77)


def fail(why):
    print("FAILED: " + why)
    sys.exit(1)


def convert(src, dst, *options):
    r = subprocess.run([dtlab, "convert", src, dst, *options], cwd=work, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"dtlab convert {src} {dst}: exit {r.returncode}: {r.stderr}")
    return r.stderr


SOURCES = ["cube_41_binary.msh", "square_41_binary.msh", "cube_22_binary.msh"]


def check_meshio():
    try:
        import meshio
        import numpy as np
    except ImportError:
        skip("meshio is not installed (Debian: python3-meshio)")

    def cells_with_refs(mesh, key):
        """{type: sorted list of (cell tuple, ref)}, and the vertex refs."""
        out = {}
        for block, refs in zip(mesh.cells, mesh.cell_data[key]):
            if block.type == "vertex":
                continue
            out.setdefault(block.type, []).extend(
                (tuple(int(v) for v in c), int(r)) for c, r in zip(block.data, refs))
        return {t: sorted(v) for t, v in out.items()}

    def vertex_refs(mesh, fmt):
        n = len(mesh.points)
        if fmt in ("mesh", "meshb"):
            return [int(r) for r in mesh.point_data["medit:ref"]]
        if fmt == "vtu":
            return [int(r) for r in mesh.point_data["vertex_ref"]]
        refs = [0] * n
        for block, tags in zip(mesh.cells, mesh.cell_data["gmsh:physical"]):
            if block.type == "vertex":
                for c, t in zip(block.data, tags):
                    refs[int(c[0])] = int(t)
        return refs

    for source in SOURCES:
        base = os.path.splitext(source)[0]
        original = meshio.read(os.path.join(data, source))
        convert(os.path.join(data, source), base + ".mesh")
        reference = meshio.read(os.path.join(work, base + ".mesh"))
        ref_cells = cells_with_refs(reference, "medit:ref")
        ref_vertices = vertex_refs(reference, "mesh")
        # meshio's own reading of Gmsh's file agrees with dtlab's Medit output.
        if cells_with_refs(original, "gmsh:physical") != ref_cells:
            fail(f"{source}: meshio's cells and physical tags differ from dtlab's {base}.mesh")
        outputs = [(base + ".msh", "msh", "gmsh:physical", []), (base + "-binary.msh", "msh", "gmsh:physical", ["--binary"]),
                   (base + ".vtu", "vtu", "ref", []), (base + ".meshb", "meshb", "medit:ref", [])]
        for name, fmt, key, options in outputs:
            convert(base + ".mesh" if fmt != "msh" else os.path.join(data, source), name, *options)
            m = meshio.read(os.path.join(work, name))
            if not np.array_equal(m.points[:, : reference.points.shape[1]], reference.points):
                fail(f"{name}: points differ from {base}.mesh")
            got = cells_with_refs(m, key)
            if got != ref_cells:
                fail(f"{name}: cells or references differ: " +
                     ", ".join(f"{t} {len(got.get(t, []))} vs {len(ref_cells.get(t, []))}" for t in ref_cells))
            if vertex_refs(m, fmt) != ref_vertices:
                fail(f"{name}: vertex references differ")
            if fmt == "msh":
                names = {k: [int(x) for x in v] for k, v in m.field_data.items()}
                expected = {k: [int(x) for x in v] for k, v in original.field_data.items()}
                if names != expected:
                    fail(f"{name}: physical names {names}, Gmsh's file has {expected}")
            print(f"meshio reads {name}: {len(m.points)} points, " +
                  ", ".join(f"{len(v)} {t}" for t, v in sorted(got.items())))


def physical_names(path):
    with open(path, "rb") as f:
        text = f.read()
    m = re.search(rb"\$PhysicalNames\n(\d+)\n(.*?)\$EndPhysicalNames", text, re.S)
    return sorted(m.group(2).decode().splitlines()) if m else []


def check_gmsh():
    gmsh = shutil.which("gmsh")
    if gmsh is None:
        skip("gmsh is not installed (Debian: gmsh)")
    for source in SOURCES:
        base = os.path.splitext(source)[0]
        for name, options in [(base + ".msh", []), (base + "-binary.msh", ["--binary"])]:
            convert(os.path.join(data, source), name, *options)
            r = subprocess.run([gmsh, name, "-check"], cwd=work, capture_output=True, text=True)
            if r.returncode != 0 or "Error" in r.stdout + r.stderr:
                fail(f"gmsh -check {name}: exit {r.returncode}\n{r.stdout}{r.stderr}")
            again = "gmsh-" + name
            r = subprocess.run([gmsh, name, "-0", "-save_all", "-bin", "-format", "msh41", "-o", again],
                               cwd=work, capture_output=True, text=True)
            if r.returncode != 0 or "Error" in r.stdout + r.stderr:
                fail(f"gmsh {name} -0: exit {r.returncode}\n{r.stdout}{r.stderr}")
            convert(name, name + ".mesh")
            convert(again, again + ".mesh")
            with open(os.path.join(work, name + ".mesh")) as a, open(os.path.join(work, again + ".mesh")) as b:
                if a.read() != b.read():
                    fail(f"{again}, written by Gmsh from {name}, reads back into another mesh")
            if physical_names(os.path.join(work, again)) != physical_names(os.path.join(data, source)):
                fail(f"{again}: physical names {physical_names(os.path.join(work, again))}, expected "
                     f"{physical_names(os.path.join(data, source))}")
            print(f"gmsh checks and rewrites {name}: same mesh, same physical names")


check_meshio() if tool == "meshio" else check_gmsh()
print("ok")
