// `dtlab delaunay`: triangulate a point file or a generated point set with any registered
// variant, write the mesh, verify it exactly and report statistics.
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "apps/cli_util.hpp"
#include "apps/delaunay3d.hpp"
#include "apps/delaunay_remove.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "mesh/triangulation2.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab::cli {

namespace {

// Bounds of the numeric options: the 2D structure's point limit (mesh/triangulation2.hpp; the 3D
// one is lower and delaunay3d names it), and a thread count no machine here reaches.
constexpr std::uint64_t kMaxRandomPoints = Triangulation2::kMaxPoints;
constexpr std::uint64_t kMaxThreads = 1024;

struct DelaunayArgs {
  std::string input;
  std::string output;
  std::string algorithm = "incremental";
  bool stats = false;
  bool verify = false;
  bool list = false;
  std::size_t random = 0;
  int dim = 2;
  std::string distribution = "uniform";
  std::uint64_t seed = 1;
  unsigned threads = 1;
  std::string remove_file;        // --remove: apps/delaunay_remove.hpp
  std::optional<double> remove_fraction;  // --remove-random
};

std::string list_items(const std::vector<std::uint32_t>& items, const std::vector<std::uint32_t>& of,
                       std::size_t limit) {
  std::ostringstream s;
  for (std::size_t i = 0; i < items.size() && i < limit; ++i) {
    s << (i ? ", " : "") << items[i] + 1 << " (= " << of[i] + 1 << ")";
  }
  if (items.size() > limit) s << ", ... (" << items.size() - limit << " more)";
  return s.str();
}

int run_delaunay(const DelaunayArgs& args) {
  if (args.list) {
    if (args.dim == 3) return list_delaunay3d_variants();
    for (const Delaunay2dVariant& v : delaunay2d_variants()) std::cout << v.name << "\t" << v.description << "\n";
    return 0;
  }
  if (args.input.empty() == (args.random == 0)) {
    throw InputError("give either an INPUT file or --random N");
  }
  if (!args.remove_file.empty() || args.remove_fraction) {
    return run_delaunay_remove({args.input, args.output, args.algorithm, args.stats, args.verify, args.random,
                                args.distribution, args.seed, args.dim, args.remove_file, args.remove_fraction});
  }
  if (args.dim == 3 || (!args.input.empty() && input_dimension(args.input) == 3)) {
    return run_delaunay3d({args.input, args.output, args.algorithm, args.stats, args.verify, args.random,
                           args.distribution, args.seed, args.threads});
  }
  if (args.dim != 2) throw InputError("--dim must be 2 or 3, not " + std::to_string(args.dim));
  if (args.threads != 1) throw InputError("--threads: the 2D variants are sequential (give --threads 1 or leave it out)");
  StagedOutputs outputs({args.output});
  const std::string source = args.input.empty()
                                 ? "random " + args.distribution + " n=" + std::to_string(args.random) +
                                       " seed=" + std::to_string(args.seed)
                                 : args.input;
  const std::vector<Vec2> points = args.input.empty()
                                       ? generate_points2d(args.distribution, args.random, args.seed)
                                       : read_points2(args.input);

  Delaunay2dOptions options;
  options.algorithm = args.algorithm;
  Delaunay2dResult result = delaunay2d(points, options);
  // Memory of reading and triangulating, before any output is materialised.
  const double peak_triangulation_mb = peak_rss_mb();
  const std::size_t element_count = result.triangulation.finite_triangle_count();
  // Canonical order (each triangle from its smallest id, then sorted): every variant writes the
  // same bytes for the same triangles. Only built when written or verified.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  if (!args.output.empty() || args.verify) {
    triangles = canonical_triangle_set(result.triangulation.finite_triangles());
  }

  if (!result.duplicates.empty()) {
    std::cerr << "dtlab: " << result.duplicates.size()
              << " duplicate point(s), kept as unreferenced vertices (point = first point with the same "
                 "coordinates, numbered from 1): "
              << list_items(result.duplicates, result.duplicate_of, 20) << "\n";
  }
  if (!result.degenerate_message.empty()) {
    std::cerr << "dtlab: no triangles: " << result.degenerate_message << "\n";
  }

