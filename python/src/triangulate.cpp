// dtlab.delaunay and dtlab.constrain: the Delaunay variants (algorithms/delaunay2d, delaunay3d)
// and the constrained methods (algorithms/constrained2d, constrained3d) on numpy arrays, the GIL
// released while they run, optionally verified exactly (verify/) before the arrays are handed
// over to numpy; dtlab.variants: their registries' names and descriptions, and the optimization
// operators' (algorithms/optimize2d, optimize3d registry.hpp).
#include <pybind11/stl.h>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "algorithms/mesh2d/registry.hpp"
#include "algorithms/mesh3d/registry.hpp"
#include "algorithms/optimize2d/registry.hpp"
#include "algorithms/optimize3d/registry.hpp"
#include "kernel/error.hpp"
#include "python/src/arrays.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks3d.hpp"
#include "verify/checks_constrained2d.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab::python {

namespace {

constexpr std::uint64_t kDefaultSeed = Delaunay2dOptions{}.seed;

py::dict delaunay(const py::handle& points_obj, const std::string& algo, long long threads_asked, std::uint64_t seed,
                  bool verify, bool canonical) {
  // A Python int of any sign: refused by name out of range (pybind11 would raise its own TypeError).
  if (threads_asked < 1 || threads_asked > 1024)
    throw InputError("threads: " + std::to_string(threads_asked) + ": give 1 to 1024 threads");
  const auto threads = static_cast<unsigned>(threads_asked);
  int dim = 0;
  DoubleArray points = point_rows(points_obj, dim);
  py::dict out, stats;
  out["points"] = points;
  stats["kind"] = "delaunay";
  stats["algorithm"] = algo;
  stats["points"] = points.shape(0);
  std::vector<std::uint32_t> duplicates, duplicate_of;
  if (dim == 2) {
    if (threads != 1) throw InputError("threads: the 2D variants are sequential (give threads=1)");
    Delaunay2dResult r;
    std::vector<TriangleIds> triangles;
    std::string report;
    {
      py::gil_scoped_release nogil;
      r = delaunay2d(as_points<Vec2>(points), {.algorithm = algo, .seed = seed});
      triangles = canonical ? canonical_triangle_set(r.triangulation.finite_triangles()) : r.triangulation.finite_triangles();
      if (verify) report = to_json(verify_delaunay2d(as_points<Vec2>(points), triangles, r.duplicates));
    }
    stats["seconds"] = r.seconds;
    stats["degenerate_message"] = r.degenerate_message;
    stats["predicates"] = predicate_stats_dict(r.predicate_stats);
    stats["elements"] = triangles.size();
    if (verify) stats["verify"] = parse_json(report);
    out["cells"] = adopt<std::uint32_t>(std::move(triangles), 3);
    duplicates = std::move(r.duplicates);
    duplicate_of = std::move(r.duplicate_of);
  } else {
    Delaunay3dResult r;
    std::vector<TetrahedronIds> tetrahedra;
    std::string report;
    {
      py::gil_scoped_release nogil;
      r = delaunay3d(as_points<Vec3>(points), {.algorithm = algo, .seed = seed, .threads = threads});
      tetrahedra = canonical ? canonical_tetrahedron_set(r.tetrahedralization) : r.tetrahedralization.finite_tetrahedra();
      if (verify) report = to_json(verify_delaunay3d(as_points<Vec3>(points), r.tetrahedralization, r.duplicates));
    }
    stats["seconds"] = r.seconds;
    stats["threads"] = threads;
    stats["degenerate_message"] = r.degenerate_message;
    stats["predicates"] = predicate_stats_dict(r.predicate_stats);
    stats["elements"] = tetrahedra.size();
    if (verify) stats["verify"] = parse_json(report);
    out["cells"] = adopt<std::uint32_t>(std::move(tetrahedra), 4);
    duplicates = std::move(r.duplicates);
    duplicate_of = std::move(r.duplicate_of);
  }
  stats["duplicates"] = duplicates.size();
  out["duplicates"] = adopt<std::uint32_t>(std::move(duplicates), 0);
  out["duplicate_of"] = adopt<std::uint32_t>(std::move(duplicate_of), 0);
  out["stats"] = stats;
  check_signals();
  return out;
}

template <class Seed, class V>
std::vector<Seed> region_seeds(const py::handle& obj, const char* what) {
  constexpr py::ssize_t dim = sizeof(V) / sizeof(double);
  std::vector<Seed> seeds;
  if (obj.is_none()) return seeds;
  const DoubleArray a = double_rows(obj, dim + 1, what);
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    const double* row = a.data() + i * (dim + 1);
    Seed s;
    if constexpr (dim == 2) s.point = {row[0], row[1]};
    else s.point = {row[0], row[1], row[2]};
    const double attr = row[dim];
    if (!(attr == static_cast<double>(static_cast<int>(attr))))
      throw InputError(std::string(what) + ": the attribute (last column) of row " + std::to_string(i) + " is not an integer",
                       {static_cast<std::uint64_t>(i)});
    s.attribute = static_cast<int>(attr);
    seeds.push_back(s);
  }
  return seeds;
}

