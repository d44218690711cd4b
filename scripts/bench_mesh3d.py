#!/usr/bin/env python3
"""3D mesh generation beside its peers (issue 17, "Peers and targets"), every output measured by one
checker, `dtlab quality OUT --size H --json`.

Domain: the unit cube minus the ball of radius 0.25 at its centre, an OpenCASCADE .geo written into
the work folder; its surface by `gmsh -2 cube_ball.geo -clmax H -format mesh` (H = 0.04: about
10,100 triangles), the same triangles for dtlab and TetGen:
  dtlab        `dtlab mesh surface.mesh -o OUT.mesh --size H --remove-cavities --stats` (the default
               optimization effort, standard; the ball's inside is a cavity, dropped), and with
               `--optimize thorough` (rounds until no gain)
  TetGen       `tetgen -pq1.414a<V>` on surface.smesh (the same triangles, a hole point at the
               centre), V = H^3 / (6 sqrt 2) the volume of the regular tetrahedron of edge H; and
               with -O9/7 (TetGen's strongest mesh optimization: level 9, every operation).
               Measured from its .node/.ele (its .mesh has a Corners section the reader refuses).
  Gmsh         `gmsh -3 cube_ball.geo -clmax H -format mesh` (Delaunay with its default
               optimization) and with -algo hxt; Gmsh meshes the surface again itself (the same
               surface algorithm and -clmax, so the same surface).
  Netgen       not run (Debian's netgen is the GUI build; its batch mode needs a display).
Each tool's output: tetrahedra, min and max dihedral angle, worst Q (Q_K, 1 = regular), share of Q in
[1, 2], share of edges of length in [1/sqrt2, sqrt2] H; wall time of the whole command (/usr/bin/time,
file output included), tetrahedra per second of that wall time, peak RSS (max resident set of the
process) in bytes per tetrahedron. Runs are interleaved (round 1 of every tool, then round 2, ...; the
order rotated by one tool each round) so that a slow spell of this shared machine falls on every
tool; times are medians with the min - max range, never a minimum. The quality is measured on the
first round's output (every tool here is deterministic; the tetrahedron counts of later rounds are
checked against it).

Then `dtlab optimize IN -o OUT --size H` on TetGen's and Gmsh's meshes: min dihedral and worst Q
before and after, the time, and whether the boundary is untouched (the set of boundary faces, each
as its three corner coordinates, the same before and after).

  scripts/bench_mesh3d.py                                   # 5 rounds, h = 0.04, docs/performance_mesh3d.md
  scripts/bench_mesh3d.py --runs 3 --size 0.06 --out /tmp/p.md --json /tmp/p.json
  scripts/bench_mesh3d.py --from-json /tmp/p.json --out docs/performance_mesh3d.md

The tables replace everything above END_MARK in --out; what follows the marker is kept.
"""
import argparse
import datetime
import json
import math
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_report import md_table, progress, spread  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

END_MARK = "<!-- bench_mesh3d.py writes everything above this line; what follows is kept -->"

