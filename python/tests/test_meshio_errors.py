"""Mesh.to_meshio / from_meshio round trips (points bit for bit, cells and references kept) through
the formats meshio writes, meshio reading dtlab's own Medit files, and the error contract: bad
input of any kind is a dtlab.InputError (or a TypeError for a non-array), never a crash."""

import numpy as np
import pytest
from hypothesis import given, strategies as st
from hypothesis.extra import numpy as hnp

import dtlab

meshio = pytest.importorskip("meshio")


def sample_2d():
    from test_constrain_mesh import HOLES, MARKERS, POINTS, REGIONS, SEGMENTS
    return dtlab.constrain(POINTS, SEGMENTS, markers=MARKERS, holes=HOLES, regions=REGIONS)


def sample_3d():
    from test_constrain_mesh import CUBE, CUBE_TRIANGLES
    return dtlab.constrain(CUBE, triangles=CUBE_TRIANGLES, markers=np.arange(12) + 1)


@pytest.mark.parametrize("make", [sample_2d, sample_3d], ids=["2d", "3d"])
@pytest.mark.parametrize("ext,ref_name", [(".vtu", "ref"), (".mesh", "medit:ref"), (".msh", "gmsh:physical")])
def test_meshio_round_trip(tmp_path, make, ext, ref_name):
    m = make()
    path = tmp_path / f"m{ext}"
    out = m.to_meshio(ref_name=ref_name)
    if ext == ".msh":
        out.cell_data["gmsh:geometrical"] = out.cell_data[ref_name]
        meshio.write(path, out, file_format="gmsh22", binary=False)
    else:
        meshio.write(path, out)
    back = dtlab.Mesh.from_meshio(meshio.read(path))
    assert back.dim == m.dim
    if ext == ".vtu":  # binary: bit for bit
        assert back.points.tobytes() == m.points.tobytes()
    else:
        np.testing.assert_allclose(back.points, m.points, rtol=1e-15, atol=0)
    np.testing.assert_array_equal(back.cells, m.cells)
    np.testing.assert_array_equal(back.cell_refs, m.cell_refs)
    np.testing.assert_array_equal(back.boundary_cells, m.boundary_cells)
    np.testing.assert_array_equal(back.boundary_refs, m.boundary_refs)


def test_meshio_reads_dtlab_medit(tmp_path):
    m = sample_2d()
    m.write(tmp_path / "m.mesh")
    r = meshio.read(tmp_path / "m.mesh")
    assert r.points.shape == (len(m.points), 2)
    assert r.points.tobytes() == m.points.tobytes()  # dtlab writes the shortest round-trip text
    back = dtlab.Mesh.from_meshio(r)
    np.testing.assert_array_equal(back.cells, m.cells)
    np.testing.assert_array_equal(back.cell_refs, m.cell_refs)
    again = dtlab.read_medit(tmp_path / "m.mesh")
    np.testing.assert_array_equal(again.boundary_refs, m.boundary_refs)


def test_error_classes(tmp_path):
    assert issubclass(dtlab.InputError, dtlab.Error) and issubclass(dtlab.InputError, ValueError)
    assert issubclass(dtlab.InternalError, RuntimeError)
    with pytest.raises(dtlab.InputError) as e:
        dtlab.delaunay(np.array([[0, 0], [1, 0], [0, 1], [np.inf, 2]]))
    assert e.value.items == [3]
    bad = tmp_path / "bad.mesh"
    bad.write_text("MeshVersionFormatted 2\nDimension 2\nVertices 2\n0 0 0\nEnd\n")
    with pytest.raises(dtlab.ParseError) as e:
        dtlab.read_medit(bad)
    assert e.value.file == str(bad) and e.value.line > 0
    with pytest.raises(dtlab.InputError, match="unknown|algorithm"):
        dtlab.delaunay(np.random.default_rng(0).random((10, 2)), algo="nope")
    with pytest.raises(dtlab.InputError, match="sequential"):
        dtlab.delaunay(np.random.default_rng(0).random((10, 2)), threads=4)


junk = st.one_of(
    hnp.arrays(st.sampled_from([np.float64, np.float32, np.int64, np.int8]), hnp.array_shapes(min_dims=0, max_dims=3, max_side=5)),
    hnp.arrays(np.float64, st.tuples(st.integers(0, 8), st.sampled_from([2, 3])),
               elements=st.sampled_from([0.0, 1.0, -1.0, np.nan, np.inf, 1e300, 1e-300, 5e-324])),
    st.just(None), st.just("text"), st.lists(st.integers(-3, 3), max_size=6),
)


@given(junk, junk)
def test_junk_never_crashes(points, cells):
    for call in (lambda: dtlab.delaunay(points), lambda: dtlab.constrain(points, cells),
                 lambda: dtlab.quality(points, cells), lambda: dtlab.verify(points, cells),
                 lambda: dtlab.predicates.orient2d(points, cells, points), lambda: dtlab.mesh(points, cells, size=0.5)):
        try:
            call()
        except (dtlab.Error, TypeError):
            pass


def test_stubs_cover_the_api():
    import ast
    import pathlib
    stub = pathlib.Path(dtlab.__file__).with_suffix(".pyi")
    names = {n.name for n in ast.parse(stub.read_text()).body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    missing = [n for n in dtlab.__all__ if n not in names and n != "predicates"]
    assert not missing
