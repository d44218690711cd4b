// dtlab.quality, dtlab.verify and the Medit .mesh reader and writer on numpy arrays: the
// library's own measures (mesh/mesh_quality.hpp, kernel/quality.hpp), exact checkers (verify/)
// and files (mesh/io/medit*.hpp), the ones the CLI prints and writes.
#include <pybind11/stl.h>

#include "kernel/error.hpp"
#include "kernel/quality.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "mesh/mesh_quality.hpp"
#include "mesh/tetrahedralization3_build.hpp"
#include "python/src/arrays.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks3d.hpp"

namespace dtlab::python {

namespace {

// One metric per point: None (none), sizes (n,) as h^-2 I, or tensors (n, 3) / (n, 6) in
// Medit's order (kernel/metric.hpp).
template <class M>
std::vector<M> metrics(const py::handle& obj, py::ssize_t n) {
  constexpr py::ssize_t k = std::tuple_size_v<decltype(M{}.m)>;
  std::vector<M> out;
  if (obj.is_none()) return out;
  const DoubleArray a = DoubleArray::ensure(obj);
  if (!a) throw InputError("metric: not a float array");
  if (a.ndim() == 1 && a.shape(0) == n) {
    for (py::ssize_t i = 0; i < n; ++i) {
      if (!(a.data()[i] > 0.0)) throw InputError("metric: size not positive at point " + std::to_string(i), {std::uint64_t(i)});
      out.push_back(M::isotropic(a.data()[i]));
    }
    return out;
  }
  if (a.ndim() != 2 || a.shape(0) != n || a.shape(1) != k)
    throw InputError("metric: one size or one row of " + std::to_string(k) + " components per point (" + std::to_string(n) + ")");
  for (py::ssize_t i = 0; i < n; ++i) {
    M m;
    for (py::ssize_t j = 0; j < k; ++j) m.m[static_cast<std::size_t>(j)] = a.data()[i * k + j];
    out.push_back(m);
  }
  return out;
}

py::object quality(const py::handle& points_obj, const py::handle& cells_obj, const py::handle& metric) {
  int dim = 0;
  const DoubleArray points = point_rows(points_obj, dim);
  std::string json;
  if (dim == 2) {
    const IndexArray cells = index_rows(cells_obj, 3, "cells");
    const std::vector<Metric2> m = metrics<Metric2>(metric, points.shape(0));
    py::gil_scoped_release nogil;
    json = quality_json(measure_quality(as_points<Vec2>(points), as_cells<3>(cells), m));
  } else {
    const IndexArray cells = index_rows(cells_obj, 4, "cells");
    const std::vector<Metric3> m = metrics<Metric3>(metric, points.shape(0));
    py::gil_scoped_release nogil;
    json = quality_json(measure_quality(as_points<Vec3>(points), as_cells<4>(cells), m));
  }
  return parse_json(json);
}

// Q_K per element (kernel/quality.hpp): 1 for the equilateral element, +inf for a flat one.
py::array element_quality(const py::handle& points_obj, const py::handle& cells_obj) {
  int dim = 0;
  const DoubleArray points = point_rows(points_obj, dim);
  const py::ssize_t n = points.shape(0);
  const IndexArray cells = index_rows(cells_obj, dim + 1, "cells");
  const std::uint32_t* c = cells.data();
  for (py::ssize_t i = 0; i < cells.shape(0) * (dim + 1); ++i)
    if (c[i] >= n) throw InputError("cells: vertex id out of range in cell " + std::to_string(i / (dim + 1)), {std::uint64_t(i / (dim + 1))});
  std::vector<double> q(static_cast<std::size_t>(cells.shape(0)));
  {
    py::gil_scoped_release nogil;
    if (dim == 2) {
      const auto p = as_points<Vec2>(points);
      for (std::size_t t = 0; t < q.size(); ++t) q[t] = shape_quality(p[c[3 * t]], p[c[3 * t + 1]], p[c[3 * t + 2]]);
    } else {
      const auto p = as_points<Vec3>(points);
      for (std::size_t t = 0; t < q.size(); ++t)
        q[t] = shape_quality(p[c[4 * t]], p[c[4 * t + 1]], p[c[4 * t + 2]], p[c[4 * t + 3]]);
    }
  }
  return adopt<double>(std::move(q), 0);
}

py::object verify(const py::handle& points_obj, const py::handle& cells_obj, const py::handle& duplicates_obj) {
  int dim = 0;
  const DoubleArray points = point_rows(points_obj, dim);
  std::vector<std::uint32_t> duplicates;
  if (!duplicates_obj.is_none()) {
    const IndexArray d = index_rows(py::array::ensure(duplicates_obj).attr("reshape")(-1, 1), 1, "duplicates");
    duplicates.assign(d.data(), d.data() + d.shape(0));
  }
  std::string json;
  if (dim == 2) {
    const IndexArray cells = index_rows(cells_obj, 3, "cells");
    py::gil_scoped_release nogil;
    json = to_json(verify_delaunay2d(as_points<Vec2>(points), as_cells<3>(cells), duplicates));
  } else {
    const IndexArray cells = index_rows(cells_obj, 4, "cells");
    py::gil_scoped_release nogil;
    const auto p = as_points<Vec3>(points);
    const Tetrahedralization3 t = tetrahedralization_from_tetrahedra(std::vector<Vec3>(p.begin(), p.end()), as_cells<4>(cells));
    json = to_json(verify_delaunay3d(p, t, duplicates));
  }
  return parse_json(json);
}

template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> cell_vector(const py::handle& obj, const char* what) {
  const IndexArray a = index_rows(obj, K, what);
  const auto s = as_cells<K>(a);
  return {s.begin(), s.end()};
}

std::vector<int> refs_or_zeros(const py::handle& obj, std::size_t m, const char* what) {
  std::vector<int> r = int_values(obj, static_cast<py::ssize_t>(m), what);
  if (r.empty()) r.assign(m, 0);
  return r;
}

void write_medit(const std::string& path, const py::handle& points_obj, const py::handle& cells, const py::handle& cell_refs,
                 const py::handle& boundary, const py::handle& boundary_refs, const py::handle& point_refs) {
  int dim = 0;
  const DoubleArray points = point_rows(points_obj, dim);
  if (dim == 2) {
    MeshData2 d;
    const auto p = as_points<Vec2>(points);
    d.vertices.assign(p.begin(), p.end());
    d.vertex_refs = refs_or_zeros(point_refs, d.vertices.size(), "point_refs");
    d.triangles = cell_vector<3>(cells, "cells");
    d.triangle_refs = refs_or_zeros(cell_refs, d.triangles.size(), "cell_refs");
    d.edges = cell_vector<2>(boundary, "boundary_cells");
    d.edge_refs = refs_or_zeros(boundary_refs, d.edges.size(), "boundary_refs");
    py::gil_scoped_release nogil;
    StagedOutputs outputs({path});  // as the command line: a folder that is missing is named
    outputs.write(path, [&](const std::string& to) { write_medit2(to, d); });
    outputs.commit();
  } else {
    MeshData3 d;
    const auto p = as_points<Vec3>(points);
    d.vertices.assign(p.begin(), p.end());
    d.vertex_refs = refs_or_zeros(point_refs, d.vertices.size(), "point_refs");
    d.tetrahedra = cell_vector<4>(cells, "cells");
    d.tetrahedron_refs = refs_or_zeros(cell_refs, d.tetrahedra.size(), "cell_refs");
    d.triangles = cell_vector<3>(boundary, "boundary_cells");
    d.triangle_refs = refs_or_zeros(boundary_refs, d.triangles.size(), "boundary_refs");
    py::gil_scoped_release nogil;
    StagedOutputs outputs({path});
    outputs.write(path, [&](const std::string& to) { write_medit3(to, d); });
    outputs.commit();
  }
}

py::dict read_medit(const std::string& path, int dim) {
  py::dict out;
  if (dim == 2) {
    MeshData2 d;
    {
      py::gil_scoped_release nogil;
      d = read_medit2(path);
    }
    out["points"] = adopt<double>(std::move(d.vertices), 2);
    out["point_refs"] = adopt<std::int32_t>(std::move(d.vertex_refs), 0);
    out["cells"] = adopt<std::uint32_t>(std::move(d.triangles), 3);
    out["cell_refs"] = adopt<std::int32_t>(std::move(d.triangle_refs), 0);
    out["boundary_cells"] = adopt<std::uint32_t>(std::move(d.edges), 2);
    out["boundary_refs"] = adopt<std::int32_t>(std::move(d.edge_refs), 0);
  } else {
    MeshData3 d;
    {
      py::gil_scoped_release nogil;
      d = read_medit3(path);
    }
    out["points"] = adopt<double>(std::move(d.vertices), 3);
    out["point_refs"] = adopt<std::int32_t>(std::move(d.vertex_refs), 0);
    out["cells"] = adopt<std::uint32_t>(std::move(d.tetrahedra), 4);
    out["cell_refs"] = adopt<std::int32_t>(std::move(d.tetrahedron_refs), 0);
    out["boundary_cells"] = adopt<std::uint32_t>(std::move(d.triangles), 3);
    out["boundary_refs"] = adopt<std::int32_t>(std::move(d.triangle_refs), 0);
  }
  return out;
}

}  // namespace

void bind_measures(py::module_& m) {
  m.def("quality", &quality, py::arg("points"), py::arg("cells"), py::arg("metric") = py::none());
  m.def("element_quality", &element_quality, py::arg("points"), py::arg("cells"));
  m.def("verify", &verify, py::arg("points"), py::arg("cells"), py::arg("duplicates") = py::none());
  m.def("write_medit", &write_medit, py::arg("path"), py::arg("points"), py::arg("cells"), py::arg("cell_refs") = py::none(),
        py::arg("boundary_cells") = py::none(), py::arg("boundary_refs") = py::none(), py::arg("point_refs") = py::none());
  m.def("read_medit", &read_medit, py::arg("path"), py::arg("dim"));
}

}  // namespace dtlab::python