GEO = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {0.5, 0.5, 0.5, 0.25};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
"""


def tools(dtlab, h):
    v = h ** 3 / (6.0 * math.sqrt(2.0))
    a = f"{v:.6g}"
    return {
        "dtlab": {"label": "dtlab `mesh --size` (default: `--optimize standard`)",
                  "cmd": [dtlab, "mesh", "surface.mesh", "-o", "dtlab.mesh", "--size", str(h), "--remove-cavities",
                          "--stats"], "out": "dtlab.mesh"},
        "dtlab_thorough": {"label": "dtlab `mesh --size --optimize thorough`",
                           "cmd": [dtlab, "mesh", "surface.mesh", "-o", "dtlab_thorough.mesh", "--size", str(h),
                                   "--remove-cavities", "--optimize", "thorough", "--stats"],
                           "out": "dtlab_thorough.mesh"},
        "tetgen": {"label": f"TetGen `-pq1.414 -a{a}`", "cmd": ["tetgen", f"-pq1.414a{a}Q", "tg/surface.smesh"],
                   "out": "tg/surface.1.ele", "dir": "tg"},
        "tetgen_O": {"label": f"TetGen `-pq1.414 -a{a} -O9/7`", "cmd": ["tetgen", f"-pq1.414a{a}O9/7Q", "tgo/surface.smesh"],
                     "out": "tgo/surface.1.ele", "dir": "tgo"},
        "gmsh": {"label": "Gmsh `-3` (Delaunay + default optimization)",
                 "cmd": ["gmsh", "-3", "cube_ball.geo", "-clmax", str(h), "-format", "mesh", "-o", "gmsh.mesh"],
                 "out": "gmsh.mesh"},
        "gmsh_hxt": {"label": "Gmsh `-3 -algo hxt`",
                     "cmd": ["gmsh", "-3", "-algo", "hxt", "cube_ball.geo", "-clmax", str(h), "-format", "mesh", "-o",
                             "gmsh_hxt.mesh"], "out": "gmsh_hxt.mesh"},
    }


def medit_sections(path):
    toks = open(path).read().split()
    out, i = {}, 0
    widths = {"Vertices": 4, "Triangles": 4, "Tetrahedra": 5, "Edges": 3}
    while i < len(toks):
        t = toks[i]
        if t in widths:
            n = int(toks[i + 1])
            w = widths[t]
            out[t] = [toks[i + 2 + w * k: i + 2 + w * k + w] for k in range(n)]
            i += 2 + w * n
        else:
            i += 1
    return out


def write_smesh(surface, path):
    s = medit_sections(surface)
    with open(path, "w") as f:
        f.write(f"{len(s['Vertices'])} 3 0 0\n")
        for k, v in enumerate(s["Vertices"]):
            f.write(f"{k + 1} {v[0]} {v[1]} {v[2]}\n")
        f.write(f"{len(s['Triangles'])} 1\n")
        for t in s["Triangles"]:
            f.write(f"3 {t[0]} {t[1]} {t[2]} {t[3]}\n")
        f.write("1\n1 0.5 0.5 0.5\n0\n")
    return len(s["Triangles"])


def points_and_tets(path):
    """Vertex coordinates (as doubles) and tetrahedra (0-based) of a Medit .mesh or a TetGen .ele."""
    if path.endswith(".ele"):
        node = open(path[:-4] + ".node").read().split("\n")
        head = node[0].split()
        first = None
        pts = {}
        for line in node[1:]:
            f = line.split("#")[0].split()
            if len(f) >= 4:
                pts[int(f[0])] = tuple(float(x) for x in f[1:4])
                first = int(f[0]) if first is None else first
        ele = open(path).read().split("\n")
        n = int(ele[0].split()[0])
        tets = []
        for line in ele[1:]:
            f = line.split("#")[0].split()
            if len(f) >= 5:
                tets.append([pts[int(x)] for x in f[1:5]])
        assert len(tets) == n, (path, len(tets), n, head)
        return tets
    s = medit_sections(path)
    v = [tuple(float(c) for c in x[:3]) for x in s["Vertices"]]
    return [[v[int(i) - 1] for i in t[:4]] for t in s.get("Tetrahedra", [])]


def boundary_faces(path):
    """Faces in one tetrahedron, each a frozenset of three coordinate triples."""
    count = {}
    for t in points_and_tets(path):
        for skip in range(4):
            f = frozenset(t[:skip] + t[skip + 1:])
            count[f] = count.get(f, 0) + 1
    return {f for f, c in count.items() if c == 1}


def quality(dtlab, path, h):
    p = subprocess.run([dtlab, "quality", path, "--size", str(h), "--json"], capture_output=True, text=True, check=True)
    q = json.loads(p.stdout.strip().splitlines()[-1])
    return {"tets": q["elements"], "min_dihedral": q["min_dihedral_deg"], "max_dihedral": q["max_dihedral_deg"],
            "worst_q": q["quality_worst"], "share_1_2": q["share_1_2"], "unit_edges": q["unit_edge_share"]}


def timed(cmd, cwd, timeout):
    """(wall seconds, peak RSS bytes, stdout, CPU seconds: user + system) of one command under /usr/bin/time."""
    tf = os.path.join(cwd, ".time")
    t0 = time.time()
    p = subprocess.run(["/usr/bin/time", "-f", "%e %M %U %S", "-o", tf] + cmd, cwd=cwd, capture_output=True, text=True,
                       timeout=timeout)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()[-400:]}")
    e, m, u, sy = open(tf).read().split()[-4:]
    return float(e) if float(e) > 0 else wall, int(m) * 1024, p.stdout, float(u) + float(sy)


def prepare(work, h):
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "cube_ball.geo"), "w") as f:
        f.write(GEO)
    subprocess.run(["gmsh", "-2", "cube_ball.geo", "-clmax", str(h), "-format", "mesh", "-o", "surface.mesh"], cwd=work,
                   check=True, capture_output=True)
    triangles = None
    for d in ("tg", "tgo"):
        os.makedirs(os.path.join(work, d), exist_ok=True)
        triangles = write_smesh(os.path.join(work, "surface.mesh"), os.path.join(work, d, "surface.smesh"))
    return triangles


def optimize_peers(args, data, names, ts):
    """`dtlab optimize` on each peer's first-round mesh (kept as keep_<tool>.*)."""
    work, h, dtlab = os.path.abspath(args.work), args.size, os.path.abspath(args.dtlab)
    for n in [x for x in names if x.startswith("tetgen") or x.startswith("gmsh")]:
        if n == "tetgen_O" and data["quality"].get("tetgen") == data["quality"][n]:
            progress("optimize tetgen_O: skipped, the same mesh as tetgen's (same quality report)")
            continue
        src = os.path.join(work, f"keep_{n}" + os.path.splitext(ts[n]["out"])[1])
        dst = os.path.join(work, f"opt_{n}.mesh")
        wall, rss, out, cpu = timed([dtlab, "optimize", src, "-o", dst, "--size", str(h), "--stats"], work, args.timeout)
        same = boundary_faces(src) == boundary_faces(dst)
        data["optimize"][n] = {"before": data["quality"][n], "after": quality(dtlab, dst, h), "wall": wall,
                               "cpu": cpu, "boundary_untouched": same}
        save(args, data)
        progress(f"optimize {n}: {wall:.1f} s, boundary {'untouched' if same else 'CHANGED'}")


