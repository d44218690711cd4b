// dtlab.mesh and dtlab.optimize: 2D mesh generation governed by sizes or a metric
// (algorithms/mesh2d) and 2D optimization (algorithms/optimize2d) on numpy arrays, set up as the
// `dtlab mesh` and `dtlab optimize` commands set them up (apps/mesh.cpp, apps/optimize.cpp), so
// that the same input gives the same mesh from Python and from the shell.
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>

#include "algorithms/mesh2d/control_space.hpp"
#include "mesh/implied_metrics.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "python/src/arrays.hpp"
#include "verify/checks_mesh2d.hpp"

namespace dtlab::python {

namespace {

// Metrics at n vertices: sizes (n,) as h^-2 I, or tensors (n, 3) as (m11, m12, m22); empty for None.
std::vector<Metric2> metrics_at(const py::handle& sizes, const py::handle& tensors, py::ssize_t n) {
  std::vector<Metric2> out;
  if (!sizes.is_none() && !tensors.is_none()) throw InputError("give sizes or metric, not both");
  if (!sizes.is_none()) {
    const auto a = DoubleArray::ensure(sizes);
    if (!a || a.ndim() != 1 || a.shape(0) != n)
      throw InputError("size: a number, or one size per vertex (" + std::to_string(n) + ")");
    for (py::ssize_t i = 0; i < n; ++i) {
      const double h = a.data()[i];
      if (!(h > 0.0) || !std::isfinite(h)) throw InputError("size: not a positive finite size at vertex " + std::to_string(i), {std::uint64_t(i)});
      out.push_back(Metric2::isotropic(h));
    }
  } else if (!tensors.is_none()) {
    const DoubleArray a = double_rows(tensors, 3, "metric");
    if (a.shape(0) != n) throw InputError("metric: one (m11, m12, m22) row per vertex (" + std::to_string(n) + ")");
    for (py::ssize_t i = 0; i < n; ++i) {
      Metric2 m{{a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]}};
      if (!m.is_positive_definite())
        throw InputError("metric: not positive definite at vertex " + std::to_string(i), {std::uint64_t(i)});
      out.push_back(m);
    }
  }
  return out;
}

MeshData2 mesh_data(const DoubleArray& points, const IndexArray& triangles, const std::vector<int>& triangle_refs,
                    const IndexArray& edges, const std::vector<int>& edge_refs) {
  MeshData2 d;
  const auto p = as_points<Vec2>(points);
  d.vertices.assign(p.begin(), p.end());
  d.vertex_refs.assign(d.vertices.size(), 0);
  const auto t = as_cells<3>(triangles);
  d.triangles.assign(t.begin(), t.end());
  d.triangle_refs = triangle_refs.empty() ? std::vector<int>(d.triangles.size(), 0) : triangle_refs;
  const auto e = as_cells<2>(edges);
  d.edges.assign(e.begin(), e.end());
  d.edge_refs = edge_refs.empty() ? std::vector<int>(d.edges.size(), 0) : edge_refs;
  return d;
}

py::dict mesh_result(MeshData2&& data, std::vector<Metric2>&& metrics, py::dict stats) {
  py::dict out;
  std::vector<std::array<double, 3>> m;
  m.reserve(metrics.size());
  for (const Metric2& x : metrics) m.push_back(x.m);
  out["points"] = adopt<double>(std::move(data.vertices), 2);
  out["cells"] = adopt<std::uint32_t>(std::move(data.triangles), 3);
  out["cell_refs"] = adopt<std::int32_t>(std::move(data.triangle_refs), 0);
  out["boundary_cells"] = adopt<std::uint32_t>(std::move(data.edges), 2);
  out["boundary_refs"] = adopt<std::int32_t>(std::move(data.edge_refs), 0);
  out["metric"] = adopt<double>(std::move(m), 3);
  out["stats"] = stats;
  return out;
}

py::dict mesh(const py::handle& points_obj, const py::handle& segments_obj, const py::handle& markers_obj,
              const py::handle& holes_obj, const py::handle& regions_obj, const py::handle& size, const py::handle& metric,
              const py::handle& background_points, const py::handle& background_triangles, const std::string& method,
              const std::string& interpolation, bool optimize, bool keep_boundary, long long max_elements,
              bool verify) {
  if (max_elements < 0) throw InputError("max_elements: " + std::to_string(max_elements) + ": give 0 (the default) or a count");
  const DoubleArray points = double_rows(points_obj, 2, "points");
  if (points.shape(0) == 0) throw InputError("points: no vertices");
  const IndexArray segments = index_rows(segments_obj, 2, "segments");
  const std::vector<int> markers = int_values(markers_obj, segments.shape(0), "markers");
  const DoubleArray holes = holes_obj.is_none() ? DoubleArray(std::vector<py::ssize_t>{0, 2}) : double_rows(holes_obj, 2, "holes");
  std::vector<RegionSeed2> regions;
  if (!regions_obj.is_none()) {
    const DoubleArray r = double_rows(regions_obj, 3, "regions");
    for (py::ssize_t i = 0; i < r.shape(0); ++i)
      regions.push_back({{r.data()[3 * i], r.data()[3 * i + 1]}, static_cast<int>(r.data()[3 * i + 2])});
  }
  const Mesh2dInput input{.points = as_points<Vec2>(points),
                          .segments = as_cells<2>(segments),
                          .segment_markers = markers,
                          .holes = as_points<Vec2>(holes),
                          .regions = regions};
  Mesh2dOptions options;
  options.method = method;
  options.optimize = optimize;
  options.interrupt = python_interrupt_check();
  options.keep_boundary = keep_boundary;
  options.max_elements = static_cast<std::uint64_t>(max_elements);
  if (interpolation != "sizes" && interpolation != "log-euclidean")
    throw InputError("interpolation: 'sizes' or 'log-euclidean', not '" + interpolation + "'");
  options.interpolation = interpolation == "log-euclidean" ? MetricInterpolation::LogEuclidean : MetricInterpolation::Sizes;

  std::optional<ControlSpace2> control;
  std::vector<Metric2> input_metrics;
  const bool scalar_size = !size.is_none() && (py::isinstance<py::float_>(size) || py::isinstance<py::int_>(size));
  if (scalar_size) {
    if (!metric.is_none()) throw InputError("give size or metric, not both");
    if (!background_points.is_none()) throw InputError("background: goes with per-vertex sizes or a metric, not a uniform size");
    control.emplace(ControlSpace2::uniform_size(input.points, size.cast<double>()));
  } else if (!background_points.is_none()) {
    const DoubleArray bp = double_rows(background_points, 2, "background points");
    const IndexArray bt = index_rows(background_triangles, 3, "background triangles");
    std::vector<Metric2> m = metrics_at(size, metric, bp.shape(0));
    if (m.empty()) throw InputError("background: give the size or metric at its vertices");
    control.emplace(mesh_data(bp, bt, {}, index_rows(py::none(), 2, "edges"), {}), std::move(m), options.interpolation);
  } else {
    input_metrics = metrics_at(size, metric, points.shape(0));
    options.input_metrics = input_metrics;
  }
  if (keep_boundary && !control && input_metrics.empty())
    throw InputError("keep_boundary needs a size or metric: with the classical sizes, which come from the boundary "
                     "itself, it is always kept");
  if (control) options.control = &*control;

  Mesh2dResult r;
  std::string report;
  {
    py::gil_scoped_release nogil;
    r = mesh2d(input, options);
    if (verify) report = to_json(check_mesh2d(input, constrained2d(input), r.output));
  }
  py::dict stats;
  const Mesh2dStats& s = r.stats;
  stats["kind"] = "mesh2d";
  stats["method"] = method;
  stats["input_points"] = s.input_points;
  stats["segments"] = s.segments;
  stats["boundary_points"] = s.boundary_points;
  stats["long_boundary_segments"] = s.long_boundary_segments;
  stats["estimated_triangles"] = s.estimated_triangles;
  stats["field_points"] = s.field_points;
  stats["filtered"] = s.filtered;
  stats["not_inserted"] = s.not_inserted;
  stats["passes"] = s.passes;
  stats["cavity_corrections"] = s.cavity_corrections;
  stats["swaps"] = s.swaps;
  stats["relocations"] = s.relocations;
  stats["collapses"] = s.collapses;
  stats["splits"] = s.splits;
  stats["optimization_rounds"] = s.optimization_rounds;
  stats["seconds"] = s.seconds;
  stats["seconds_empty_mesh"] = s.seconds_empty_mesh;
  stats["seconds_control_space"] = s.seconds_control_space;
  stats["seconds_field_points"] = s.seconds_field_points;
  stats["seconds_optimization"] = s.seconds_optimization;
  stats["messages"] = r.messages;
  stats["elements"] = r.output.triangles.size();
  if (verify) stats["verify"] = parse_json(report);
  py::dict out = mesh_result(std::move(r.output), std::move(r.output_metrics), stats);
  check_signals();
  return out;
}

py::dict optimize(const py::handle& points_obj, const py::handle& cells_obj, const py::handle& cell_refs,
                  const py::handle& boundary_obj, const py::handle& boundary_refs, const py::handle& size,
                  const py::handle& metric, long long max_rounds, bool shape_only, bool boundary_splits, bool valence) {
  if (max_rounds < 0 || max_rounds > 1000)
    throw InputError("max_rounds: " + std::to_string(max_rounds) + ": give 0 to 1000 rounds");
  const DoubleArray points = double_rows(points_obj, 2, "points");
  const IndexArray cells = index_rows(cells_obj, 3, "cells");
  const IndexArray boundary = index_rows(boundary_obj, 2, "boundary_cells");
  const MeshData2 input = mesh_data(points, cells, int_values(cell_refs, cells.shape(0), "cell_refs"), boundary,
                                    int_values(boundary_refs, boundary.shape(0), "boundary_refs"));
  const bool uniform = !size.is_none() && (py::isinstance<py::float_>(size) || py::isinstance<py::int_>(size));
  std::vector<Metric2> metrics;
  if (uniform) {
    if (!metric.is_none()) throw InputError("give size or metric, not both");
    const double h = size.cast<double>();
    if (!(h > 0.0) || !std::isfinite(h)) throw InputError("size: a positive finite number");
    metrics.assign(input.vertices.size(), Metric2::isotropic(h));
  } else {
    metrics = metrics_at(size, metric, points.shape(0));
    if (metrics.empty()) metrics = implied_metrics(input);
  }
  Mesh2 mesh;
  try {
    mesh = mesh2_from_data(input);
  } catch (const InputError& e) {  // the arguments' names, as a file's name on the command line
    throw InputError(std::string("cells: ") + e.what(), e.items());
  }
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, metrics[v]);
  MetricField2 field;
  std::shared_ptr<ControlSpace2> control;
  if (uniform) {
    const Metric2 m = metrics.front();
    field = [m](const Vec2&) { return m; };
  } else {
    control = std::make_shared<ControlSpace2>(input, metrics);
    auto hint = std::make_shared<std::uint32_t>(ControlSpace2::kNoHint);
    field = [control, hint](const Vec2& p) { return control->metric_at(p, *hint); };
  }
  Optimize2dOptions options;
  options.interrupt = python_interrupt_check();
  options.max_rounds = static_cast<std::uint32_t>(max_rounds);
  options.collapses = options.splits = !shape_only;
  options.split.boundary = boundary_splits;
  options.valence = valence;
  Optimize2dStats s;
  MeshData2 out;
  std::vector<Metric2> out_metrics;
  {
    py::gil_scoped_release nogil;
    s = optimize2d(mesh, options, field);
    std::vector<std::uint32_t> ids;
    out = mesh.domain(&ids);
    for (std::uint32_t v : ids) out_metrics.push_back(mesh.metric(v));
  }
  py::dict stats;
  stats["kind"] = "optimize2d";
  stats["swaps"] = s.swaps;
  stats["relocations"] = s.relocations;
  stats["collapses"] = s.collapses;
  stats["splits"] = s.splits;
  stats["valence_swaps"] = s.valence_swaps;
  stats["rounds"] = s.rounds;
  stats["stopped_by"] = s.stopped_by;
  stats["worst_before"] = s.worst_before;
  stats["mean_before"] = s.mean_before;
  stats["worst_after"] = s.worst_after;
  stats["mean_after"] = s.mean_after;
  stats["triangles_before"] = s.triangles_before;
  stats["triangles_after"] = s.triangles_after;
  stats["seconds"] = s.seconds;
  stats["elements"] = out.triangles.size();
  py::dict result = mesh_result(std::move(out), std::move(out_metrics), stats);
  check_signals();
  return result;
}

}  // namespace

void bind_mesh2d(py::module_& m) {
  m.def("mesh", &mesh, py::arg("points"), py::arg("segments"), py::arg("markers") = py::none(), py::arg("holes") = py::none(),
        py::arg("regions") = py::none(), py::arg("size") = py::none(), py::arg("metric") = py::none(),
        py::arg("background_points") = py::none(), py::arg("background_triangles") = py::none(),
        py::arg("method") = "edge", py::arg("interpolation") = "sizes", py::arg("optimize") = true,
        py::arg("keep_boundary") = false, py::arg("max_elements") = 0, py::arg("verify") = false);
  m.def("optimize", &optimize, py::arg("points"), py::arg("cells"), py::arg("cell_refs") = py::none(),
        py::arg("boundary_cells") = py::none(), py::arg("boundary_refs") = py::none(), py::arg("size") = py::none(),
        py::arg("metric") = py::none(), py::arg("max_rounds") = static_cast<long long>(Optimize2dOptions{}.max_rounds),
        py::arg("shape_only") = false, py::arg("boundary_splits") = false, py::arg("valence") = false);
}

}  // namespace dtlab::python
