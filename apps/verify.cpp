// `dtlab verify POINTS MESH`: the exact checks of verify/ on files produced by any tool.
#include <iostream>
#include <memory>

#include "algorithms/delaunay2d/prepare.hpp"
#include "apps/cli_util.hpp"
#include "apps/input_files.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "verify/checks2d.hpp"

namespace dtlab::cli {

namespace {

struct VerifyArgs {
  std::string points;
  std::string mesh;
  bool json = false;
};

int run_verify(const VerifyArgs& args) {
  const std::vector<Vec2> points = read_points2(args.points);
  const MeshData2 mesh = read_mesh2(args.mesh);
  // The mesh must be on exactly these points, in this order.
  if (mesh.vertices.size() != points.size()) {
    throw InputError(args.mesh + " has " + std::to_string(mesh.vertices.size()) + " vertices but " + args.points +
                     " has " + std::to_string(points.size()) + " points");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(mesh.vertices[i] == points[i])) {
      throw InputError("vertex " + std::to_string(i + 1) + " of " + args.mesh + " differs from point " +
                           std::to_string(i + 1) + " of " + args.points,
                       {i});
    }
  }
  const PreparedPoints2 prepared = prepare_points2(points, 0);
  const CheckReport2 report = verify_delaunay2d(points, mesh.triangles, prepared.duplicates);
  const std::string text = args.json ? to_json(report) : to_text(report);
  std::cout << text << (text.ends_with('\n') ? "" : "\n");
  return report.ok ? 0 : 3;
}

}  // namespace

void add_verify(CLI::App& app) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Check a 2D triangulation exactly: topology, orientation, empty circles, hull coverage, duplicates");
  cmd->add_option("points", args->points, "The input points (plain, .node or .mesh)")->required();
  cmd->add_option("mesh", args->mesh, "The triangulation (.mesh or .ele)")->required();
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->callback([args] {
    exit_code() = run_verify(*args);
  });
}

}  // namespace dtlab::cli
