#!/usr/bin/env python3
"""`dtlab mesh` on the real closed surfaces of Debian's CGAL data (issue 17, "Done when": the
closed surfaces of libcgal-demo meshed in every case), one run per surface and mode, each with a
wall-clock limit, every output checked by `--verify` (exact validity, conformity, the boundary,
region volumes).

  scripts/sweep_mesh3d_real.py                          # every .off/.stl of data/meshes/
  scripts/sweep_mesh3d_real.py --files femur.off,dino.off --limit 300 --out /tmp/sweep.md

Modes: classical (`dtlab mesh F -o OUT.mesh --verify --stats`) and sized (`--size h`, h = 1/15 of
the bounding box's diagonal, as verify/tests/cli_mesh3d_cgal.cmake chooses). A row: the surface,
then for each mode "verified, N tets, T s (Q_M, min dihedral)", "refused: <reason>" (exit 1, the
first line of stderr), "FAILED --verify", "crashed (exit C)" or "not finished within L s".
Also writes --json with every record.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tarfile
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"


def bounding_diagonal(path):
    """The bounding box diagonal of an OFF or STL file's vertices (STL: ASCII or binary)."""
    lo, hi = [math.inf] * 3, [-math.inf] * 3

    def add(p):
        for i in range(3):
            lo[i] = min(lo[i], p[i])
            hi[i] = max(hi[i], p[i])

    if path.endswith(".stl"):
        data = open(path, "rb").read()
        if data[:5] == b"solid" and b"facet" in data[:400]:
            for line in data.decode(errors="replace").splitlines():
                t = line.split()
                if len(t) == 4 and t[0] == "vertex":
                    add([float(x) for x in t[1:]])
        else:
            import struct
            n = struct.unpack("<I", data[80:84])[0]
            for k in range(n):
                base = 84 + 50 * k + 12
                for j in range(3):
                    add(struct.unpack("<3f", data[base + 12 * j: base + 12 * j + 12]))
    else:
        toks = []
        for line in open(path, errors="replace"):
            line = line.split("#")[0]
            toks.extend(line.split())
        i = 1 if toks[0].upper().endswith("OFF") else 0
        nv = int(toks[i])
        i += 3
        for k in range(nv):
            add([float(x) for x in toks[i + 3 * k: i + 3 * k + 3]])
    return math.dist(lo, hi)


def run(dtlab, surface, work, extra, limit):
    out = os.path.join(work, "out.mesh")
    if os.path.exists(out):
        os.remove(out)
    cmd = [dtlab, "mesh", surface, "-o", out, "--verify", "--stats"] + extra
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return {"outcome": "timeout", "limit": limit}
    wall = time.monotonic() - start
    rec = {"wall": wall, "rc": p.returncode}
    if p.returncode == 1:
        err = [l for l in p.stderr.splitlines() if l.strip()]
        rec.update(outcome="refused", reason=err[0] if err else "")
    elif p.returncode == 3:
        rec["outcome"] = "verify_failed"
    elif p.returncode != 0:
        rec["outcome"] = "crashed"
    else:
        stats = json.loads(p.stdout.strip().splitlines()[-1])
        ok = any(l.startswith("ok: ") for l in p.stdout.splitlines())
        rec.update(outcome="verified" if ok else "verify_unclear", tets=stats["tetrahedra"],
                   worst=stats["quality"]["quality_worst"], min_dihedral=stats["quality"]["min_dihedral_deg"],
                   seconds=stats["seconds"])
    return rec


def cell(rec):
    o = rec["outcome"]
    if o == "timeout":
        return f"not finished within {rec['limit']:.0f} s"
    if o == "refused":
        return "refused: " + rec["reason"].replace("|", "/")
    if o == "verify_failed":
        return "FAILED --verify"
    if o == "crashed":
        return f"crashed (exit {rec['rc']})"
    return (f"{'verified' if o == 'verified' else 'ran (no ok line)'}, {rec['tets']:,} tets, {rec['wall']:.1f} s "
            f"(Q_M {rec['worst']:.3g}, min dihedral {rec['min_dihedral']:.1f}°)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dtlab", default=os.path.join(ROOT, "build", "dtlab"))
    ap.add_argument("--archive", default=CGAL_DATA)
    ap.add_argument("--files", help="comma-separated file names of data/meshes/ (default: every .off and .stl)")
    ap.add_argument("--limit", type=float, default=120, help="wall seconds per run")
    ap.add_argument("--modes", default="classical,sized")
    ap.add_argument("--out", default="/tmp/dtlab-sweep-mesh3d.md")
    ap.add_argument("--json", default="/tmp/dtlab-sweep-mesh3d.json")
    args = ap.parse_args()
    if not os.path.exists(args.archive):
        print(f"{args.archive} is absent (apt install libcgal-demo)", file=sys.stderr)
        return 77
    work = tempfile.mkdtemp(prefix="dtlab-sweep-")
    with tarfile.open(args.archive) as tar:
        members = [m for m in tar.getmembers() if "/meshes/" in m.name and m.name.endswith((".off", ".stl"))]
        wanted = set(args.files.split(",")) if args.files else None
        members = [m for m in members if wanted is None or os.path.basename(m.name) in wanted]
        for m in members:
            m.name = os.path.basename(m.name)
            tar.extract(m, work)
    modes = args.modes.split(",")
    records = []
    rows = []
    for m in members:
        path = os.path.join(work, m.name)
        row = {"surface": m.name}
        for mode in modes:
            extra = []
            if mode == "sized":
                h = bounding_diagonal(path) / 15.0
                extra = ["--size", f"{h:.3g}"]
                row["h"] = f"{h:.3g}"
            rec = run(args.dtlab, path, work, extra, args.limit)
            rec.update(surface=m.name, mode=mode)
            records.append(rec)
            row[mode] = cell(rec)
            print(f"{m.name} {mode}: {row[mode]}", file=sys.stderr, flush=True)
            if rec["outcome"] == "refused":
                break  # the same input checks refuse it in every mode
        rows.append(row)
        with open(args.json, "w") as f:
            json.dump(records, f, indent=1)
    lines = ["| surface | classical | --size h (1/15 of the bounding box's diagonal) |", "|---|---|---|"]
    for r in rows:
        sized = f"h = {r['h']}: {r['sized']}" if "sized" in r else ""
        lines.append(f"| {r['surface']} | {r.get('classical', '')} | {sized} |")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
