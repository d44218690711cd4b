#!/usr/bin/env python3
"""Rasterise a `dtlab plot` canvas (the JSON of apps/svg_canvas.hpp) to PNG with matplotlib.

  scripts/plot_png.py CANVAS.json OUT.png

`dtlab plot MESH -o OUT.png` writes the canvas and runs this script; the layout is the one of the
SVG output, drawn at twice its pixel size. Exit status 3 when matplotlib cannot be imported (the
command then tries the next Python interpreter, or names the package to install).
"""
import json
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.patches import Rectangle
except ImportError as e:
    if os.environ.get("DTLAB_PLOT_PNG_QUIET") != "1":  # set by `dtlab plot`, which names the package itself
        print(f"plot_png.py: {e} (Debian: apt-get install python3-matplotlib)", file=sys.stderr)
    sys.exit(3)

DPI = 200  # two pixels per canvas unit


def draw(canvas, out):
    w, h = canvas["width"], canvas["height"]
    fig = plt.figure(figsize=(w / 100.0, h / 100.0), dpi=DPI)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_xlim(0, w)
    ax.set_ylim(h, 0)
    ax.set_axis_off()
    px = 72.0 / 100.0  # one canvas unit in points
    group, polys, fills = None, [], []

    def flush():
        if polys:
            ax.add_collection(PolyCollection(list(polys), facecolors=list(fills), edgecolors=group["stroke"],
                                             linewidths=group["width"] * px, joinstyle="round"))
        polys.clear()  # the collection keeps the lists it was given: copies above
        fills.clear()

    for it in canvas["items"]:
        kind = it["kind"]
        if kind != "polygon":
            flush()
        if kind == "group":
            group = it
        elif kind == "polygon":
            p = it["points"]
            polys.append(list(zip(p[0::2], p[1::2])))
            fills.append(it["fill"])
        elif kind == "segments":
            p = it["points"]
            lines = [((p[i], p[i + 1]), (p[i + 2], p[i + 3])) for i in range(0, len(p), 4)]
            ax.add_collection(LineCollection(lines, colors=it["stroke"], linewidths=it["width"] * px,
                                             capstyle="round"))
        elif kind == "rect":
            ax.add_patch(Rectangle((it["x"], it["y"]), it["w"], it["h"],
                                   facecolor=it["fill"] if it["fill"] != "none" else "none",
                                   edgecolor=it["stroke"] if it["stroke"] != "none" else "none",
                                   linewidth=px if it["stroke"] != "none" else 0))
        elif kind == "text":
            ax.text(it["x"], it["y"], it["text"], fontsize=it["size"] * px, ha={"start": "left", "middle": "center",
                    "end": "right"}[it["anchor"]], va="baseline", fontweight="bold" if it["bold"] else "normal")
    flush()
    # No date or software version in the file: the same canvas gives the same bytes.
    fig.savefig(out, dpi=DPI, facecolor="white", metadata={"Software": None})
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1]) as f:
        canvas = json.load(f)
    draw(canvas, sys.argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main())
