#!/usr/bin/env python3
"""2D mesh generation beside its peers (issue 22, "Peers and targets"), every output measured by one
checker, `dtlab quality OUT --size H --json`.

Domain: the unit square minus the disc of radius 0.2 at (0.5, 0.5), the boundary cut at spacing h
(data/make_mesh2d_examples.py's square_disc(h): round(1/h) pieces a side, round(2 pi 0.2 / h) on the
circle), written for each h into the work folder, the same points for every tool:
  dtlab      `dtlab mesh square_disc.poly -o OUT.mesh --size h --method edge|front [--no-optimize] --stats`
  Gmsh       a .geo with the same boundary points (a Line between neighbours, characteristic length h
             at every point), `gmsh -2 -algo front2d|del2d|bamg square_disc.geo -clmax h -format mesh
             -o OUT.mesh` (Mesh.Algorithm 6, 5, 7; without -clmax Gmsh's BAMG ignores the point sizes
             and makes 1.6k triangles at h = 0.01, the other two are the same with or without it).
             Gmsh writes Medit with Dimension 3 (z = 0), FreeFem++ adds BAMG's own sections: both are
             rewritten with Vertices (x y ref), Edges and Triangles for the checker (medit_as_2d: the
             coordinates are copied as written).
  FreeFem++  a .edp: `buildmesh` (BAMG) of four straight borders of round(1/h) pieces and the circle
             of -round(2 pi 0.2 / h) (a hole), `savemesh` to OUT.mesh; the time of buildmesh alone is
             taken inside the script (clock(): CPU seconds of FreeFem++'s one thread).
  Triangle   `triangle -pq30 -a<A> -V square_disc.poly` with A = sqrt(3)/4 h^2 (the area of the
             equilateral triangle of side h), Triangle 1.6 built from its public source (not in
             Debian; give it with --triangle). Its meshing time: the sum of the Delaunay, Segment,
             Hole and Quality milliseconds that -V prints (no file output).
A peer that is not installed is skipped and the report says so.

Two tables, and optionally a third:
  quality  h = 0.01 (--quality-size): every tool: triangles, worst Q_K and mean Q_K (1 = equilateral),
           min angle, share of edges of length in [1/sqrt2, sqrt2] h, the meshing time (each tool's
           own timing of its meshing call, no file output: dtlab's `--stats` seconds, Gmsh's "Done
           meshing 1D/2D" wall times, FreeFem++'s buildmesh, Triangle's -V milliseconds) and the
           wall time of the whole command, medians of --runs interleaved runs [min - max], and
           triangles per minute of the meshing time; dtlab's phases (empty mesh, control space,
           field points with insertion, optimization).
  speed    h = 0.01, 0.003, 0.0015 (--speed-sizes; --large adds 0.00045, about 10^7 triangles, for
           the tools in --large-tools): dtlab front and edge, BAMG (FreeFem++), Gmsh front2d,
           Triangle: microseconds per triangle of the meshing time and of the process CPU time
           (user + system of the whole command, /usr/bin/time: one clock for every tool, and the
           one a loaded machine disturbs least), each with its ratio to BAMG's in the same run; the
           wall time; peak resident memory (max RSS of the process, /usr/bin/time -f %M) in bytes
           per triangle. The quality table's size is not run twice: its runs serve this table.
           A tool whose first run at a size takes longer than --slow seconds gets --slow-runs runs
           there (the table says so).
  aniso    (--aniso) dtlab on the analytic fields of data/make_mesh2d_examples.py (UGAWG's linear
           and polar-1 layers, h0 = 10^-3) given on data/unit_square_bg.mesh, with
           the boundary cut in the metric (the default); FreeFem++ adaptmesh (BAMG) of the same fields after six cycles each
           re-evaluating the analytic field on its own mesh. Measured by `dtlab quality --metric`:
           share of edges of metric length l = (la - lb)/ln(la/lb) in [1/sqrt2, sqrt2], worst and
           mean mean-ratio quality (1 = equilateral) in the metric, worst Q_K; once with the
           analytic field evaluated at the output's vertices (exact.sol, written by this script),
           once with the background's .sol interpolated (`--background`).
Runs are interleaved (round 1 of every tool, then round 2, ...; the order rotated by one tool each
round) so that a slow spell of this shared machine falls on every tool; results are medians with
the min - max range, never a minimum. Every run goes to the JSON file (--json).

  scripts/bench_mesh2d.py --triangle /tmp/peers/triangle/triangle                   # quality + speed
  scripts/bench_mesh2d.py --triangle /tmp/peers/triangle/triangle --aniso --update-readme
  scripts/bench_mesh2d.py --tables quality --runs 3                                  # one table
  scripts/bench_mesh2d.py --tables speed --speed-sizes 0.0015 --slow 200 --slow-runs 2 --json b.json
  scripts/bench_mesh2d.py --from-json a.json,b.json --update-readme    # the runs of both, one report

--update-readme writes the tables between <!-- perf-mesh2d:begin --> and <!-- perf-mesh2d:end -->
in docs/performance.md's "Meshing in 2D" section (inserted at that section's end if absent;
--readme PATH writes another file); nothing else
changes.
"""
import argparse
import datetime
import json
import math
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

import bench_delaunay2d as d2
import bench_report
import readme_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "data"))
import make_mesh2d_examples as examples  # noqa: E402

TIME = "/usr/bin/time"
SECTION = "### Meshing in 2D"
KEY = "mesh2d"

