"""dtlab.constrain (2D and 3D), dtlab.mesh and dtlab.optimize: exactly verified results with the
markers and regions carried, the same bytes as `dtlab mesh` / `dtlab optimize`, and errors that
name the offending items."""

import subprocess

import numpy as np
import pytest

import dtlab

# A square [0,4]^2 (markers 1) with a square hole [1,2]^2 (marker 2) and two crossing segments in
# the right half (marker 3); a region seed in the right half.
POINTS = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [2, 1], [2, 2], [1, 2],
                   [2.5, 0.5], [3.5, 3.5], [2.5, 3.5], [3.5, 0.5]], float)
SEGMENTS = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [8, 9], [10, 11]])
MARKERS = np.array([1, 1, 1, 1, 2, 2, 2, 2, 3, 3])
HOLES = np.array([[1.5, 1.5]])
REGIONS = np.array([[3.9, 2.0, 5]])


@pytest.mark.parametrize("method", [name for name, _ in dtlab.variants()["constrained2d"]])
def test_constrain_2d(method):
    m = dtlab.constrain(POINTS, SEGMENTS, markers=MARKERS, holes=HOLES, regions=REGIONS, method=method, verify=True)
    assert m.stats["verify"]["ok"], m.stats["verify"]["problems"][:5]
    assert m.stats["crossing_steiner_points"] == 1 and len(m.points) >= len(POINTS) + 1
    np.testing.assert_array_equal(m.points[:len(POINTS)], POINTS)
    assert set(m.boundary_refs.tolist()) == {1, 2, 3}
    assert 5 in set(m.cell_refs.tolist())
    # Nothing inside the hole: no triangle has its centroid there.
    centroids = m.points[m.cells].mean(axis=1)
    assert not np.any(np.all((centroids > 1) & (centroids < 2), axis=1))
    area = dtlab.quality(m)["area"]
    assert area == pytest.approx(16 - 1)


def test_constrain_errors_name_the_items():
    with pytest.raises(dtlab.InputError) as e:
        dtlab.constrain(POINTS, np.array([[0, 1], [1, 99]]))
    assert e.value.items == [1]
    with pytest.raises(dtlab.InputError) as e:
        dtlab.constrain(POINTS, np.array([[0, 1], [2, 2], [1, 2]]))
    assert e.value.items == [1]
    with pytest.raises(dtlab.InputError) as e:
        dtlab.constrain(POINTS, np.array([[0, 1], [1, -1]]))
    assert e.value.items == [1]
    with pytest.raises(dtlab.InputError):
        dtlab.constrain(POINTS, SEGMENTS, markers=[1, 2])
    assert isinstance(e.value, ValueError) and isinstance(e.value, dtlab.Error)


CUBE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
CUBE_TRIANGLES = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                           [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])


@pytest.mark.parametrize("method", [name for name, _ in dtlab.variants()["constrained3d"]])
def test_constrain_3d_cube(method):
    inner = CUBE * 0.5 + 0.25 + np.array([0.01, 0.02, 0.03])  # a nested cube: two regions
    points = np.vstack([CUBE, inner])
    triangles = np.vstack([CUBE_TRIANGLES, CUBE_TRIANGLES + 8])
    refs = np.repeat([1, 2], 12)
    m = dtlab.constrain(points, triangles=triangles, markers=refs, method=method, verify=True)
    assert m.stats["verify"]["ok"], m.stats["verify"]["problems"][:5]
    assert m.dim == 3 and m.cells.shape[1] == 4
    assert set(m.boundary_refs.tolist()) == {1, 2}
    assert m.stats["region_count"] == 2
    assert dtlab.quality(m)["volume"] == pytest.approx(1.0)


@pytest.mark.parametrize("method", [name for name, _ in dtlab.variants()["constrained2d"]])
def test_constrain_2d_same_bytes_as_cli(cli, tmp_path, method):
    write_poly(tmp_path / "in.poly", POINTS, SEGMENTS, MARKERS, HOLES)
    subprocess.run([cli, "constrain", str(tmp_path / "in.poly"), "--method", method, "-o", str(tmp_path / "cli.mesh")],
                   check=True, capture_output=True)
    dtlab.constrain(POINTS, SEGMENTS, markers=MARKERS, holes=HOLES, method=method).write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()


