// `dtlab transfer OLD.mesh U.sol NEW.mesh -o U_new.sol`: a vertex solution moved from one mesh to
// another (algorithms/adapt/transfer.hpp; book §9.8, §12.2.6). A scalar is interpolated P1
// (optionally with the conservative global correction); a tensor .sol is a metric (Medit's type
// 3 is the symmetric tensor MMG exchanges metrics in) and is interpolated as a metric, so it stays
// positive definite. Triangle and tetrahedral meshes.
#include <iostream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "algorithms/adapt/transfer.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit_sol.hpp"

namespace dtlab::cli {
namespace {

template <int D>
auto read_mesh2_or_3(const std::string& path) {
  if constexpr (D == 2) return read_mesh2(path);
  else return read_mesh3(path);
}

struct TransferArgs {
  std::string old_mesh, sol, new_mesh, output;
  bool conservative = false;
  bool stats = false;
};

// The transfer in dimension D (2 or 3): the meshes read, the solution checked, transferred.
template <int D>
SolData transfer_sol(const TransferArgs& args, const SolData& sol, TransferStats& stats, std::size_t& new_vertices) {
  const auto old_mesh = read_mesh2_or_3<D>(args.old_mesh);
  const auto new_mesh = read_mesh2_or_3<D>(args.new_mesh);
  check_sol_matches(sol, old_mesh.vertices.size(), args.sol);
  new_vertices = new_mesh.vertices.size();
  SolData out;
  out.dimension = D;
  out.kind = sol.kind;
  try {
    if (sol.kind == SolData::Kind::Tensor) {
      if (args.conservative) throw InputError("--conservative applies to scalar solutions, not to metrics");
      if constexpr (D == 2) {
        out = sol_from_metrics(transfer_metrics2(old_mesh, metrics2_from_sol(sol, args.sol), new_mesh, {}, &stats));
      } else {
        out = sol_from_metrics(transfer_metrics3(old_mesh, metrics3_from_sol(sol, args.sol), new_mesh, {}, &stats));
      }
    } else {
      const TransferOptions options{.conservative = args.conservative};
      if constexpr (D == 2) out.values = transfer_field2(old_mesh, sol.values, 1, new_mesh, options, &stats);
      else out.values = transfer_field3(old_mesh, sol.values, 1, new_mesh, options, &stats);
    }
  } catch (const InputError& e) {
    throw InputError(args.old_mesh + " -> " + args.new_mesh + ": " + e.what(), e.items());
  }
  return out;
}

int run_transfer(const TransferArgs& args) {
  const int dimension = input_dimension(args.old_mesh);
  if (input_dimension(args.new_mesh) != dimension) {
    throw InputError(args.old_mesh + " is a " + std::to_string(dimension) + "D mesh but " + args.new_mesh + " is not");
  }
  StagedOutputs outputs({args.output});
  const SolData sol = read_medit_sol(args.sol);
  if (sol.dimension != dimension) {
    throw InputError(args.sol + ": a " + std::to_string(sol.dimension) + "D solution for " + std::to_string(dimension) +
                     "D meshes");
  }
  TransferStats stats;
  std::size_t new_vertices = 0;
  const SolData out = dimension == 3 ? transfer_sol<3>(args, sol, stats, new_vertices)
                                     : transfer_sol<2>(args, sol, stats, new_vertices);
  outputs.write(args.output, [&](const std::string& path) { write_medit_sol(path, out); });
  outputs.commit();
  if (args.stats) {
    std::cout << "{\"vertices\": " << new_vertices << ", \"located\": " << stats.located
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
  cmd->add_option("old", args->old_mesh, "The mesh the solution lives on (Medit .mesh, or Triangle / TetGen .ele): triangles or tetrahedra")->required();
  cmd->add_option("sol", args->sol, "Medit .sol/.solb at OLD's vertices (scalar, or a metric tensor)")->required();
  cmd->add_option("new", args->new_mesh, "The mesh to transfer to")->required();
  cmd->add_option("-o,--output", args->output, "The transferred .sol/.solb")->required();
  cmd->add_flag("--conservative", args->conservative,
                "Scalar: shift by a constant so that the P1 integral over NEW equals the one over OLD");
  cmd->add_flag("--stats", args->stats, "Print one JSON line: located, snapped, integrals");
  cmd->callback([args] { exit_code() = run_transfer(*args); });
}

}  // namespace dtlab::cli