# Every row of the tables: name -> (kind, options). The quality table runs them all.
TOOLS = {
    "dtlab edge": ("dtlab", ["--method", "edge"]),
    "dtlab edge --no-optimize": ("dtlab", ["--method", "edge", "--no-optimize"]),
    "dtlab front": ("dtlab", ["--method", "front"]),
    "dtlab front --no-optimize": ("dtlab", ["--method", "front", "--no-optimize"]),
    "Gmsh front2d": ("gmsh", ["front2d"]),
    "Gmsh del2d": ("gmsh", ["del2d"]),
    "Gmsh bamg": ("gmsh", ["bamg"]),
    "FreeFem++ buildmesh (BAMG)": ("freefem", []),
    "Triangle -pq30 -a": ("triangle", []),
}
BAMG = "FreeFem++ buildmesh (BAMG)"
SPEED_TOOLS = ["dtlab front", "dtlab edge", BAMG, "Gmsh front2d", "Triangle -pq30 -a"]
LARGE_H = 0.00045


def progress(msg):
    print(f"[{datetime.datetime.now():%H:%M:%S}] {msg}", file=sys.stderr, flush=True)


# --- Inputs -----------------------------------------------------------------------------------

def h_name(h):
    return f"{h:g}".replace(".", "p")


def write_domain(folder, h):
    """square_disc.poly, .geo and .edp for spacing h in folder; returns their paths."""
    os.makedirs(folder, exist_ok=True)
    outer, circle = examples.square_disc(h)
    poly = os.path.join(folder, "square_disc.poly")
    examples.write_poly(poly, [(outer, 1), (circle, 2)], [(0.5, 0.5)],
                        f"unit square minus the disc r = 0.2 at (0.5, 0.5), boundary spacing {h}")
    geo = os.path.join(folder, "square_disc.geo")
    with open(geo, "w") as f:
        f.write(f"// the points of square_disc.poly, a Line between neighbours\nh = {h!r};\n")
        k, loops = 1, []
        for loop in (outer, circle):
            first = k
            for x, y in loop:
                f.write(f"Point({k}) = {{{x!r}, {y!r}, 0, h}};\n")
                k += 1
            for i in range(len(loop)):
                f.write(f"Line({first + i}) = {{{first + i}, {first + (i + 1) % len(loop)}}};\n")
            loops.append(range(first, first + len(loop)))
        for j, ids in enumerate(loops, 1):
            f.write(f"Curve Loop({j}) = {{{', '.join(map(str, ids))}}};\n")
        f.write("Plane Surface(1) = {1, 2};\nPhysical Curve(1) = {%s};\nPhysical Curve(2) = {%s};\n"
                "Physical Surface(1) = {1};\n" % (", ".join(map(str, loops[0])), ", ".join(map(str, loops[1]))))
    n, m = round(1.0 / h), max(3, round(2 * math.pi * 0.2 / h))
    edp = os.path.join(folder, "square_disc.edp")
    with open(edp, "w") as f:
        f.write(f"""// square_disc.poly's boundary: sides of {n} pieces, the circle of {m} (a hole)
border b1(t=0,1){{x=t; y=0; label=1;}}
border b2(t=0,1){{x=1; y=t; label=1;}}
border b3(t=0,1){{x=1-t; y=1; label=1;}}
border b4(t=0,1){{x=0; y=1-t; label=1;}}
border c(t=0,2*pi){{x=0.5+0.2*cos(t); y=0.5+0.2*sin(t); label=2;}}
real t0 = clock();
mesh Th = buildmesh(b1({n})+b2({n})+b3({n})+b4({n})+c(-{m}));
real t1 = clock();
cout << "BUILDMESH_SECONDS " << (t1-t0) << endl;
cout << "TRIANGLES " << Th.nt << endl;
savemesh(Th, "freefem.mesh");
""")
    return {"poly": poly, "geo": geo, "edp": edp}


def triangle_area(h):
    return math.sqrt(3.0) / 4.0 * h * h


def command(tool, h, paths, exe):
    """(argv, output file given to the checker) of one run of `tool` at spacing h, run in the
    domain's folder."""
    kind, opts = TOOLS[tool]
    if kind == "dtlab":
        out = f"dtlab_{opts[1]}{'_noopt' if '--no-optimize' in opts else ''}.mesh"
        return [exe["dtlab"], "mesh", "square_disc.poly", "-o", out, "--size", repr(h)] + opts + ["--stats"], out
    if kind == "gmsh":
        out = f"gmsh_{opts[0]}.mesh"
        return [exe["gmsh"], "-2", "-algo", opts[0], "square_disc.geo", "-clmax", repr(h), "-format", "mesh",
                "-o", out], out
    if kind == "freefem":
        return [exe["freefem"], "-nw", "-ne", "-v", "0", "square_disc.edp"], "freefem.mesh"
    if kind == "triangle":
        # Triangle's -a takes digits and a point only: no exponent.
        area = f"{triangle_area(h):.17f}".rstrip("0")
        return [exe["triangle"], "-pq30", f"-a{area}", "-V", "square_disc.poly"], "square_disc.1.ele"
    raise ValueError(tool)


# --- Running ----------------------------------------------------------------------------------

