// `dtlab constrain`: the constrained triangulation of a planar straight line graph (Triangle's
// .poly: vertices, segments with markers, holes, regions) with any registered method
// (algorithms/constrained2d), written as Medit .mesh: Vertices (input first, in input order,
// then Steiner points), Edges (the constrained edges with their segments' markers), Triangles
// (ccw, region attribute as reference).
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "apps/cli_util.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/poly_format.hpp"

namespace dtlab::cli {

namespace {

struct ConstrainArgs {
  std::string input;
  std::string output;
  std::string method = "cdt";
  bool keep_exterior = false;
  bool stats = false;
  bool list = false;
};

int run_constrain(const ConstrainArgs& args) {
  if (args.list) {
    for (const Constrained2dMethod& m : constrained2d_methods()) std::cout << m.name << "\t" << m.description << "\n";
    return 0;
  }
  if (args.input.empty()) throw InputError("give an INPUT .poly file");
  const PolyData2 poly = read_triangle_poly(args.input);
  std::vector<RegionSeed2> regions;
  for (const PolyRegion& r : poly.regions) {
    const double rounded = std::nearbyint(r.attribute);
    if (rounded != r.attribute || std::fabs(rounded) > 2e9)
      std::cerr << "dtlab: region attribute " << r.attribute << " written as the integer reference " << rounded << "\n";
    regions.push_back({r.point, static_cast<int>(std::fabs(rounded) > 2e9 ? 0 : rounded)});
  }
  ConstrainedInput2 input{.points = poly.points,
                          .segments = poly.segments,
                          .segment_markers = poly.segment_markers,
                          .holes = poly.holes,
                          .regions = regions};
  const Constrained2dResult result =
      constrained2d(input, {.method = args.method, .keep_exterior = args.keep_exterior});
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
    write_medit2(args.output, mesh);
  }
  if (args.stats) {
    const double per_minute =
        result.seconds > 0 ? static_cast<double>(result.triangles.size()) * 60.0 / result.seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"method\":" << json_string(args.method)
         << ",\"points\":" << poly.points.size() << ",\"segments\":" << poly.segments.size()
         << ",\"crossing_steiner_points\":" << result.crossing_steiner_points
         << ",\"split_steiner_points\":" << result.split_steiner_points
         << ",\"constrained_edges\":" << result.constrained_edges.size() << ",\"triangles\":" << result.triangles.size()
         << ",\"flips\":" << result.flips << ",\"rounding_checks_failed\":" << result.rounding_checks_failed
         << ",\"seconds\":" << json_number(result.seconds) << ",\"triangles_per_minute\":" << json_number(per_minute)
         << ",\"peak_rss_mb\":" << json_number(peak_mb) << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return result.rounding_checks_failed == 0 ? 0 : 3;
}

}  // namespace

void add_constrain(CLI::App& app) {
  auto args = std::make_shared<ConstrainArgs>();
  CLI::App* cmd = app.add_subcommand("constrain", "Constrained triangulation of a planar straight line graph (.poly)");
  cmd->add_option("input", args->input, "Triangle .poly file (vertices, segments with markers, holes, regions)");
  cmd->add_option("-o,--output", args->output, "Write OUT.mesh (Medit): Vertices, Edges with markers, Triangles with regions");
  std::string names;
  for (const Constrained2dMethod& m : constrained2d_methods()) names += (names.empty() ? "" : "|") + std::string(m.name);
  cmd->add_option("--method", args->method, "Method: " + names)->capture_default_str();
  cmd->add_flag("--keep-exterior", args->keep_exterior, "Keep the triangles outside the segments (holes are still removed)");
  cmd->add_flag("--stats", args->stats, "Print one JSON object with counts, seconds and predicate stages as the last line");
  cmd->add_flag("--list-methods", args->list, "List the registered methods (name, tab, description) and exit");
  cmd->callback([args] { exit_code() = run_constrain(*args); });
}

}  // namespace dtlab::cli
