"""dtlab.delaunay: the same bytes as the `dtlab delaunay` command, every variant the same cells,
exact verification, and scipy.spatial.Delaunay (Qhull) as an independent comparison: equal on
general-position input, wrong or merged on near-degenerate input where dtlab stays exact."""

import subprocess

import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, settings, strategies as st
from hypothesis.extra import numpy as hnp

import dtlab

ALGOS_2D = [name for name, _ in dtlab.variants()["delaunay2d"]]
ALGOS_3D = [name for name, _ in dtlab.variants()["delaunay3d"]]


def write_points(path, points):
    # repr() is the shortest text that reads back to the same double: the CLI gets the same points.
    path.write_text("".join(" ".join(repr(float(x)) for x in row) + "\n" for row in points))


@pytest.mark.parametrize("algo", ALGOS_2D)
def test_cli_same_bytes_2d(cli, tmp_path, algo):
    points = np.random.default_rng(7).random((2000, 2))
    points[100:150] = points[:50]  # duplicates
    write_points(tmp_path / "p.txt", points)
    subprocess.run([cli, "delaunay", str(tmp_path / "p.txt"), "--algo", algo, "-o", str(tmp_path / "cli.mesh")],
                   check=True, capture_output=True)
    m = dtlab.delaunay(points, algo=algo)
    m.write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()
    assert list(m.stats["duplicates"]) == list(range(100, 150))


@pytest.mark.parametrize("algo", ALGOS_3D)
def test_cli_same_bytes_3d(cli, tmp_path, algo):
    points = np.random.default_rng(8).random((1500, 3))
    write_points(tmp_path / "p.txt", points)
    extra = ["--threads", "2"] if algo == "parallel" else []
    subprocess.run([cli, "delaunay", str(tmp_path / "p.txt"), "--algo", algo, "-o", str(tmp_path / "cli.mesh")] + extra,
                   check=True, capture_output=True)
    m = dtlab.delaunay(points, algo=algo, threads=2 if algo == "parallel" else 1)
    m.write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()


def test_no_copy_of_float64_input():
    points = np.random.default_rng(1).random((100, 2))
    m = dtlab.delaunay(points)
    assert m.points is points
    assert m.cells.dtype == np.uint32 and m.cells.flags.c_contiguous
    # Other layouts are converted once, not refused.
    m2 = dtlab.delaunay(np.asfortranarray(points.astype(np.float32)))
    assert m2.points.dtype == np.float64


# Coordinates in the supported range (0 or magnitudes 2^-142..2^142; outside it InputError),
# small integers among them so that duplicates and collinear triples are drawn often.
coordinates = st.one_of(st.integers(-8, 8).map(float),
                        st.floats(-1e3, 1e3, allow_nan=False, allow_subnormal=False).filter(lambda x: x == 0 or abs(x) > 1e-40))

points2d = st.one_of(
    hnp.arrays(np.float64, st.tuples(st.integers(3, 60), st.just(2)), elements=coordinates),
    # grids and collinear runs: the degenerate cases of the perturbation
    st.integers(2, 7).map(lambda k: np.array([[i, j] for i in range(k) for j in range(k)], float) * 0.1),
    st.integers(3, 30).map(lambda n: np.array([[i, 2 * i] for i in range(n)], float)),
)


@given(points2d)
def test_every_variant_same_cells_and_exactly_delaunay(points):
    reference = dtlab.delaunay(points, verify=True)
    assert reference.stats["verify"]["ok"] or reference.stats["degenerate_message"], reference.stats["verify"]
    for algo in ALGOS_2D[1:]:
        m = dtlab.delaunay(points, algo=algo)
        np.testing.assert_array_equal(m.cells, reference.cells)


@given(hnp.arrays(np.float64, st.tuples(st.integers(4, 40), st.just(3)), elements=coordinates))
def test_3d_variants_agree(points):
    reference = dtlab.delaunay(points, verify=True)
    assert reference.stats["verify"]["ok"] or reference.stats["degenerate_message"]
    for algo in ALGOS_3D[1:]:
        np.testing.assert_array_equal(dtlab.delaunay(points, algo=algo).cells, reference.cells)


def ccw_canonical(points, simplices):
    """Qhull's triangles turned counter-clockwise (by the exact orient2d) as a set of sorted
    vertex rotations, comparable with dtlab's canonical cells."""
    t = simplices.astype(np.uint32).copy()
    s = dtlab.predicates.orient2d(points[t[:, 0]], points[t[:, 1]], points[t[:, 2]])
    flip = s < 0
    t[flip, 1], t[flip, 2] = t[flip, 2].copy(), t[flip, 1].copy()
    return {tuple(np.roll(row, -int(np.argmin(row)))) for row in t}, t


