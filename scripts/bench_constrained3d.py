#!/usr/bin/env python3
"""Steiner points and time of dtlab's 3D constrained methods beside TetGen, one process per run.

Inputs: the Schönhardt family written by bench/constrained3d_inputs (Schönhardt's polyhedron at
5, 30 and 55 degrees, twisted 4-, 6- and 8-gonal prisms, a stack of three twisted prisms,
Chazelle's polyhedron with 2, 4 and 8 notches a side), the closed surfaces of Debian's CGAL
data (libcgal-demo: /usr/share/doc/libcgal-dev/data.tar.gz) named by --cgal-meshes (cube_quad.off:
quadrilateral facets), dtlab's own polygon-facet inputs (data/quad_cube.off, data/box_with_window.poly:
a TetGen facet with a hole), and, where
Debian's gmsh is installed, the CAD part data/cad_part.geo meshed by `gmsh -2 -clmax H` for each
H in --gmsh-sizes (10^3 to 10^6 triangles; Medit .mesh, which both programs read). For each:
    build/dtlab constrain IN.off --method M --stats          (every 3D method dtlab lists)
    build/dtlab constrain IN.off --method M --stats --merge-coplanar   (--merge both or on)
    tetgen -p IN.off                                         (TetGen 1.5, Debian's binary)
    tetgen -pM IN.off                                        (TetGen without merging coplanar facets)
RUNS times each; prints a Markdown table row per (input, program): input vertices and triangles,
Steiner points (dtlab: its --stats on edges / faces / interior; TetGen: "Mesh points" less
"Input points", split as its report splits them), tetrahedra, seconds (each program's own timing:
dtlab's "total", wall clock; TetGen's "Total running seconds" less its "Output seconds", clock(),
CPU time; median over the runs with the spread min–max) and time / TetGen (ratio of the
medians). The runs are interleaved: round 1 of every program on an input, then round 2, ..., so
that a burst of load on the machine falls on every program alike. An input a program refuses gets its first
line of error instead (dtlab names open or self-intersecting surfaces; TetGen may return zero
tetrahedra with exit status 0, which is reported as such). A machine and commit line comes first.
With --merge-coplanar dtlab joins neighbouring coplanar facets with equal references and
triangulates them again (TetGen's default; -M turns it off); its row gives how many facets merged.
--no-times leaves the seconds out (on a loaded machine they mean nothing; Steiner counts do).
--cad NAME:H,... meshes data/cad/NAME.geo by `gmsh -2 -clmax H` (issue 20's surfaces, which the
benchmark had not been tuned on: a plate with nine holes, a filleted bracket, a thin-walled box, a
flange, a pipe tee; 1.2e5 to 8e5 triangles); --only-cad leaves every other input out, and
--methods picks the dtlab methods (default: every 3D method). --baseline DIR runs DIR/dtlab beside
(a build before a change: before and after in the same interleaved rounds); --phases adds dtlab's
phases (its --stats seconds, medians).

  scripts/bench_constrained3d.py --build build
  scripts/bench_constrained3d.py --build build --runs 7 --cgal-meshes elephant.off,eight.off
  scripts/bench_constrained3d.py --build build --update-readme     # the table into docs/performance.md
  scripts/bench_constrained3d.py --build build-x --inputs build/bench/constrained3d_inputs --runs 1 --no-times
  scripts/bench_constrained3d.py --only-cad --methods cdt,recover --merge off --runs 5 --phases   # issue 20
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile

import readme_tables
from bench_delaunay2d import fmt, fmt_spread, machine, progress

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
DEFAULT_GMSH_SIZES = "0.05,0.015,0.005"
# data/cad/NAME.geo at -clmax H (Gmsh 4.8): 122k, 124k, 124k, 130k, 202k and 795k triangles.
DEFAULT_CAD = ("box_holes:0.009,fillet_bracket:0.007,thin_shell:0.01,flange:0.007,pipe_tee:0.01,"
               "box_holes:0.0035")
DEFAULT_MESHES = ("tetrahedron.off,icosahedron.off,sphere.stl,elephant.off,eight.off,cow.off,fandisk.off,knot1.off,"
                  "cube_quad.off")
PRODUCER_CAD = ("Produced by `scripts/bench_constrained3d.py --only-cad --methods cdt,recover --merge off "
                "--update-readme` (the surfaces of data/cad/ by `gmsh -2`, through `dtlab constrain --stats` and "
                "`tetgen -p`, same files).")
BUNDLED = ["quad_cube.off", "box_with_window.poly"]  # in data/
PRODUCER = ("Produced by `scripts/bench_constrained3d.py --update-readme` (dtlab's 3D constrained methods "
            "through `dtlab constrain --stats`, TetGen 1.5 through `tetgen -p`, same files).")


def run(cmd, cwd, timeout):
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, f"timed out after {timeout} s"
    return p, None


def dtlab_once(dtlab, path, method, work, timeout, merge=False):
    p, err = run([dtlab, "constrain", path, "--method", method, "--stats", "-o",
                  os.path.join(work, "out.mesh")] + (["--merge-coplanar"] if merge else []), work, timeout)
    if err:
        return {"error": err}
    if p.returncode != 0:
        # The error is dtlab's last line (--merge-coplanar reports its merges before the checks run).
        return {"error": (p.stderr.strip().splitlines() or ["exit status %d" % p.returncode])[-1]}
    stats = json.loads(p.stdout.strip().splitlines()[-1])
    s = stats["steiner_points"]
    return {"seconds": stats["seconds"]["total"], "phases": stats["seconds"],
            "steiner": s["on_edges"] + s["on_faces"] + s["interior"],
            "split": f"{s['on_edges']} / {s['on_faces']} / {s['interior']}", "tets": stats["elements"],
            "points": stats["points"], "triangles": stats["input_triangles"],
            "merged": stats.get("merged_facets", 0)}


def tetgen_once(path, work, timeout, switches="-p"):
    local = os.path.join(work, os.path.basename(path))
    shutil.copy(path, local)
    p, err = run(["tetgen", switches, os.path.basename(local)], work, timeout)
    if err:
        return {"error": err}
    out = p.stdout
    def number(label, kind=float):
        m = re.search(r"^\s*" + re.escape(label) + r":\s*([0-9.eE+-]+)", out, re.M)
        return kind(m.group(1)) if m else None
    if p.returncode != 0 or number("Total running seconds") is None:
        last = (p.stderr.strip() or out.strip()).splitlines()
        return {"error": f"exit status {p.returncode}: " + (last[-1] if last else "no output")}
    tets = number("Mesh tetrahedra", int)
    if not tets:
        return {"error": "0 tetrahedra, exit status 0"}
    parts = [number(f"Steiner points {where}", int) or 0 for where in ("on segments", "in facets", "in volume")]
    steiner = number("Mesh points", int) - number("Input points", int)
    return {"seconds": number("Total running seconds") - (number("Output seconds") or 0.0), "steiner": steiner,
            "split": " / ".join(str(x) for x in parts), "tets": tets}


def summarise(results):
    """One row from a program's runs on one input: the counts of its first successful run (they
    are the same in every run: the programs are deterministic), seconds the median of the runs
    and times the list; the first error when no run succeeded."""
    ok = [r for r in results if "error" not in r]
    if not ok:
        return results[0]
    row = dict(ok[0])
    row["times"] = [r["seconds"] for r in ok]
    row["seconds"] = statistics.median(row["times"])
    if "phases" in row:
        row["phases"] = {k: statistics.median(r["phases"][k] for r in ok) for k in row["phases"]}
    return row


def extract_meshes(names, into):
    if not os.path.exists(CGAL_DATA):
        progress(f"{CGAL_DATA} absent (Debian package libcgal-demo): CGAL surfaces left out")
        return []
    paths = []
    with tarfile.open(CGAL_DATA) as tar:
        for name in names:
            try:
                member = tar.getmember("data/meshes/" + name)
            except KeyError:
                progress(f"{name}: not in {CGAL_DATA}, left out")
                continue
            member.name = os.path.basename(member.name)
            tar.extract(member, into)
            paths.append(os.path.join(into, member.name))
    return paths


def gmsh_surfaces(specs, into, timeout):
    """Each (geo file, -clmax) meshed by gmsh -2 into NAME_H.mesh; none without gmsh."""
    if not specs:
        return []
    if shutil.which("gmsh") is None:
        progress("bench_constrained3d: gmsh not installed (apt-get install gmsh): CAD surfaces left out")
        return []
    os.makedirs(into, exist_ok=True)
    paths = []
    for geo, h in specs:
        name = os.path.splitext(os.path.basename(geo))[0]
        path = os.path.join(into, f"{name}_{h}.mesh")
        progress(f"bench_constrained3d: gmsh -2 {os.path.relpath(geo, ROOT)} -clmax {h}")
        p, err = run(["gmsh", "-2", geo, "-clmax", h, "-format", "mesh", "-o", path], into, timeout)
        if err or p.returncode != 0 or not os.path.exists(path):
            progress(f"bench_constrained3d: gmsh failed for {name} at -clmax {h}: {err or p.stderr.strip()[-200:]}")
            continue
        paths.append(path)
    return paths


def cad_specs(text):
    """'NAME:H,...' as (data/cad/NAME.geo or data/NAME.geo, H) pairs; a name with no file is an error."""
    specs = []
    for item in (x for x in text.split(",") if x):
        name, sep, h = item.partition(":")
        geo = os.path.join(ROOT, "data", "cad", name + ".geo")
        if not os.path.exists(geo):  # data/cad_part.geo, the benchmark's first CAD part
            geo = os.path.join(ROOT, "data", name + ".geo")
        if not sep or not os.path.exists(geo):
            raise SystemExit(f"--cad: '{item}' is not NAME:H with data/cad/NAME.geo or data/NAME.geo present")
        specs.append((geo, h))
    return specs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--timeout", type=int, default=300, help="seconds per run")
    ap.add_argument("--cgal-meshes", default=DEFAULT_MESHES, help="comma-separated names in CGAL's data/meshes")
    ap.add_argument("--gmsh-sizes", default=DEFAULT_GMSH_SIZES,
                    help="comma-separated -clmax values for data/cad_part.geo (empty: none)")
    ap.add_argument("--cad", default=DEFAULT_CAD, help="comma-separated NAME:H for data/cad/NAME.geo at -clmax H "
                    "(empty: none)")
    ap.add_argument("--only-cad", action="store_true", help="only the --cad surfaces")
    ap.add_argument("--methods", help="comma-separated dtlab methods (default: every 3D method)")
    ap.add_argument("--merge", choices=("off", "on", "both"), default="both",
                    help="dtlab runs without --merge-coplanar, with it, or both (default)")
    ap.add_argument("--inputs", help="the constrained3d_inputs binary (default BUILD/bench/constrained3d_inputs)")
    ap.add_argument("--no-times", action="store_true", help="leave the seconds columns out")
    ap.add_argument("--phases", action="store_true", help="a second table: dtlab's phases, medians")
    ap.add_argument("--baseline", help="another build folder: its dtlab runs the same methods in the same rounds, "
                    "labelled '(baseline)' (before and after a change, interleaved)")
    ap.add_argument("--update-readme", action="store_true", help="write the table into docs/performance.md")
    ap.add_argument("--readme", default=readme_tables.PERFORMANCE_MD, help="the file --update-readme writes")
    args = ap.parse_args()

    args.build = os.path.abspath(args.build)
    dtlab = os.path.join(args.build, "dtlab")
    inputs_bin = os.path.abspath(args.inputs) if args.inputs else os.path.join(args.build, "bench", "constrained3d_inputs")
    for b in (dtlab,) + (() if args.only_cad else (inputs_bin,)):
        if not os.path.exists(b):
            raise SystemExit(f"{b} not found: build it (cmake --build {args.build} --target dtlab_cli constrained3d_inputs)")
    baseline = os.path.join(os.path.abspath(args.baseline), "dtlab") if args.baseline else None
    if baseline and not os.path.exists(baseline):
        raise SystemExit(f"{baseline} not found")
    have_tetgen = shutil.which("tetgen") is not None
    listing = subprocess.run([dtlab, "constrain", "--list-methods"], stdout=subprocess.PIPE, text=True).stdout
    methods3 = [line.split("\t")[0] for line in listing.split("3D", 1)[-1].splitlines()[1:] if "\t" in line]
    if args.methods:
        unknown = [m for m in args.methods.split(",") if m not in methods3]
        if unknown:
            raise SystemExit(f"--methods: {', '.join(unknown)} not among dtlab's 3D methods ({', '.join(methods3)})")
        methods3 = args.methods.split(",")
    cad = cad_specs(args.cad)

    work = tempfile.mkdtemp(prefix="dtlab-c3d-")
    try:
        files = []
        if not args.only_cad:
            files = subprocess.run([inputs_bin, os.path.join(work, "family")], stdout=subprocess.PIPE, text=True,
                                   check=True).stdout.split()
            files += extract_meshes([n for n in args.cgal_meshes.split(",") if n], os.path.join(work, "cgal"))
            files += [os.path.join(ROOT, "data", n) for n in BUNDLED]
            part = os.path.join(ROOT, "data", "cad_part.geo")
            files += gmsh_surfaces([(part, h) for h in args.gmsh_sizes.split(",") if h], os.path.join(work, "gmsh"),
                                   args.timeout)
        files += gmsh_surfaces(cad, os.path.join(work, "cad"), args.timeout)
        merges = {"off": [False], "on": [True], "both": [False, True]}[args.merge]
        rows = []
        for path in files:
            name = os.path.basename(path)
            programs = [(m + (" --merge-coplanar" if merge else ""),
                         lambda p=path, m=m, merge=merge: dtlab_once(dtlab, p, m, work, args.timeout, merge))
                        for m in methods3 for merge in merges]
            if baseline:
                programs += [(m + (" --merge-coplanar" if merge else "") + " (baseline)",
                              lambda p=path, m=m, merge=merge: dtlab_once(baseline, p, m, work, args.timeout, merge))
                             for m in methods3 for merge in merges]
            if have_tetgen:
                programs.append(("tetgen", lambda p=path: tetgen_once(p, work, args.timeout)))
                programs.append(("tetgen -M", lambda p=path: tetgen_once(p, work, args.timeout, "-pM")))
            runs = {label: [] for label, _ in programs}
            for k in range(args.runs):
                for label, once in programs:
                    progress(f"bench_constrained3d: {name}, {label} (run {k + 1}/{args.runs})")
                    runs[label].append(once())
            results = {label: summarise(r) for label, r in runs.items()}
            size = next((r for r in results.values() if "points" in r), {})
            for label, r in results.items():
                rows.append((name, size, label, r, results.get("tetgen")))
        m = machine(dtlab)
        load = ", ".join(f"{x:.1f}" for x in m["load_average"])
        lines = [f"Machine: {m['cpu']}, {m['cpus']} CPUs (load average {load} at the start); "
                 f"`{m['dtlab_version']}` (tree at {m['commit']}); TetGen 1.5 (Debian). One process per run; "
                 f"seconds: median (min–max) of {args.runs} interleaved runs, each program's own timing (TetGen's: CPU time, less "
                 f"its file output); Steiner points split as on edges / on faces / interior (TetGen: on "
                 f"segments / in facets / in volume).", "",
                 "| input | vertices | triangles | program | Steiner points | split | tetrahedra |" +
                 ("" if args.no_times else " seconds: median (min–max) | time / TetGen (medians) |"),
                 "|---|---|---|---|---|---|---|" + ("" if args.no_times else "---|---|")]
        if args.no_times:
            lines[0] = lines[0].replace("seconds: median (min–max) of", "seconds left out (--no-times);").replace(
                " interleaved runs, each program's own timing (TetGen's: CPU time, less its file output)", " run(s)")
        for name, size, label, r, t in rows:
            if r.get("merged"):
                label += f" ({r['merged']} facets merged)"
            head = f"| {name} | {size.get('points', '-')} | {r.get('triangles', size.get('triangles', '-'))} | {label} |"
            if "error" in r:
                lines.append(f"{head} refused: {r['error']} | | |" + ("" if args.no_times else " | |"))
                continue
            ratio = fmt(r["seconds"] / t["seconds"], 2) if t and "error" not in t and t["seconds"] > 0 else "-"
            times = "" if args.no_times else f" {fmt_spread(r['times'])} | {ratio} |"
            lines.append(f"{head} {r['steiner']} | {r['split']} | {r['tets']} |{times}")
        if args.phases and not args.no_times:
            lines += ["", "dtlab's phases (its --stats seconds, median of the runs each; 'other' is the total less "
                      "the phases: building the constraints, copies, output arrays):", "",
                      "| input | program | checks | Delaunay | edge recovery | face recovery | regions | other | total |",
                      "|---|---|---|---|---|---|---|---|---|"]
            keys = ("checks", "delaunay", "edge_recovery", "face_recovery", "regions")
            for name, size, label, r, t in rows:
                if "phases" not in r:
                    continue
                ph = r["phases"]
                other = ph["total"] - sum(ph[k] for k in keys)
                lines.append(f"| {name} | {label} | " + " | ".join(fmt(ph[k], 3) for k in keys) +
                             f" | {fmt(other, 3)} | {fmt(ph['total'], 3)} |")
        text = "\n".join(lines) + "\n"
        print(text)
        if args.update_readme:
            if args.only_cad:
                readme_tables.write_block(args.readme, "constrained3d_cad",
                                          "3D constrained on CAD surfaces it was not tuned on (issue 20) beside TetGen",
                                          PRODUCER_CAD, text)
            else:
                readme_tables.write_block(args.readme, "constrained3d",
                                          "3D constrained (Schönhardt family, CGAL's closed surfaces, a gmsh CAD part) beside TetGen",
                                          PRODUCER, text)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