def run_measured(cmd, cwd, timeout):
    """{"wall_seconds", "peak_rss_bytes", "user_seconds", "system_seconds", "stdout", "stderr"} or
    {"error"}. Through /usr/bin/time (-f %M: the program's own max RSS; a program forked from this
    Python process would carry Python's resident size as its floor). A session of its own, so that
    a timeout kills the program, not only /usr/bin/time."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as tf:
        full = ([TIME, "-o", tf.name, "-f", "%M %U %S"] if os.access(TIME, os.X_OK) else []) + cmd
        start = time.perf_counter()
        proc = subprocess.Popen(full, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                start_new_session=True)
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            return {"error": f"timed out after {timeout:g} s"}
        wall = time.perf_counter() - start
        if proc.returncode != 0:
            return {"error": f"exit {proc.returncode}: {(err or out).strip()[-300:]}"}
        rec = {"wall_seconds": wall, "stdout": out, "stderr": err}
        fields = tf.read().split()
        if len(fields) >= 3:
            rec.update({"peak_rss_bytes": int(fields[-3]) * 1024, "user_seconds": float(fields[-2]),
                        "system_seconds": float(fields[-1])})
        return rec


def parse_tool(kind, out, err):
    """The tool's own figures: meshing seconds (no file output), triangles, phases."""
    text = out + "\n" + err
    if kind == "dtlab":
        js = json.loads([line for line in out.splitlines() if line.startswith("{")][-1])
        return {"meshing_seconds": js["seconds"], "triangles": js["triangles"], "clock": "wall",
                "phases": {k: js[f"seconds_{k}"] for k in ("empty_mesh", "control_space", "field_points",
                                                            "optimization")},
                "counts": {k: js.get(k) for k in ("vertices", "boundary_points", "field_points", "filtered",
                                                  "swaps", "relocations", "collapses", "splits")}}
    if kind == "gmsh":
        walls = {int(d): float(w) for d, w, _ in re.findall(
            r"Done meshing (\d)D \(Wall ([0-9.eE+-]+)s, CPU ([0-9.eE+-]+)s\)", text)}
        if 2 not in walls:
            raise ValueError("no 'Done meshing 2D' line in Gmsh's output")
        return {"meshing_seconds": walls.get(1, 0.0) + walls[2], "clock": "wall",
                "phases": {"1D": walls.get(1, 0.0), "2D": walls[2]}}
    if kind == "freefem":
        found = re.search(r"BUILDMESH_SECONDS\s+([0-9.eE+-]+)", text)
        nt = re.search(r"TRIANGLES\s+(\d+)", text)
        return {"meshing_seconds": float(found.group(1)), "triangles": int(nt.group(1)), "clock": "CPU"}
    if kind == "triangle":
        ms = dict(re.findall(r"^(\w+) milliseconds:\s+(\d+)", text, re.M))
        nt = re.search(r"Mesh triangles:\s+(\d+)", text)
        parts = {k: int(ms.get(k, 0)) / 1000.0 for k in ("Delaunay", "Segment", "Hole", "Quality")}
        return {"meshing_seconds": sum(parts.values()), "triangles": int(nt.group(1)), "clock": "wall",
                "phases": parts}
    raise ValueError(kind)


def medit_as_2d(path):
    """A peer's Medit file rewritten in place with what the checker's 2D reader keeps: Vertices
    (x y ref), Edges, Triangles. Gmsh writes Dimension 3 with z = 0 (the z column is dropped),
    FreeFem++ adds BAMG's sections (Identifier, Geometry, SubDomainFromMesh, VertexOnGeometric*,
    ...), which are left out. The coordinates are copied as written, not parsed."""
    with open(path) as f:
        lines = [line.split() for line in f]
    lines = [w for w in lines if w]
    out, i, dim = ["MeshVersionFormatted 2", "Dimension 2"], 0, 2
    while i < len(lines):
        w = lines[i]
        key = w[0]
        if not key[0].isalpha():
            i += 1
            continue
        if key == "End":
            break
        if key == "Dimension":
            dim = int(w[1]) if len(w) > 1 else int(lines[i + 1][0])
            i += 1 if len(w) > 1 else 2
            continue
        if key in ("Vertices", "Edges", "Triangles"):
            if len(w) > 1:
                n, i = int(w[1]), i + 1
            else:
                n, i = int(lines[i + 1][0]), i + 2
            out.append(f"{key}\n{n}")
            for v in lines[i:i + n]:
                out.append(f"{v[0]} {v[1]} {v[dim]}" if key == "Vertices" else " ".join(v))
            i += n
            continue
        i += 1  # a section the checker does not read: skipped up to the next keyword
    with open(path, "w") as f:
        f.write("\n".join(out) + "\nEnd\n")


def check_quality(exe, cwd, out, extra, timeout=600):
    r = subprocess.run([exe["dtlab"], "quality", out, "--json"] + extra, cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True, timeout=timeout)
    if r.returncode != 0:
        return {"error": r.stderr.strip()[-300:]}
    return json.loads([line for line in r.stdout.splitlines() if line.startswith("{")][-1])


QUALITY_KEYS = ("vertices", "elements", "quality_worst", "quality_mean", "min_angle_deg", "max_angle_deg",
                "unit_edge_share", "edges", "metric_length_min", "metric_length_max", "mean_ratio_worst",
                "mean_ratio_mean", "share_1_2", "area", "inverted", "flat")


