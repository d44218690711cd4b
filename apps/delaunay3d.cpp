// `dtlab delaunay` in 3D: tetrahedralize a point file or generated points with any registered 3D
// variant, write a Medit mesh, check the structure and report statistics (the same JSON fields
// as the 2D path, apps/delaunay.cpp).
#include "apps/delaunay3d.hpp"

#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "apps/cli_util.hpp"
#include "kernel/error.hpp"
#include "mesh/io/point_file.hpp"

namespace dtlab::cli {

namespace {

std::vector<Vec3> generate_points3(const std::string& distribution, std::size_t n, std::uint64_t seed) {
  if (distribution != "uniform")
    throw InputError("3D point distribution '" + distribution + "' is not available (only: uniform)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = {unit(rng), unit(rng), unit(rng)};
  return out;
}

// Medit ASCII, version 2 (double precision): 1-based ids, reference 0 everywhere. Medit's
// positive tetrahedron is ours (orient3d > 0).
void write_medit3(const std::string& path, const Tetrahedralization3& tet) {
  if (extension_of(path) != "mesh")
    throw InputError("cannot write '" + path + "': the supported 3D output is .mesh (Medit)");
  std::ofstream out(path);
  if (!out) throw InputError("cannot open '" + path + "' for writing");
  out.precision(17);
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << tet.point_count() << "\n";
  for (const Vec3& p : tet.points()) out << p.x << " " << p.y << " " << p.z << " 0\n";
  const auto tetrahedra = tet.finite_tetrahedra();
  out << "Tetrahedra\n" << tetrahedra.size() << "\n";
  for (const auto& t : tetrahedra) out << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << " " << t[3] + 1 << " 0\n";
  out << "End\n";
  if (!out) throw InputError("writing '" + path + "' failed");
}

}  // namespace

int list_delaunay3d_variants() {
  for (const Delaunay3dVariant& v : delaunay3d_variants()) std::cout << v.name << "\t" << v.description << "\n";
  return 0;
}

int run_delaunay3d(const Delaunay3dCliArgs& args) {
  if (args.input.empty() == (args.random == 0)) throw InputError("give either an INPUT file or --random N");
  const std::string source = args.input.empty() ? "random " + args.distribution + " n=" + std::to_string(args.random) +
                                                      " seed=" + std::to_string(args.seed)
                                                : args.input;
  std::vector<Vec3> points =
      args.input.empty() ? generate_points3(args.distribution, args.random, args.seed) : read_point_file3(args.input);

  const std::size_t point_count = points.size();
  // The points move into the result: one copy of the coordinates fewer at the peak.
  Delaunay3dResult result =
      delaunay3d(std::move(points), {.algorithm = args.algorithm, .threads = args.threads});
  const std::size_t elements = result.tetrahedralization.finite_tetrahedron_count();
  if (!result.duplicates.empty())
    std::cerr << "dtlab: " << result.duplicates.size()
              << " duplicate point(s), kept as unreferenced vertices (the first is point "
              << result.duplicates[0] + 1 << " = point " << result.duplicate_of[0] + 1 << ", numbered from 1)\n";
  if (!result.degenerate_message.empty()) std::cerr << "dtlab: no tetrahedra: " << result.degenerate_message << "\n";
  if (!args.output.empty()) write_medit3(args.output, result.tetrahedralization);

  bool ok = true;
  if (args.verify) {
    try {
      result.tetrahedralization.check_topology();
      std::cout << "topology: ok (" << result.tetrahedralization.tetrahedron_count()
                << " tetrahedra with ghosts); exact geometric checks of 3D results are not available yet\n";
    } catch (const InternalError& e) {
      std::cout << "topology: FAILED: " << e.what() << "\n";
      ok = false;
    }
  }
  if (args.stats) {
    const double seconds = result.seconds;
    const double per_minute = seconds > 0 ? static_cast<double>(elements) * 60.0 / seconds : 0.0;
    std::ostringstream json;
    json << "{\"input\":" << json_string(source) << ",\"dim\":3,\"algo\":" << json_string(args.algorithm)
         << ",\"threads\":" << args.threads
         << ",\"points\":" << point_count << ",\"distinct_points\":" << point_count - result.duplicates.size()
         << ",\"duplicates\":" << result.duplicates.size() << ",\"elements\":" << elements
         << ",\"seconds\":" << json_number(seconds) << ",\"elements_per_minute\":" << json_number(per_minute)
         << ",\"peak_rss_mb\":" << json_number(peak_rss_mb())
         << ",\"predicates\":" << result.predicate_stats.to_json() << "}";
    std::cout << json.str() << "\n";
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
