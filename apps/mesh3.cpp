// `dtlab mesh` for volumes: 3D mesh generation governed by a control space (algorithms/mesh3d,
// book §7): the domain is a closed surface (several shells allowed) read as `dtlab constrain`
// reads it (mesh/io/surface_input.hpp; polygonal facets triangulated in their planes); the sizes
// are classical (from the surface discretisation), a uniform --size, a size map (--size-map
// S.sol, scalars) or a metric map (--metric M.sol, symmetric tensors) at the vertices of
// --background (a tetrahedral Medit mesh). Output: Medit .mesh with Tetrahedra (region
// references) and the boundary Triangles (input references). --stats prints the book's Table 7.1
// and 7.2 columns (ne, np, target, Q_M, % in [1,2], time, elements per minute, share of time in
// point insertion) with the quality report (dihedral angles, unit edges) and one JSON object.
#include "apps/mesh_args.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "algorithms/constrained3d/plc/surface_problem.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "kernel/error.hpp"
#include "kernel/quality.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh_quality.hpp"
#include "verify/checks_mesh3d.hpp"

namespace dtlab::cli {

namespace {

// The best Q_K of a tetrahedron on triangle (a, b, c) (book §7.13's "target"): the apex on the
// normal through the centroid, its height found by a golden-section search (Q_K is unimodal in it).
double best_quality_on(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double nn = norm(n);
  if (!(nn > 0.0)) return std::numeric_limits<double>::infinity();
  const Vec3 unit = (1.0 / nn) * n;
  const Vec3 g = (1.0 / 3.0) * (a + b + c);
  const double l = std::max({norm(b - a), norm(c - b), norm(a - c)});
  const auto q = [&](double t) { return shape_quality(a, b, c, g + (t * l) * unit); };
  double lo = 0.01, hi = 3.0;
  const double phi = 0.6180339887498949;
  double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo), f1 = q(x1), f2 = q(x2);
  for (int k = 0; k < 60; ++k) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - phi * (hi - lo), f1 = q(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + phi * (hi - lo), f2 = q(x2);
    }
  }
  return std::min(f1, f2);
}

double quality_target(const MeshData3& mesh) {
  double target = 1.0;
  for (const auto& f : mesh.triangles)
    target = std::max(target, best_quality_on(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]));
  return target;
}

}  // namespace

