#!/usr/bin/env python3
"""Bad-input matrix (issue 42): every `dtlab` subcommand, and the Python twin of each where one
exists, on malformed and degenerate inputs generated here, under a time and an address-space limit.

    python3 verify/tests/cli/bad_input_matrix.py --dtlab build/dtlab --python build/python \
            --work build/bad-input-matrix [--jobs 2] [--only REGEX] [--verbose]

A run passes when it
  - exits 0 and each output it names exists and reads back (`dtlab convert` for a mesh, `dtlab
    quality --metric` for a .sol, an XML parse for .svg/.vtu), or
  - exits 1 with stderr whose first line starts `dtlab:`, which names an input file or an option
    of the run, with no C++ library text (`std::`, `basic_string`, `what():`, `terminate`), no
    `internal error`, and no output file (nor scratch folder) left behind;
and never ends on a signal, another exit code, the time limit or the memory limit. A Python twin
passes when it returns, or raises ValueError / dtlab.Error (not InternalError, not SystemError,
not a crash: each call runs in its own interpreter).

The corpus (a few hundred small files) is written into WORK at each run, never checked in. The
script prints a table (input kind x subcommand: runs per outcome), the failures, and exits 1 on a
failure that KNOWN_FAILURES does not list (an entry that no longer fails is reported, so that it
can be removed).
"""
from __future__ import annotations

import argparse
import concurrent.futures
import fnmatch
import os
import random
import re
import resource
import shutil
import struct
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

TIME_LIMIT_S = 20
MEMORY_LIMIT = 2 << 30  # address space of each run (RLIMIT_AS)

# Runs that fail today, each with the issue item it waits for. Patterns are fnmatch patterns on
# "RUN_ID OUTCOME" (both printed in the failure list), so an entry never hides another symptom. Keep this list short: fix what is not ours to wait for.
KNOWN_FAILURES: dict[str, str] = {
}

FORBIDDEN_TEXT = re.compile(r"std::|basic_string|what\(\):|terminate|internal error|Run with --help")


# ---------------------------------------------------------------------------------------------
# The corpus: writers of each format from (points, elements, header overrides), then the cases.
# ---------------------------------------------------------------------------------------------

def fmt(x) -> str:
    return x if isinstance(x, str) else repr(float(x))


def points_text(pts, count=None, **_):
    return "".join(" ".join(fmt(c) for c in p) + "\n" for p in pts)


def triangle_node(pts, dim=None, count=None, **_):
    d = dim if dim is not None else (len(pts[0]) if pts else 2)
    n = count if count is not None else len(pts)
    return f"{n} {d} 0 0\n" + "".join(f"{i + 1} " + " ".join(fmt(c) for c in p) + "\n" for i, p in enumerate(pts))


def triangle_ele(elems, count=None, **_):
    k = len(elems[0]) if elems else 3
    n = count if count is not None else len(elems)
    return f"{n} {k} 0\n" + "".join(f"{i + 1} " + " ".join(str(v) for v in e) + "\n" for i, e in enumerate(elems))


def triangle_poly(pts, elems, dim=None, count=None, **_):
    # 2D: elems are segments. 3D (TetGen): elems are triangular facets.
    d = dim if dim is not None else (len(pts[0]) if pts else 2)
    s = triangle_node(pts, dim=d, count=count)
    if len(pts[0] if pts else [0, 0]) == 3:
        s += f"{len(elems)} 0\n" + "".join("1\n3 " + " ".join(str(v) for v in e) + "\n" for e in elems)
    else:
        s += f"{len(elems)} 0\n" + "".join(f"{i + 1} {e[0]} {e[1]}\n" for i, e in enumerate(elems))
    return s + "0\n"


def smesh(pts, elems, count=None, **_):
    n = count if count is not None else len(pts)
    s = f"{n} 3 0 0\n" + "".join(f"{i + 1} " + " ".join(fmt(c) for c in p) + "\n" for i, p in enumerate(pts))
    s += f"{len(elems)} 0\n" + "".join("3 " + " ".join(str(v) for v in e) + "\n" for e in elems)
    return s + "0\n0\n"


def medit(pts, elems, dim=None, count=None, edges=(), keyword=None, **_):
    d = dim if dim is not None else (len(pts[0]) if pts else 2)
    n = count if count is not None else len(pts)
    s = f"MeshVersionFormatted 2\nDimension {d}\nVertices\n{n}\n"
    s += "".join(" ".join(fmt(c) for c in p) + " 0\n" for p in pts)
    if edges:
        s += f"Edges\n{len(edges)}\n" + "".join(f"{a} {b} 1\n" for a, b in edges)
    kw = keyword or ({3: "Triangles", 4: "Tetrahedra"}[len(elems[0])] if elems else "Triangles")
    s += f"{kw}\n{len(elems)}\n" + "".join(" ".join(str(v) for v in e) + " 1\n" for e in elems)
    return s + "End\n"


def medit3_volume(pts, elems, count=None, **kw):
    # A tetrahedron mesh with its boundary triangles.
    s = medit(pts, elems, count=count, **kw)
    tris = [[e[0], e[2], e[1]] for e in elems] if elems and len(elems[0]) == 4 else []
    return s.replace("End\n", f"Triangles\n{len(tris)}\n" + "".join(" ".join(map(str, t)) + " 1\n" for t in tris) + "End\n")


