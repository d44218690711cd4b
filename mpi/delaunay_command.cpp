#include "mpi/delaunay_command.hpp"

#include <chrono>
#include <iostream>
#include <sstream>

#include "algorithms/distributed/distributed_in_process.hpp"
#include "kernel/error.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "mesh/triangulation2.hpp"
#include "mpi/distributed_delaunay.hpp"
#include "verify/generators/points2d.hpp"
#include "verify/generators/points3d.hpp"
#include "verify/problem_report.hpp"

namespace dtlab::mpi {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Rank 0's report: the degenerate case, --check, --stats.
template <class Result, class Points, class Sequential>
int finish(const Comm& comm, const DelaunayArgs& args, const Prepared& p, const Result& result, double seconds,
           const Points& points, const Sequential& sequential) {
  if (comm.rank() != 0) return 0;
  if (!result.degenerate_message.empty())
    std::cerr << "dtlab-mpi: no elements: " << result.degenerate_message << "\n";
  int code = 0;
  if (args.check) {
    const bool same = sequential() == result.elements;
    std::cout << (same ? "check: the same elements as the sequential call\n"
                       : "check: FAILED: the elements differ from the sequential call's\n");
    code = same ? 0 : 3;
  }
  if (args.stats) {
    std::cout << "{\"input\":" << json_string(p.source) << ",\"dim\":" << p.dim << ",\"ranks\":" << comm.size()
              << ",\"points\":" << points.size() << ",\"elements\":" << result.elements.size()
              << ",\"rounds\":" << result.rounds << ",\"ghosts\":" << result.ghosts
              << ",\"ghost_share\":" << number(points.empty() ? 0.0 : double(result.ghosts) / double(points.size()))
              << ",\"questions\":" << result.questions << ",\"bytes_exchanged\":" << result.bytes_exchanged
              << ",\"seconds_triangulating_max_rank\":" << number(result.seconds_max_triangulating)
              << ",\"seconds\":" << number(seconds) << "}\n";
  }
  return code;
}

}  // namespace

void add_delaunay(CLI::App& app, DelaunayArgs& args) {
  CLI::App* cmd = app.add_subcommand("delaunay", "Delaunay triangulation of a point set, one k-d tile per rank");
  cmd->add_option("input", args.input, "Point file, as `dtlab delaunay` reads it (every rank reads it)");
  cmd->add_option("-o,--output", args.output, "Write the mesh (rank 0): OUT.mesh, the bytes `dtlab delaunay -o` writes");
  cmd->add_option("--random", args.random, "Triangulate N generated points instead of a file");
  cmd->add_option("--dim", args.dim, "Dimension of the generated points")->capture_default_str()->check(CLI::Range(2, 3));
  cmd->add_option("--distribution", args.distribution, "Distribution of the generated points (as `dtlab delaunay`)")
      ->capture_default_str();
  cmd->add_option("--seed", args.seed, "Seed of the generated points")->capture_default_str();
  cmd->add_flag("--stats", args.stats, "Print rounds, ghost points, bytes exchanged and time as JSON (rank 0)");
  cmd->add_flag("--check", args.check,
                "Rank 0 also runs the sequential call and compares (exit 3 when they differ)");
}

Prepared prepare(const DelaunayArgs& args) {
  if (args.input.empty() == (args.random == 0)) throw InputError("give either an INPUT file or --random N");
  Prepared p;
  p.dim = args.input.empty() ? args.dim : input_dimension(args.input);
  // The sequential structures' limits (every rank holds the points, rank 0 the elements).
  const std::uint64_t limit = p.dim == 3 ? Tetrahedralization3::kMaxPoints : Triangulation2::kMaxPoints;
  if (args.random > limit)
    throw InputError("--random: " + std::to_string(args.random) + " points exceed the " + std::to_string(p.dim) +
                     "D limit of " + std::to_string(limit));
  p.source = args.input.empty() ? "random " + args.distribution + " n=" + std::to_string(args.random) +
                                      " seed=" + std::to_string(args.seed)
                                : args.input;
  if (p.dim == 3) {
    p.points3 = args.input.empty() ? generate_points3d(args.distribution, args.random, args.seed) : read_points3(args.input);
  } else {
    p.points2 = args.input.empty() ? generate_points2d(args.distribution, args.random, args.seed) : read_points2(args.input);
  }
  return p;
}

int run_delaunay(const Comm& comm, const DelaunayArgs& args, const Prepared& p) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  if (p.dim == 3) {
    const auto result = distributed_delaunay(comm, std::span<const Vec3>(p.points3));
    const double seconds = comm.max(elapsed());
    if (comm.rank() == 0 && !args.output.empty()) {
      MeshData3 mesh;
      mesh.vertices = p.points3;
      mesh.tetrahedra = result.elements;
      write_mesh3(args.output, mesh);
    }
    return finish(comm, args, p, result, seconds, p.points3,
                  [&] { return canonical_delaunay_elements(std::span<const Vec3>(p.points3)); });
  }
  const auto result = distributed_delaunay(comm, std::span<const Vec2>(p.points2));
  const double seconds = comm.max(elapsed());
  if (comm.rank() == 0 && !args.output.empty()) {
    MeshData2 mesh;
    mesh.vertices = p.points2;
    mesh.vertex_refs.assign(p.points2.size(), 0);
    mesh.triangles = result.elements;
    mesh.triangle_refs.assign(result.elements.size(), 0);
    write_mesh2(args.output, mesh);
  }
  return finish(comm, args, p, result, seconds, p.points2,
                [&] { return canonical_delaunay_elements(std::span<const Vec2>(p.points2)); });
}

}  // namespace dtlab::mpi
