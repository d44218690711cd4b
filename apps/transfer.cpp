// `dtlab transfer OLD.mesh U.sol NEW.mesh -o U_new.sol`: a vertex solution moved from one mesh to
// another (algorithms/adapt/transfer.hpp; book §9.8, §12.2.6). A scalar is interpolated P1
// (optionally with the conservative global correction); a tensor .sol is a metric (Medit's type
// 3 is the symmetric tensor MMG exchanges metrics in) and is interpolated as a metric, so it stays
// positive definite. 2D meshes only so far.
#include <iostream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/adapt/transfer.hpp"
#include "apps/cli_util.hpp"
#include "apps/input_files.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit_sol.hpp"

namespace dtlab::cli {
namespace {

struct TransferArgs {
  std::string old_mesh, sol, new_mesh, output;
  bool conservative = false;
  bool stats = false;
};

int run_transfer(const TransferArgs& args) {
  if (input_dimension(args.old_mesh) != 2 || input_dimension(args.new_mesh) != 2) {
    throw InputError("dtlab transfer handles 2D meshes only (" + args.old_mesh + ", " + args.new_mesh + ")");
  }
  const MeshData2 old_mesh = read_mesh2(args.old_mesh);
  const MeshData2 new_mesh = read_mesh2(args.new_mesh);
  const SolData sol = read_medit_sol(args.sol);
  if (sol.dimension != 2) throw InputError(args.sol + ": a " + std::to_string(sol.dimension) + "D solution for 2D meshes");
  check_sol_matches(sol, old_mesh.vertices.size(), args.sol);
  TransferStats stats;
  SolData out;
  out.dimension = 2;
  out.kind = sol.kind;
  try {
    if (sol.kind == SolData::Kind::Tensor) {
      if (args.conservative) throw InputError("--conservative applies to scalar solutions, not to metrics");
      const std::vector<Metric2> metrics = metrics2_from_sol(sol, args.sol);
      out = sol_from_metrics(transfer_metrics2(old_mesh, metrics, new_mesh, {}, &stats));
    } else {
      out.values = transfer_field2(old_mesh, sol.values, 1, new_mesh, {.conservative = args.conservative}, &stats);
    }
  } catch (const InputError& e) {
    throw InputError(args.old_mesh + " -> " + args.new_mesh + ": " + e.what(), e.items());
  }
  write_medit_sol(args.output, out);
  if (args.stats) {
    std::cout << "{\"vertices\": " << new_mesh.vertices.size() << ", \"located\": " << stats.located
              << ", \"snapped\": " << stats.snapped << ", \"rescanned\": " << stats.rescanned
              << ", \"max_outside_distance\": " << json_number(stats.max_outside_distance);
    if (!stats.integral_old.empty()) {
      std::cout << ", \"integral_old\": " << json_number(stats.integral_old[0])
                << ", \"integral_new\": " << json_number(stats.integral_new[0]);
    }
    std::cout << "}\n";
  }
  return 0;
}

}  // namespace

void add_transfer(CLI::App& app) {
  auto args = std::make_shared<TransferArgs>();
  CLI::App* cmd = app.add_subcommand(
      "transfer", "Move a vertex solution (.sol) from OLD.mesh to the vertices of NEW.mesh: P1 interpolation, "
                  "metrics as metrics; vertices outside OLD take the nearest boundary point's value");
  cmd->add_option("old", args->old_mesh, "The mesh the solution lives on (Medit .mesh or Triangle .ele)")->required();
  cmd->add_option("sol", args->sol, "Medit .sol/.solb at OLD's vertices (scalar, or a metric tensor)")->required();
  cmd->add_option("new", args->new_mesh, "The mesh to transfer to")->required();
  cmd->add_option("-o,--output", args->output, "The transferred .sol/.solb")->required();
  cmd->add_flag("--conservative", args->conservative,
                "Scalar: shift by a constant so that the P1 integral over NEW equals the one over OLD");
  cmd->add_flag("--stats", args->stats, "Print one JSON line: located, snapped, integrals");
  cmd->callback([args] { exit_code() = run_transfer(*args); });
}

}  // namespace dtlab::cli
