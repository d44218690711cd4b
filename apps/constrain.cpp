// `dtlab constrain`: the constrained triangulation of a planar straight line graph (Triangle's
// .poly: vertices, segments with markers, holes, regions; or Medit .mesh: Vertices, and Edges
// with their references as markers) with any registered method (algorithms/constrained2d),
// written as Medit .mesh: Vertices (input first, in input order, then Steiner points), Edges
// (the constrained edges with their segments' markers), Triangles (ccw, region attribute as
// reference); --verify runs the exact checks (verify/checks_constrained2d.hpp). Messages number
// points and segments as the input file does (Medit from 1, .poly from its first vertex number).
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <sstream>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/constrained3d/constrained3d.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/constrain3d.hpp"
#include "apps/graph_input.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/poly_format.hpp"
#include "verify/checks_constrained2d.hpp"

namespace dtlab::cli {

namespace {

struct ConstrainArgs {
  std::string input;
  std::string output;
  std::string method;  // empty: the dimension's default (cdt in 2D, conforming in 3D)
  bool keep_exterior = false;
  bool remove_cavities = false;       // 3D only
  bool merge_coplanar = false;        // 3D only
  // 3D only: Steiner points at most this times (points + triangles); kNotGiven: the default.
  static constexpr std::uint32_t kNotGiven = UINT32_MAX;
  std::uint32_t steiner_limit = kNotGiven;
  std::string swap_order = "queue";  // 2D only
  bool stats = false;
  bool verify = false;
  bool list = false;
};

int run_constrain(ConstrainArgs args) {
  if (args.list) {
    std::cout << "2D (planar straight line graphs):\n";
    for (const Constrained2dMethod& m : constrained2d_methods()) std::cout << m.name << "\t" << m.description << "\n";
    std::cout << "3D (piecewise linear complexes):\n";
    return list_constrained3d_methods();
  }
  if (args.input.empty()) throw InputError("give an INPUT file (.poly, .mesh; in 3D also .smesh, .off, .obj, .stl)");
  if (is_surface_input(args.input)) {
    if (args.swap_order != "queue")
      throw InputError("--swap-order applies to 2D input (planar straight line graphs), not to " + args.input);
    return run_constrain3d({args.input, args.output, args.method.empty() ? "conforming" : args.method,
                            args.keep_exterior, args.remove_cavities, args.stats, args.verify,
                            args.steiner_limit == ConstrainArgs::kNotGiven ? Constrained3dOptions{}.steiner_limit_factor
                                                                            : args.steiner_limit,
                            args.merge_coplanar});
  }
  if (args.remove_cavities)
    throw InputError("--remove-cavities applies to 3D input (surfaces), not to " + args.input);
  if (args.merge_coplanar)
    throw InputError("--merge-coplanar applies to 3D input (surfaces), not to " + args.input);
  if (args.steiner_limit != ConstrainArgs::kNotGiven)
    throw InputError("--steiner-limit applies to 3D input (surfaces), not to " + args.input);
  if (args.method.empty()) args.method = "cdt";
  StagedOutputs outputs({args.output});
  const GraphInput graph = read_graph(args.input, true);
  const PolyData2& poly = graph.poly;
  const std::vector<RegionSeed2>& regions = graph.regions;
  ConstrainedInput2 input{.points = poly.points,
                          .segments = poly.segments,
                          .segment_markers = poly.segment_markers,
                          .holes = poly.holes,
                          .regions = regions};
  Constrained2dOptions options;
  options.method = args.method;
  options.keep_exterior = args.keep_exterior;
  options.random_swaps = args.swap_order == "random";
  options.first_number = graph.first_number;
  Constrained2dResult result;
  try {
    result = constrained2d(input, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  const double peak_mb = peak_rss_mb();
  for (const std::string& m : result.messages) std::cerr << "dtlab: " << m << "\n";
  if (result.message_count > result.messages.size())
    std::cerr << "dtlab: ... " << result.message_count - result.messages.size() << " more messages\n";
  if (!result.degenerate_message.empty()) std::cerr << "dtlab: no triangles: " << result.degenerate_message << "\n";

  if (!args.output.empty()) {
    MeshData2 mesh;
    const auto points = result.triangulation.points();
    mesh.vertices.assign(points.begin(), points.end());
    mesh.vertex_refs.assign(points.size(), 0);
    for (const ConstrainedEdge2& e : result.constrained_edges) {
      mesh.edges.push_back({e.a, e.b});
      mesh.edge_refs.push_back(e.marker);
    }
    mesh.triangles = result.triangles;
    mesh.triangle_refs = result.triangle_region;
    outputs.write(args.output, [&](const std::string& path) { write_medit2(path, mesh); });
    outputs.commit();
  }
  bool verified_ok = true;
  if (args.verify) {
    const ConstrainedCheckReport2 report = verify_constrained2d(
        input, result, {.method = args.method, .keep_exterior = args.keep_exterior, .first_number = graph.first_number});
    std::cout << to_text(report);
    verified_ok = report.ok;
  }
  if (args.stats) {
    const double per_minute =
        result.seconds > 0 ? static_cast<double>(result.triangles.size()) * 60.0 / result.seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"method\":" << json_string(args.method)
         << ",\"points\":" << poly.points.size() << ",\"segments\":" << poly.segments.size()
         << ",\"crossing_steiner_points\":" << result.crossing_steiner_points
         << ",\"split_steiner_points\":" << result.split_steiner_points
         << ",\"constrained_edges\":" << result.constrained_edges.size()
         << ",\"shared_edges\":" << result.shared_edges.size() << ",\"bent_crossings\":" << result.bent_crossings.size()
         << ",\"triangles\":" << result.triangles.size()
         << ",\"flips\":" << result.flips << ",\"rounding_checks_failed\":" << result.rounding_checks_failed
         << ",\"seconds\":" << json_number(result.seconds) << ",\"triangles_per_minute\":" << json_number(per_minute)
         << ",\"peak_rss_mb\":" << json_number(peak_mb) << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return verified_ok && result.rounding_checks_failed == 0 ? 0 : 3;
}

}  // namespace

void add_constrain(CLI::App& app) {
  auto args = std::make_shared<ConstrainArgs>();
  CLI::App* cmd = app.add_subcommand(
      "constrain",
      "Constrained triangulation of a planar straight line graph (.poly, .mesh) or tetrahedralization of a "
      "piecewise linear complex of planar polygonal facets (TetGen .poly/.smesh, Medit .mesh, OFF, OBJ, STL)");
  cmd->add_option("input", args->input,
                  "2D: Triangle .poly file (vertices, segments with markers, holes, regions) or Medit .mesh (Vertices, "
                  "Edges with references as markers); 3D: TetGen .poly/.smesh (facets of polygons with holes), Medit .mesh "
                  "(Dimension 3, Triangles, Quadrilaterals), .off and .obj (polygons), .stl: a closed surface of planar "
                  "facets, internal faces allowed");
  cmd->add_option("-o,--output", args->output, "Write OUT.mesh (Medit): Vertices, Edges with markers, Triangles with regions");
  std::string names;
  for (const Constrained2dMethod& m : constrained2d_methods()) names += (names.empty() ? "" : "|") + std::string(m.name);
  std::string names3;
  for (const auto& m : constrained3d_method_list()) names3 += (names3.empty() ? "" : "|") + std::string(m.name);
  cmd->add_option("--method", args->method,
                  "Method; 2D: " + names + " (default cdt); 3D: " + names3 + " (default conforming)");
  cmd->add_option("--swap-order", args->swap_order,
                  "2D: the order in which edges crossing a missing segment are swapped: queue (Sloan's, default) or "
                  "random (seeded, reproducible)")
      ->check(CLI::IsMember({"queue", "random"}));
  cmd->add_flag("--remove-cavities", args->remove_cavities,
                "3D: drop the regions bounded only by shells nested inside another shell (cavities)");
  cmd->add_flag("--merge-coplanar", args->merge_coplanar,
                "3D: merge neighbouring coplanar facets with the same reference into one facet, triangulated "
                "again in its plane (TetGen's default), and say which were merged");
  cmd->add_option("--steiner-limit", args->steiner_limit,
                  "3D: stop with an error naming the item being recovered once the Steiner points would exceed this "
                  "times (input points + triangles) (default 200; 0: none allowed)")
      ->check(integer_in(0, 1000000));
  cmd->add_flag("--keep-exterior", args->keep_exterior, "Keep the triangles outside the segments (holes are still removed)");
  cmd->add_flag("--stats", args->stats, "Print one JSON object with counts, seconds and predicate stages as the last line");
  cmd->add_flag("--verify", args->verify,
                "Check the result exactly (constraints as chains, Steiner rounding bounds, validity in doubles, the "
                "method's Delaunay property), print the report; exit 3 if it fails");
  cmd->add_flag("--list-methods", args->list, "List the registered methods (name, tab, description) and exit");
  cmd->callback([args] { exit_code() = run_constrain(*args); });
}

}  // namespace dtlab::cli
