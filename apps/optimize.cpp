// `dtlab optimize MESH -o OUT [--metric M.sol | --size H] [--stats]`: mesh optimization (book
// §8) of a 2D mesh (Medit .mesh or Triangle .ele: algorithms/optimize2d) or a 3D one (Medit .mesh
// with Tetrahedra or TetGen .ele with its .node and .face: algorithms/optimize3d): swaps (face
// swaps and shell transformations in 3D), relocation, collapses and splits toward a unit mesh in
// the metric, the boundary (the file's boundary edges / triangles and its Edges / Triangles
// entries, constrained) kept as it is. The metric: H^-2 I (--size), one per vertex from a .sol
// (--metric; in 2D the input mesh is its background, interpolated at moved and new points; in 3D
// moved points keep theirs and new ones interpolate), or, with neither, the mesh's own sizes
// (each vertex: the mean length of its edges), so that mostly the shapes change. Prints the
// quality tables (mesh/mesh_quality.hpp) before and after; --stats adds one JSON line with the
// operation counts and both reports. --list-operators lists the operators of a round (their
// registries, optimize2d/registry.hpp and optimize3d/registry.hpp) for MESH's dimension, or both.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/mesh3d/local_remesh.hpp"
#include "algorithms/optimize2d/registry.hpp"
#include "algorithms/optimize3d/registry.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/implied_metrics.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "mesh/mesh3_from_data.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab::cli {

namespace {

struct OptimizeArgs {
  std::string input;
  std::string output;
  std::string metric;
  std::string size;  // kept as text: refused with our own message, exit code 1
  bool size_given = false;
  std::uint32_t rounds = Optimize2dOptions{}.max_rounds;
  bool shape_only = false;
  bool boundary_splits = false;
  bool valence = false;
  bool no_remesh = false;
  bool stats = false;
  bool list = false;
  std::uint64_t max_elements = 0;  // Optimize2d/3dOptions::max_elements (0: from the memory)
};

// The operators of a round, name tab description, for `dimension` (0: both, under headings).
int list_operators(int dimension) {
  if (dimension == 0) std::cout << "2D (optimize2d):\n";
  if (dimension != 3)
    for (const Optimize2dOperator& op : optimize2d_operators()) std::cout << op.name << "\t" << op.description << "\n";
  if (dimension == 0) std::cout << "3D (optimize3d):\n";
  if (dimension != 2)
    for (const Optimize3dOperator& op : optimize3d_operators()) std::cout << op.name << "\t" << op.description << "\n";
  return 0;
}

// The domain as a file, with the metric of each of its vertices, and the input's vertex
// references kept for the boundary vertices (never moved or removed; the others are 0).
struct Snapshot {
  MeshData2 data;
  std::vector<Metric2> metrics;
};

Snapshot snapshot(const Mesh2& mesh, const MeshData2& input) {
  Snapshot s;
  std::vector<std::uint32_t> ids;
  s.data = mesh.domain(&ids);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    s.metrics.push_back(mesh.metric(ids[i]));
    const std::uint32_t v = ids[i];
    if (v < input.vertex_refs.size() && (mesh.flags(v) & Mesh2::kOnBoundary) != 0) s.data.vertex_refs[i] = input.vertex_refs[v];
  }
  return s;
}

struct Snapshot3 {
  MeshData3 data;
  std::vector<Metric3> metrics;
};

Snapshot3 snapshot3(const Mesh3& mesh, const MeshData3& input) {
  Snapshot3 s;
  std::vector<std::uint32_t> ids;
  s.data = mesh.domain(&ids);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    s.metrics.push_back(mesh.metric(ids[i]));
    const std::uint32_t v = ids[i];
    if (v < input.vertex_refs.size() && (mesh.flags(v) & Mesh3::kOnBoundary) != 0) s.data.vertex_refs[i] = input.vertex_refs[v];
  }
  // The input's Edges (ridges) that are still edges, with their references.
  for (std::size_t e = 0; e < input.edges.size(); ++e) {
    const auto [a, b] = input.edges[e];
    const auto ia = std::lower_bound(ids.begin(), ids.end(), a), ib = std::lower_bound(ids.begin(), ids.end(), b);
    if (ia == ids.end() || *ia != a || ib == ids.end() || *ib != b) continue;
    s.data.edges.push_back({static_cast<std::uint32_t>(ia - ids.begin()), static_cast<std::uint32_t>(ib - ids.begin())});
    s.data.edge_refs.push_back(input.edge_refs.empty() ? 0 : input.edge_refs[e]);
  }
  return s;
}