def measure_sizes(args, exe, tools, sizes, table, records, save):
    """One record per (table, h, tool, run); the quality of each (h, tool) from its first run."""
    failed = set()
    for h in sizes:
        folder = os.path.join(args.work, f"h{h_name(h)}")
        paths = write_domain(folder, h)
        mine = [t for t in tools if t not in failed]
        runs_of = {t: args.runs for t in mine}
        progress(f"{table}: h = {h:g}, {len(mine)} tools x {args.runs} runs")
        for run in range(args.runs):
            k = run % len(mine) if mine else 0
            for tool in mine[k:] + mine[:k]:
                if tool in failed or run >= runs_of[tool]:
                    continue
                kind = TOOLS[tool][0]
                cmd, out = command(tool, h, paths, exe)
                res = run_measured(cmd, folder, args.timeout * max(1.0, (0.01 / h) ** 2 / 20))
                rec = {"table": table, "h": h, "tool": tool, "run": run, "command": " ".join(cmd)}
                if "error" in res:
                    rec["error"] = res["error"]
                    failed.add(tool)
                    progress(f"  {tool} h={h:g} run {run + 1}: ERROR {res['error']}")
                    records.append(rec)
                    continue
                rec.update({k2: res[k2] for k2 in ("wall_seconds", "peak_rss_bytes", "user_seconds",
                                                   "system_seconds") if k2 in res})
                try:
                    rec.update(parse_tool(kind, res["stdout"], res["stderr"]))
                except (ValueError, KeyError, IndexError, AttributeError) as e:
                    rec["error"] = f"cannot read the tool's output: {e}"
                    failed.add(tool)
                if run == 0 and "error" not in rec and rec["wall_seconds"] > args.slow and args.slow_runs < args.runs:
                    runs_of[tool] = args.slow_runs
                    rec["slow"] = f"its first run took {rec['wall_seconds']:.0f} s > --slow {args.slow:g} s: {args.slow_runs} runs"
                    progress(f"  {tool} h={h:g}: {rec['slow']}")
                if run == 0 and "error" not in rec:
                    if kind in ("gmsh", "freefem"):
                        medit_as_2d(os.path.join(folder, out))
                    q = check_quality(exe, folder, out, ["--size", repr(h)])
                    rec["quality"] = q if "error" in q else {k2: q.get(k2) for k2 in QUALITY_KEYS}
                    if "error" in q:
                        progress(f"  {tool}: the checker failed: {q['error']}")
                progress(f"  {tool} h={h:g} run {run + 1}/{args.runs}: meshing {rec.get('meshing_seconds', 0):.3f} s, "
                         f"wall {rec['wall_seconds']:.2f} s, {rec.get('peak_rss_bytes', 0) / 2**20:.0f} MB"
                         + (f", {rec['quality']['elements']} triangles" if rec.get("quality", {}).get("elements") else ""))
                records.append(rec)
                save()
        if h < 0.002:
            # The largest meshes take disk (tens of MB each): gone once measured.
            for name in os.listdir(folder):
                if name.endswith((".mesh", ".node", ".ele")) and not name.startswith("square_disc.p"):
                    os.remove(os.path.join(folder, name))


# --- Anisotropic ------------------------------------------------------------------------------

H0 = 1e-3


def field(name, x, y):
    """(m11, m12, m22) of the analytic field of data/make_mesh2d_examples.py."""
    if name == "linear":
        return examples.tensor((1.0, 0.0), 0.1, H0 + 2 * (0.1 - H0) * abs(y - 0.5))
    r = math.hypot(x, y)
    e = (x / r, y / r) if r > 0 else (1.0, 0.0)
    return examples.tensor(e, H0 + 2 * (0.1 - H0) * abs(r - 0.5), 0.1)


def medit_vertices(path):
    with open(path) as f:
        words = f.read().split()
    i = words.index("Dimension")
    dim = int(words[i + 1])
    i = words.index("Vertices")
    n = int(words[i + 1])
    step = dim + 1
    return [(float(words[i + 2 + k * step]), float(words[i + 3 + k * step])) for k in range(n)]


def write_exact_sol(mesh, name, sol):
    examples.write_sol(sol, [field(name, x, y) for x, y in medit_vertices(mesh)], "tensor")


FREEFEM_ADAPT = """// six cycles of adaptmesh (BAMG), each evaluating the analytic field on the current mesh
real h0 = {h0!r};
mesh Th = square(10, 10);
fespace Vh(Th, P1);
Vh m11, m12, m22;
real t0 = clock();
for (int i = 0; i < 6; ++i) {{
  {body}
  Th = adaptmesh(Th, m11, m12, m22, IsMetric=1, nbvx=2000000, hmin=1e-5, hmax=0.5);
}}
real t1 = clock();
cout << "ADAPT_SECONDS " << (t1-t0) << endl;
cout << "TRIANGLES " << Th.nt << endl;
savemesh(Th, "{out}");
"""
FREEFEM_FIELDS = {
    "linear": "m11 = 1/(0.1^2); m12 = 0; m22 = 1/(h0 + 2*(0.1-h0)*abs(y-0.5))^2;",
    "polar": ("func r = sqrt(x^2+y^2) + 1e-300; func hr = h0 + 2*(0.1-h0)*abs(r-0.5);\n"
              "  m11 = (x/r)^2/hr^2 + (y/r)^2/0.1^2; m12 = (x/r)*(y/r)*(1/hr^2 - 1/0.1^2);\n"
              "  m22 = (y/r)^2/hr^2 + (x/r)^2/0.1^2;"),
}


