"""dtlab: robust Delaunay triangulation and meshing, from Python.

numpy in, numpy out: every function takes float64 point arrays (viewed in place when they are
C-contiguous float64 already) and integer index arrays, and returns a :class:`Mesh` whose arrays
are the C++ results handed over without a copy. Every combinatorial decision is exact (the
staged predicates of :mod:`dtlab.predicates`); degenerate input is resolved by symbolic
perturbation, never by a tolerance. The GIL is released while the C++ code runs; errors are
:class:`InputError` (``.items``: the offending input indices, 0-based), :class:`ParseError`
(``.file``, ``.line``) and :class:`InternalError`, all subclasses of :class:`Error`.

See docs/python.md for examples.
"""

from __future__ import annotations

import numbers
import re

import numpy as np

from . import _dtlab
from . import predicates
from ._dtlab import Error, InputError, InternalError, ParseError

__all__ = [
    "Mesh", "delaunay", "constrain", "mesh", "optimize", "quality", "element_quality", "verify",
    "read_medit", "variants", "predicates", "Error", "InputError", "ParseError", "InternalError",
]

_CELL_TYPES = {2: ("triangle", "line"), 3: ("tetra", "triangle")}


class Mesh:
    """A triangle (2D) or tetrahedron (3D) mesh.

    Attributes:
        points: ``(n, d)`` float64 coordinates.
        cells: ``(m, d + 1)`` uint32 vertex ids; triangles counter-clockwise, tetrahedra positive
            (``orient3d > 0``).
        cell_refs: ``(m,)`` int32 reference (region) of each cell.
        boundary_cells: ``(k, d)`` uint32: constrained / boundary edges (2D) or triangles (3D).
        boundary_refs: ``(k,)`` int32 reference (marker) of each boundary cell.
        point_data: dict of per-point arrays (``"metric"`` after meshing / optimization).
        stats: dict of what the call did: counts, seconds, predicate stage counts
            (``stats["predicates"]``), messages, and ``stats["verify"]`` when asked for.
    """

    def __init__(self, points, cells, cell_refs=None, boundary_cells=None, boundary_refs=None,
                 stats=None, point_data=None):
        self.points = np.asarray(points, dtype=np.float64)
        d = self.points.shape[1] if self.points.ndim == 2 else 0
        if d not in (2, 3):
            raise InputError("points: shape (n, 2) or (n, 3) expected")
        self.cells = _index_array(cells, d + 1)
        self.cell_refs = (np.zeros(len(self.cells), np.int32) if cell_refs is None
                          else np.asarray(cell_refs, dtype=np.int32))
        self.boundary_cells = _index_array(boundary_cells, d)
        self.boundary_refs = (np.zeros(len(self.boundary_cells), np.int32) if boundary_refs is None
                              else np.asarray(boundary_refs, dtype=np.int32))
        self.point_data = dict(point_data or {})
        self.stats = dict(stats or {})

    @property
    def dim(self) -> int:
        return int(self.points.shape[1])

    @property
    def cell_type(self) -> str:
        """meshio's name of the cells: ``"triangle"`` or ``"tetra"``."""
        return _CELL_TYPES[self.dim][0]

    def __repr__(self):
        return (f"Mesh(dim={self.dim}, points={len(self.points)}, {self.cell_type}={len(self.cells)}, "
                f"boundary={len(self.boundary_cells)})")

    def quality(self, metric=None) -> dict:
        """:func:`dtlab.quality` of this mesh (in ``metric``, or the mesh's own ``point_data["metric"]``
        when ``metric="own"``)."""
        if isinstance(metric, str) and metric == "own":
            metric = self.point_data.get("metric")
        return quality(self.points, self.cells, metric=metric)

    def to_meshio(self, ref_name: str = "ref"):
        """A ``meshio.Mesh``: the cells and the boundary cells as two cell blocks, the references
        as cell data ``ref_name`` (``"medit:ref"`` for Medit files, ``"gmsh:physical"`` for Gmsh),
        ``point_data`` as point data (metrics flattened to their components)."""
        import meshio
        cell_type, boundary_type = _CELL_TYPES[self.dim]
        blocks = [(cell_type, self.cells.astype(np.int64))]
        refs = [self.cell_refs]
        if len(self.boundary_cells):
            blocks.append((boundary_type, self.boundary_cells.astype(np.int64)))
            refs.append(self.boundary_refs)
        return meshio.Mesh(self.points, blocks, point_data=dict(self.point_data), cell_data={ref_name: refs})

    @classmethod
    def from_meshio(cls, m, ref_name: str | None = None) -> "Mesh":
        """The inverse of :meth:`to_meshio`: the first triangle (2D) or tetra block, in 2D the
        ``line`` block and in 3D the ``triangle`` block as boundary; references from ``ref_name``
        or the first of ``ref``, ``medit:ref``, ``gmsh:physical`` present. 2D when the points
        have two columns, or a third that is all zero and there are no tetrahedra."""
        points = np.asarray(m.points, dtype=np.float64)
        types = [b.type for b in m.cells]
        if "tetra" in types:
            dim = 3
        else:
            dim = 2
            if points.shape[1] == 3:
                if np.any(points[:, 2] != 0):
                    raise InputError("from_meshio: 3D points without tetrahedra")
                points = np.ascontiguousarray(points[:, :2])
        names = [ref_name] if ref_name else ["ref", "medit:ref", "gmsh:physical"]
        name = next((n for n in names if n in m.cell_data), None)
        cell_type, boundary_type = _CELL_TYPES[dim]

        def block(kind):
            for i, b in enumerate(m.cells):
                if b.type == kind:
                    refs = m.cell_data[name][i] if name else np.zeros(len(b.data), np.int32)
                    return b.data, refs
            return np.zeros((0, dim + 1 if kind == cell_type else dim), np.uint32), np.zeros(0, np.int32)

        cells, cell_refs = block(cell_type)
        boundary, boundary_refs = block(boundary_type)
        return cls(points, cells, cell_refs, boundary, boundary_refs, point_data=dict(m.point_data))

    def write(self, path: str, point_refs=None) -> None:
        """Writes a Medit ``.mesh`` with dtlab's own writer: the same bytes as the ``dtlab``
        command writes for the same mesh."""
        if not str(path).endswith(".mesh"):
            raise InputError(f"{path}: Mesh.write writes Medit .mesh (use to_meshio() for other formats)")
        _dtlab.write_medit(str(path), self.points, self.cells, self.cell_refs, self.boundary_cells,
                           self.boundary_refs, point_refs)