def strictly_non_delaunay_edges(points, cells):
    """Interior edges whose opposite vertex lies strictly inside the other triangle's
    circumcircle, by the exact (unperturbed) incircle: wrong for any Delaunay triangulation."""
    side = {}
    for k, (a, b, c) in enumerate(cells.tolist()):
        for u, v, w in ((b, c, a), (c, a, b), (a, b, c)):
            side[(u, v)] = (k, w)
    tri, opposite = [], []
    for (u, v), (k, _) in side.items():
        if (v, u) in side:
            tri.append(cells[k])
            opposite.append(side[(v, u)][1])
    if not tri:
        return 0
    tri = np.array(tri)
    s = dtlab.predicates.incircle(points[tri[:, 0]], points[tri[:, 1]], points[tri[:, 2]],
                                  points[np.array(opposite)], stage="exact")
    return int(np.sum(s > 0))


general_position = st.tuples(st.integers(5, 400), st.integers(0, 2**32 - 1)).map(
    lambda a: np.random.default_rng(a[1]).random((a[0], 2)))


@settings(max_examples=30)
@given(general_position)
def test_same_as_scipy_on_general_position(points):
    # Uniform random doubles: general position (no three collinear, no four cocircular) in practice.
    d = scipy.spatial.Delaunay(points)
    assert len(d.coplanar) == 0
    theirs, _ = ccw_canonical(points, d.simplices)
    assert theirs == {tuple(row) for row in dtlab.delaunay(points).cells.tolist()}


def test_scipy_on_uniform_points_equal():
    points = np.random.default_rng(3).random((5000, 2))
    theirs, _ = ccw_canonical(points, scipy.spatial.Delaunay(points).simplices)
    assert theirs == {tuple(row) for row in dtlab.delaunay(points).cells.tolist()}


def test_qhull_wrong_on_a_jittered_grid_dtlab_exact():
    # A 10 x 10 integer grid moved by ~1e-12: every quadruple of a cell is nearly cocircular.
    rng = np.random.default_rng(0)
    points = np.array([[i, j] for i in range(10) for j in range(10)], float) + rng.uniform(-1e-12, 1e-12, (100, 2))
    _, theirs = ccw_canonical(points, scipy.spatial.Delaunay(points).simplices)
    assert strictly_non_delaunay_edges(points, theirs) > 0      # Qhull: edges that are not Delaunay
    ours = dtlab.delaunay(points, verify=True)
    assert strictly_non_delaunay_edges(points, ours.cells) == 0
    assert ours.stats["verify"]["ok"]


def test_qhull_merges_points_of_a_tiny_grid_dtlab_keeps_them():
    # An 8 x 8 grid of spacing 1e-14 at (1, 1): Qhull treats most points as coplanar and leaves
    # them out ("merged"); dtlab triangulates all 64 exactly.
    points = 1.0 + np.array([[i, j] for i in range(8) for j in range(8)], float) * 1e-14
    d = scipy.spatial.Delaunay(points)
    assert len(d.coplanar) > 0
    assert len(np.unique(d.simplices)) < len(points)
    ours = dtlab.delaunay(points, verify=True)
    assert ours.stats["verify"]["ok"]
    assert len(np.unique(ours.cells)) == len(points)
    assert len(ours.cells) == 2 * (7 * 7)


def test_degenerate_input_gives_no_cells_and_a_message():
    m = dtlab.delaunay(np.array([[0, 0], [1, 1], [2, 2.0]]))
    assert len(m.cells) == 0 and "collinear" in m.stats["degenerate_message"]


def test_threads_give_the_same_cells():
    from concurrent.futures import ThreadPoolExecutor
    sets = [np.random.default_rng(s).random((3000, 3)) for s in range(4)]
    with ThreadPoolExecutor(4) as pool:
        meshes = list(pool.map(dtlab.delaunay, sets))
    for p, m in zip(sets, meshes):
        np.testing.assert_array_equal(m.cells, dtlab.delaunay(p, algo="parallel", threads=2).cells)


def test_gil_released_during_a_long_call():
    import threading
    import time
    points = np.random.default_rng(5).random((400000, 2))
    span = {}

    def work():
        span["start"] = time.perf_counter()
        dtlab.delaunay(points, canonical=False)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    duration = span["end"] - span["start"]
    inside = [t for t in ticks if span["start"] < t < span["end"]]
    # With the GIL held for the call, this thread would stall for all of it.
    gaps = np.diff([span["start"]] + inside + [span["end"]])
    assert len(inside) > 100 and gaps.max() < duration / 2, (duration, gaps.max(), len(inside))