int run_optimize3(const OptimizeArgs& args) {
  if (args.boundary_splits)
    throw InputError("--split-boundary: " + args.input + " is 3D; the 3D optimization keeps its boundary (2D meshes only)");
  if (args.valence) throw InputError("--valence: " + args.input + " is 3D; valence relaxation is for 2D meshes only");
  StagedOutputs outputs({args.output});
  const MeshData3 input = read_mesh3(args.input);
  std::vector<Metric3> metrics;
  if (args.size_given) {
    metrics.assign(input.vertices.size(), Metric3::isotropic(parse_size(args.size)));
  } else if (!args.metric.empty()) {
    metrics = read_metrics<Metric3>(args.metric, input.vertices.size());
  } else {
    metrics = implied_metrics(input);
  }
  Mesh3 mesh;
  std::vector<std::string> messages;
  try {
    mesh = mesh3_from_data(input, {}, &messages);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  for (const std::string& m : messages) std::cerr << "dtlab: " << args.input << ": " << m << "\n";
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, metrics[v]);
  MetricField3 field;
  if (args.size_given) {
    const Metric3 m = metrics.front();
    field = [m](const Vec3&) { return m; };
  }

  const Snapshot3 before = snapshot3(mesh, input);
  const QualityReport report_before = measure_quality(before.data.vertices, before.data.tetrahedra, before.metrics);
  Optimize3dOptions options;
  options.max_rounds = args.rounds;
  options.max_elements = args.max_elements;
  options.collapses = options.splits = !args.shape_only;
  const Optimize3dStats stats = optimize3d(mesh, options, field);
  // What the operators leave below 20 degrees, meshed again (algorithms/mesh3d/local_remesh.hpp).
  LocalRemesh3Stats remesh;
  const auto remesh_start = std::chrono::steady_clock::now();
  if (!args.shape_only && !args.no_remesh) remesh = remesh_small_angles(mesh, field);
  const double remesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - remesh_start).count();
  const Snapshot3 after = snapshot3(mesh, input);
  const QualityReport report_after = measure_quality(after.data.vertices, after.data.tetrahedra, after.metrics);
  outputs.write(args.output, [&](const std::string& path) { write_mesh3(path, after.data); });
  outputs.commit();

  std::cout << "before:\n" << quality_table(report_before) << "after:\n" << quality_table(report_after);
  std::cout << "operations: " << stats.face_swaps << " face swaps, " << stats.shell_transformations
            << " shell transformations, " << stats.relocations << " relocations, " << stats.collapses << " collapses, "
            << stats.splits << " splits in " << stats.rounds << " rounds (" << stats.stopped_by << "), "
            << json_number(stats.seconds) << " s; " << remesh.remeshed << " of " << remesh.tried
            << " regions remeshed (" << remesh.vertices_added << " vertices added, " << remesh.vertices_removed
            << " removed)" << (remesh.work_bound_reached ? ", stopped at its work bound" : "") << ", "
            << json_number(remesh_seconds) << " s\n";
  if (args.stats) {
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"face_swaps\":" << stats.face_swaps
         << ",\"shell_transformations\":" << stats.shell_transformations << ",\"relocations\":" << stats.relocations
         << ",\"collapses\":" << stats.collapses << ",\"splits\":" << stats.splits << ",\"rounds\":" << stats.rounds
         << ",\"remeshed_regions\":" << remesh.remeshed << ",\"remesh_tried\":" << remesh.tried
         << ",\"remesh_seconds\":" << json_number(remesh_seconds)
         << ",\"remesh_work_bound_reached\":" << (remesh.work_bound_reached ? "true" : "false")
         << ",\"stopped_by\":" << json_string(stats.stopped_by) << ",\"worst_before\":" << json_number(stats.worst_before)
         << ",\"mean_before\":" << json_number(stats.mean_before) << ",\"worst_after\":" << json_number(stats.worst_after)
         << ",\"mean_after\":" << json_number(stats.mean_after) << ",\"tetrahedra_before\":" << stats.tetrahedra_before
         << ",\"tetrahedra_after\":" << stats.tetrahedra_after << ",\"seconds\":" << json_number(stats.seconds)
         << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << ",\"before\":" << quality_json(report_before)
         << ",\"after\":" << quality_json(report_after) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

int run_optimize(const OptimizeArgs& args) {
  if (args.list) return list_operators(args.input.empty() ? 0 : input_dimension(args.input));
  if (args.input.empty()) throw InputError("give a MESH file (Medit .mesh, Triangle .ele, TetGen .ele)");
  if (args.size_given && !args.metric.empty())
    throw InputError("--size " + args.size + ": give either --size or --metric");
  if (input_dimension(args.input) == 3) return run_optimize3(args);
  if (args.no_remesh)
    throw InputError("--no-remesh: " + args.input + " is 2D; the local remeshing after the rounds is 3D only");
  StagedOutputs outputs({args.output});
  const MeshData2 input = read_mesh2(args.input);
  std::vector<Metric2> metrics;
  if (args.size_given) {
    metrics.assign(input.vertices.size(), Metric2::isotropic(parse_size(args.size)));
  } else if (!args.metric.empty()) {
    metrics = read_metrics<Metric2>(args.metric, input.vertices.size());
  } else {
    metrics = implied_metrics(input);
  }
  Mesh2 mesh;
  try {
    mesh = mesh2_from_data(input);
  } catch (const InputError& e) {
    throw InputError(args.input + ": " + e.what(), e.items());
  }
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, metrics[v]);

  // The control space: constant for --size, else the input mesh as background.
  MetricField2 field;
  std::shared_ptr<ControlSpace2> control;
  if (args.size_given) {
    const Metric2 m = metrics.front();
    field = [m](const Vec2&) { return m; };
  } else {
    control = std::make_shared<ControlSpace2>(input, metrics);
    auto hint = std::make_shared<std::uint32_t>(ControlSpace2::kNoHint);
    field = [control, hint](const Vec2& p) { return control->metric_at(p, *hint); };
  }

  const Snapshot before = snapshot(mesh, input);
  const QualityReport report_before = measure_quality(before.data.vertices, before.data.triangles, before.metrics);
  Optimize2dOptions options;
  options.max_rounds = args.rounds;
  options.max_elements = args.max_elements;
  options.collapses = options.splits = !args.shape_only;
  options.split.boundary = args.boundary_splits;
  options.valence = args.valence;
  const Optimize2dStats stats = optimize2d(mesh, options, field);
  const Snapshot after = snapshot(mesh, input);
  const QualityReport report_after = measure_quality(after.data.vertices, after.data.triangles, after.metrics);
  outputs.write(args.output, [&](const std::string& path) { write_mesh2(path, after.data); });
  outputs.commit();

  std::cout << "before:\n" << quality_table(report_before) << "after:\n" << quality_table(report_after);
  std::cout << "operations: " << stats.swaps << " swaps, " << stats.relocations << " relocations, " << stats.collapses
            << " collapses, " << stats.splits << " splits, " << stats.valence_swaps << " valence swaps in "
            << stats.rounds << " rounds (" << stats.stopped_by << ")\n";
  if (args.stats) {
    std::ostringstream json;
    json << "{\"input\":" << json_string(args.input) << ",\"swaps\":" << stats.swaps
         << ",\"relocations\":" << stats.relocations << ",\"collapses\":" << stats.collapses
         << ",\"splits\":" << stats.splits << ",\"valence_swaps\":" << stats.valence_swaps
         << ",\"rounds\":" << stats.rounds << ",\"stopped_by\":" << json_string(stats.stopped_by)
         << ",\"worst_before\":" << json_number(stats.worst_before) << ",\"mean_before\":" << json_number(stats.mean_before)
         << ",\"worst_after\":" << json_number(stats.worst_after) << ",\"mean_after\":" << json_number(stats.mean_after)
         << ",\"triangles_before\":" << stats.triangles_before << ",\"triangles_after\":" << stats.triangles_after
         << ",\"seconds\":" << json_number(stats.seconds) << ",\"peak_rss_mb\":" << json_number(peak_rss_mb())
         << ",\"before\":" << quality_json(report_before) << ",\"after\":" << quality_json(report_after) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

}  // namespace

void add_optimize(CLI::App& app) {
  auto args = std::make_shared<OptimizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "optimize",
      "Optimize a triangle or tetrahedral mesh in a metric (book §8): swaps, relocation, collapses and splits toward "
      "unit edges; the boundary is kept");
  cmd->add_option("mesh", args->input,
                  "The mesh: Medit .mesh (2D: Edges, its constrained edges; 3D: Tetrahedra, with Triangles its "
                  "constrained faces), Triangle .ele (2D) or TetGen .ele (3D, with .node and .face)");
  cmd->add_option("-o,--output", args->output, "Write the optimized mesh (Medit .mesh, or Triangle / TetGen .ele/.node)");
  cmd->add_option("--metric", args->metric, "Medit .sol with the metric (or size) at the mesh's vertices");
  CLI::Option* size = cmd->add_option("--size", args->size, "Optimize toward the isotropic size H (the metric H^-2 I)");
  cmd->add_option("--rounds", args->rounds, "At most this many rounds of the strategy (default 8)")
      ->check(CLI::Range(0u, 1000u));
  cmd->add_option("--max-elements", args->max_elements,
                  "With a size or metric: refuse, before any change, one that asks for more elements than this "
                  "(estimated from its complexity; default: half this machine's memory at the bytes an element costs)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 48));
  cmd->add_flag("--shape-only", args->shape_only, "No collapses or splits: swaps and relocation only");
  cmd->add_flag("--split-boundary", args->boundary_splits,
                "Split long boundary edges too (2D only: the new points lie on them, their references kept)");
  cmd->add_flag("--valence", args->valence, "Add valence relaxation (degrees toward 6)");
  cmd->add_flag("--no-remesh", args->no_remesh,
                "3D: leave out the last step, which meshes again (by the generator) the regions around the "
                "tetrahedra still below 20 degrees");
  cmd->add_flag("--stats", args->stats, "Print one JSON object with the counts and both quality reports as the last line");
  cmd->add_flag("--list-operators", args->list,
                "List the operators of a round in their order (name, tab, description) for MESH's dimension, or "
                "for both without MESH, and exit");
  cmd->callback([args, size] {
    args->size_given = size->count() > 0;
    exit_code() = run_optimize(*args);
  });
}

}  // namespace dtlab::cli