def measure_aniso(args, exe, records, save):
    folder = os.path.join(args.work, "aniso")
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(ROOT, "data")
    tools = [("dtlab edge", "linear"), ("dtlab front", "linear"), ("dtlab edge", "polar"), ("dtlab front", "polar")]
    if exe.get("freefem"):
        tools += [("FreeFem++ adaptmesh (BAMG)", "linear"), ("FreeFem++ adaptmesh (BAMG)", "polar")]
        for name, body in FREEFEM_FIELDS.items():
            with open(os.path.join(folder, f"adapt_{name}.edp"), "w") as f:
                f.write(FREEFEM_ADAPT.format(h0=H0, body=body, out=f"freefem_{name}.mesh"))
    progress(f"aniso: {len(tools)} cases x {args.runs} runs")
    for run in range(args.runs):
        k = run % len(tools)
        for tool, name in tools[k:] + tools[:k]:
            sol = os.path.join(data, f"{name}_layer.sol")
            bg = os.path.join(data, "unit_square_bg.mesh")
            if tool.startswith("dtlab"):
                out = f"{tool.split()[1]}_{name}.mesh"
                cmd = [exe["dtlab"], "mesh", os.path.join(data, "unit_square.poly"), "--metric", sol,
                       "--background", bg, "--method", tool.split()[1], "-o", out, "--stats"]
                kind = "dtlab"
            else:
                out = f"freefem_{name}.mesh"
                cmd = [exe["freefem"], "-nw", "-ne", "-v", "0", f"adapt_{name}.edp"]
                kind = "freefem_adapt"
            res = run_measured(cmd, folder, args.timeout)
            rec = {"table": "aniso", "tool": tool, "field": name, "run": run, "command": " ".join(cmd)}
            if "error" in res:
                rec["error"] = res["error"]
                progress(f"  {tool} {name} run {run + 1}: ERROR {res['error']}")
                records.append(rec)
                continue
            rec.update({k2: res[k2] for k2 in ("wall_seconds", "peak_rss_bytes") if k2 in res})
            if kind == "dtlab":
                rec.update(parse_tool("dtlab", res["stdout"], res["stderr"]))
            else:
                text = res["stdout"] + res["stderr"]
                rec["meshing_seconds"] = float(re.search(r"ADAPT_SECONDS\s+([0-9.eE+-]+)", text).group(1))
                rec["triangles"] = int(re.search(r"TRIANGLES\s+(\d+)", text).group(1))
                rec["clock"] = "CPU"
            if run == 0:
                if kind == "freefem_adapt":
                    medit_as_2d(os.path.join(folder, out))
                exact = os.path.join(folder, f"exact_{os.path.splitext(out)[0]}.sol")
                write_exact_sol(os.path.join(folder, out), name, exact)
                rec["quality"] = check_quality(exe, folder, out, ["--metric", exact])
                rec["quality_background"] = check_quality(exe, folder, out, ["--metric", sol, "--background", bg])
            progress(f"  {tool} {name} run {run + 1}/{args.runs}: {rec['meshing_seconds']:.3f} s"
                     + (f", in band {100 * rec['quality']['unit_edge_share']:.1f} %, worst mean ratio "
                        f"{rec['quality']['mean_ratio_worst']:.3f}" if "quality" in rec and "error" not in rec["quality"] else ""))
            records.append(rec)
        save()


# --- Tables -----------------------------------------------------------------------------------

def med_range(values, digits=3):
    """'median [min – max]' of the values."""
    if not values:
        return "–"
    f = d2.fmt
    if len(values) == 1:
        return f(values[0], digits)
    return f"{f(statistics.median(values), digits)} [{f(min(values), digits)}–{f(max(values), digits)}]"


def group(records, table):
    out = {}
    for r in records:
        if r["table"] == table:
            out.setdefault((r.get("h"), r["tool"], r.get("field")), []).append(r)
    return out


def summary(recs):
    ok = [r for r in recs if "error" not in r]
    s = {"runs": len(ok), "error": next((r["error"] for r in recs if "error" in r), None)
         or next((r["slow"] for r in recs if "slow" in r), None)}
    if not ok:
        return s
    q = next((r["quality"] for r in ok if "quality" in r), {})
    s["quality"] = q
    s["triangles"] = q.get("elements") or ok[0].get("triangles")
    counts = {r["triangles"] for r in ok if r.get("triangles")}
    s["counts_vary"] = len(counts) > 1
    s["meshing"] = [r["meshing_seconds"] for r in ok]
    s["wall"] = [r["wall_seconds"] for r in ok]
    s["rss"] = [r["peak_rss_bytes"] for r in ok if r.get("peak_rss_bytes")]
    s["cpu"] = [r["user_seconds"] + r["system_seconds"] for r in ok if "user_seconds" in r]
    s["clock"] = ok[0].get("clock", "wall")
    phases = [r["phases"] for r in ok if r.get("phases")]
    s["phases"] = {k: statistics.median(p[k] for p in phases) for k in phases[0]} if phases else {}
    s["counts"] = ok[0].get("counts", {})
    return s


def pct(x):
    return "–" if x is None or x != x else f"{100 * x:.2f} %"


def num(x, spec):
    return "–" if x is None or x != x else format(x, spec)


def k_label(n):
    return "–" if not n else (f"{n / 1e6:.3g}M" if n >= 1e6 else f"{n / 1e3:.3g}k")