@pytest.mark.parametrize("method", [name for name, _ in dtlab.variants()["constrained3d"]])
def test_constrain_3d_same_bytes_as_cli(cli, tmp_path, method):
    inner = CUBE * 0.5 + 0.25 + np.array([0.01, 0.02, 0.03])
    points, triangles = np.vstack([CUBE, inner]), np.vstack([CUBE_TRIANGLES, CUBE_TRIANGLES + 8])
    refs = np.repeat([1, 2], 12)
    # The surface as a Medit file (no tetrahedra): the CLI's input.
    dtlab.Mesh(points, np.zeros((0, 4), np.uint32), None, triangles, refs).write(tmp_path / "surface.mesh")
    subprocess.run([cli, "constrain", str(tmp_path / "surface.mesh"), "--method", method, "-o", str(tmp_path / "cli.mesh")],
                   check=True, capture_output=True)
    dtlab.constrain(points, triangles=triangles, markers=refs, method=method).write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()


def write_poly(path, points, segments, markers, holes):
    lines = [f"{len(points)} 2 0 0"] + [f"{i} {x!r} {y!r}" for i, (x, y) in enumerate(points.tolist())]
    lines += [f"{len(segments)} 1"] + [f"{i} {a} {b} {k}" for i, ((a, b), k) in enumerate(zip(segments.tolist(), markers))]
    lines += [f"{len(holes)}"] + [f"{i} {x!r} {y!r}" for i, (x, y) in enumerate(holes.tolist())]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("method", ["edge", "front"])
def test_mesh_same_bytes_as_cli(cli, tmp_path, method):
    points, segments, markers = POINTS[:8], SEGMENTS[:8], MARKERS[:8]
    write_poly(tmp_path / "in.poly", points, segments, markers, HOLES)
    subprocess.run([cli, "mesh", str(tmp_path / "in.poly"), "--size", "0.25", "--method", method,
                    "-o", str(tmp_path / "cli.mesh")], check=True, capture_output=True)
    m = dtlab.mesh(points, segments, markers=markers, holes=HOLES, size=0.25, method=method,
                   verify=True)
    assert m.stats["verify"]["ok"], m.stats["verify"]["problems"][:5]
    m.write(tmp_path / "py.mesh")
    cli_mesh = dtlab.read_medit(tmp_path / "cli.mesh")
    np.testing.assert_array_equal(m.points, cli_mesh.points)
    np.testing.assert_array_equal(m.cells, cli_mesh.cells)
    np.testing.assert_array_equal(m.boundary_refs, cli_mesh.boundary_refs)
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()
    q = m.quality(metric="own")
    assert q["quality_worst"] < 3 and q["unit_edge_share"] > 0.9


def test_mesh_classical_and_anisotropic():
    points, segments = POINTS[:4], SEGMENTS[:4]
    classical = dtlab.mesh(points, segments, verify=True)
    assert classical.stats["verify"]["ok"]
    # An anisotropic metric at the four corners: sizes 0.5 along x, 0.1 along y.
    metric = np.tile([1 / 0.5**2, 0.0, 1 / 0.1**2], (4, 1))
    aniso = dtlab.mesh(points, segments, metric=metric, verify=True)
    assert aniso.stats["verify"]["ok"]
    assert aniso.quality(metric="own")["unit_edge_share"] > 0.8
    assert len(aniso.cells) > 4 * len(classical.cells)
    with pytest.raises(dtlab.InputError):
        dtlab.mesh(points, segments, metric=np.tile([1.0, 2.0, 1.0], (4, 1)))  # not positive definite
    # keep_boundary keeps the 4 sides, each longer than sqrt 2 in the metric, and says so.
    kept = dtlab.mesh(points, segments, metric=metric, keep_boundary=True)
    assert kept.stats["long_boundary_segments"] == 4 and kept.stats["boundary_points"] == 0
    assert aniso.stats["long_boundary_segments"] == 0 and aniso.stats["boundary_points"] > 0
    with pytest.raises(dtlab.InputError, match="keep_boundary needs a size"):
        dtlab.mesh(points, segments, keep_boundary=True)