def _index_array(a, columns):
    if a is None:
        return np.zeros((0, columns), np.uint32)
    a = np.asarray(a)
    if a.size == 0:
        return np.zeros((0, columns), np.uint32)
    if a.ndim != 2 or a.shape[1] != columns:
        raise InputError(f"cells: shape (m, {columns}) expected, not {a.shape}")
    if a.dtype != np.uint32:
        if a.dtype.kind not in "iu":
            raise InputError(f"cells: an integer array is required, not dtype {a.dtype}")
        if a.min() < 0 or a.max() >= 0xFFFFFFFE:
            raise InputError("cells: vertex ids must be in [0, 2^32 - 3]")
        a = a.astype(np.uint32)
    return a


def _mesh(result) -> Mesh:
    point_data = {}
    if "metric" in result:
        point_data["metric"] = result["metric"]
    mesh = Mesh(result["points"], result["cells"], result.get("cell_refs"), result.get("boundary_cells"),
                result.get("boundary_refs"), result["stats"], point_data)
    for key in ("duplicates", "duplicate_of", "boundary_sources"):
        if key in result:
            mesh.stats[key] = result[key]
    return mesh


def _size(size):
    if isinstance(size, numbers.Real) and not isinstance(size, bool):
        return float(size)
    return size


def variants() -> dict:
    """The registered variants and methods, ``{"delaunay2d": [(name, description), ...],
    "delaunay3d": ..., "constrained2d": ..., "constrained3d": ..., "optimize2d": ..., "optimize3d": ...,
    "mesh2d": ..., "mesh3d": ...}`` (optimize*: the optimization operators of a round, in their order;
    mesh*: the meshers' field point methods, ``method=`` of :func:`mesh`)."""
    return _dtlab.variants()