def measure(args):
    work = os.path.abspath(args.work)
    h = args.size
    dtlab = os.path.abspath(args.dtlab)
    missing = [t for t in ("gmsh", "tetgen") if shutil.which(t) is None]
    if missing:
        sys.exit(f"bench_mesh3d: {', '.join(missing)} not installed (apt-get install gmsh tetgen)")
    triangles = prepare(work, h)
    progress(f"surface: {triangles} triangles (gmsh -2, h = {h})")
    ts = tools(dtlab, h)
    names = [n for n in ts if n in args.tools.split(",")]
    data = {"size": h, "triangles": triangles, "runs": args.runs, "tools": {n: ts[n]["label"] for n in names},
            "commands": {n: " ".join(os.path.basename(c) if i == 0 else c for i, c in enumerate(ts[n]["cmd"]))
                         for n in names},
            "records": [], "quality": {}, "optimize": {}, "cpus": os.cpu_count(),
            "load_start": list(os.getloadavg()), "date": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
            "commit": subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                                     text=True).stdout.strip(),
            "versions": {"tetgen": "1.5 (Debian)",
                         "gmsh": subprocess.run(["gmsh", "--version"], capture_output=True, text=True).stderr.strip()
                         or subprocess.run(["gmsh", "--version"], capture_output=True, text=True).stdout.strip()}}
    for r in range(args.runs):
        order = names[r % len(names):] + names[:r % len(names)]
        for n in order:
            t = ts[n]
            wall, rss, out, cpu = timed(t["cmd"], work, args.timeout)
            rec = {"tool": n, "round": r, "wall": wall, "cpu": cpu, "rss": rss, "load": os.getloadavg()[0]}
            if n.startswith("dtlab"):
                rec["own_seconds"] = json.loads(out.strip().splitlines()[-1])["seconds"]
            if r == 0:
                data["quality"][n] = quality(dtlab, os.path.join(work, t["out"]), h)
                if n.startswith("tetgen") or n.startswith("gmsh"):
                    keep = os.path.join(work, f"keep_{n}" + os.path.splitext(t["out"])[1])
                    for ext in ((".ele", ".node", ".face") if t["out"].endswith(".ele") else (".mesh",)):
                        shutil.copy(os.path.join(work, os.path.splitext(t["out"])[0] + ext),
                                    os.path.splitext(keep)[0] + ext)
            rec["tets"] = len(points_and_tets(os.path.join(work, t["out"]))) if r > 0 and args.check_counts else None
            data["records"].append(rec)
            progress(f"round {r + 1}/{args.runs} {n}: {wall:.2f} s, {rss / 2 ** 20:.0f} MB, load {rec['load']:.1f}")
        save(args, data)  # after every round: a report can be made of the rounds done (--from-json)
    if not args.no_optimize:
        optimize_peers(args, data, names, ts)
    data["load_end"] = list(os.getloadavg())
    return data


