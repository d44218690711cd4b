// `dtlab adapt` on a 3D mesh (adapt3.hpp): the input mesh with its vertex metrics is the
// background control space (algorithms/mesh3d/control_space.hpp); the mesh is adapted in place
// (book §9.3.1) and written with its references.
#include "apps/adapt3.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/adapt/adapt3d.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "kernel/error.hpp"
#include "mesh/element_edges.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh3_from_data.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab::cli {

namespace {

// The domain as a file: the input's vertex references kept for boundary vertices, its Edges
// (ridges) that are still edges with their references.
MeshData3 output_data(const Mesh3& mesh, const MeshData3& input) {
  std::vector<std::uint32_t> ids;
  MeshData3 out = mesh.domain(&ids);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::uint32_t v = ids[i];
    if (v < input.vertex_refs.size() && (mesh.flags(v) & Mesh3::kOnBoundary) != 0) out.vertex_refs[i] = input.vertex_refs[v];
  }
  for (std::size_t e = 0; e < input.edges.size(); ++e) {
    const auto [a, b] = input.edges[e];
    const auto ia = std::lower_bound(ids.begin(), ids.end(), a), ib = std::lower_bound(ids.begin(), ids.end(), b);
    if (ia == ids.end() || *ia != a || ib == ids.end() || *ib != b) continue;
    out.edges.push_back({static_cast<std::uint32_t>(ia - ids.begin()), static_cast<std::uint32_t>(ib - ids.begin())});
    out.edge_refs.push_back(input.edge_refs.empty() ? 0 : input.edge_refs[e]);
  }
  return out;
}

}  // namespace

int run_adapt3(const AdaptRequest& request) {
  if (request.method == "reconstruct")
    throw InputError("--method reconstruct: the reconstruction (book §9.3.2) is 2D only; use --method local for " +
                     request.mesh);
  if (request.method != "local") throw InputError("--method " + request.method + ": give local or reconstruct");
  if (request.max_rounds == 0 || request.max_rounds > 1000)
    throw InputError("--rounds " + std::to_string(request.max_rounds) + ": give 1 to 1000 rounds");
  if (request.boundary_deviation)
    throw InputError("--hausd: 3D adaptation removes no boundary vertex yet, so there is no deviation to bound (" +
                     request.mesh + ")");
  StagedOutputs outputs({request.output, request.output_metric});
  const MeshData3 input = read_mesh3(request.mesh);
  if (input.tetrahedra.empty()) throw InputError(request.mesh + ": no Tetrahedra (a 3D mesh is needed)");
  std::vector<Metric3> metrics = read_metrics<Metric3>(request.metric, input.vertices.size());
  if (request.hgrad) {
    if (!(*request.hgrad > 1.0))
      throw InputError("--hgrad " + json_number(*request.hgrad) + ": give a gradation above 1");
    apply_gradation(input.vertices, element_edges(std::span<const std::array<std::uint32_t, 4>>(input.tetrahedra)), metrics,
                    *request.hgrad);
  }
  Mesh3 mesh;
  std::vector<std::string> messages;
  try {
    mesh = mesh3_from_data(input, {}, &messages);
  } catch (const InputError& e) {
    throw InputError(request.mesh + ": " + e.what(), e.items());
  }
  for (const std::string& m : messages) std::cerr << "dtlab: " << request.mesh << ": " << m << "\n";
  ControlSpace3 control = [&] {
    try {
      return ControlSpace3(input, metrics);
    } catch (const InputError& e) {
      throw InputError(request.mesh + " / " + request.metric + ": " + e.what(), e.items());
    }
  }();
  Adapt3dOptions options;
  options.max_rounds = request.max_rounds;
  options.max_elements = request.max_elements;
  options.ridge_angle_degrees = request.ridge_angle;  // the surface support's ridges and corners
  options.boundary = !request.keep_boundary;
  const Adapt3dStats stats = adapt3d(mesh, control, options);
  outputs.write(request.output, [&](const std::string& path) { write_mesh3(path, output_data(mesh, input)); });
  outputs.write(request.output_metric, [&](const std::string& path) {
    std::vector<std::uint32_t> ids;
    mesh.domain(&ids);
    std::vector<Metric3> at_vertices;
    at_vertices.reserve(ids.size());
    for (const std::uint32_t v : ids) at_vertices.push_back(mesh.metric(v));
    write_medit_sol(path, sol_from_metrics(at_vertices));
  });
  outputs.commit();

  std::cout << "before:\n" << quality_table(stats.before) << "after:\n" << quality_table(stats.after);
  std::cout << "operations: " << stats.collapses << " collapses, " << stats.splits << " splits, " << stats.boundary_splits << " boundary splits, " << stats.face_swaps
            << " face swaps, " << stats.shell_transformations << " shell transformations, " << stats.relocations
            << " relocations in " << stats.rounds << " rounds (" << stats.stopped_by << "), "
            << json_number(stats.seconds) << " s, " << json_number(stats.tetrahedra_per_second) << " tetrahedra/s\n";
  if (request.stats) {
    std::ostringstream json;
    json << "{\"input\":" << json_string(request.mesh) << ",\"dimension\":3,\"method\":" << json_string(request.method)
         << ",\"collapses\":" << stats.collapses << ",\"splits\":" << stats.splits << ",\"boundary_splits\":" << stats.boundary_splits << ",\"face_swaps\":" << stats.face_swaps
         << ",\"shell_transformations\":" << stats.shell_transformations << ",\"relocations\":" << stats.relocations
         << ",\"rounds\":" << stats.rounds << ",\"stopped_by\":" << json_string(stats.stopped_by)
         << ",\"seconds\":" << json_number(stats.seconds)
         << ",\"tetrahedra_per_second\":" << json_number(stats.tetrahedra_per_second)
         << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << ",\"before\":" << quality_json(stats.before)
         << ",\"after\":" << quality_json(stats.after) << "}";
    std::cout << json.str() << "\n";
  }
  return 0;
}

}  // namespace dtlab::cli
