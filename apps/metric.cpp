// `dtlab metric MESH.mesh --solution U.sol [--solution V.sol ...] -o M.sol [--norm inf|Lp]
//  [--p P] [--complexity N | --error EPS] [--relative CUTOFF] [--hessian lsq|l2] [--hmin A]
//  [--hmax B] [--hgrad G] [--stats]`: the metric that equidistributes the P1 interpolation error
// of the given fields (algorithms/adapt/metric_from_solution.hpp, book §12.2; Frey and Alauzet
// 2005; Loseille and Alauzet 2011), in 2D or 3D (the mesh's dimension), written as a Medit
// tensor .sol at the mesh's vertices for `dtlab adapt --metric`. Several --solution files give
// the intersection of their metrics.
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/adapt/metric_from_solution.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit_sol.hpp"

namespace dtlab::cli {

namespace {

struct MetricArgs {
  std::string mesh;
  std::vector<std::string> solutions;
  std::string output;
  std::string norm = "inf";
  double p = 2.0;
  bool p_given = false;  // --p was given (with --norm Lp only)
  std::optional<double> complexity, error, relative, hmin, hmax, hgrad;
  std::string hessian = "lsq";
  bool stats = false;
};

// Each --solution: one scalar per vertex of the mesh, else a named error.
std::vector<std::vector<double>> read_fields(const MetricArgs& args, std::size_t vertices, int dimension) {
  std::vector<std::vector<double>> fields;
  for (const std::string& path : args.solutions) {
    const SolData sol = read_medit_sol(path);
    if (sol.kind != SolData::Kind::Scalar)
      throw InputError(path + ": a tensor solution; --solution takes a scalar field (one value per vertex)");
    if (sol.dimension != dimension)
      throw InputError(path + ": a " + std::to_string(sol.dimension) + "D solution for the " +
                       std::to_string(dimension) + "D mesh " + args.mesh);
    check_sol_matches(sol, vertices, path);
    fields.push_back(sol.values);
  }
  return fields;
}

SolutionMetricOptions options_of(const MetricArgs& args) {
  SolutionMetricOptions o;
  o.recovery = args.hessian == "l2" ? HessianRecovery::L2Projection : HessianRecovery::LeastSquares;
  o.p = args.norm == "inf" ? std::numeric_limits<double>::infinity() : args.norm == "L2" ? 2.0 : args.p;
  o.complexity = args.complexity;
  o.error = args.error;
  o.relative_cutoff = args.relative;
  o.h_min = args.hmin;
  o.h_max = args.hmax;
  o.gradation = args.hgrad;
  o.field_names = args.solutions;
  return o;
}

void report(const MetricArgs& args, const SolutionMetricStats& s, std::size_t vertices) {
  std::cout << "metric at " << vertices << " vertices: complexity " << json_number(s.complexity) << " (before clipping "
            << json_number(s.complexity_before_clipping) << "), sizes " << json_number(s.h_min) << " to "
            << json_number(s.h_max) << ", anisotropy up to " << json_number(s.max_anisotropy) << "\n";
  if (!args.stats) return;
  std::ostringstream json;
  json << "{\"mesh\":" << json_string(args.mesh) << ",\"fields\":" << args.solutions.size()
       << ",\"norm\":" << json_string(args.norm) << ",\"complexity_asked\":"
       << (args.complexity ? json_number(*args.complexity) : std::string("null"))
       << ",\"complexity_before_clipping\":" << json_number(s.complexity_before_clipping)
       << ",\"complexity_before_gradation\":" << json_number(s.complexity_before_gradation)
       << ",\"normalisation_scale\":" << json_number(s.normalisation_scale)
       << ",\"complexity\":" << json_number(s.complexity) << ",\"h_min\":" << json_number(s.h_min)
       << ",\"h_max\":" << json_number(s.h_max) << ",\"max_anisotropy\":" << json_number(s.max_anisotropy)
       << ",\"gradation_passes\":" << s.gradation_passes << "}";
  std::cout << json.str() << "\n";
}

// The library's refusals (Hessian recovery, the default sizes, the complexity) name the mesh.
template <class Compute>
auto named(const MetricArgs& args, const Compute& compute) {
  try {
    return compute();
  } catch (const InputError& e) {
    throw InputError(args.mesh + ": " + e.what(), e.items());
  }
}

int run_metric(const MetricArgs& args) {
  if (args.solutions.empty()) throw InputError("give --solution U.sol (a scalar field at the mesh's vertices)");
  if (args.norm == "Lp" && !args.p_given) throw InputError("--norm Lp needs --p P (p >= 1), the exponent of the norm");
  if (args.norm != "Lp" && args.p_given)
    throw InputError("--p goes with --norm Lp; --norm " + args.norm + " has its own exponent");
  if (args.norm == "Lp" && !(args.p >= 1.0)) throw InputError("--p " + std::to_string(args.p) + ": give p >= 1");
  if (args.complexity.has_value() == args.error.has_value())
    throw InputError("give either --complexity N (about the vertex count wanted) or --error EPS (L-infinity only)");
  if (args.complexity && !(*args.complexity > 0.0))
    throw InputError("--complexity " + std::to_string(*args.complexity) + ": give a positive number of vertices");
  // The options' values, named as the command line spells them (the library names its parameters).
  for (const auto& [value, name] : {std::pair{args.error, "--error"}, std::pair{args.relative, "--relative"},
                                    std::pair{args.hmin, "--hmin"}, std::pair{args.hmax, "--hmax"}}) {
    if (value && !(std::isfinite(*value) && *value > 0.0))
      throw InputError(std::string(name) + " " + json_number(*value) + ": give a positive finite value");
  }
  if (args.hgrad && !(std::isfinite(*args.hgrad) && *args.hgrad >= 1.0))
    throw InputError("--hgrad " + json_number(*args.hgrad) + ": give a gradation G >= 1");
  if (args.hmin && args.hmax && *args.hmin > *args.hmax)
    throw InputError("--hmin " + json_number(*args.hmin) + " exceeds --hmax " + json_number(*args.hmax));
  const SolutionMetricOptions options = options_of(args);
  StagedOutputs outputs({args.output});
  SolutionMetricStats stats;
  if (input_dimension(args.mesh) == 3) {
    const MeshData3 mesh = read_mesh3(args.mesh);
    const auto fields = read_fields(args, mesh.vertices.size(), 3);
    const auto metrics = named(args, [&] { return metric_from_solutions(mesh.vertices, mesh.tetrahedra, fields, options, &stats); });
    outputs.write(args.output, [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(metrics)); });
    report(args, stats, mesh.vertices.size());
  } else {
    const MeshData2 mesh = read_mesh2(args.mesh);
    const auto fields = read_fields(args, mesh.vertices.size(), 2);
    const auto metrics = named(args, [&] { return metric_from_solutions(mesh.vertices, mesh.triangles, fields, options, &stats); });
    outputs.write(args.output, [&](const std::string& path) { write_medit_sol(path, sol_from_metrics(metrics)); });
    report(args, stats, mesh.vertices.size());
  }
  outputs.commit();
  return 0;
}

}  // namespace

