"""dtlab.predicates: the stages agree wherever they decide, the filtered predicate equals the GMP
oracle, the single stages leave the hard cases UNDECIDED, and the counters count."""

import numpy as np
import pytest
from hypothesis import given, strategies as st
from hypothesis.extra import numpy as hnp

import dtlab
from dtlab import predicates as P

STAGES = ["semi_static", "dynamic", "expansion"]


def near_collinear(n, seed):
    # c on the line through a and b, rounded: the sign is decided by the last bits.
    rng = np.random.default_rng(seed)
    a, b = rng.random((n, 2)), rng.random((n, 2))
    t = rng.random((n, 1))
    return a, b, a + t * (b - a)


def check_stages(exact, by_stage):
    for stage, s in by_stage.items():
        decided = s != P.UNDECIDED
        np.testing.assert_array_equal(s[decided], exact[decided], err_msg=stage)


def test_orient2d_stages_on_near_collinear_points():
    a, b, c = near_collinear(2000, 1)
    exact = P.orient2d(a, b, c, stage="exact")
    np.testing.assert_array_equal(P.orient2d(a, b, c), exact)
    by_stage = {s: P.orient2d(a, b, c, stage=s) for s in STAGES}
    check_stages(exact, by_stage)
    assert np.any(by_stage["semi_static"] == P.UNDECIDED)      # the filter gives up on these
    assert np.all(by_stage["expansion"] != P.UNDECIDED)


def test_incircle_and_insphere_on_cocircular_points():
    angles = np.random.default_rng(2).random((500, 4)) * 2 * np.pi
    pts = [np.stack([np.cos(angles[:, i]), np.sin(angles[:, i])], axis=1) for i in range(4)]
    exact = P.incircle(*pts, stage="exact")
    np.testing.assert_array_equal(P.incircle(*pts), exact)
    check_stages(exact, {s: P.incircle(*pts, stage=s) for s in STAGES})
    # Exactly cocircular (a square): zero, and the perturbation decides.
    square = [np.array(p, float) for p in ([0, 0], [1, 0], [1, 1], [0, 1])]
    assert P.incircle(*square) == 0
    assert P.incircle(*square, perturbed=True) in (-1, 1)
    cube = [np.array(p, float) for p in ([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1])]
    assert P.insphere(*cube) == 0 and P.insphere(*cube, stage="exact") == 0
    assert P.insphere(*cube, perturbed=True) in (-1, 1)


@given(hnp.arrays(np.float64, (5, 3), elements=st.integers(-4, 4).map(float)),
       st.sampled_from(STAGES + ["exact"]))
def test_orient3d_insphere_small_integers(pts, stage):
    a, b, c, d, e = pts
    s3, e3 = P.orient3d(a, b, c, d, stage=stage), P.orient3d(a, b, c, d, stage="exact")
    assert s3 in (e3, P.UNDECIDED)
    s5, e5 = P.insphere(a, b, c, d, e, stage=stage), P.insphere(a, b, c, d, e, stage="exact")
    assert s5 in (e5, P.UNDECIDED)
    assert P.orient3d(a, b, c, d) == e3 and P.insphere(a, b, c, d, e) == e5


def test_broadcast_and_scalar_results():
    c = np.array([[0, 1], [2, 0], [0, -1]], float)
    np.testing.assert_array_equal(P.orient2d([0, 0], [1, 0], c), [1, 0, -1])
    assert isinstance(P.orient2d([0, 0], [1, 0], [0, 1]), int)
    assert P.orient2d([0, 0], [1, 0], c).dtype == np.int8


def test_counters():
    P.reset_stats()
    a, b, c = near_collinear(1000, 3)
    P.orient2d(a, b, c)
    s = P.stats()["orient2d"]
    assert s["calls"] == 1000 and s["semistatic"] + s["adaptive"] + s["exact"] == 1000
    assert s["adaptive"] + s["exact"] > 0
    P.orient2d(a, b, c, stage="exact")  # single stages are not counted
    assert P.stats()["orient2d"]["calls"] == 1000
    P.reset_stats()
    assert P.stats()["orient2d"]["calls"] == 0
    m = dtlab.delaunay(np.random.default_rng(0).random((100, 2)))
    assert P.stats()["incircle"]["calls"] == m.stats["predicates"]["incircle"]["calls"] > 0


def test_bad_arguments_are_input_errors():
    with pytest.raises(dtlab.InputError, match="stage"):
        P.orient2d([0, 0], [1, 0], [0, 1], stage="fast")
    with pytest.raises(dtlab.InputError, match="argument b"):
        P.orient2d([0, 0], [np.nan, 0], [0, 1])
    with pytest.raises(dtlab.InputError):
        P.orient2d(np.zeros((3, 2)), np.zeros((4, 2)), np.zeros((3, 2)))
    with pytest.raises(dtlab.InputError):
        P.orient3d([0, 0], [1, 0], [0, 1], [1, 1])
