// `dtlab verify POINTS MESH`: the exact checks of verify/ on files produced by any tool.
#include <iostream>
#include <memory>

#include "algorithms/delaunay2d/prepare.hpp"
#include "algorithms/delaunay3d/prepare.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/tetrahedralization3_build.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks3d.hpp"

namespace dtlab::cli {

namespace {

struct VerifyArgs {
  std::string points;
  std::string mesh;
  bool json = false;
};

// The same in 3D: the mesh's tetrahedra become a Tetrahedralization3 (closed by ghosts), which
// the exact checks of verify/checks3d.hpp then examine.
int run_verify3(const VerifyArgs& args) {
  std::vector<Vec3> points = read_points3(args.points);
  const MeshData3 mesh = read_mesh3(args.mesh);
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
  const PreparedPoints3 prepared = prepare_points3(points, 0);
  const std::vector<std::uint32_t> duplicates = prepared.duplicates;
  const Tetrahedralization3 tet = tetrahedralization_from_tetrahedra(std::move(points), mesh.tetrahedra);
  const CheckReport3 report = verify_delaunay3d(tet.points(), tet, duplicates);
  const std::string text = args.json ? to_json(report) : to_text(report);
  std::cout << text << (text.ends_with('\n') ? "" : "\n");
  return report.ok ? 0 : 3;
}

int run_verify(const VerifyArgs& args) {
  if (input_dimension(args.points) == 3) return run_verify3(args);
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
      "verify",
      "Check a 2D or 3D Delaunay triangulation exactly: topology, orientation, empty circles or spheres, hull "
      "coverage, duplicates");
  cmd->add_option("points", args->points, "The input points (plain, .node or .mesh; 2D or 3D)")->required();
  cmd->add_option("mesh", args->mesh, "The triangulation (.mesh or .ele; 3D: .mesh)")->required();
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->callback([args] {
    exit_code() = run_verify(*args);
  });
}

}  // namespace dtlab::cli