void add_metric(CLI::App& app) {
  auto args = std::make_shared<MetricArgs>();
  CLI::App* cmd = app.add_subcommand(
      "metric",
      "The metric of the P1 interpolation error of scalar fields at a mesh's vertices (book §12.2): Hessian recovery, "
      "L-infinity or Lp norm, a target complexity or error, size bounds, gradation; several fields are intersected");
  cmd->add_option("mesh", args->mesh, "The mesh: Medit .mesh (2D or 3D)")->required();
  cmd->add_option("--solution", args->solutions, "Medit .sol with one scalar per vertex; repeat for several fields")
      ->required();
  cmd->add_option("-o,--output", args->output, "Write the metric (Medit tensor .sol / .solb)")->required();
  cmd->add_option("--norm", args->norm, "inf (L-infinity, the default), L2, or Lp with --p")
      ->check(CLI::IsMember({"inf", "L2", "Lp"}));
  CLI::Option* p = cmd->add_option("--p", args->p, "p of the Lp norm (with --norm Lp, required there)");
  cmd->add_option("--complexity", args->complexity, "Target complexity N: about the number of vertices wanted");
  cmd->add_option("--error", args->error, "Target L-infinity interpolation error (instead of --complexity)");
  cmd->add_option("--relative", args->relative, "Relative error: |H| / max(|u|, CUTOFF max|u|)");
  cmd->add_option("--hessian", args->hessian, "Hessian recovery: lsq (least squares, the default) or l2 (double L2 projection)")
      ->check(CLI::IsMember({"lsq", "l2"}));
  cmd->add_option("--hmin", args->hmin, "Smallest size (default 1e-8 of the diagonal)");
  cmd->add_option("--hmax", args->hmax, "Largest size (default the diagonal)");
  cmd->add_option("--hgrad", args->hgrad, "Gradation: bound the size ratio along a unit edge by G >= 1");
  cmd->add_flag("--stats", args->stats, "Print one JSON object with the complexity and the sizes last");
  cmd->callback([args, p] {
    args->p_given = p->count() > 0;
    exit_code() = run_metric(*args);
  });
}

}  // namespace dtlab::cli
