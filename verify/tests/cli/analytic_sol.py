#!/usr/bin/env python3
"""Writes a Medit .sol of an analytic metric field at the vertices of an ASCII Medit mesh, for
the CLI tests of `dtlab adapt`:

    analytic_sol.py MESH.mesh OUT.sol FIELD

FIELD: size:H (the isotropic H^-2 I, written as the scalar H), tanh:K (the scalar field
tanh(K (y - 0.5 - 0.1 sin(2 pi x))), a solution with a layer), linear:H0 (the 2D UGAWG "linear"
field: h_x = 0.1, h_y = H0 + 2 (0.1 - H0) |y - 0.5|, a symmetric tensor), expr:E (the scalar
field given by the Python expression E of x, y, z and the math module's names, e.g. expr:2*x+3*y),
or bad (a tensor that is not positive definite at vertex 2)."""
import math
import sys


def vertices(path):
    words = open(path).read().split()
    dim = int(words[words.index("Dimension") + 1])
    at = words.index("Vertices")
    count = int(words[at + 1])
    values = words[at + 2 : at + 2 + count * (dim + 1)]
    return dim, [tuple(float(values[k * (dim + 1) + i]) for i in range(dim)) for k in range(count)]


def main():
    mesh, out, field = sys.argv[1:4]
    dim, points = vertices(mesh)
    lines = []
    if field.startswith("size:"):
        kind = 1
        lines = [field[5:]] * len(points)
    elif field.startswith("tanh:"):
        kind = 1
        k = float(field[5:])
        lines = ["%.17g" % math.tanh(k * (p[1] - 0.5 - 0.1 * math.sin(2 * math.pi * p[0]))) for p in points]
    elif field.startswith("expr:"):
        kind = 1
        names = {k: getattr(math, k) for k in dir(math) if not k.startswith("_")}
        for p in points:
            names.update(x=p[0], y=p[1], z=p[2] if dim == 3 else 0.0)
            lines.append(repr(float(eval(field[5:], {"__builtins__": {"abs": abs, "float": float, "min": min, "max": max}}, names))))
    else:
        kind = 3
        for k, p in enumerate(points):
            if field == "bad":
                lines.append("1 2 1" if k == 1 else "1 0 1")
                continue
            h0 = float(field.split(":")[1])
            hy = h0 + 2 * (0.1 - h0) * abs(p[1] - 0.5)
            lines.append("%.17g 0 %.17g" % (1 / 0.1**2, 1 / hy**2))
    with open(out, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension %d\nSolAtVertices\n%d\n1 %d\n" % (dim, len(points), kind))
        f.write("\n".join(lines) + "\nEnd\n")


main()