int run_mesh3(const MeshCliArgs& args) {
  const int given = args.sizes_given();
  if (given > 1) throw InputError("give one of --size, --size-map, --metric");
  if (!args.background.empty() && args.size_map.empty() && args.metric.empty())
    throw InputError("--background needs --size-map or --metric (the file of values at its vertices)");
  if ((!args.size_map.empty() || !args.metric.empty()) && args.background.empty())
    throw InputError("for a volume, --size-map and --metric need --background B.mesh (a tetrahedral mesh holding their "
                     "vertices)");
  if (args.resample_boundary) throw_resample_boundary_refused();
  if (args.keep_boundary && given == 0)
    throw InputError("--keep-boundary needs a size (--size, --size-map or --metric): with the classical sizes, which come "
                     "from the surface itself, it is always kept");

  StagedOutputs outputs({args.output, args.output_metric});
  FacetTriangulationOptions facet_options;
  facet_options.triangulate_nonplanar = args.triangulate_nonplanar;
  const SurfaceProblem problem = read_surface_problem(args.input, facet_options);
  for (const std::string& m : problem.messages) std::cerr << "dtlab: " << m << "\n";
  const Mesh3dInput input = problem.input();
  Mesh3dOptions options;
  options.method = args.method;
  options.optimize = !args.no_optimize;
  options.local_remesh = !args.no_remesh;
  options.threads = args.threads;
  options.insertion_regions = args.insertion_regions;
  options.optimization = optimize3d_effort(args.optimize);
  options.remove_cavities = args.remove_cavities;
  options.keep_boundary = args.keep_boundary;
  options.max_elements = args.max_elements;
  const MetricInterpolation mode =
      args.interpolation == "log-euclidean" ? MetricInterpolation::LogEuclidean : MetricInterpolation::Sizes;
  std::optional<ControlSpace3> control;
  if (args.size_given) {
    control.emplace(ControlSpace3::uniform_size(input.points, parse_size(args.size)));
  } else if (given == 1) {
    const MeshData3 background = read_medit3(args.background);
    try {
      control.emplace(background, read_size_file<Metric3>(args, background.vertices.size(), args.background), mode);
    } catch (const InputError& e) {
      throw InputError(args.background + ": " + e.what(), e.items());
    }
  }
  if (control) options.control = &*control;

  Mesh3dResult result;
  try {
    result = mesh3d(input, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  const double peak_mb = peak_rss_mb();
  result.mesh = Mesh3();  // the output holds what follows needs: the working mesh's memory goes back
  for (const std::string& m : result.messages) std::cerr << "dtlab: " << m << "\n";

  bool ok = true;
  if (args.verify) {
    const MeshCheckReport3 report = check_mesh3d(input, recover_domain(input, args.remove_cavities), result.output,
                                                         result.output_metrics, {.remove_cavities = args.remove_cavities});
    std::cout << to_text(report);
    ok = report.ok;
  }
  outputs.write(args.output, [&](const std::string& path) { write_mesh3(path, result.output); });
  outputs.write(args.output_metric,
                [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(result.output_metrics)); });
  outputs.commit();
  if (args.stats) {
    const QualityReport quality = measure_quality(result.output.vertices, result.output.tetrahedra, result.output_metrics);
    const Mesh3dStats& s = result.stats;
    const double ne = static_cast<double>(result.output.tetrahedra.size());
    const double per_second = s.seconds > 0 ? ne / s.seconds : 0.0;
    const double target = quality_target(result.output);
    const double insertion_share = s.seconds > 0 ? s.seconds_insertion / s.seconds : 0.0;
    std::cout << quality_table(quality);
    std::ostringstream table;
    table << "Table 7.1: ne " << result.output.tetrahedra.size() << ", np " << quality.vertices << ", target "
          << json_number(target) << ", Q_M " << json_number(quality.quality_worst) << ", 1-2 "
          << json_number(100.0 * quality.quality_shares[0]) << " %, t " << json_number(s.seconds) << " s\n"
          << "Table 7.2: v " << json_number(per_second * 60.0) << " elements per minute (" << json_number(per_second)
          << " per second), Del " << json_number(100.0 * insertion_share) << " % of the time in point insertion\n";
    std::cout << table.str();
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"dim\":3,\"method\":" << json_string(args.method)
         << ",\"points\":" << s.input_points << ",\"input_triangles\":" << s.input_triangles
         << ",\"steiner_points\":" << s.steiner_points << ",\"empty_mesh_tetrahedra\":" << s.empty_mesh_tetrahedra
         << ",\"boundary_points\":" << s.boundary_points << ",\"long_boundary_edges\":" << s.long_boundary_edges
         << ",\"estimated_tetrahedra\":" << json_number(s.estimated_tetrahedra)
         << ",\"vertices\":" << result.output.vertices.size() << ",\"tetrahedra\":" << result.output.tetrahedra.size()
         << ",\"triangles\":" << result.output.triangles.size() << ",\"field_points\":" << s.field_points
         << ",\"filtered\":" << s.filtered << ",\"not_inserted\":" << s.not_inserted << ",\"passes\":" << s.passes
         << ",\"cavity_corrections\":" << s.cavity_corrections << ",\"insertion_deferred\":" << s.insertion_deferred
         << ",\"threads\":" << options.threads << ",\"insertion_regions\":" << options.insertion_regions << ",\"optimized\":" << (options.optimize ? "true" : "false")
         << ",\"face_swaps\":" << s.face_swaps << ",\"shell_transformations\":" << s.shell_transformations
         << ",\"relocations\":" << s.relocations << ",\"collapses\":" << s.collapses << ",\"splits\":" << s.splits
         << ",\"optimization_rounds\":" << s.optimization_rounds
         << ",\"optimization_stopped_by\":" << json_string(s.optimization_stopped_by)
         << ",\"remeshed_regions\":" << s.remeshed_regions
         << ",\"remesh_work_bound_reached\":" << (s.remesh_work_bound_reached ? "true" : "false")
         << ",\"target\":" << json_number(target) << ",\"seconds\":" << json_number(s.seconds)
         << ",\"seconds_empty_mesh\":" << json_number(s.seconds_empty_mesh)
         << ",\"seconds_control_space\":" << json_number(s.seconds_control_space)
         << ",\"seconds_field_points\":" << json_number(s.seconds_field_points)
         << ",\"seconds_insertion\":" << json_number(s.seconds_insertion)
         << ",\"seconds_optimization\":" << json_number(s.seconds_optimization)
         << ",\"tetrahedra_per_second\":" << json_number(per_second)
         << ",\"tetrahedra_per_minute\":" << json_number(per_second * 60.0)
         << ",\"insertion_share\":" << json_number(insertion_share) << ",\"peak_rss_mb\":" << json_number(peak_mb)
         << ",\"quality\":" << quality_json(quality) << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