def save(args, data):
    if args.json:
        with open(args.json, "w") as f:
            json.dump(dict(data, load_end=list(os.getloadavg())), f, indent=1)


def fmt(v, digits=3):
    if v is None:
        return "-"
    if abs(v) >= 1000:
        return f"{v:,.0f}"
    return f"{v:.{digits}g}"


def report(data):
    h = data["size"]
    rounds = len({r["round"] for r in data["records"]})
    lines = [f"# 3D mesh generation beside its peers (issue 17)\n",
             f"Generated by `scripts/bench_mesh3d.py` ({data['date']}, commit {data['commit']}): the unit cube minus a "
             f"ball of radius 0.25, surface by `gmsh -2 -clmax {h}` ({data['triangles']} triangles), h = {h}. One "
             f"checker for every output: `dtlab quality OUT --size {h} --json`. Times: wall clock of the whole "
             f"command (file output included), median [min - max] of {rounds} interleaved rounds; CPU: user + system "
             f"seconds of the process (the clock a loaded machine disturbs least), median; tets/s = tetrahedra / "
             f"median wall time (and / median CPU time); memory = peak RSS / tetrahedra.\n",
             f"**Load**: {data['cpus']} CPUs shared with other work; 1-minute load average "
             f"{data['load_start'][0]:.1f} at the start, {data['load_end'][0]:.1f} at the end, "
             f"{min(r['load'] for r in data['records']):.1f} - {max(r['load'] for r in data['records']):.1f} "
             f"across the runs. Absolute times are pessimistic and noisy; the quality columns are exact.\n",
             "## Quality and speed\n"]
    rows = []
    for n, label in data["tools"].items():
        q = data["quality"][n]
        recs = [r for r in data["records"] if r["tool"] == n]
        lo, med, hi, _ = spread([r["wall"] for r in recs])
        cpu = spread([r["cpu"] for r in recs])[1]
        rss = max(r["rss"] for r in recs)
        rows.append([label, f"{q['tets']:,}", f"{q['min_dihedral']:.1f}°", f"{q['max_dihedral']:.1f}°",
                     f"{q['worst_q']:.2f}", f"{100 * q['share_1_2']:.2f} %", f"{100 * q['unit_edges']:.1f} %",
                     f"{med:.2f} [{lo:.2f} - {hi:.2f}]", f"{cpu:.2f}", f"{q['tets'] / med:,.0f} ({q['tets'] / cpu:,.0f})",
                     f"{rss / q['tets']:.0f}"])
    lines.append(md_table(["tool", "tets", "min dihedral", "max dihedral", "worst Q", "Q in [1,2]",
                           f"edges in [1/√2, √2]·h", "wall s median [min - max]", "CPU s", "tets/s wall (CPU)",
                           "bytes/tet"], rows))
    d = [r for r in data["records"] if r["tool"] == "dtlab" and "own_seconds" in r]
    if d:
        lo, med, hi, _ = spread([r["own_seconds"] for r in d])
        lines.append(f"\ndtlab's own `--stats` seconds (the meshing call, no file output): {med:.2f} "
                     f"[{lo:.2f} - {hi:.2f}].\n")
    lines.append("Commands (run in the work folder):\n")
    for n, c in data["commands"].items():
        lines.append(f"- {n}: `{c}`")
    if not data["optimize"]:  # --no-optimize
        lines.append("")
        return "\n".join(lines)
    lines.append("\n## `dtlab optimize` on the peers' meshes\n")
    lines.append(f"`dtlab optimize IN -o OUT --size {h}` (default rounds), measured by the same checker; boundary: the "
                 "set of boundary faces (corner coordinates) identical before and after.\n")
    rows = []
    for n, o in data["optimize"].items():
        b, a = o["before"], o["after"]
        rows.append([data["tools"][n], f"{b['tets']:,} → {a['tets']:,}",
                     f"{b['min_dihedral']:.1f}° → {a['min_dihedral']:.1f}°",
                     f"{b['max_dihedral']:.1f}° → {a['max_dihedral']:.1f}°", f"{b['worst_q']:.2f} → {a['worst_q']:.2f}",
                     f"{100 * b['share_1_2']:.1f} → {100 * a['share_1_2']:.1f} %",
                     f"{100 * b['unit_edges']:.1f} → {100 * a['unit_edges']:.1f} %", f"{o['wall']:.1f} ({o['cpu']:.1f})",
                     "yes" if o["boundary_untouched"] else "**no**"])
    lines.append(md_table(["mesh", "tets", "min dihedral", "max dihedral", "worst Q", "Q in [1,2]", "unit edges",
                           "wall s (CPU s)", "boundary untouched"], rows))
    lines.append("")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", default=os.path.join(ROOT, "build", "dtlab"))
    ap.add_argument("--size", type=float, default=0.04)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--tools", default="dtlab,dtlab_thorough,tetgen,tetgen_O,gmsh,gmsh_hxt")
    ap.add_argument("--work", default="/tmp/dtlab-bench-mesh3d")
    ap.add_argument("--timeout", type=float, default=1200)
    ap.add_argument("--check-counts", action="store_true", help="recount the tetrahedra of every round")
    ap.add_argument("--json", help="write every measurement here (after every round)")
    ap.add_argument("--no-optimize", action="store_true", help="leave out the dtlab optimize table")
    ap.add_argument("--optimize-only", action="store_true",
                    help="only the dtlab optimize table, on the meshes kept in --work, added to --json")
    ap.add_argument("--from-json", help="report from an earlier --json instead of measuring")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "performance_mesh3d.md"))
    args = ap.parse_args()
    if args.optimize_only:
        # The optimize table alone, on the meshes a measuring run kept in --work, added to its --json.
        data = json.load(open(args.json))
        ts = tools(os.path.abspath(args.dtlab), args.size)
        optimize_peers(args, data, list(data["tools"]), ts)
        save(args, data)
    elif args.from_json:
        data = json.load(open(args.from_json))
    else:
        data = measure(args)
        save(args, data)
    text = report(data) + "\n" + END_MARK + "\n"
    # What follows the marker in an existing file (notes written by hand) is kept.
    if os.path.exists(args.out):
        old = open(args.out).read()
        if END_MARK in old:
            text += old.split(END_MARK, 1)[1].lstrip("\n")
    with open(args.out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
