// `dtlab adapt MESH.mesh --metric M.sol -o OUT.mesh [--method local] [--hgrad G] [--stats]`: adapts
// a triangle mesh (or a tetrahedral one: apps/adapt3.hpp, algorithms/adapt/adapt3d.hpp) to a
// metric given at its vertices (book §9.3.1, local modification,
// algorithms/adapt/adapt2d.hpp): the result has unit edges in the metric, its boundary corners
// and references kept, new boundary points on a smooth support of the boundary. The metric is a
// Medit .sol at the mesh's vertices (a size h, or a symmetric tensor), interpolated on the input
// mesh at every new or moved vertex; --hgrad bounds its growth along the edges first (Borouchaki,
// Hecht, Frey 1998). Prints the quality tables (mesh/mesh_quality.hpp: the book's Q statistics and
// the UGAWG metric measures) before and after; --stats adds one JSON line.
#include <cmath>
#include <iostream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/adapt/adapt2d.hpp"
#include "algorithms/adapt/reconstruct2d.hpp"
#include "apps/adapt3.hpp"
#include "apps/adapt_request.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/element_edges.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh2_from_data.hpp"

namespace dtlab::cli {

namespace {

// The domain with its vertex references: an input vertex still in the mesh (same slot, same
// point) keeps its own; a new boundary vertex takes the reference of its boundary edge; the
// others 0.
MeshData2 adapted_data(const Mesh2& mesh, const MeshData2& input, std::vector<Metric2>& metrics) {
  std::vector<std::uint32_t> ids;
  MeshData2 data = mesh.domain(&ids);
  metrics.clear();
  std::vector<std::uint32_t> ring;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::uint32_t v = ids[i];
    metrics.push_back(mesh.metric(v));
    if (v < input.vertices.size() && mesh.point(v) == input.vertices[v]) {
      data.vertex_refs[i] = v < input.vertex_refs.size() ? input.vertex_refs[v] : 0;
    } else if ((mesh.flags(v) & Mesh2::kOnBoundary) != 0) {
      mesh.ball(v, ring);
      for (const std::uint32_t h : ring) {
        if (mesh.is_constrained(Mesh2::prev(h))) {
          data.vertex_refs[i] = mesh.edge_ref(Mesh2::prev(h));
          break;
        }
      }
    }
  }
  return data;
}

// --method reconstruct (algorithms/adapt/reconstruct2d.hpp): the mesh generated anew.
int run_reconstruct2(const AdaptRequest& request, const MeshData2& input, const ControlSpace2& control,
                     std::span<const Metric2> metrics, StagedOutputs& outputs) {
  if (request.keep_boundary) throw InputError("--keep-boundary: the reconstruction cuts the boundary anew (use --method local)");
  Reconstruct2dOptions options;
  options.ridge_angle = request.ridge_angle;
  options.max_elements = request.max_elements;
  const QualityReport before = measure_quality(input.vertices, input.triangles, metrics);
  Reconstruct2dResult r;
  try {
    r = reconstruct2d(input, control, options);
  } catch (const InputError& e) {
    throw InputError(request.mesh + ": " + e.what(), e.items());
  }
  const MeshData2& out = r.generated.output;
  const QualityReport after = measure_quality(out.vertices, out.triangles, r.generated.output_metrics);
  outputs.write(request.output, [&](const std::string& path) { write_mesh2(path, out); });
  outputs.write(request.output_metric,
                [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(r.generated.output_metrics)); });
  outputs.commit();
  const Mesh2dStats& s = r.generated.stats;
  std::cout << "before:\n" << quality_table(before) << "after:\n" << quality_table(after);
  std::cout << "reconstruction: " << r.segments << " segments (" << r.merged_chains << " straight chains merged), "
            << s.boundary_points << " boundary points, " << s.field_points << " field points, " << r.region_seeds
            << " regions, " << r.hole_seeds << " boundary loops; " << json_number(s.seconds) << " s\n";
  if (request.stats) {
    std::ostringstream json;
    json << "{\"input\":" << json_string(request.mesh) << ",\"dimension\":2,\"method\":" << json_string(request.method)
         << ",\"segments\":" << r.segments << ",\"merged_chains\":" << r.merged_chains
         << ",\"boundary_points\":" << s.boundary_points << ",\"field_points\":" << s.field_points
         << ",\"triangles_before\":" << input.triangles.size() << ",\"triangles_after\":" << out.triangles.size()
         << ",\"seconds\":" << json_number(s.seconds)
         << ",\"triangles_per_second\":" << json_number(static_cast<double>(out.triangles.size()) / std::max(s.seconds, 1e-9))
         << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << ",\"before\":" << quality_json(before)
         << ",\"after\":" << quality_json(after) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

int run_adapt2(const AdaptRequest& request) {
  StagedOutputs outputs({request.output, request.output_metric});
  const MeshData2 input = read_mesh2(request.mesh);
  std::vector<Metric2> metrics = read_metrics<Metric2>(request.metric, input.vertices.size());
  if (request.hgrad) apply_gradation(input.vertices, element_edges(std::span<const std::array<std::uint32_t, 3>>(input.triangles)), metrics, *request.hgrad);
  Mesh2 mesh;
  try {
    mesh = mesh2_from_data(input);
  } catch (const InputError& e) {
    throw InputError(request.mesh + ": " + e.what(), e.items());
  }
  const ControlSpace2 control(input, metrics);
  if (request.method == "reconstruct") return run_reconstruct2(request, input, control, metrics, outputs);

  Adapt2dOptions options;
  options.max_rounds = request.max_rounds;
  options.max_elements = request.max_elements;
  options.ridge_angle = request.ridge_angle;
  if (request.boundary_deviation) options.boundary_deviation = *request.boundary_deviation;
  options.boundary_changes = !request.keep_boundary;
  const Adapt2dStats stats = adapt2d(mesh, control, options);

  std::vector<Metric2> out_metrics;
  const MeshData2 out = adapted_data(mesh, input, out_metrics);
  outputs.write(request.output, [&](const std::string& path) { write_mesh2(path, out); });
  outputs.write(request.output_metric, [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(out_metrics)); });
  outputs.commit();

  const Optimize2dStats& ops = stats.operations;
  std::cout << "before:\n" << quality_table(stats.before) << "after:\n" << quality_table(stats.after);
  std::cout << "operations: " << ops.splits << " splits, " << ops.collapses << " collapses, "
            << ops.boundary_collapses << " boundary collapses, " << ops.swaps << " swaps, " << ops.relocations
            << " relocations in " << ops.rounds << " rounds (" << ops.stopped_by << "); " << stats.corners
            << " corners kept; " << json_number(stats.seconds) << " s\n";
  if (request.stats) {
    std::ostringstream json;
    json << "{\"input\":" << json_string(request.mesh) << ",\"dimension\":2,\"method\":" << json_string(request.method)
         << ",\"splits\":" << ops.splits << ",\"collapses\":" << ops.collapses
         << ",\"boundary_collapses\":" << ops.boundary_collapses
         << ",\"boundary_support_fallbacks\":" << ops.boundary_support_fallbacks << ",\"swaps\":" << ops.swaps
         << ",\"relocations\":" << ops.relocations << ",\"rounds\":" << ops.rounds
         << ",\"stopped_by\":" << json_string(ops.stopped_by) << ",\"corners\":" << stats.corners
         << ",\"boundary_deviation\":" << json_number(stats.boundary_deviation)
         << ",\"triangles_before\":" << ops.triangles_before << ",\"triangles_after\":" << ops.triangles_after
         << ",\"seconds\":" << json_number(stats.seconds)
         << ",\"triangles_per_second\":" << json_number(static_cast<double>(ops.triangles_after) / std::max(stats.seconds, 1e-9))
         << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << ",\"before\":" << quality_json(stats.before)
         << ",\"after\":" << quality_json(stats.after) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

int run_adapt(const AdaptRequest& request) {
  if (request.hgrad && !(*request.hgrad >= 1.0 && std::isfinite(*request.hgrad)))
    throw InputError("--hgrad " + std::to_string(*request.hgrad) + ": give a gradation G >= 1 (1: uniform sizes)");
  if (request.boundary_deviation && !(*request.boundary_deviation >= 0.0 && std::isfinite(*request.boundary_deviation)))
    throw InputError("--hausd " + std::to_string(*request.boundary_deviation) + ": give a distance >= 0");
  if (!(request.ridge_angle >= 0.0 && request.ridge_angle <= 180.0))
    throw InputError("--ridge-angle " + std::to_string(request.ridge_angle) + ": give an angle in [0, 180] degrees");
  return input_dimension(request.mesh) == 3 ? run_adapt3(request) : run_adapt2(request);
}

}  // namespace

void add_adapt(CLI::App& app) {
  auto request = std::make_shared<AdaptRequest>();
  CLI::App* cmd = app.add_subcommand(
      "adapt",
      "Adapt a mesh to a metric given at its vertices (book §9.3.1): splits, collapses, swaps and relocation toward "
      "unit edges in the metric, boundary corners and references kept, new boundary points on a smooth support");
  cmd->add_option("mesh", request->mesh, "The mesh: Medit .mesh / .meshb")->required();
  cmd->add_option("--metric", request->metric, "Medit .sol / .solb with the metric (or size) at the mesh's vertices")
      ->required();
  cmd->add_option("-o,--output", request->output, "Write the adapted mesh (Medit .mesh / .meshb)");
  cmd->add_option("--output-metric", request->output_metric, "Write the metric at the adapted mesh's vertices (.sol)");
  cmd->add_option("--method", request->method, "local: local modification (§9.3.1, the default); reconstruct: the mesh generated anew in the metric (§9.3.2, 2D)")
      ->check(CLI::IsMember({"local", "reconstruct"}));
  cmd->add_option("--hgrad", request->hgrad, "Bound the metric's growth along the input's edges by G first (G >= 1)");
  cmd->add_option("--rounds", request->max_rounds, "At most this many rounds (default 12)")->check(CLI::Range(1u, 1000u));
  cmd->add_option("--max-elements", request->max_elements,
                  "Refuse, before any change, a metric that asks for more elements than this (estimated from its "
                  "complexity; default: half this machine's memory at the bytes an element costs)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 48));
  cmd->add_option("--ridge-angle", request->ridge_angle,
                  "Boundary vertices where the boundary turns by more than this many degrees are corners, kept (45)");
  cmd->add_option("--hausd", request->boundary_deviation,
                  "How far a removed boundary vertex may lie from the new boundary (default: 1e-3 of the diagonal)");
  cmd->add_flag("--keep-boundary", request->keep_boundary, "Add or remove no boundary vertex");
  cmd->add_flag("--stats", request->stats, "Print one JSON object with the counts and both quality reports last");
  cmd->callback([request] { exit_code() = run_adapt(*request); });
}

}  // namespace dtlab::cli