def delaunay(points, algo: str = "incremental", threads: int = 1, *, seed: int | None = None,
             verify: bool = False, canonical: bool = True) -> Mesh:
    """The Delaunay triangulation (``points`` of shape ``(n, 2)``) or tetrahedralization
    (``(n, 3)``), by any registered variant (:func:`variants`); every variant returns the same
    cells, degenerate input included (symbolic perturbation).

    ``threads`` is for the 3D ``parallel`` variant (2D variants are sequential). ``canonical``:
    cells in dtlab's canonical order (each from its smallest id, then sorted), as the ``dtlab``
    command writes them; ``False`` keeps the structure's order (no sort). ``verify``: check the
    result exactly (verify/) into ``mesh.stats["verify"]``. Duplicate points are referenced by no
    cell: ``mesh.stats["duplicates"]`` and ``["duplicate_of"]`` list them. ``mesh.points`` is the
    input array itself when it is C-contiguous float64.
    """
    kwargs = {} if seed is None else {"seed": seed}
    return _mesh(_dtlab.delaunay(points, algo, threads, verify=verify, canonical=canonical, **kwargs))


def constrain(points, segments=None, *, triangles=None, markers=None, holes=None, regions=None,
              method: str | None = None, keep_exterior: bool = False, random_swaps: bool = False,
              remove_cavities: bool = False, verify: bool = False) -> Mesh:
    """A constrained triangulation: 2D ``points`` ``(n, 2)`` with ``segments`` ``(m, 2)``
    (methods ``"cdt"`` (default), ``"swap"``, ``"conforming"``), or 3D ``points`` ``(n, 3)`` with
    ``triangles`` ``(m, 3)`` (a piecewise linear complex; methods ``"conforming"`` (default),
    ``"cdt"``, ``"recover"``, ...: :func:`variants`).

    ``markers``: one int per segment / triangle, carried to ``mesh.boundary_refs``; ``holes``:
    points ``(h, d)`` whose region is removed; ``regions``: rows ``(x, y[, z], attribute)`` giving
    their region the attribute (``mesh.cell_refs``). ``mesh.boundary_cells`` are the constrained
    edges (2D) or the input triangles' pieces (3D), ``mesh.stats["boundary_sources"]`` the input
    segment / triangle each comes from. Steiner points follow the input points in
    ``mesh.points``. ``verify``: exact check into ``mesh.stats["verify"]``.
    """
    if (segments is None) == (triangles is None):
        raise InputError("constrain: give segments (2D) or triangles (3D)")
    constraints = segments if segments is not None else triangles
    return _mesh(_dtlab.constrain(points, constraints, markers=markers, holes=holes, regions=regions,
                                  method=method or "", keep_exterior=keep_exterior, random_swaps=random_swaps,
                                  remove_cavities=remove_cavities, verify=verify))


def mesh(points, segments, *, markers=None, holes=None, regions=None, size=None, metric=None,
         background=None, method: str = "edge", interpolation: str = "sizes", optimize: bool = True,
         keep_boundary: bool = False, max_elements: int = 0, verify: bool = False) -> Mesh:
    """A 2D mesh of the domain bounded by ``segments`` (the boundary discretisation), governed by

    * nothing: the classical sizes, from the boundary discretisation;
    * ``size``: a number (uniform size), or one size per point (of ``points``, or of
      ``background``);
    * ``metric``: one ``(m11, m12, m22)`` row per point (of ``points`` or of ``background``);

    ``background``: ``(points, triangles)`` of a background mesh carrying the sizes / metric.
    ``method``: ``"edge"`` (the edge method) or ``"front"`` (advancing front). The result has the
    domain's triangles with their regions, the boundary edges with their markers, and
    ``point_data["metric"]``. ``verify``: exact check into ``mesh.stats["verify"]``.

    With a size or metric, the segments longer than sqrt 2 in it are cut anew (``keep_boundary``
    keeps them as given). ``max_elements``: refuse, before any work, a size or metric that asks
    for more triangles (0: half this machine's memory at the bytes a triangle costs).
    """
    bp = bt = None
    if background is not None:
        bp, bt = background
    return _mesh(_dtlab.mesh(points, segments, markers=markers, holes=holes, regions=regions, size=_size(size),
                             metric=metric, background_points=bp, background_triangles=bt, method=method,
                             interpolation=interpolation, optimize=optimize, keep_boundary=keep_boundary,
                             max_elements=max_elements, verify=verify))