def medit_sol(values, dim=2, kind=1, count=None, **_):
    n = count if count is not None else len(values)
    return (f"MeshVersionFormatted 2\nDimension {dim}\nSolAtVertices\n{n}\n1 {kind}\n"
            + "".join(" ".join(fmt(c) for c in v) + "\n" for v in values) + "End\n")


def gmsh22(pts, elems, count=None, **_):
    n = count if count is not None else len(pts)
    s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + f"{n}\n"
    s += "".join(f"{i + 1} " + " ".join(fmt(c) for c in (list(p) + [0.0] * (3 - len(p)))) + "\n" for i, p in enumerate(pts))
    s += "$EndNodes\n$Elements\n" + f"{len(elems)}\n"
    for i, e in enumerate(elems):
        t = 2 if len(e) == 3 else 4
        s += f"{i + 1} {t} 2 1 1 " + " ".join(map(str, e)) + "\n"
    return s + "$EndElements\n"


def off(pts, elems, count=None, **_):
    n = count if count is not None else len(pts)
    return (f"OFF\n{n} {len(elems)} 0\n" + "".join(" ".join(fmt(c) for c in p) + "\n" for p in pts)
            + "".join(f"{len(e)} " + " ".join(str(v - 1) for v in e) + "\n" for e in elems))


def obj(pts, elems, **_):
    return "".join("v " + " ".join(fmt(c) for c in p) + "\n" for p in pts) + "".join(
        "f " + " ".join(map(str, e)) + "\n" for e in elems)


def stl_ascii(pts, elems, **_):
    s = "solid t\n"
    for e in elems:
        s += "facet normal 0 0 0\nouter loop\n"
        for v in e:
            p = pts[v - 1] if 1 <= v <= len(pts) else [0.0, 0.0, 0.0]
            s += "vertex " + " ".join(fmt(c) for c in p) + "\n"
        s += "endloop\nendfacet\n"
    return s + "endsolid t\n"


def stl_binary(pts, elems, count=None, **_):
    n = count if count is not None else len(elems)
    b = b"binary stl".ljust(80, b" ") + struct.pack("<I", n & 0xFFFFFFFF)
    for e in elems:
        vals = [0.0, 0.0, 0.0]
        for v in e:
            p = pts[v - 1] if 1 <= v <= len(pts) else [0.0, 0.0, 0.0]
            vals += [float(c) if not isinstance(c, str) else float(c) for c in p]
        b += struct.pack("<12f", *vals) + b"\0\0"
    return b


SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
SQUARE_TRIS = [[1, 2, 4], [2, 3, 4]]  # the diagonal the perturbed incircle keeps
SQUARE_SEGS = [[1, 2], [2, 3], [3, 4], [4, 1]]
TET = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
TET_FACES = [[1, 3, 2], [1, 2, 4], [2, 3, 4], [1, 4, 3]]
CUBE5 = TET + [[0.3, 0.3, 0.3]]
TET5 = [[1, 2, 3, 5], [1, 2, 5, 4], [2, 3, 5, 4], [1, 5, 3, 4]]  # the tetrahedron split at an interior point


# A 6 x 6 grid of the unit square: enough neighbours for `dtlab metric`'s Hessian fit.
GRID = [[i / 5.0, j / 5.0] for j in range(6) for i in range(6)]
GRID_TRIS = [t for j in range(5) for i in range(5)
             for t in ([6 * j + i + 1, 6 * j + i + 2, 6 * j + i + 8], [6 * j + i + 1, 6 * j + i + 8, 6 * j + i + 7])]


@dataclass
class Kind:
    """One input kind: a file extension, what it is for (its role), and how to write it."""
    name: str
    ext: str
    role: str           # points2 points3 plc2 plc3 mesh2 mesh3
    write: object       # (pts, elems, **overrides) -> str | bytes
    pts: list
    elems: list
    companion: object = None  # writes a file beside it (Triangle .ele needs its .node)


KINDS = [
    Kind("txt2", "txt", "points2", lambda p, e, **k: points_text(p, **k), SQUARE, []),
    Kind("xyz3", "xyz", "points3", lambda p, e, **k: points_text(p, **k), CUBE5, []),
    Kind("node2", "node", "points2", lambda p, e, **k: triangle_node(p, **k), SQUARE, []),
    Kind("node3", "node", "points3", lambda p, e, **k: triangle_node(p, **k), CUBE5, []),
    Kind("poly2", "poly", "plc2", triangle_poly, SQUARE, SQUARE_SEGS),
    Kind("poly3", "poly", "plc3", triangle_poly, TET, TET_FACES),
    Kind("smesh3", "smesh", "plc3", smesh, TET, TET_FACES),
    Kind("mesh2", "mesh", "mesh2", lambda p, e, **k: medit(p, e, edges=SQUARE_SEGS if len(p) >= 4 else (), **k), SQUARE, SQUARE_TRIS),
    Kind("mesh3", "mesh", "mesh3", medit3_volume, CUBE5, TET5),
    Kind("surf3", "mesh", "plc3", medit, TET, TET_FACES),
    Kind("ele2", "ele", "mesh2", lambda p, e, **k: triangle_ele(e, **k), SQUARE, SQUARE_TRIS,
         companion=lambda p, e: ("node", triangle_node(p))),
    Kind("ele3", "ele", "mesh3", lambda p, e, **k: triangle_ele(e, **k), CUBE5, TET5,
         companion=lambda p, e: ("node", triangle_node(p))),
    Kind("msh2", "msh", "mesh2", gmsh22, SQUARE, SQUARE_TRIS),
    Kind("msh3", "msh", "mesh3", gmsh22, CUBE5, TET5),
    Kind("off3", "off", "plc3", off, TET, TET_FACES),
    Kind("obj3", "obj", "plc3", obj, TET, TET_FACES),
    Kind("stl3", "stl", "plc3", stl_ascii, TET, TET_FACES),
    Kind("stlb3", "stl", "plc3", stl_binary, TET, TET_FACES),
]


