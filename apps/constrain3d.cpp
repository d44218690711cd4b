// `dtlab constrain` in 3D: read a closed surface of planar polygonal facets (plus internal faces,
// holes and region points where the format has them), triangulate each facet in its plane
// (facet_triangulation.hpp; coplanar neighbours merged with --merge-coplanar), refuse bad input
// by name (facet_triangulation.hpp, plc_checks.hpp), build the
// constrained tetrahedralization with any registered method (algorithms/constrained3d), write
// Medit, check the result exactly (verify/checks_constrained3d.hpp) and report statistics.
#include "apps/constrain3d.hpp"

#include <iostream>
#include <sstream>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/constrained3d/plc/surface_problem.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "verify/checks_constrained3d.hpp"

namespace dtlab::cli {

int list_constrained3d_methods() {
  for (const auto& m : constrained3d_method_list()) std::cout << m.name << "\t" << m.description << "\n";
  return 0;
}

namespace {

// What the facet triangulation did that the user should know: merged groups (the first few
// named), facets without area, and segments that are no constraint of a tetrahedralization.
void report_facets(const SurfaceProblem& problem, bool merge) {
  const SurfaceInput& in = problem.surface;
  const FacetTriangulation& facets = problem.facets;
  for (const std::string& m : problem.messages) std::cerr << "dtlab: " << m << "\n";
  if (facets.segments_alone > 0)
    std::cerr << "dtlab: " << facets.segments_alone
              << " facet(s) of segments or isolated vertices only (no area): not constraints of the "
                 "tetrahedralization, ignored\n";
  if (!merge) return;
  std::cerr << "dtlab: --merge-coplanar: " << facets.merged_facets << " facets merged into " << facets.merged.size()
            << " group(s) of coplanar neighbours" << (facets.merged.empty() ? "" : ":") << "\n";
  constexpr std::size_t kShown = 10, kShownPerGroup = 12;
  for (std::size_t g = 0; g < facets.merged.size() && g < kShown; ++g) {
    const auto& group = facets.merged[g];
    std::cerr << "dtlab:   ";
    for (std::size_t k = 0; k < group.size() && k < kShownPerGroup; ++k)
      std::cerr << (k ? ", " : "") << in.facet_name(group[k]);
    if (group.size() > kShownPerGroup) std::cerr << ", ... (" << group.size() << " in all)";
    std::cerr << " (reference " << in.plc.facets[group.front()].marker << ")\n";
  }
  if (facets.merged.size() > kShown) std::cerr << "dtlab:   ... and " << facets.merged.size() - kShown << " more groups\n";
}

}  // namespace

int run_constrain3d(const Constrain3dCliArgs& args) {
  StagedOutputs outputs({args.output});
  FacetTriangulationOptions facet_options;
  facet_options.merge_coplanar = args.merge_coplanar;
  const SurfaceProblem problem = read_surface_problem(args.input, facet_options);
  const SurfaceInput& in = problem.surface;
  const FacetTriangulation& facets = problem.facets;
  report_facets(problem, args.merge_coplanar);
  const ConstrainedInput3 input = problem.input();
  Constrained3dOptions options;
  options.method = args.method;
  options.keep_exterior = args.keep_exterior;
  options.remove_cavities = args.remove_cavities;
  options.steiner_limit_factor = args.steiner_limit;
  Constrained3dResult result;
  try {
    result = constrained3d(input, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  const double peak_mb = peak_rss_mb();
  for (const std::string& m : result.messages) std::cerr << "dtlab: " << m << "\n";

  if (!args.output.empty()) {
    MeshData3 mesh;
    mesh.vertices = result.vertices;
    mesh.triangles = result.triangles;
    mesh.triangle_refs = result.triangle_refs;
    mesh.tetrahedra = result.tetrahedra;
    mesh.tetrahedron_refs = result.tetrahedron_regions;
    outputs.write(args.output, [&](const std::string& path) { write_mesh3(path, mesh); });
    outputs.commit();
  }
  bool ok = true;
  if (args.verify) {
    const ConstrainedCheckReport3 c = check_constrained3d(
        input, result, {.method = args.method, .keep_exterior = args.keep_exterior, .first_number = 1});
    std::cout << (c.ok ? "ok" : "FAILED") << ": " << result.tetrahedra.size() << " tetrahedra, "
              << result.triangles.size() << " boundary triangles, " << result.steiner_points.total()
              << " Steiner points; " << c.input_triangles << " input triangles covered exactly, " << c.input_edges
              << " input edges as chains, " << c.regions << " region volumes (" << c.exact_volumes << " exact)\n";
    for (const std::string& p : c.problems) std::cout << "  " << p << "\n";
    if (c.problems.size() < c.problem_count)
      std::cout << "  ... and " << c.problem_count - c.problems.size() << " more\n";
    ok = c.ok;
  }
  if (args.stats) {
    const auto& s = result.seconds;
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"dim\":3,\"method\":" << json_string(args.method)
         << ",\"points\":" << result.input_point_count << ",\"input_facets\":" << in.plc.facets.size()
         << ",\"polygon_facets\":" << facets.polygon_facets << ",\"merged_facets\":" << facets.merged_facets
         << ",\"merged_groups\":" << facets.merged.size() << ",\"input_triangles\":" << facets.triangles.size()
         << ",\"elements\":" << result.tetrahedra.size() << ",\"regions\":" << result.region_count
         << ",\"steiner_points\":{\"on_edges\":" << result.steiner_points.on_edges
         << ",\"on_faces\":" << result.steiner_points.on_faces << ",\"interior\":" << result.steiner_points.interior
         << "},\"rounding_checks_failed\":" << result.rounding_checks_failed
         << ",\"constrained_delaunay\":" << (result.constrained_delaunay ? "true" : "false") << ",\"rounds\":" << result.rounds
         << ",\"seconds\":{\"checks\":"
         << json_number(s.checks) << ",\"delaunay\":" << json_number(s.delaunay)
         << ",\"edge_recovery\":" << json_number(s.edge_recovery) << ",\"face_recovery\":" << json_number(s.face_recovery)
         << ",\"regions\":" << json_number(s.regions) << ",\"total\":" << json_number(s.total)
         << "},\"peak_rss_mb\":" << json_number(peak_mb) << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