def optimize(mesh_or_points, cells=None, *, cell_refs=None, boundary_cells=None, boundary_refs=None,
             size=None, metric=None, max_rounds: int = 8, shape_only: bool = False,
             boundary_splits: bool = False, valence: bool = False) -> Mesh:
    """Optimizes a 2D triangle mesh (a :class:`Mesh`, or ``points`` and ``cells``) toward a unit
    mesh in ``size`` (a number or one per point) or ``metric`` (``(n, 3)``); by default the
    metric the mesh implies (mean edge length at each vertex). Swaps, relocation, collapses and
    splits (``shape_only``: swaps and relocation only); the boundary (``boundary_cells``, plus
    every edge with one triangle) is kept. ``stats`` has the counts and the worst / mean Q_K
    before and after.
    """
    if isinstance(mesh_or_points, Mesh):
        m = mesh_or_points
        if m.dim != 2:
            raise InputError("optimize: a 2D mesh is required")
        points, cells = m.points, m.cells
        cell_refs = m.cell_refs if cell_refs is None else cell_refs
        boundary_cells = m.boundary_cells if boundary_cells is None else boundary_cells
        boundary_refs = m.boundary_refs if boundary_refs is None else boundary_refs
    else:
        points = mesh_or_points
    return _mesh(_dtlab.optimize(points, cells, cell_refs=cell_refs, boundary_cells=boundary_cells,
                                 boundary_refs=boundary_refs, size=_size(size), metric=metric,
                                 max_rounds=max_rounds, shape_only=shape_only, boundary_splits=boundary_splits,
                                 valence=valence))


def quality(mesh_or_points, cells=None, *, metric=None) -> dict:
    """The quality report of ``dtlab quality`` (mesh/mesh_quality.hpp): counts, Q_K worst / mean
    and the book's bins, angles, edge lengths, and with ``metric`` (one size or tensor per point)
    metric lengths, unit-edge share and mean ratio; undefined figures are ``None``."""
    points, cells = _points_cells(mesh_or_points, cells)
    return _dtlab.quality(points, cells, metric)


def element_quality(mesh_or_points, cells=None) -> np.ndarray:
    """Q_K of each cell (1 = equilateral, ``inf`` = flat), as a float64 array."""
    points, cells = _points_cells(mesh_or_points, cells)
    return _dtlab.element_quality(points, cells)


def verify(mesh_or_points, cells=None, *, duplicates=None) -> dict:
    """Exact check that ``cells`` are the Delaunay triangulation / tetrahedralization of
    ``points`` (verify/checks2d.hpp, checks3d.hpp): ``{"ok": ..., "problem_count": ...,
    "counts": {...}, "problems": [...]}``. For a Mesh made by :func:`constrain` or :func:`mesh`
    with ``verify=True`` it returns the report made then (the constrained checks)."""
    if isinstance(mesh_or_points, Mesh):
        m = mesh_or_points
        if "verify" in m.stats:
            return m.stats["verify"]
        if duplicates is None:
            duplicates = m.stats.get("duplicates")
        return _dtlab.verify(m.points, m.cells, duplicates)
    return _dtlab.verify(mesh_or_points, cells, duplicates)


def read_medit(path: str) -> Mesh:
    """A Medit ``.mesh`` file read by dtlab's reader (2D or 3D from its Dimension);
    ``point_data["ref"]`` holds the vertex references."""
    with open(path, "rb") as f:
        head = f.read(4096).decode("ascii", "replace")
    found = re.search(r"Dimension\s+(\d)", head)
    dim = int(found.group(1)) if found else 2
    r = _dtlab.read_medit(str(path), dim)
    return Mesh(r["points"], r["cells"], r["cell_refs"], r["boundary_cells"], r["boundary_refs"],
                point_data={"ref": r["point_refs"]})


def _points_cells(mesh_or_points, cells):
    if isinstance(mesh_or_points, Mesh):
        return mesh_or_points.points, mesh_or_points.cells
    if cells is None:
        raise InputError("cells: required with a points array")
    return mesh_or_points, cells