def cases_of(kind: Kind, rng: random.Random) -> dict[str, bytes]:
    """Every malformed or degenerate variant of one kind, by case name."""
    def w(pts, elems, **k):
        s = kind.write(pts, elems, **k)
        return s if isinstance(s, bytes) else s.encode()

    p, e = kind.pts, kind.elems
    dim = len(p[0])
    out: dict[str, bytes] = {}
    valid = w(p, e)
    out["valid"] = valid
    out["empty"] = b""
    out["zero_counts"] = w([], [])
    if e:
        out["one_element"] = w(p, e[:1])
        out["oob_index"] = w(p, [[99] + list(x[1:]) for x in e])
        out["zero_index"] = w(p, [[0] + list(x[1:]) for x in e]) if kind.ext not in ("off",) else w(p, [[-5] + list(x[1:]) for x in e])
        out["repeated_index"] = w(p, [[x[0], x[0]] + list(x[2:]) for x in e])
    else:
        out["one_element"] = w(p[:1], [])
    for name, bad in (("nan_coord", "nan"), ("inf_coord", "inf"), ("huge_coord", "1e308"), ("text_coord", "abc")):
        q = [list(x) for x in p]
        q[1][0] = bad
        if kind.ext == "stl" and kind.name == "stlb3" and name == "text_coord":
            continue
        if kind.name == "stlb3":
            q[1][0] = {"nan": float("nan"), "inf": float("inf"), "huge_coord": 3e38}.get(bad, 3e38)
        out[name] = w(q, e)
    out["duplicate_points"] = w([list(p[0])] * len(p), e)
    if dim == 2:
        degenerate = [[float(i), float(i)] for i in range(len(p))]
    else:
        degenerate = [[float(i % 2), float(i // 2), 0.0] for i in range(len(p))]
    out["degenerate"] = w(degenerate, e)
    out["wrong_dim"] = w(p, e, dim=5 if dim == 3 else 3) if kind.ext in ("node", "poly", "mesh") else w([x[:-1] for x in p], [])
    if kind.ext in ("node", "poly", "mesh", "ele", "msh", "off", "smesh") or kind.name == "stlb3":
        out["huge_count"] = w(p, e, count=10**12) if kind.name != "stlb3" else w(p, e, count=0xFFFFFFFF)
    out["truncated"] = valid[: len(valid) // 2]
    out["random_bytes"] = bytes(rng.getrandbits(8) for _ in range(rng.randrange(1, 600)))
    out["random_text"] = "".join(rng.choice("0123456789 -.e\n") for _ in range(400)).encode()
    return out


def sol_cases(dim: int, n: int) -> dict[str, bytes]:
    """.sol files at the n vertices of the valid mesh of dimension dim: metrics and scalars."""
    t = 3 if dim == 2 else 6
    ident = [1.0, 0.0, 1.0] if dim == 2 else [1.0, 0.0, 1.0, 0.0, 0.0, 1.0]
    neg = [1.0, 0.0, -1.0] if dim == 2 else [1.0, 0.0, 1.0, 0.0, 0.0, -1.0]
    out = {
        "metric_valid": medit_sol([ident] * n, dim, 3),
        "metric_indefinite": medit_sol([neg] * n, dim, 3),
        "metric_zero": medit_sol([[0.0] * t] * n, dim, 3),
        "metric_nan": medit_sol([["nan"] + ident[1:]] * n, dim, 3),
        "metric_huge": medit_sol([[1e300] + ident[1:]] * n, dim, 3),
        "metric_tiny": medit_sol([[1e-300, 0.0, 1e-300] + [0.0, 0.0, 1e-300][: t - 3]] * n, dim, 3),
        "scalar_valid": medit_sol([[0.1]] * n, dim, 1),
        "scalar_negative": medit_sol([[-0.1]] * n, dim, 1),
        "scalar_nan": medit_sol([["nan"]] * n, dim, 1),
        "scalar_zero": medit_sol([[0.0]] * n, dim, 1),
        "wrong_count": medit_sol([[0.1]] * (n + 3), dim, 1),
        "huge_count": medit_sol([[0.1]] * n, dim, 1, count=10**12),
        "wrong_dim": medit_sol([[0.1]] * n, 4, 1),
        "wrong_type": medit_sol([[0.1]] * n, dim, 7),
        "empty": b"",
        "truncated": medit_sol([ident] * n, dim, 3)[:60],
    }
    return {k: (v if isinstance(v, bytes) else v.encode()) for k, v in out.items()}


# ---------------------------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------------------------

@dataclass
class Run:
    id: str
    group: str                    # the table's row: the input kind (or "options", "python")
    sub: str                      # the table's column: the subcommand
    argv: list[str]
    outputs: list[str] = field(default_factory=list)
    readback: list[list[str]] = field(default_factory=list)  # commands (after dtlab) run on exit 0
    python: str | None = None     # Python source for a twin


@dataclass
class Result:
    run: Run
    outcome: str                  # ok, refused, or the failure's kind
    detail: str = ""
    seconds: float = 0.0


def limit_resources():
    if MEMORY_LIMIT > 0:  # 0 under AddressSanitizer, whose shadow memory needs terabytes of address space
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run_process(argv, cwd, env=None):
    start = time.monotonic()
    try:
        p = subprocess.run(argv, cwd=cwd, capture_output=True, timeout=TIME_LIMIT_S,
                           preexec_fn=limit_resources, env=env)
        return p.returncode, p.stdout.decode(errors="replace"), p.stderr.decode(errors="replace"), time.monotonic() - start
    except subprocess.TimeoutExpired:
        return None, "", "", time.monotonic() - start


def check_cli(run: Run, dtlab: str, cwd: str) -> Result:
    rc, out, err, secs = run_process([dtlab] + run.argv, cwd)
    res = lambda o, d="": Result(run, o, d, secs)  # noqa: E731
    first = err.strip().splitlines()[0] if err.strip() else ""
    if rc is None:
        return res("timeout", f"over {TIME_LIMIT_S} s")
    if rc < 0:
        return res("signal", f"signal {-rc}; stderr: {err.strip()[-300:]}")
    if FORBIDDEN_TEXT.search(err):
        return res("library-text", err.strip()[-300:])
    if rc == 0:
        for o in run.outputs:
            if not os.path.exists(os.path.join(cwd, o)):
                return res("no-output", f"{o} missing after exit 0")
        for cmd in run.readback:
            if cmd[0] == "xml":
                try:
                    ET.parse(os.path.join(cwd, cmd[1]))
                except ET.ParseError as ex:
                    return res("readback", f"{cmd[1]}: {ex}")
                continue
            rrc, _, rerr, _ = run_process([dtlab] + cmd, cwd)
            if rrc != 0:
                return res("readback", f"dtlab {' '.join(cmd)}: exit {rrc}: {rerr.strip()[:300]}")
        return res("ok")
    if rc == 3 and run.sub == "verify":
        return res("refused")  # the exact check found a problem: what `dtlab verify` is for
    if rc != 1:
        return res(f"exit-{rc}", err.strip()[-300:])
    if not first.startswith("dtlab:"):
        return res("message", f"stderr does not start with 'dtlab:': {err.strip()[:300]!r}")
    # Named: an input or output by its base name (a .poly's .node beside it counts), an option,
    # or an option's value of three characters or more as a word ('nope' in "unknown method 'nope'").
    names = {os.path.splitext(os.path.basename(a))[0] for a in run.argv if "." in a and not a.startswith("-")}
    names |= {a for a in run.argv if a.startswith("--")} | {a for a in run.argv[1:2] if "." not in a}
    values = [v for o, v in zip(run.argv, run.argv[1:]) if o.startswith("--") and len(v) >= 3 and "/" not in v]
    if not any(n in err for n in names) and not any(re.search(r"(?<![\w.])" + re.escape(v) + r"(?![\w])", err) for v in values):
        return res("unnamed", f"names no file or option of the run: {err.strip()[:300]!r}")
    left = [o for o in run.outputs if os.path.exists(os.path.join(cwd, o))]
    left += [f for f in os.listdir(cwd) if f.startswith(".dtlab-partial")]
    if left:
        return res("output-left", f"exit 1 left {left}")
    return res("refused")


PY_PRELUDE = """
import sys, numpy as np, dtlab
nan, inf = float('nan'), float('inf')
try:
    r = {call}
except dtlab.InternalError as e:
    print('INTERNAL', e); sys.exit(4)
except (ValueError, dtlab.Error) as e:
    print('REFUSED', type(e).__name__, e); sys.exit(0)
except Exception as e:
    print('OTHER', type(e).__name__, e); sys.exit(5)
print('OK')
"""


def check_python(run: Run, pythonpath: str, cwd: str) -> Result:
    env = dict(os.environ, PYTHONPATH=pythonpath, PYTHONDONTWRITEBYTECODE="1")
    rc, out, err, secs = run_process([sys.executable, "-c", PY_PRELUDE.format(call=run.python)], cwd, env)
    res = lambda o, d="": Result(run, o, d, secs)  # noqa: E731
    if rc is None:
        return res("timeout", f"over {TIME_LIMIT_S} s")
    if rc < 0:
        return res("signal", f"signal {-rc}; {err.strip()[-300:]}")
    if rc == 4:
        return res("internal", out.strip()[:300])
    if rc == 5:
        return res("exception", out.strip()[:300])
    if rc != 0:
        return res(f"exit-{rc}", (out + err).strip()[-300:])
    if "MemoryError" in out:
        return res("refused")
    return res("refused" if out.startswith("REFUSED") else "ok")


def build_runs(work: str, dtlab: str, rng: random.Random) -> list[Run]:
    corpus = os.path.join(work, "corpus")
    os.makedirs(corpus, exist_ok=True)

    def put(name, data):
        path = os.path.join(corpus, name)
        with open(path, "wb") as f:
            f.write(data)
        return path

    runs: list[Run] = []
    valid: dict[str, str] = {}
    inputs: list[tuple[Kind, str, str]] = []  # kind, case, path
    for kind in KINDS:
        for case, data in cases_of(kind, rng).items():
            path = put(f"{kind.name}_{case}.{kind.ext}", data)
            if kind.companion:
                ext, text = kind.companion(kind.pts, kind.elems)
                put(f"{kind.name}_{case}.{ext}", text.encode())
            inputs.append((kind, case, path))
            if case == "valid":
                valid[kind.name] = path
    # Binary formats written by dtlab itself from the valid meshes, then damaged.
    for src, name, ext, extra in (("mesh2", "meshb2", "meshb", []), ("mesh3", "meshb3", "meshb", []),
                                  ("mesh2", "mshb2", "msh", ["--binary"]), ("mesh3", "mshb3", "msh", ["--binary"]),
                                  ("mesh3", "msh41_3", "msh", [])):
        out = os.path.join(corpus, f"{name}_valid.{ext}")
        subprocess.run([dtlab, "convert", valid[src], out] + extra, check=True, capture_output=True)
        data = open(out, "rb").read()
        role = "mesh2" if src == "mesh2" else "mesh3"
        k = Kind(name, ext, role, None, [], [])
        inputs.append((k, "valid", out))
        variants = {"truncated": data[: len(data) // 2], "truncated_tail": data[:-7],
                    "flipped_bytes": bytes(b ^ (0xFF if i % 37 == 5 else 0) for i, b in enumerate(data)),
                    "huge_count": re.sub(rb"\n(\d+)\n", b"\n1000000000000\n", data, count=1) if ext == "msh"
                    else data[:30] + b"\xff\xff\xff\x7f" + data[34:]}
        for case, d in variants.items():
            inputs.append((k, case, put(f"{name}_{case}.{ext}", d)))
        valid[name] = out
    valid["grid2"] = put("grid2_valid.mesh", medit(GRID, GRID_TRIS).encode())
    grid_sols = {case: put(f"grid2_{case}.sol", d) for case, d in sol_cases(2, len(GRID)).items()}
    grid_u = put("grid2_u.sol", medit_sol([[x * x + 3 * y * y] for x, y in GRID], 2, 1).encode())
    sols = {2: sol_cases(2, 4), 3: sol_cases(3, 5)}
    sol_paths = {dim: {case: put(f"sol{dim}_{case}.sol", d) for case, d in cases.items()} for dim, cases in sols.items()}

    def add(group, sub, case, argv, outputs=(), readback=()):
        runs.append(Run(f"{sub}:{group}:{case}", group, sub, argv, list(outputs), list(readback)))

    for kind, case, path in inputs:
        g = kind.name
        dim = 2 if kind.role.endswith("2") else 3
        if kind.role in ("points2", "points3", "mesh2", "mesh3"):
            add(g, "delaunay", case, ["delaunay", path, "-o", "out.mesh"], ["out.mesh"],
                [["convert", "out.mesh", "back.mesh"]])
        if kind.role in ("points2", "points3"):
            mesh = valid["mesh2" if dim == 2 else "mesh3"]
            add(g, "verify", case, ["verify", path, mesh])
        if kind.role in ("mesh2", "mesh3"):
            pts = valid["node2" if dim == 2 else "node3"]
            add(g, "verify", case, ["verify", pts, path])
        if kind.role in ("plc2", "plc3", "mesh2") and kind.ext in ("poly", "smesh", "mesh", "off", "obj", "stl"):
            add(g, "constrain", case, ["constrain", path, "-o", "out.mesh"], ["out.mesh"],
                [["convert", "out.mesh", "back.mesh"]])
            add(g, "mesh", case, ["mesh", path, "--size", "0.4", "-o", "out.mesh"], ["out.mesh"],
                [["quality", "out.mesh"]])
        if kind.role in ("mesh2", "mesh3"):
            add(g, "quality", case, ["quality", path])
            add(g, "optimize", case, ["optimize", path, "-o", "out.mesh", "--size", "0.5"], ["out.mesh"],
                [["quality", "out.mesh"]])
            add(g, "convert", case, ["convert", path, "out.msh"], ["out.msh"], [["convert", "out.msh", "back.mesh"]])
            add(g, "plot", case, ["plot", path, "-o", "out.svg"], ["out.svg"], [["xml", "out.svg"]])
            if kind.ext in ("mesh", "meshb"):
                sol = sol_paths[dim]
                add(g, "adapt", case, ["adapt", path, "--metric", sol["metric_valid"], "-o", "out.mesh", "--rounds", "2"],
                    ["out.mesh"], [["quality", "out.mesh"]])
                add(g, "metric", case, ["metric", path, "--solution", sol["scalar_valid"], "--complexity", "100", "-o", "out.sol"],
                    ["out.sol"], [["quality", path, "--metric", "out.sol"]])
                add(g, "transfer", case, ["transfer", path, sol["scalar_valid"], valid["mesh2" if dim == 2 else "mesh3"],
                                          "-o", "out.sol"], ["out.sol"])
                add(g, "transfer", case + "_as_new", ["transfer", valid["mesh2" if dim == 2 else "mesh3"],
                                                      sol["scalar_valid"], path, "-o", "out.sol"], ["out.sol"])
        if kind.role == "plc3" or (kind.role == "mesh2"):
            pass
    # Damaged .sol files beside a valid mesh.
    for dim, paths in sol_paths.items():
        mesh = valid[f"mesh{dim}"]
        g = f"sol{dim}"
        for case, sol in paths.items():
            add(g, "quality", case, ["quality", mesh, "--metric", sol])
            add(g, "optimize", case, ["optimize", mesh, "--metric", sol, "-o", "out.mesh"], ["out.mesh"],
                [["quality", "out.mesh"]])
            add(g, "adapt", case, ["adapt", mesh, "--metric", sol, "-o", "out.mesh", "--rounds", "2"], ["out.mesh"],
                [["quality", "out.mesh"]])
            mm, ms = (valid["grid2"], grid_sols[case]) if dim == 2 else (mesh, sol)
            add(g, "metric", case, ["metric", mm, "--solution", ms, "--complexity", "100", "-o", "out.sol"], ["out.sol"],
                [["quality", mm, "--metric", "out.sol"]])
            add(g, "transfer", case, ["transfer", mesh, sol, mesh, "-o", "out.sol"], ["out.sol"])
            add(g, "plot", case, ["plot", mesh, "--metric", sol, "-o", "out.svg"], ["out.svg"], [["xml", "out.svg"]])
            add(g, "convert", case, ["convert", mesh, "out.vtu", "--sol", sol], ["out.vtu"], [["xml", "out.vtu"]])
            if dim == 2:
                opt = "--size-map" if case.startswith("scalar") else "--metric"
                add(g, "mesh", case, ["mesh", valid["poly2"], opt, sol, "--background", mesh, "-o", "out.mesh"],
                    ["out.mesh"], [["quality", "out.mesh"]])
    # Options: numbers out of range, not numbers, names that are not known.
    sizes = ["1e-300", "1e-9", "1e300", "0", "-1", "nan", "inf", "-inf", "abc", ""]
    plc2, plc3, m2, m3 = valid["poly2"], valid["off3"], valid["mesh2"], valid["mesh3"]
    g = "options"
    for s in sizes:
        add(g, "mesh", f"2d:size={s}", ["mesh", plc2, "--size", s, "-o", "out.mesh"], ["out.mesh"], [["quality", "out.mesh"]])
        add(g, "mesh", f"3d:size={s}", ["mesh", plc3, "--size", s, "-o", "out.mesh"], ["out.mesh"], [["quality", "out.mesh"]])
        add(g, "optimize", f"2d:size={s}", ["optimize", m2, "--size", s, "-o", "out.mesh"], ["out.mesh"], [["quality", "out.mesh"]])
        add(g, "optimize", f"3d:size={s}", ["optimize", m3, "--size", s, "-o", "out.mesh"], ["out.mesh"], [["quality", "out.mesh"]])
        add(g, "quality", f"size={s}", ["quality", m2, "--size", s])
    numbers = ["0", "-1", "nan", "1e300", "1e-300", "1e12", "abc"]
    for v in numbers:
        add(g, "delaunay", f"random={v}", ["delaunay", "--random", v, "-o", "out.mesh"], ["out.mesh"], [["convert", "out.mesh", "b.mesh"]])
        add(g, "delaunay", f"threads={v}", ["delaunay", "--random", "50", "--dim", "3", "--algo", "parallel", "--threads", v])
        add(g, "delaunay", f"seed={v}", ["delaunay", "--random", "50", "--seed", v])
        add(g, "constrain", f"steiner-limit={v}", ["constrain", plc3, "--method", "recover", "--steiner-limit", v])
        add(g, "mesh", f"threads={v}", ["mesh", plc3, "--size", "0.4", "--threads", v])
        add(g, "mesh", f"insertion-regions={v}", ["mesh", plc3, "--size", "0.4", "--insertion-regions", v])
        add(g, "optimize", f"rounds={v}", ["optimize", m2, "--rounds", v, "-o", "out.mesh"], ["out.mesh"])
        add(g, "adapt", f"rounds={v}", ["adapt", m2, "--metric", sol_paths[2]["metric_valid"], "--rounds", v, "-o", "out.mesh"], ["out.mesh"])
        for opt in ("--hgrad", "--hausd", "--ridge-angle"):
            add(g, "adapt", f"{opt[2:]}={v}", ["adapt", m2, "--metric", sol_paths[2]["metric_valid"], opt, v, "--rounds", "2", "-o", "out.mesh"], ["out.mesh"])
        for opt in ("--complexity", "--error", "--hmin", "--hmax", "--hgrad", "--relative"):
            add(g, "metric", f"{opt[2:]}={v}", ["metric", valid["grid2"], "--solution", grid_u]
                + ([] if opt in ("--complexity", "--error") else ["--complexity", "100"]) + [opt, v, "-o", "out.sol"],
                ["out.sol"], [["quality", valid["grid2"], "--metric", "out.sol"]])
        add(g, "metric", f"p={v}", ["metric", valid["grid2"], "--solution", grid_u, "--norm", "Lp", "--p", v, "--complexity", "100", "-o", "out.sol"], ["out.sol"])
        add(g, "selfcheck", f"cases={v}", ["selfcheck", "--cases", v])
    for sub, argv in (("delaunay", ["delaunay", "--random", "10", "--algo", "nope"]),
                      ("delaunay", ["delaunay", "--random", "10", "--distribution", "nope"]),
                      ("delaunay", ["delaunay", "--random", "10", "--dim", "4"]),
                      ("constrain", ["constrain", plc2, "--method", "nope"]),
                      ("constrain", ["constrain", plc2, "--method", "swap", "--swap-order", "nope"]),
                      ("mesh", ["mesh", plc2, "--method", "nope"]),
                      ("mesh", ["mesh", plc2, "--interpolation", "nope"]),
                      ("mesh", ["mesh", plc3, "--optimize", "nope"]),
                      ("mesh", ["mesh", plc2, "--size-map", sol_paths[2]["scalar_valid"]]),
                      ("mesh", ["mesh", plc2, "--size", "0.3", "--metric", sol_paths[2]["metric_valid"], "--background", m2]),
                      ("metric", ["metric", m2, "--solution", sol_paths[2]["scalar_valid"], "--norm", "nope", "-o", "out.sol"]),
                      ("metric", ["metric", m2, "--solution", sol_paths[2]["scalar_valid"], "--hessian", "nope", "-o", "out.sol"]),
                      ("metric", ["metric", m2, "--solution", sol_paths[2]["scalar_valid"], "--hmin", "2", "--hmax", "1", "-o", "out.sol"]),
                      ("adapt", ["adapt", m2, "--metric", sol_paths[2]["metric_valid"], "--method", "nope", "-o", "out.mesh"]),
                      ("plot", ["plot", m2, "--color", "nope", "-o", "out.svg"]),
                      ("plot", ["plot", m2, "-o", "out.nope"]),
                      ("convert", ["convert", m2, "out.nope"]),
                      ("convert", ["convert", m2, "missing-dir/out.mesh"]),
                      ("quality", ["quality", "missing.mesh"]),
                      ("transfer", ["transfer", m2, sol_paths[2]["scalar_valid"], m3, "-o", "out.sol"]),
                      ("verify", ["verify", valid["node2"], m3])):
        add(g, sub, " ".join(a if not a.startswith("/") else os.path.basename(a) for a in argv[1:]), argv,
            [a for a in argv if a.startswith("out.")])
    return runs


def python_runs(work: str) -> list[Run]:
    corpus = os.path.join(work, "corpus")
    sq = "[[0,0],[1,0],[1,1],[0,1]]"
    segs = "[[0,1],[1,2],[2,3],[3,0]]"
    tris = "[[0,1,3],[1,2,3]]"
    pts_cases = {"empty": "np.zeros((0,2))", "one": "[[0,0]]", "nan": "[[0,0],[nan,0],[1,1]]",
                 "inf": "[[0,0],[inf,0],[1,1]]", "huge": "[[0,0],[1e308,0],[0,1e308],[-1e308,-1e308]]",
                 "dup": "[[0,0]]*4", "collinear": "[[0,0],[1,1],[2,2],[3,3]]", "cols4": "np.zeros((4,4))",
                 "flat": "[0,1,2,3]", "text": "'abc'", "ragged": "[[0,0],[1]]"}
    calls: dict[str, str] = {}
    for k, p in pts_cases.items():
        calls[f"delaunay:{k}"] = f"dtlab.delaunay({p})"
        calls[f"delaunay3:{k}"] = f"dtlab.delaunay({p.replace('[0,0]', '[0,0,0]').replace(',0]', ',0,0]').replace(',1]', ',1,0]')})"
        calls[f"constrain:{k}"] = f"dtlab.constrain({p}, {segs})"
        calls[f"mesh:{k}"] = f"dtlab.mesh({p}, {segs}, size=0.3)"
        calls[f"optimize:{k}"] = f"dtlab.optimize({p}, {tris}, size=0.5)"
        calls[f"quality:{k}"] = f"dtlab.quality({p}, {tris})"
        calls[f"verify:{k}"] = f"dtlab.verify({p}, {tris})"
    for k, c in {"oob": "[[0,1,99]]", "negative": "[[0,1,-1]]", "repeated": "[[0,0,1]]", "empty": "np.zeros((0,3),int)",
                 "float": "[[0.5,1,2]]", "cols2": "[[0,1]]", "huge": "[[0,1,2**40]]"}.items():
        calls[f"optimize:cells={k}"] = f"dtlab.optimize({sq}, {c}, size=0.5)"
        calls[f"quality:cells={k}"] = f"dtlab.quality({sq}, {c})"
        calls[f"verify:cells={k}"] = f"dtlab.verify({sq}, {c})"
    for k, s in {"oob": "[[0,99]]", "negative": "[[0,-1]]", "zero_length": "[[0,0],[0,1],[1,2],[2,3],[3,0]]",
                 "cols3": "[[0,1,2]]"}.items():
        calls[f"constrain:segments={k}"] = f"dtlab.constrain({sq}, {s})"
        calls[f"mesh:segments={k}"] = f"dtlab.mesh({sq}, {s}, size=0.3)"
    for s in ["1e-300", "1e-9", "1e300", "0", "-1", "nan", "inf", "'abc'", "[0.1]", "[0.1]*4", "[-0.1]*4"]:
        calls[f"mesh:size={s}"] = f"dtlab.mesh({sq}, {segs}, size={s})"
        calls[f"optimize:size={s}"] = f"dtlab.optimize({sq}, {tris}, size={s})"
    for k, m in {"indefinite": "[[1,0,-1]]*4", "zero": "[[0,0,0]]*4", "nan": "[[nan,0,1]]*4", "short": "[[1,0,1]]",
                 "cols2": "[[1,0]]*4"}.items():
        calls[f"optimize:metric={k}"] = f"dtlab.optimize({sq}, {tris}, metric={m})"
        calls[f"quality:metric={k}"] = f"dtlab.quality({sq}, {tris}, metric={m})"
        calls[f"mesh:metric={k}"] = (f"dtlab.mesh({sq}, {segs}, metric={m}, background=({sq}, {tris}))")
    for k, v in {"-1": "-1", "0": "0", "huge": "10**12"}.items():
        calls[f"optimize:max_rounds={k}"] = f"dtlab.optimize({sq}, {tris}, size=0.5, max_rounds={v})"
        calls[f"delaunay:threads={k}"] = f"dtlab.delaunay({sq}, threads={v})"
    calls["delaunay:algo=nope"] = f"dtlab.delaunay({sq}, algo='nope')"
    calls["mesh:method=nope"] = f"dtlab.mesh({sq}, {segs}, size=0.3, method='nope')"
    calls["constrain:method=nope"] = f"dtlab.constrain({sq}, {segs}, method='nope')"
    calls["convert:write=nope"] = f"dtlab.delaunay({sq}).write('out.nope')"
    calls["convert:write=missing_dir"] = f"dtlab.delaunay({sq}).write('missing-dir/out.mesh')"
    for f in sorted(os.listdir(corpus)):
        if f.endswith(".mesh"):
            calls[f"convert:read_medit={f}"] = f"dtlab.read_medit({os.path.join(corpus, f)!r})"
    sub_of = {"delaunay3": "delaunay"}
    runs = []
    for cid, call in calls.items():
        sub = cid.split(":")[0]
        runs.append(Run(f"py:{cid}", "python", "py:" + sub_of.get(sub, sub), [], python=call))
    return runs


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", required=True)
    ap.add_argument("--python", help="PYTHONPATH holding the built dtlab package (omit: no Python twins)")
    ap.add_argument("--work", required=True)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--only", help="run only the ids matching this regex")
    ap.add_argument("--seed", type=int, default=42)
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--memory-limit-mb", type=int, default=2048,
                    help="address-space limit of each run (0: none, for a sanitizer build)")
    args = ap.parse_args()
    global MEMORY_LIMIT
    MEMORY_LIMIT = args.memory_limit_mb << 20
    dtlab = os.path.abspath(args.dtlab)
    args.python = os.path.abspath(args.python) if args.python else None
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    rng = random.Random(args.seed)
    runs = build_runs(args.work, dtlab, rng)
    have_python = False
    if args.python:
        probe = subprocess.run([sys.executable, "-c", "import dtlab"], capture_output=True,
                               env=dict(os.environ, PYTHONPATH=args.python))
        have_python = probe.returncode == 0
        if have_python:
            runs += python_runs(args.work)
        else:
            print(f"Python twins skipped: cannot import dtlab from {args.python}")
    if args.only:
        runs = [r for r in runs if re.search(args.only, r.id)]

    def one(i_run):
        i, run = i_run
        cwd = os.path.join(args.work, "runs", str(i))
        os.makedirs(cwd)
        result = check_python(run, args.python, cwd) if run.python else check_cli(run, dtlab, cwd)
        if result.outcome in ("ok", "refused"):
            shutil.rmtree(cwd, ignore_errors=True)
        return result

    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(one, enumerate(runs)))
    elapsed = time.monotonic() - start

    # The table: rows the input kind, columns the subcommand, cells "ok/refused/failed".
    subs = sorted({r.run.sub for r in results}, key=lambda s: (s.startswith("py:"), s))
    groups = list(dict.fromkeys(r.run.group for r in results))
    cells: dict[tuple[str, str], list[int]] = {}
    for r in results:
        c = cells.setdefault((r.run.group, r.run.sub), [0, 0, 0])
        c[0 if r.outcome == "ok" else 1 if r.outcome == "refused" else 2] += 1
    width = max(len(s) for s in subs)
    print("cells: ok/refused/failed")
    print("input".ljust(10) + "".join(s.rjust(max(width, 9) + 1) for s in subs))
    for g in groups:
        row = g.ljust(10)
        for s in subs:
            c = cells.get((g, s))
            row += ("/".join(map(str, c)) if c else "-").rjust(max(width, 9) + 1)
        print(row)
    outcomes: dict[str, int] = {}
    for r in results:
        outcomes[r.outcome] = outcomes.get(r.outcome, 0) + 1
    slowest = max(results, key=lambda r: r.seconds)
    print(f"\n{len(results)} runs ({len(groups)} input groups x {len(subs)} subcommands), {elapsed:.1f} s "
          f"with {args.jobs} jobs; outcomes: " + ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items()))
          + f"; slowest {slowest.seconds:.1f} s ({slowest.run.id})")

    def known(r):
        key = f"{r.run.id} {r.outcome}"
        return next((why for pat, why in KNOWN_FAILURES.items() if fnmatch.fnmatchcase(key, pat)), None)

    failures = [r for r in results if r.outcome not in ("ok", "refused")]
    new = [r for r in failures if not known(r)]
    print(f"\nfailures: {len(failures)} ({len(failures) - len(new)} known, {len(new)} new)")
    for r in failures:
        why = known(r)
        cmd = r.run.python if r.run.python else "dtlab " + " ".join(r.run.argv)
        print(f"  [{'known: ' + why if why else 'NEW'}] {r.run.id}: {r.outcome}: {r.detail}\n      {cmd}")
    failing = [f"{r.run.id} {r.outcome}" for r in failures]
    ran = [r.run.id for r in results]
    stale = [pat for pat in KNOWN_FAILURES if not any(fnmatch.fnmatchcase(k, pat) for k in failing)
             and any(fnmatch.fnmatchcase(i, pat.rsplit(" ", 1)[0]) for i in ran)]
    for pat in stale:
        print(f"  known failure '{pat}' ({KNOWN_FAILURES[pat]}) passes now: remove it from KNOWN_FAILURES")
    if args.verbose:
        for r in results:
            print(f"{r.outcome:10} {r.seconds:6.2f} {r.run.id}")
    return 1 if new else 0


if __name__ == "__main__":
    sys.exit(main())
