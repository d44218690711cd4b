// `dtlab quality MESH [--metric M.sol] [--background B.mesh] [--size H] [--json]`: the quality
// figures of mesh/mesh_quality.hpp (the book's Tables 7.1-8.3 and the UGAWG unit-mesh measures)
// for any triangle or tetrahedron mesh: Medit .mesh, Triangle or TetGen .node/.ele (the .ele
// path, or the base name). The metric: none, the isotropic H^-2 I, one per vertex from a Medit
// .sol, or (2D) a .sol on a background mesh interpolated at the vertices (ControlSpace2).
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "algorithms/mesh2d/control_space.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/io/planar_mesh.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab::cli {

namespace {

struct QualityArgs {
  std::string mesh;
  std::string metric;      // .sol: at the mesh's vertices, or at the background's
  std::string background;  // 2D only
  std::string size;        // kept as text: refused with our own message, exit code 1
  bool size_given = false;
  bool json = false;
};

template <class Cells>
std::vector<char> used_vertices(std::size_t count, const Cells& cells) {
  std::vector<char> used(count, 0);
  for (const auto& c : cells)
    for (std::uint32_t v : c)
      if (v < count) used[v] = 1;
  return used;
}

void print(const QualityReport& report, bool json) {
  if (json)
    std::cout << quality_json(report) << "\n";
  else
    std::cout << quality_table(report);
}

int run_quality2(const QualityArgs& args, const MeshData2& mesh, const std::string& path, const std::optional<double>& size) {
  if (mesh.triangles.empty())
    throw InputError(path + ": no triangles (" + std::to_string(mesh.vertices.size()) + " vertices): nothing to measure");
  std::vector<Metric2> metrics;
  if (size) {
    metrics.assign(mesh.vertices.size(), Metric2::isotropic(*size));
  } else if (!args.background.empty()) {
    const MeshData2 background = read_mesh2(args.background);
    std::vector<Metric2> at_background;
    try {
      at_background = read_metrics<Metric2>(args.metric, background.vertices.size());
    } catch (const InputError& e) {  // "the mesh" of the message is the background here
      throw InputError("--background " + args.background + ": " + e.what(), e.items());
    }
    ControlSpace2 control(background, std::move(at_background));
    // The vertices the elements use, in index order, each walk starting where the last ended.
    const std::vector<char> used = used_vertices(mesh.vertices.size(), mesh.triangles);
    metrics.assign(mesh.vertices.size(), Metric2{});
    std::uint32_t hint = ControlSpace2::kNoHint;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      if (used[v]) metrics[v] = control.metric_at(mesh.vertices[v], hint);
  } else if (!args.metric.empty()) {
    metrics = read_metrics<Metric2>(args.metric, mesh.vertices.size());
  }
  print(measure_quality(mesh.vertices, mesh.triangles, metrics), args.json);
  return 0;
}

int run_quality3(const QualityArgs& args, const std::string& path, const std::optional<double>& size) {
  const MeshData3 mesh = read_mesh3(path, NonPositiveTetrahedra::Keep);  // inverted ones counted
  if (mesh.tetrahedra.empty()) {
    // A 2D mesh in a 3D file (Gmsh writes Medit's Dimension 3 with every z = 0): measured as 2D.
    if (!mesh.triangles.empty() && is_planar(mesh)) return run_quality2(args, planar_to_mesh2(mesh, path), path, size);
    if (mesh.triangles.empty())
      throw InputError(path + ": no tetrahedra and no triangles (" + std::to_string(mesh.vertices.size()) +
                       " vertices): nothing to measure");
    throw InputError(path + ": no tetrahedra, and its " + std::to_string(mesh.triangles.size()) +
                     " triangles are not all at z = 0: dtlab quality measures tetrahedron meshes and triangle "
                     "meshes in the plane");
  }
  if (!args.background.empty())
    throw InputError("--background " + args.background + ": a background mesh is supported for 2D meshes only, and " +
                     path + " is 3D (give --metric at its vertices, or --size)");
  std::vector<Metric3> metrics;
  if (size)
    metrics.assign(mesh.vertices.size(), Metric3::isotropic(*size));
  else if (!args.metric.empty())
    metrics = read_metrics<Metric3>(args.metric, mesh.vertices.size());
  print(measure_quality(mesh.vertices, mesh.tetrahedra, metrics), args.json);
  return 0;
}

int run_quality(const QualityArgs& args) {
  const std::optional<double> size = args.size_given ? std::optional<double>(parse_size(args.size)) : std::nullopt;
  if (size && (!args.metric.empty() || !args.background.empty()))
    throw InputError("--size " + args.size + ": give either --size or --metric (with or without --background)");
  if (!args.background.empty() && args.metric.empty())
    throw InputError("--background " + args.background + " needs --metric, the metric at its vertices");
  const std::string path = mesh_input_path(args.mesh, "quality");
  return input_dimension(path) == 3 ? run_quality3(args, path, size) : run_quality2(args, read_mesh2(path), path, size);
}

}  // namespace

void add_quality(CLI::App& app) {
  auto args = std::make_shared<QualityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "quality",
      "Measure a triangle or tetrahedron mesh: Q_M and the share of elements with Q in [1,2], ]2,3], ]3,10], > 10 "
      "(the book's tables), angles, edge lengths, unit edges and mean ratio in a metric, inverted elements");
  cmd->add_option("mesh", args->mesh, "The mesh: Medit .mesh, Triangle/TetGen .ele (or their base name)")->required();
  cmd->add_option("--metric", args->metric, "Medit .sol with the metric at the mesh's (or the background's) vertices");
  cmd->add_option("--background", args->background,
                  "2D: the background mesh of --metric, interpolated at the mesh's vertices");
  CLI::Option* size = cmd->add_option("--size", args->size, "Measure against the isotropic metric of size H (H^-2 I)");
  cmd->add_flag("--json", args->json, "Print one JSON object on one line");
  cmd->callback([args, size] {
    args->size_given = size->count() > 0;
    exit_code() = run_quality(*args);
  });
}

}  // namespace dtlab::cli