  if (!args.output.empty()) {
    MeshData2 mesh;
    mesh.vertices = points;
    mesh.vertex_refs.assign(points.size(), 0);
    mesh.triangles = triangles;
    mesh.triangle_refs.assign(triangles.size(), 0);
    outputs.write(args.output, [&](const std::string& path) { write_mesh2(path, mesh); });
    outputs.commit();  // before --verify: a failed check (exit 3) leaves the output to look at
  }

  bool verified_ok = true;
  if (args.verify) {
    const CheckReport2 report = verify_delaunay2d(points, triangles, result.duplicates);
    std::cout << to_text(report);
    if (to_text(report).back() != '\n') std::cout << "\n";
    verified_ok = report.ok;
  }

  if (args.stats) {
    const double seconds = result.seconds;
    const double per_minute = seconds > 0 ? static_cast<double>(element_count) * 60.0 / seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(source) << ",\"dim\":2,\"algo\":" << json_string(args.algorithm)
         << ",\"points\":" << points.size() << ",\"distinct_points\":" << points.size() - result.duplicates.size()
         << ",\"duplicates\":" << result.duplicates.size() << ",\"elements\":" << element_count
         << ",\"seconds\":" << json_number(seconds) << ",\"elements_per_minute\":" << json_number(per_minute)
         << ",\"peak_rss_mb\":" << json_number(peak_triangulation_mb)
         << ",\"peak_rss_total_mb\":" << json_number(peak_rss_mb())
         << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return verified_ok ? 0 : 3;
}

}  // namespace

void add_delaunay(CLI::App& app) {
  auto args = std::make_shared<DelaunayArgs>();
  CLI::App* cmd = app.add_subcommand("delaunay", "Delaunay triangulation of a point set");
  cmd->add_option("input", args->input, "Point file: plain 'x y' or 'x y z' lines, Triangle .node, or Medit .mesh (2D or 3D)");
  cmd->add_option("-o,--output", args->output, "Write the mesh: OUT.mesh (Medit) or OUT.ele (Triangle's or, in 3D, TetGen's .node + .ele)");
  std::string names;
  for (const Delaunay2dVariant& v : delaunay2d_variants()) names += (names.empty() ? "" : "|") + std::string(v.name);
  cmd->add_option("--algo", args->algorithm, "Variant: " + names)->capture_default_str();
  cmd->add_flag("--stats", args->stats,
                "Print one JSON object with points, elements, seconds, elements_per_minute, peak_rss_mb, "
                "algo and predicate stage counts as the last line");
  cmd->add_flag("--list-algos", args->list,
                "List the registered variants (name, tab, description) and exit; with --dim 3 the 3D ones");
  cmd->add_option("--threads", args->threads, "Threads for the 3D variant 'parallel' (others are sequential)")
      ->capture_default_str()
      ->check(integer_in(1, kMaxThreads));
  cmd->add_flag("--verify", args->verify, "Check the result with exact predicates and print the report");
  cmd->add_option("--random", args->random, "Triangulate N generated points instead of a file")
      ->check(integer_in(1, kMaxRandomPoints));
  cmd->add_option("--dim", args->dim, "Dimension of the generated points")->capture_default_str()->check(integer_in(2, 3));
  std::string dists;
  for (const std::string& d : distribution_names2d()) dists += (dists.empty() ? "" : "|") + d;
  std::string dists3;
  for (const std::string& d : distribution_names3d()) dists3 += (dists3.empty() ? "" : "|") + d;
  cmd->add_option("--distribution", args->distribution,
                  "Generated distribution; 2D: " + dists + "; 3D: " + dists3)
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the generated points")
      ->capture_default_str()
      ->check(integer_in(0, UINT64_MAX));
  cmd->add_option("--remove", args->remove_file,
                  "Then remove the points numbered (from 1) in this file, in its order, and write the survivors' "
                  "mesh (dynamic Delaunay removal)");
  cmd->add_option("--remove-random", args->remove_fraction,
                  "Then remove this fraction F (0 < F <= 1) of the points, drawn with --seed");
  cmd->callback([args] {
    exit_code() = run_delaunay(*args);
  });
}

}  // namespace dtlab::cli
