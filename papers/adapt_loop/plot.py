#!/usr/bin/env python3
"""Convergence plot of the closed adaptive loop: python3 plot.py LOOP.tsv OUT.png

Reads the table adapt_loop --tsv writes (one row per mesh) and draws the L-infinity interpolation
error and the L2 finite element error against the number of vertices for the three series, with
the slope N^-1 for reference (the optimal order of P1 in 2D, reached by anisotropic meshes)."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
    if not rows:
        print(f"plot.py: {sys.argv[1]} has no rows", file=sys.stderr)
        return 1
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    styles = {"uniform": ("s-", "tab:gray"), "isotropic": ("o-", "tab:blue"), "anisotropic": ("^-", "tab:red")}
    for ax, column, title in ((axes[0], "interp_max", "P1 interpolation error, L-inf"),
                              (axes[1], "fe_l2", "finite element error, L2")):
        for series, (marker, colour) in styles.items():
            pts = sorted((int(r["vertices"]), float(r[column])) for r in rows if r["series"] == series)
            if not pts:
                continue
            xs, ys = zip(*pts)
            n = len(xs)
            lx = [math.log(x) for x in xs]
            ly = [math.log(y) for y in ys]
            mx, my = sum(lx) / n, sum(ly) / n
            slope = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
            ax.loglog(xs, ys, marker, color=colour, label=f"{series} (slope {slope:.2f})")
        aniso = sorted((int(r["vertices"]), float(r[column])) for r in rows if r["series"] == "anisotropic")
        if aniso:
            x0, y0 = aniso[0]
            x1 = aniso[-1][0]
            ax.loglog([x0, x1], [y0 * 0.5, y0 * 0.5 * x0 / x1], "k--", lw=0.8, label="N^-1")
        ax.set_xlabel("vertices")
        ax.set_ylabel(column)
        ax.set_title(title)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("-Δu = f, u = tanh(50 (y - 0.5 - 0.2 sin 2πx)): dtlab metric + dtlab adapt, 5 cycles")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
