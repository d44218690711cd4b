"""Linear fields on a Medit mesh's vertices for the `dtlab transfer` CLI tests.

  transfer_field.py write MESH SOL       writes u = 3x - 2y + 0.5 (+ 1.5 z in 3D) at MESH's vertices
  transfer_field.py check MESH SOL TOL   exits 1 unless SOL holds that u to TOL (relative)
"""
import sys


def section(path, name, width):
    toks = open(path).read().split()
    i = toks.index(name)
    n = int(toks[i + 1])
    return [toks[i + 2 + k * width:i + 2 + (k + 1) * width] for k in range(n)]


def u(x, y, z=0.0):
    return 3.0 * x - 2.0 * y + 0.5 + 1.5 * z


mode, mesh, sol = sys.argv[1:4]
words = open(mesh).read().split()
dim = int(words[words.index("Dimension") + 1])
verts = [tuple(float(c) for c in v[:dim]) for v in section(mesh, "Vertices", dim + 1)]
if mode == "write":
    with open(sol, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension %d\nSolAtVertices\n%d\n1 1\n" % (dim, len(verts)))
        for p in verts:
            f.write("%.17g\n" % u(*p))
        f.write("End\n")
else:
    toks = open(sol).read().split()
    i = toks.index("SolAtVertices")  # then: count, "1" field, type 1, the values
    values = [float(t) for t in toks[i + 4:i + 4 + int(toks[i + 1])]]
    tol = float(sys.argv[4])
    if len(values) != len(verts):
        sys.exit("%d values for %d vertices" % (len(values), len(verts)))
    worst = max(abs(w - u(*p)) / (1.0 + abs(u(*p))) for w, p in zip(values, verts))
    print("worst relative error %.3g" % worst)
    sys.exit(0 if worst <= tol else 1)
