// `dtlab delaunay` in 3D: tetrahedralize a point file or generated points with any registered 3D
// variant, write a Medit mesh, check the result exactly (verify/checks3d.hpp) and report
// statistics (the same JSON fields as the 2D path, apps/delaunay.cpp).
#include "apps/delaunay3d.hpp"

#include <iostream>
#include <sstream>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "kernel/error.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "verify/checks3d.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab::cli {

int list_delaunay3d_variants() {
  for (const Delaunay3dVariant& v : delaunay3d_variants()) std::cout << v.name << "\t" << v.description << "\n";
  return 0;
}

int run_delaunay3d(const Delaunay3dCliArgs& args) {
  if (args.input.empty() == (args.random == 0)) throw InputError("give either an INPUT file or --random N");
  if (args.random > Tetrahedralization3::kMaxPoints)
    throw InputError("--random: " + std::to_string(args.random) + " points exceed the 3D limit of " +
                     std::to_string(Tetrahedralization3::kMaxPoints));
  StagedOutputs outputs({args.output});
  const std::string source = args.input.empty() ? "random " + args.distribution + " n=" + std::to_string(args.random) +
                                                      " seed=" + std::to_string(args.seed)
                                                : args.input;
  std::vector<Vec3> points =
      args.input.empty() ? generate_points3d(args.distribution, args.random, args.seed) : read_points3(args.input);

  const std::size_t point_count = points.size();
  // The points move into the result: one copy of the coordinates fewer at the peak.
  Delaunay3dResult result =
      delaunay3d(std::move(points), {.algorithm = args.algorithm, .threads = args.threads});
  // Memory of reading and tetrahedralizing, before any output is materialised.
  const double peak_tetrahedralization_mb = peak_rss_mb();
  const Tetrahedralization3& tet = result.tetrahedralization;
  const std::size_t elements = tet.finite_tetrahedron_count();
  if (!result.duplicates.empty())
    std::cerr << "dtlab: " << result.duplicates.size()
              << " duplicate point(s), kept as unreferenced vertices (the first is point "
              << result.duplicates[0] + 1 << " = point " << result.duplicate_of[0] + 1 << ", numbered from 1)\n";
  if (!result.degenerate_message.empty()) std::cerr << "dtlab: no tetrahedra: " << result.degenerate_message << "\n";

  if (!args.output.empty()) {
    // Canonical order (each tetrahedron from its smallest id, then sorted): every variant and
    // thread count writes the same bytes for the same tetrahedra.
    MeshData3 mesh;
    mesh.vertices.assign(tet.points().begin(), tet.points().end());
    mesh.tetrahedra = canonical_tetrahedron_set(tet);
    outputs.write(args.output, [&](const std::string& path) { write_mesh3(path, mesh); });
    outputs.commit();  // before --verify: a failed check (exit 3) leaves the output to look at
  }

  bool ok = true;
  if (args.verify) {
    const CheckReport3 report = verify_delaunay3d(tet.points(), tet, result.duplicates);
    const std::string text = to_text(report);
    std::cout << text << (text.ends_with('\n') ? "" : "\n");
    ok = report.ok;
  }
  if (args.stats) {
    const double seconds = result.seconds;
    const double per_minute = seconds > 0 ? static_cast<double>(elements) * 60.0 / seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(source) << ",\"dim\":3,\"algo\":" << json_string(args.algorithm)
         << ",\"threads\":" << args.threads << ",\"points\":" << point_count
         << ",\"distinct_points\":" << point_count - result.duplicates.size()
         << ",\"duplicates\":" << result.duplicates.size() << ",\"elements\":" << elements
         << ",\"seconds\":" << json_number(seconds) << ",\"elements_per_minute\":" << json_number(per_minute)
         << ",\"peak_rss_mb\":" << json_number(peak_tetrahedralization_mb)
         << ",\"peak_rss_total_mb\":" << json_number(peak_rss_mb())
         << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