def test_mesh_element_limit():
    # Issue 42, item 4: a size whose triangle count is past the limit is refused at once, by name.
    points, segments = POINTS[:4], SEGMENTS[:4]
    with pytest.raises(dtlab.InputError, match=r"asks for about [0-9.e+]+ triangles"):
        dtlab.mesh(points, segments, size=1e-9)
    with pytest.raises(dtlab.InputError, match="limit of 100 "):
        dtlab.mesh(points, segments, size=0.05, max_elements=100)
    assert len(dtlab.mesh(points, segments, size=0.05, max_elements=100000).cells) > 100


def test_optimize_same_as_cli(cli, tmp_path):
    rng = np.random.default_rng(4)
    points = np.vstack([[[0, 0], [1, 0], [1, 1], [0, 1]], rng.random((300, 2))])
    start = dtlab.delaunay(points)
    start.write(tmp_path / "in.mesh")
    subprocess.run([cli, "optimize", str(tmp_path / "in.mesh"), "--size", "0.1", "-o", str(tmp_path / "cli.mesh")],
                   check=True, capture_output=True)
    m = dtlab.optimize(dtlab.read_medit(tmp_path / "in.mesh"), size=0.1)
    m.write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()
    assert m.stats["worst_after"] < m.stats["worst_before"]
    assert dtlab.quality(m)["inverted"] == 0 and dtlab.quality(m)["area"] == pytest.approx(1.0)


@pytest.mark.parametrize("size", [0.1, None])
@pytest.mark.parametrize("points", [np.zeros((0, 2)), np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])],
                         ids=["no_points", "no_triangles"])
def test_optimize_empty_mesh_is_refused(points, size):
    # Killed the interpreter (an empty vector's front()); now refused by argument name.
    with pytest.raises(dtlab.InputError, match=r"^cells: no triangles"):
        dtlab.optimize(points, np.zeros((0, 3), int), size=size)


def test_write_to_a_missing_folder_is_refused(tmp_path):
    # The library's staged outputs, as on the command line: the path named, nothing left behind.
    m = dtlab.constrain(POINTS, SEGMENTS, markers=MARKERS, holes=HOLES, regions=REGIONS)
    with pytest.raises(dtlab.InputError, match=r"cannot write '.*nodir/m\.mesh': no folder"):
        m.write(str(tmp_path / "nodir" / "m.mesh"))
    m.write(str(tmp_path / "m.mesh"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.mesh"]


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_points_are_named_by_array_row_and_column(bad):
    # Issue 42, item 7: optimize called a NaN coordinate "triangle 1 is not strictly
    # counter-clockwise", verify reported a problem, element_quality returned NaN.
    points = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    cells = np.array([[0, 1, 2], [0, 2, 3]])
    points[2, 1] = bad
    square = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    calls = {
        "delaunay": lambda: dtlab.delaunay(points),
        "constrain": lambda: dtlab.constrain(points, square),
        "mesh": lambda: dtlab.mesh(points, square, size=0.5),
        "optimize": lambda: dtlab.optimize(points, cells),
        "quality": lambda: dtlab.quality(points, cells),
        "element_quality": lambda: dtlab.element_quality(points, cells),
        "verify": lambda: dtlab.verify(points, cells),
    }
    for name, call in calls.items():
        with pytest.raises(dtlab.InputError, match=r"^points: row 2, column 1 is -?(nan|inf)") as e:
            call()
        assert e.value.items == [2], name
    good = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    holes = np.array([[0.5, 0.5], [0.2, bad]])
    with pytest.raises(dtlab.InputError, match=r"^holes: row 1, column 1 is"):
        dtlab.mesh(good, square, holes=holes, size=0.5)
    points3 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, bad]], float)
    with pytest.raises(dtlab.InputError, match=r"^points: row 3, column 2 is"):
        dtlab.quality(points3, np.array([[0, 1, 2, 3]]))