template <class V>
DoubleArray optional_points(const py::handle& obj, const char* what) {
  constexpr py::ssize_t dim = sizeof(V) / sizeof(double);
  if (obj.is_none()) return DoubleArray(std::vector<py::ssize_t>{0, dim});
  return double_rows(obj, dim, what);
}

py::dict constrain2(const DoubleArray& points, const py::handle& segments_obj, const py::handle& markers_obj,
                    const py::handle& holes_obj, const py::handle& regions_obj, const std::string& method,
                    bool keep_exterior, bool random_swaps, std::uint64_t seed, bool verify) {
  const IndexArray segments = index_rows(segments_obj, 2, "segments");
  const std::vector<int> markers = int_values(markers_obj, segments.shape(0), "markers");
  const DoubleArray holes = optional_points<Vec2>(holes_obj, "holes");
  const std::vector<RegionSeed2> regions = region_seeds<RegionSeed2, Vec2>(regions_obj, "regions");
  const ConstrainedInput2 input{.points = as_points<Vec2>(points),
                                .segments = as_cells<2>(segments),
                                .segment_markers = markers,
                                .holes = as_points<Vec2>(holes),
                                .regions = regions};
  Constrained2dOptions options;
  options.method = method.empty() ? "cdt" : method;
  options.keep_exterior = keep_exterior;
  options.random_swaps = random_swaps;
  options.seed = seed;
  Constrained2dResult r;
  std::string report;
  {
    py::gil_scoped_release nogil;
    r = constrained2d(input, options);
    if (verify) {
      ConstrainedCheckOptions2 check;
      check.method = options.method;
      check.keep_exterior = keep_exterior;
      report = to_json(verify_constrained2d(input, r, check));
    }
  }
  py::dict out, stats;
  stats["kind"] = "constrained2d";
  stats["method"] = options.method;
  stats["input_points"] = r.input_point_count;
  stats["crossing_steiner_points"] = r.crossing_steiner_points;
  stats["split_steiner_points"] = r.split_steiner_points;
  stats["rounding_checks_failed"] = r.rounding_checks_failed;
  stats["flips"] = r.flips;
  stats["shared_edges"] = r.shared_edges.size();
  stats["messages"] = r.messages;
  stats["message_count"] = r.message_count;
  stats["degenerate_message"] = r.degenerate_message;
  stats["predicates"] = predicate_stats_dict(r.predicate_stats);
  stats["seconds"] = r.seconds;
  stats["elements"] = r.triangles.size();
  if (verify) stats["verify"] = parse_json(report);
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<int> edge_refs;
  std::vector<std::uint32_t> edge_segments;
  edges.reserve(r.constrained_edges.size());
  for (const ConstrainedEdge2& e : r.constrained_edges) {
    edges.push_back({e.a, e.b});
    edge_refs.push_back(e.marker);
    edge_segments.push_back(e.segment);
  }
  out["points"] = adopt<double>(std::move(r.triangulation.mutable_points()), 2);
  out["cells"] = adopt<std::uint32_t>(std::move(r.triangles), 3);
  out["cell_refs"] = adopt<std::int32_t>(std::move(r.triangle_region), 0);
  out["boundary_cells"] = adopt<std::uint32_t>(std::move(edges), 2);
  out["boundary_refs"] = adopt<std::int32_t>(std::move(edge_refs), 0);
  out["boundary_sources"] = adopt<std::uint32_t>(std::move(edge_segments), 0);
  out["stats"] = stats;
  check_signals();
  return out;
}