def quality_table(records, runs):
    head = ["tool", "triangles", "worst Q", "mean Q", "min angle", "edges in [1/√2, √2]·h",
            "meshing s, median [min–max]", "wall s, median [min–max]", "process CPU s, median", "triangles/min (meshing)",
            "dtlab phases (median s): empty mesh / control / field points / optimization"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    notes = []
    for (h, tool, _), recs in group(records, "quality").items():
        s = summary(recs)
        if not s["runs"]:
            lines.append(f"| {tool} | failed: {s['error']} |" + " |" * (len(head) - 2))
            continue
        q = s["quality"]
        med = statistics.median(s["meshing"])
        ph = s["phases"]
        phases = (" / ".join(num(ph.get(k), ".3f") for k in ("empty_mesh", "control_space", "field_points", "optimization"))
                  if tool.startswith("dtlab") else "–")
        clock = " (CPU)" if s["clock"] == "CPU" else ""
        lines.append("| " + " | ".join([
            f"**{tool}**" if tool.startswith("dtlab") else tool, k_label(s["triangles"]),
            num(q.get("quality_worst"), ".3f"), num(q.get("quality_mean"), ".4f"),
            num(q.get("min_angle_deg"), ".1f") + "°", pct(q.get("unit_edge_share")),
            med_range(s["meshing"]) + clock, med_range(s["wall"]),
            d2.fmt(statistics.median(s["cpu"])) if s["cpu"] else "–", k_label(s["triangles"] * 60.0 / med) if med > 0 else "–", phases]) + " |")
        if s["runs"] < runs:
            notes.append(f"{tool}: {s['runs']} of {runs} runs ({s['error']})")
        if s["counts_vary"]:
            notes.append(f"{tool}: the number of triangles differs between runs")
    return "\n".join(lines), notes


def speed_table(records, runs):
    head = ["h", "tool", "triangles", "meshing s, median [min–max]", "µs/triangle (meshing)", "/ BAMG",
            "process CPU s, median [min–max]", "µs/triangle (CPU)", "/ BAMG (CPU)", "wall s, median",
            "peak RSS bytes/triangle"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    notes, flat = [], {}
    groups = group(records, "speed")
    shared = {h for h, _, _ in group(records, "quality")} - {h for h, _, _ in groups}
    for key, recs in group(records, "quality").items():
        if key[0] in shared and key[1] in SPEED_TOOLS:
            groups[key] = recs
    if shared:
        notes.append(f"h = {', '.join(f'{h:g}' for h in sorted(shared))}: the runs of the quality table (the same "
                     "commands, interleaved with its other tools)")
    sizes = sorted({h for h, _, _ in groups}, reverse=True)

    def per_triangle(s, key):
        return statistics.median(s[key]) * 1e6 / s["triangles"] if s.get("runs") and s.get(key) else None

    for h in sizes:
        bamg = summary(groups.get((h, BAMG, None), []))
        bamg_us, bamg_cpu = per_triangle(bamg, "meshing"), per_triangle(bamg, "cpu")
        for tool in SPEED_TOOLS:
            if (h, tool, None) not in groups:
                continue
            s = summary(groups[(h, tool, None)])
            if not s["runs"]:
                lines.append(f"| {h:g} | {tool} | failed: {s['error']} |" + " |" * (len(head) - 3))
                continue
            n = s["triangles"]
            us, cpu = per_triangle(s, "meshing"), per_triangle(s, "cpu")
            flat.setdefault(tool, []).append((n, us, cpu))
            rss = statistics.median(s["rss"]) / n if s["rss"] else None
            lines.append("| " + " | ".join([
                f"{h:g}", f"**{tool}**" if tool.startswith("dtlab") else tool, k_label(n),
                med_range(s["meshing"]) + (" (CPU)" if s["clock"] == "CPU" else ""), f"{us:.3g}",
                f"{us / bamg_us:.3g}" if bamg_us else "–", med_range(s["cpu"]), num(cpu, ".3g"),
                f"{cpu / bamg_cpu:.3g}" if bamg_cpu and cpu else "–", d2.fmt(statistics.median(s["wall"])),
                num(rss, ".0f")]) + " |")
            if s["runs"] < runs:
                notes.append(f"h = {h:g}, {tool}: {s['runs']} of {runs} runs ({s['error'] or 'fewer runs asked'})")
    if flat and LARGE_H not in sizes:
        est = [f"{tool} {pts[-1][1] * 1e7 / 1e6 / 60:.1f} min" for tool, pts in flat.items()]
        notes.append(f"10^7 triangles (h = {LARGE_H:g}, `--large`) not run: at the µs per triangle of the largest "
                     f"size above, one run would take {', '.join(est)} (meshing time alone)")
    for tool, pts in flat.items():
        if len(pts) > 1:
            text = []
            for label, v in (("meshing", [u for _, u, _ in pts]), ("CPU", [c for _, _, c in pts if c])):
                if len(v) > 1:
                    mid = (max(v) + min(v)) / 2
                    text.append(f"{label} {', '.join(f'{u:.3g}' for u in v)} (±{100 * (max(v) - min(v)) / 2 / mid:.0f} % "
                                "of the mid-range)")
            notes.append(f"{tool}: µs per triangle from {k_label(pts[0][0])} to {k_label(pts[-1][0])} triangles: "
                         + "; ".join(text))
    return "\n".join(lines), notes


def aniso_table(records, runs):
    head = ["field", "tool", "triangles", "edges in [1/√2, √2] (exact field)", "worst / mean mean-ratio (exact)",
            "worst Q (exact)", "edges in band (background .sol)", "worst mean-ratio (background)",
            "time s, median [min–max]", "wall s, median [min–max]"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for (_, tool, name), recs in sorted(group(records, "aniso").items(), key=lambda kv: (kv[0][2], kv[0][1])):
        s = summary(recs)
        if not s["runs"]:
            lines.append(f"| {name} | {tool} | failed: {s['error']} |" + " |" * (len(head) - 3))
            continue
        q = s["quality"]
        qb = next((r["quality_background"] for r in recs if "quality_background" in r), {})
        lines.append("| " + " | ".join([
            name, f"**{tool}**" if tool.startswith("dtlab") else tool, k_label(s["triangles"]),
            pct(q.get("unit_edge_share")),
            f"{num(q.get('mean_ratio_worst'), '.3f')} / {num(q.get('mean_ratio_mean'), '.3f')}",
            num(q.get("quality_worst"), ".3g"), pct(qb.get("unit_edge_share")), num(qb.get("mean_ratio_worst"), ".3f"),
            med_range(s["meshing"]) + (" (CPU, 6 cycles)" if s["clock"] == "CPU" else ""),
            med_range(s["wall"])]) + " |")
    return "\n".join(lines), []


def markdown(data):
    m = data["provenance"]
    runs = data["runs"]
    load = ", ".join(f"{x:.1f}" for x in m.get("load_average", []))
    load_end = ", ".join(f"{x:.1f}" for x in data.get("load_average_end", []))
    peers = data["peers"]
    parts = [f"Machine: {m['cpu']}, {m['cpus']} CPUs (load average {load} at the start, {load_end} at the end); "
             f"{bench_report.provenance_cell(m)}; dtlab `{m.get('dtlab_version', '')}`. Peers: "
             + "; ".join(f"{k} {v}" for k, v in peers.items()) + ". "
             f"{runs} interleaved runs of every tool (round-robin, the order rotated each round); "
             "times are medians with the [min–max] of the runs; the quality is that of the first run's output "
             "(dtlab's output is the same bytes every run; Gmsh's BAMG varies slightly between invocations), "
             "measured by `dtlab quality OUT --size h --json`. "
             "Meshing time: each tool's own timing of its meshing call without file output (dtlab `--stats` "
             "seconds, Gmsh's \"Done meshing 1D + 2D\" wall times, Triangle's -V Delaunay + Segment + Hole + "
             "Quality milliseconds, FreeFem++'s clock() around buildmesh: CPU seconds); wall: the whole "
             "command (start-up, input, file output; dtlab's includes its --stats quality pass).", ""]
    for more in data.get("more", []):
        mm = more.get("provenance", {})
        parts[0] += (f" Some sizes come from a second invocation ({mm.get('date', '')}, `{mm.get('binary_commit', '')}`, "
                     f"load average {', '.join(f'{x:.1f}' for x in mm.get('load_average', []))} at its start, "
                     f"{', '.join(f'{x:.1f}' for x in more.get('load_average_end', []))} at its end).")
    if bench_report.busy_warning(m, data.get("load_average_end", [])):
        parts += [bench_report.busy_warning(m, data.get("load_average_end", [])), ""]
    if data.get("skipped"):
        parts += ["Skipped: " + "; ".join(data["skipped"]) + ".", ""]
    records = data["records"]
    if any(r["table"] == "quality" for r in records):
        h = next(r["h"] for r in records if r["table"] == "quality")
        body, notes = quality_table(records, runs)
        parts += [f"**Quality**, h = {h:g} (boundary spacing and target size; Triangle's area bound "
                  f"√3/4·h² = {triangle_area(h):.3g}):", "", body, ""]
        parts += [f"- {n}" for n in notes] + ([""] if notes else [])
    if "speed" in data.get("tables", []) or any(r["table"] == "speed" for r in records):
        body, notes = speed_table(records, runs)
        parts += ["**Speed** (same domain; BAMG = FreeFem++'s buildmesh in the same run; peak RSS of the "
                  "whole process, its start-up and libraries included):", "", body, ""]
        parts += [f"- {n}" for n in notes] + ([""] if notes else [])
    if any(r["table"] == "aniso" for r in records):
        body, notes = aniso_table(records, runs)
        parts += ["**Anisotropic** (unit square; UGAWG linear and polar-1 layers, h0 = 10^-3; dtlab from the field "
                  "on `data/unit_square_bg.mesh` with the boundary cut in the metric (the default), one generation, no adaptation cycles; FreeFem++ adaptmesh: six "
                  "cycles from square(10, 10), each re-evaluating the analytic field on its mesh). \"exact\": the "
                  "analytic field at the output's vertices; \"background\": `--metric data/*_layer.sol "
                  "--background data/unit_square_bg.mesh` (the 50 × 50 grid's values interpolated):", "", body, ""]
    return "\n".join(parts)


def replace_section_block(readme, text):
    """The page (docs/performance.md) with the perf-mesh2d block (in the "Meshing in 2D" section) holding text."""
    begin, end = readme_tables.markers(KEY)
    if begin not in readme:
        at = readme.index(SECTION)
        nxt = readme.find("\n### ", at + 1)
        nxt2 = readme.find("\n## ", at + 1)
        stop = min(x for x in (nxt, nxt2, len(readme)) if x >= 0)
        readme = readme[:stop].rstrip("\n") + f"\n\n{begin}\n{end}\n" + readme[stop:]
    sec = readme.index(SECTION)
    if not sec < readme.index(begin) < readme.index(end):
        raise ValueError(f"{begin} / {end} must follow {SECTION!r}")
    return readme[:readme.index(begin) + len(begin)] + "\n" + text.rstrip("\n") + "\n" + readme[readme.index(end):]


def update_readme(path, text):
    with open(path) as f:
        readme = f.read()
    try:
        readme = replace_section_block(readme, text)
    except ValueError as e:
        raise SystemExit(f"{path}: {e}")
    with open(path, "w") as f:
        f.write(readme)
    progress(f"updated {path} ({KEY})")


# --- Main -------------------------------------------------------------------------------------

def version(cmd):
    try:
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        return r.stdout.strip().splitlines()[0] if r.stdout.strip() else "unknown"
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"


def debian_version(package):
    v = version(["dpkg-query", "-W", "-f", "${Version}", package])
    return f" (Debian {v})" if v != "unknown" and "no packages" not in v else ""


def find_peers(args):
    exe, peers, skipped = {}, {}, []
    gmsh = args.gmsh or shutil.which("gmsh")
    if gmsh and os.access(gmsh, os.X_OK):
        exe["gmsh"], peers["Gmsh"] = gmsh, version([gmsh, "--version"]) + debian_version("gmsh")
    else:
        skipped.append("Gmsh (not found: apt-get install gmsh, or --gmsh PATH)")
    ff = args.freefem or shutil.which("FreeFem++-nw") or shutil.which("FreeFem++")
    if ff and os.access(ff, os.X_OK):
        exe["freefem"] = ff
        v = version([ff, "-nw", "-v", "1", "-check_plugin", "x"])
        peers["FreeFem++"] = (re.search(r"version\s*:?\s*([0-9.]+\S*)", v, re.I) or re.search(r"([0-9]+\.[0-9.]+)", v)
                              or re.match("(.*)", "unknown")).group(1) + debian_version("freefem++")
    else:
        skipped.append("FreeFem++ (not found: apt-get install freefem++, or --freefem PATH)")
    tri = args.triangle
    if tri and os.access(tri, os.X_OK):
        exe["triangle"] = tri
        peers["Triangle"] = "1.6 (built from its public source, `--triangle`)" if "Version 1.6" in subprocess.run(
            [tri, "-h"], stdout=subprocess.PIPE, text=True).stdout else tri
    else:
        skipped.append("Triangle (not in Debian: build Triangle 1.6 from its public source and give --triangle PATH)"
                       if not tri else f"Triangle ({tri} not found)")
    return exe, peers, skipped


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory holding dtlab")
    ap.add_argument("--dtlab", help="the dtlab binary (default BUILD/dtlab)")
    ap.add_argument("--gmsh", help="Gmsh (default: gmsh in PATH)")
    ap.add_argument("--freefem", help="FreeFem++ (default: FreeFem++-nw in PATH)")
    ap.add_argument("--triangle", help="Triangle 1.6's triangle binary (not in Debian: skipped without it)")
    ap.add_argument("--tables", default="quality,speed", help="comma-separated: quality, speed, aniso")
    ap.add_argument("--aniso", action="store_true", help="add the anisotropic table")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--quality-size", type=float, default=0.01)
    ap.add_argument("--speed-sizes", default="0.01,0.003,0.0015")
    ap.add_argument("--large", action="store_true", help=f"add h = {LARGE_H} (about 10^7 triangles) to the speed table")
    ap.add_argument("--large-tools", default="dtlab front,dtlab edge,Triangle -pq30 -a",
                    help="the tools run at the --large size")
    ap.add_argument("--slow", type=float, default=float("inf"),
                    help="a tool whose first run at a size takes longer (wall seconds) gets --slow-runs runs there")
    ap.add_argument("--slow-runs", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=300, help="seconds a run may take at h = 0.01 (scaled with h)")
    ap.add_argument("--work", help="folder of the domains and outputs (default: a new temporary folder)")
    ap.add_argument("--json", help="write every run here (default BUILD/bench_mesh2d.json)")
    ap.add_argument("--from-json", help="print the tables of an earlier run instead of measuring (several files, "
                                        "comma-separated: their runs together)")
    ap.add_argument("--update-readme", action="store_true", help="write the tables into docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()
    args.dtlab = os.path.abspath(args.dtlab or os.path.join(args.build, "dtlab"))

    if args.from_json:
        data = None
        for name in args.from_json.split(","):
            with open(name) as f:
                more = json.load(f)
            if data is None:
                data = more
                continue
            # Later files add their runs (other sizes or tables, each from one invocation).
            data["records"] += more["records"]
            data["skipped"] = [x for x in data["skipped"] if not x.startswith("10^7")] + [
                x for x in more["skipped"] if x not in data["skipped"]]
            data["tables"] = sorted(set(data.get("tables", [])) | set(more.get("tables", [])))
            data.setdefault("more", []).append({k: more[k] for k in ("provenance", "load_average_end", "wall_seconds")
                                                if k in more})
    else:
        if not os.access(args.dtlab, os.X_OK):
            raise SystemExit(f"{args.dtlab} not found (build the dtlab_cli target, or give --dtlab)")
        tables = [t for t in args.tables.split(",") if t] + (["aniso"] if args.aniso else [])
        exe, peers, skipped = find_peers(args)
        exe["dtlab"] = args.dtlab
        if not os.access(TIME, os.X_OK):
            skipped.append(f"peak memory ({TIME} not found: Debian's package time)")
        args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="bench_mesh2d_"))
        path = os.path.abspath(args.json or os.path.join(args.build, "bench_mesh2d.json"))
        kinds = set(exe)
        data = {"provenance": bench_report.provenance(args.build, {"dtlab": args.dtlab}), "runs": args.runs,
                "peers": peers, "skipped": skipped, "work": args.work, "tables": tables, "records": []}
        started = time.time()

        def save():
            data["load_average_end"] = list(os.getloadavg())
            data["wall_seconds"] = time.time() - started
            with open(path, "w") as f:
                json.dump(data, f, indent=1)

        if "quality" in tables:
            tools = [t for t in TOOLS if TOOLS[t][0] in kinds]
            measure_sizes(args, exe, tools, [args.quality_size], "quality", data["records"], save)
        if "aniso" in tables:
            measure_aniso(args, exe, data["records"], save)
        if "speed" in tables:
            tools = [t for t in SPEED_TOOLS if TOOLS[t][0] in kinds]
            sizes = [float(x) for x in args.speed_sizes.split(",") if x]
            if "quality" in tables:
                # The quality table's runs serve its size: the same commands.
                sizes = [h for h in sizes if h != args.quality_size]
            measure_sizes(args, exe, tools, sizes, "speed", data["records"], save)
            if args.large:
                large = [t for t in args.large_tools.split(",") if t in tools]
                measure_sizes(args, exe, large, [LARGE_H], "speed", data["records"], save)
                left = [t for t in tools if t not in large]
                if left:
                    data["skipped"].append(f"at h = {LARGE_H} (about 10^7 triangles): {', '.join(left)} "
                                           "(not in --large-tools: minutes a run)")
        save()
        progress(f"wrote {path}; work folder {args.work}")

    text = markdown(data)
    print(text)
    if args.update_readme:
        producer = (f"Produced by `scripts/bench_mesh2d.py --update-readme` "
                    f"({data['provenance'].get('date', '')}).")
        update_readme(args.readme, producer + "\n\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
