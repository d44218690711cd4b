// `dtlab mesh`: 2D mesh generation governed by a control space (algorithms/mesh2d, book §5):
// the domain is a planar straight line graph (Triangle .poly, or Medit .mesh with Edges) whose
// segments are the boundary discretisation; the sizes are classical (from that discretisation),
// a uniform --size, a size map (--size-map S.sol, scalars) or a metric map (--metric M.sol,
// symmetric tensors) given at the vertices of --background (default: the input, whose own
// Triangles serve as the background when it has them, else its constrained triangulation).
// Output: Medit .mesh with Triangles (region references) and Edges (segment markers).
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <type_traits>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "algorithms/mesh2d/registry.hpp"
#include "algorithms/mesh3d/registry.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/constrain3d.hpp"
#include "apps/graph_input.hpp"
#include "apps/mesh_args.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh_quality.hpp"
#include "verify/checks_mesh2d.hpp"

namespace dtlab::cli {

template <class Metric>
std::vector<Metric> read_size_file(const MeshCliArgs& args, std::size_t vertex_count, const std::string& against) {
  constexpr int kDimension = std::is_same_v<Metric, Metric2> ? 2 : 3;
  const std::string& file = args.size_map.empty() ? args.metric : args.size_map;
  const SolData sol = read_medit_sol(file);
  if (sol.dimension != kDimension)
    throw InputError(file + ": a " + std::to_string(sol.dimension) + "D solution for a " + std::to_string(kDimension) +
                     "D domain");
  if (!args.size_map.empty() && sol.kind != SolData::Kind::Scalar)
    throw InputError(file + ": --size-map wants scalar sizes; this file holds tensors (use --metric)");
  if (!args.metric.empty() && sol.kind != SolData::Kind::Tensor)
    throw InputError(file + ": --metric wants symmetric tensors; this file holds scalar sizes (use --size-map)");
  check_sol_matches(sol, vertex_count, file + " (against " + against + ")");
  if constexpr (kDimension == 2)
    return metrics2_from_sol(sol, file);
  else
    return metrics3_from_sol(sol, file);
}
template std::vector<Metric2> read_size_file<Metric2>(const MeshCliArgs&, std::size_t, const std::string&);
template std::vector<Metric3> read_size_file<Metric3>(const MeshCliArgs&, std::size_t, const std::string&);

void throw_resample_boundary_refused() {
  throw InputError("--resample-boundary: the boundary is now cut in the size or metric by default (pieces longer than "
                   "sqrt 2 in it); leave the option out, or give --keep-boundary to keep the input's");
}

namespace {

int run_mesh(const MeshCliArgs& args) {
  if (is_patch_description(args.input) || args.surface_only) return run_mesh_patch(args);  // apps/mesh_patch.cpp
  if (is_surface_input(args.input)) {  // a closed surface: the 3D mesher (apps/mesh3.cpp)
    return run_mesh3(args);
  }
  if (args.resample_boundary) throw_resample_boundary_refused();
  if (args.threads != 1) throw InputError("--threads: the 2D mesher is sequential (give --threads 1 or leave it out)");
  if (args.insertion_regions != 1)
    throw InputError("--insertion-regions: the 2D mesher inserts one point after the other (give 1 or leave it out)");
  // Options of the 3D mesher have no effect on a planar domain: refused by name, not ignored.
  for (const auto& [given, name] : {std::pair{args.remove_cavities, "--remove-cavities"},
                                    std::pair{args.no_remesh, "--no-remesh"},
                                    std::pair{args.triangulate_nonplanar, "--triangulate-nonplanar"},
                                    std::pair{args.optimize_given, "--optimize"}}) {
    if (given)
      throw InputError(std::string(name) + ": an option for closed surfaces; " + args.input +
                       " is a planar domain (in 2D: --no-optimize, or dtlab optimize for its options)");
  }
  const int given = args.sizes_given();
  if (given > 1) throw InputError("give one of --size, --size-map, --metric");
  if (!args.background.empty() && args.size_map.empty() && args.metric.empty())
    throw InputError("--background needs --size-map or --metric (the file of values at its vertices)");
  StagedOutputs outputs({args.output, args.output_metric});
  const GraphInput graph = read_graph(args.input, false);
  const PolyData2& poly = graph.poly;
  if (poly.points.empty()) throw InputError(args.input + ": no vertices");

  Mesh2dInput input{.points = poly.points,
                    .segments = poly.segments,
                    .segment_markers = poly.segment_markers,
                    .holes = poly.holes,
                    .regions = graph.regions};
  Mesh2dOptions options;
  options.method = args.method;
  options.optimize = !args.no_optimize;
  options.keep_boundary = args.keep_boundary;
  options.max_elements = args.max_elements;
  if (args.keep_boundary && given == 0)
    throw InputError("--keep-boundary needs a size (--size, --size-map or --metric): with the classical sizes, which come "
                     "from the boundary itself, it is always kept");
  options.first_number = graph.first_number;
  options.interpolation = args.interpolation == "log-euclidean" ? MetricInterpolation::LogEuclidean : MetricInterpolation::Sizes;
  std::optional<ControlSpace2> control;
  std::vector<Metric2> input_metrics;
  if (args.size_given) {
    control.emplace(ControlSpace2::uniform_size(poly.points, parse_size(args.size)));
  } else if (given == 1) {
    if (!args.background.empty()) {
      const MeshData2 background = read_medit2(args.background);
      control.emplace(background, read_size_file<Metric2>(args, background.vertices.size(), args.background), options.interpolation);
    } else if (!graph.medit.triangles.empty()) {
      control.emplace(graph.medit, read_size_file<Metric2>(args, graph.medit.vertices.size(), args.input), options.interpolation);
    } else {
      input_metrics = read_size_file<Metric2>(args, poly.points.size(), args.input);
      options.input_metrics = input_metrics;
    }
  }
  if (control) options.control = &*control;

  Mesh2dResult result;
  try {
    result = mesh2d(input, options);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  const double peak_mb = peak_rss_mb();
  for (const std::string& m : result.messages) std::cerr << "dtlab: " << m << "\n";

  bool ok = true;
  if (args.verify) {
    const MeshCheckReport2 report = check_mesh2d(input, constrained2d(input), result.output, graph.first_number);
    std::cout << to_text(report);
    ok = report.ok;
  }
  outputs.write(args.output, [&](const std::string& path) { write_medit2(path, result.output); });
  outputs.write(args.output_metric,
                [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(result.output_metrics)); });
  outputs.commit();
  if (args.stats) {
    const QualityReport quality = measure_quality(result.output.vertices, result.output.triangles, result.output_metrics);
    std::cout << quality_table(quality);
    const Mesh2dStats& s = result.stats;
    const double per_minute = s.seconds > 0 ? static_cast<double>(result.output.triangles.size()) * 60.0 / s.seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"method\":" << json_string(args.method)
         << ",\"points\":" << s.input_points << ",\"segments\":" << s.segments
         << ",\"vertices\":" << result.output.vertices.size() << ",\"triangles\":" << result.output.triangles.size()
         << ",\"boundary_points\":" << s.boundary_points << ",\"long_boundary_segments\":" << s.long_boundary_segments
         << ",\"estimated_triangles\":" << json_number(s.estimated_triangles) << ",\"field_points\":" << s.field_points << ",\"filtered\":" << s.filtered
         << ",\"not_inserted\":" << s.not_inserted << ",\"passes\":" << s.passes
         << ",\"cavity_corrections\":" << s.cavity_corrections << ",\"swaps\":" << s.swaps
         << ",\"relocations\":" << s.relocations << ",\"collapses\":" << s.collapses << ",\"splits\":" << s.splits
         << ",\"seconds\":" << json_number(s.seconds) << ",\"seconds_empty_mesh\":" << json_number(s.seconds_empty_mesh)
         << ",\"seconds_control_space\":" << json_number(s.seconds_control_space)
         << ",\"seconds_field_points\":" << json_number(s.seconds_field_points)
         << ",\"seconds_optimization\":" << json_number(s.seconds_optimization)
         << ",\"triangles_per_minute\":" << json_number(per_minute) << ",\"peak_rss_mb\":" << json_number(peak_mb)
         << ",\"quality\":" << quality_json(quality) << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace

void add_mesh(CLI::App& app) {
  auto args = std::make_shared<MeshCliArgs>();
  CLI::App* cmd = app.add_subcommand(
      "mesh", "Mesh generation governed by sizes or a metric: 2D domains (book chapter 5), closed surfaces (chapter 7)");
  cmd->add_option("input", args->input,
                  "Domain: Triangle .poly (vertices, segments with markers, holes, regions) or Medit .mesh (Vertices, "
                  "Edges with references); the segments are the boundary discretisation. A closed surface (.off .obj "
                  ".stl .smesh, TetGen .poly or Medit .mesh in 3D) is meshed in volume (apps/mesh3.cpp)")
      ->required();
  cmd->add_option("-o,--output", args->output, "Write OUT.mesh (Medit): Vertices, Edges with markers, Triangles with regions");
  CLI::Option* size = cmd->add_option("--size", args->size, "Uniform target size H (> 0)");
  cmd->add_option("--size-map", args->size_map, "Medit .sol/.solb of scalar sizes at the vertices of --background");
  cmd->add_option("--metric", args->metric, "Medit .sol/.solb of symmetric tensors (m11 m12 m22) at the vertices of --background");
  cmd->add_option("--background", args->background,
                  "Medit .mesh holding the --size-map / --metric vertices (default: the input; its Triangles, or its "
                  "constrained triangulation)");
  cmd->add_option("--method", args->method,
                  "Field points: " + mesh2d_methods().names(", ") + " in 2D (edge: the edge method, front: advancing "
                  "front); " + mesh3d_methods().names(", ") + " in 3D");
  cmd->add_option("--interpolation", args->interpolation, "Metric interpolation: sizes (default) or log-euclidean")
      ->check(CLI::IsMember({"sizes", "log-euclidean"}));
  cmd->add_option("--output-metric", args->output_metric, "Write the metric at the output vertices (Medit .sol)");
  cmd->add_flag("--keep-boundary", args->keep_boundary,
                "Keep the input segments (2D) or surface triangles (3D) as given; by default, with a size or metric, "
                "those longer than sqrt 2 in it are cut (the count of those kept long is said on stderr)");
  cmd->add_flag("--resample-boundary", args->resample_boundary, "Former option: the boundary is now cut by default")
      ->group("");
  cmd->add_option("--max-elements", args->max_elements,
                  "Refuse, before any work, a size or metric that asks for more elements than this (estimated from "
                  "the metric's complexity; default: half this machine's memory at the bytes an element costs)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 48));
  cmd->add_flag("--no-optimize", args->no_optimize, "Skip the optimization step");
  cmd->add_flag("--no-remesh", args->no_remesh,
                "Surfaces: after the optimization, do not mesh again the regions around the tetrahedra still below "
                "its goal's smallest dihedral angle");
  cmd->add_option("--threads", args->threads,
                  "Surfaces: threads for the field point insertion, sharing its regions (--insertion-regions); "
                  "the same mesh for every count (default 1)")
      ->check(CLI::Range(1u, 1024u));
  cmd->add_option("--insertion-regions", args->insertion_regions,
                  "Surfaces: insert each pass's field points by up to this many regions, which --threads share "
                  "(default 1: one after the other; another count gives another mesh, the same for every --threads)")
      ->check(CLI::Range(1u, 4096u));
  cmd->add_flag("--triangulate-nonplanar", args->triangulate_nonplanar,
                "Closed surfaces: triangulate a polygonal face whose corners are not in one plane in its projection "
                "(each triangle a boundary face with the face's marker) instead of refusing it; counted on stderr");
  CLI::Option* optimize = cmd->add_option("--optimize", args->optimize,
                  "Closed surfaces: the optimization effort: light (one round), standard (rounds until Q_K <= 3 and "
                  "dihedral angles in [20, 150] deg and 97 % of Q_K in [1, 2], or no more gain; the default), thorough (two relocation sweeps "
                  "a round, rounds until no gain, then vertices moved for dihedral angles of at least 25 deg)")
      ->check(CLI::IsMember({"light", "standard", "thorough"}));
  cmd->add_flag("--remove-cavities", args->remove_cavities,
                "Closed surfaces: drop the regions bounded only by shells nested inside another (a cube minus a ball)");
  cmd->add_flag("--stats", args->stats, "Print the quality table and one JSON object (counts, phases, quality) last");
  cmd->add_flag("--verify", args->verify,
                "Check the output exactly (validity, segments as chains, regions, area); exit 3 if it fails");
  cmd->add_flag("--surface-only", args->surface_only,
                "Patches (PATCH.json: plane, sphere, cylinder, cone, torus, sine_graph, bspline): mesh the surface only "
                "(book chapter 6), written as Medit Triangles (ref: chart) and Edges (free sides)");
  cmd->add_option("--hausdorff", args->hausdorff,
                  "Patches: the largest gap E between a triangle and the surface: sizes from the principal radii rho, "
                  "2 sqrt(E (2 rho - E)) (with --size: the smaller)");
  cmd->add_option("--relative-gap", args->relative_gap,
                  "Patches: the book's relative gap eps (sizes alpha rho, alpha = 2 sqrt(eps (2 - eps))) instead of --hausdorff");
  cmd->add_option("--geometric", args->geometric,
                  "Patches: the geometric metric with --hausdorff / --relative-gap: isotropic (the smallest radius, "
                  "default) or anisotropic (both principal radii and directions)")
      ->check(CLI::IsMember({"isotropic", "anisotropic"}));
  cmd->add_option("--hmin", args->hmin, "Patches: the geometric sizes' lower bound (default: none)");
  cmd->add_option("--hmax", args->hmax, "Patches: the geometric sizes' upper bound (default: --size, else a tenth of the patch's extent)");
  cmd->add_option("--background-cells", args->background_cells,
                  "Patches: the control space's grid per chart and direction (default 64)")
      ->check(CLI::Range(2u, 4096u));
  cmd->callback([args, size, optimize] {
    args->size_given = size->count() > 0;
    args->optimize_given = optimize->count() > 0;
    exit_code() = run_mesh(*args);
  });
}

}  // namespace dtlab::cli