py::dict constrain3(const DoubleArray& points, const py::handle& triangles_obj, const py::handle& refs_obj,
                    const py::handle& holes_obj, const py::handle& regions_obj, const std::string& method,
                    bool keep_exterior, bool remove_cavities, bool verify) {
  const IndexArray triangles = index_rows(triangles_obj, 3, "triangles");
  const std::vector<int> refs = int_values(refs_obj, triangles.shape(0), "markers");
  const DoubleArray holes = optional_points<Vec3>(holes_obj, "holes");
  const std::vector<RegionSeed3> regions = region_seeds<RegionSeed3, Vec3>(regions_obj, "regions");
  const ConstrainedInput3 input{.points = as_points<Vec3>(points),
                                .triangles = as_cells<3>(triangles),
                                .triangle_refs = refs,
                                .holes = as_points<Vec3>(holes),
                                .regions = regions};
  Constrained3dOptions options;
  options.method = method.empty() ? "conforming" : method;
  options.keep_exterior = keep_exterior;
  options.remove_cavities = remove_cavities;
  Constrained3dResult r;
  std::string report;
  {
    py::gil_scoped_release nogil;
    r = constrained3d(input, options);
    if (verify) {
      ConstrainedCheckOptions3 check;
      check.method = options.method;
      check.keep_exterior = keep_exterior;
      report = to_json(check_constrained3d(input, r, check));
    }
  }
  py::dict out, stats, seconds;
  stats["kind"] = "constrained3d";
  stats["method"] = options.method;
  stats["input_points"] = r.input_point_count;
  stats["steiner_on_edges"] = r.steiner_points.on_edges;
  stats["steiner_on_faces"] = r.steiner_points.on_faces;
  stats["steiner_interior"] = r.steiner_points.interior;
  stats["region_count"] = r.region_count;
  stats["rounding_checks_failed"] = r.rounding_checks_failed;
  stats["rounds"] = r.rounds;
  stats["constrained_delaunay"] = r.constrained_delaunay;
  stats["messages"] = r.messages;
  stats["predicates"] = predicate_stats_dict(r.predicate_stats);
  seconds["checks"] = r.seconds.checks;
  seconds["delaunay"] = r.seconds.delaunay;
  seconds["edge_recovery"] = r.seconds.edge_recovery;
  seconds["face_recovery"] = r.seconds.face_recovery;
  seconds["regions"] = r.seconds.regions;
  stats["phase_seconds"] = seconds;
  stats["seconds"] = r.seconds.total;
  stats["elements"] = r.tetrahedra.size();
  if (verify) stats["verify"] = parse_json(report);
  out["points"] = adopt<double>(std::move(r.vertices), 3);
  out["cells"] = adopt<std::uint32_t>(std::move(r.tetrahedra), 4);
  out["cell_refs"] = adopt<std::int32_t>(std::move(r.tetrahedron_regions), 0);
  out["boundary_cells"] = adopt<std::uint32_t>(std::move(r.triangles), 3);
  out["boundary_refs"] = adopt<std::int32_t>(std::move(r.triangle_refs), 0);
  out["boundary_sources"] = adopt<std::uint32_t>(std::move(r.triangle_face), 0);
  out["stats"] = stats;
  check_signals();
  return out;
}

py::dict constrain(const py::handle& points_obj, const py::handle& constraints, const py::handle& markers,
                   const py::handle& holes, const py::handle& regions, const std::string& method, bool keep_exterior,
                   bool random_swaps, bool remove_cavities, std::uint64_t seed, bool verify) {
  int dim = 0;
  const DoubleArray points = point_rows(points_obj, dim);
  if (dim == 2) return constrain2(points, constraints, markers, holes, regions, method, keep_exterior, random_swaps, seed, verify);
  if (random_swaps) throw InputError("random_swaps: a 2D option (the 3D methods have none)");
  return constrain3(points, constraints, markers, holes, regions, method, keep_exterior, remove_cavities, verify);
}

py::dict variants() {
  py::dict out;
  py::list d2, d3, c2, c3, o2, o3, m2, m3;
  for (const Delaunay2dVariant& v : delaunay2d_variants()) d2.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const Delaunay3dVariant& v : delaunay3d_variants()) d3.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const Constrained2dMethod& v : constrained2d_methods()) c2.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const Constrained3dMethodInfo& v : constrained3d_method_list())
    c3.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const Optimize2dOperator& v : optimize2d_operators()) o2.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const Optimize3dOperator& v : optimize3d_operators()) o3.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const FieldPointMethod2& v : mesh2d_methods()) m2.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  for (const FieldPointMethod3& v : mesh3d_methods()) m3.append(py::make_tuple(std::string(v.name), std::string(v.description)));
  out["delaunay2d"] = d2;
  out["delaunay3d"] = d3;
  out["constrained2d"] = c2;
  out["constrained3d"] = c3;
  out["optimize2d"] = o2;
  out["optimize3d"] = o3;
  out["mesh2d"] = m2;  // the meshers' field point methods (method= of dtlab.mesh)
  out["mesh3d"] = m3;
  return out;
}

}  // namespace

void bind_triangulate(py::module_& m) {
  m.def("delaunay", &delaunay, py::arg("points"), py::arg("algo") = "incremental", py::arg("threads") = 1,
        py::arg("seed") = kDefaultSeed, py::arg("verify") = false, py::arg("canonical") = true);
  m.def("constrain", &constrain, py::arg("points"), py::arg("constraints"), py::arg("markers") = py::none(),
        py::arg("holes") = py::none(), py::arg("regions") = py::none(), py::arg("method") = "",
        py::arg("keep_exterior") = false, py::arg("random_swaps") = false, py::arg("remove_cavities") = false,
        py::arg("seed") = kDefaultSeed, py::arg("verify") = false);
  m.def("variants", &variants);
}

}  // namespace dtlab::python
