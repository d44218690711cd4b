// `dtlab delaunay ... --remove`: parses the removal list, calls delaunay2d_remove /
// delaunay3d_remove (algorithms/delaunay*/dynamic_delaunay*.hpp), writes and reports.
#include "apps/delaunay_remove.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>
#include <vector>

#include "algorithms/delaunay2d/dynamic_delaunay2.hpp"
#include "algorithms/delaunay3d/dynamic_delaunay3.hpp"
#include "apps/cli_util.hpp"
#include "kernel/error.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "verify/checks2d.hpp"
#include "verify/checks3d.hpp"
#include "verify/generators/points2d.hpp"
#include "verify/generators/points3d.hpp"
#include "verify/generators/portable_random.hpp"

namespace dtlab::cli {
namespace {

// The point numbers of `path` (from 1), as 0-based indices; each in range and given once.
std::vector<std::uint32_t> read_removal_list(const std::string& path, std::size_t point_count) {
  std::ifstream in(path);
  if (!in) throw InputError("--remove " + path + ": cannot open the file");
  std::vector<std::uint32_t> out;
  std::vector<std::uint8_t> seen(point_count, 0);
  std::string line;
  for (std::uint64_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      if (word[0] == '#') break;
      std::size_t used = 0;
      long long k = 0;
      try {
        k = std::stoll(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size()) throw ParseError(path, number, "'" + word + "' is not a point number");
      if (k < 1 || static_cast<unsigned long long>(k) > point_count)
        throw ParseError(path, number, "point " + word + " is not among the " + std::to_string(point_count) +
                                           " points (numbered from 1)");
      if (seen[static_cast<std::size_t>(k - 1)]++)
        throw ParseError(path, number, "point " + word + " is given twice");
      out.push_back(static_cast<std::uint32_t>(k - 1));
    }
  }
  return out;
}

// round(fraction * n) distinct indices, drawn by a portable shuffle with `seed`.
std::vector<std::uint32_t> random_removal(std::size_t point_count, double fraction, std::uint64_t seed) {
  std::vector<std::uint32_t> all(point_count);
  std::iota(all.begin(), all.end(), 0u);
  portable::Rng rng(seed);
  portable::shuffle(all, rng);
  all.resize(static_cast<std::size_t>(std::llround(fraction * static_cast<double>(point_count))));
  return all;
}

std::vector<std::uint32_t> removal_of(const DelaunayRemoveCliArgs& args, std::size_t point_count) {
  if (!args.remove_file.empty() && args.remove_fraction)
    throw InputError("give either --remove FILE or --remove-random F, not both");
  if (!args.remove_file.empty()) return read_removal_list(args.remove_file, point_count);
  if (!(*args.remove_fraction > 0.0 && *args.remove_fraction <= 1.0))
    throw InputError("--remove-random: give a fraction F with 0 < F <= 1");
  return random_removal(point_count, *args.remove_fraction, args.seed);
}

// The survivors renumbered in input order, and the elements in that numbering.
template <class Point, std::size_t kCorners>
void survivors_mesh(std::span<const Point> points, const std::vector<std::uint8_t>& removed,
                    std::vector<std::array<std::uint32_t, kCorners>>& elements, std::vector<Point>& kept) {
  std::vector<std::uint32_t> renumber(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (removed[i]) continue;
    renumber[i] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(points[i]);
  }
  for (auto& e : elements)
    for (auto& v : e) v = renumber[v];
}

template <class Removal>
void print_stats(const DelaunayRemoveCliArgs& args, const std::string& source, int dim, std::size_t points,
                 std::size_t removed, std::size_t elements, const Removal& r, const std::string& counts) {
  const double per_second = r.remove_seconds > 0 ? static_cast<double>(removed) / r.remove_seconds : 0.0;
  std::cout << "{\"input\":" << json_string(source) << ",\"dim\":" << dim << ",\"algo\":" << json_string(args.algorithm)
            << ",\"points\":" << points << ",\"removed\":" << removed << ",\"elements\":" << elements
            << ",\"build_seconds\":" << json_number(r.build_seconds)
            << ",\"remove_seconds\":" << json_number(r.remove_seconds)
            << ",\"removals_per_second\":" << json_number(per_second) << "," << counts
            << ",\"peak_rss_mb\":" << json_number(peak_rss_mb()) << "}\n";
}

// The library's removal errors name 0-based vertex ids; the command line numbers points from 1.
template <class Call>
auto numbered_from_one(Call&& call) {
  try {
    return call();
  } catch (const DegenerateRemovalError& e) {
    const std::uint64_t v = e.items().empty() ? 0 : e.items()[0];
    throw InputError("--remove: point " + std::to_string(v + 1) + " (numbered from 1) cannot be removed: " + e.what(),
                     e.items());
  }
}

}  // namespace

int run_delaunay_remove(const DelaunayRemoveCliArgs& args) {
  if (args.input.empty() == (args.random == 0)) throw InputError("give either an INPUT file or --random N");
  const int dim = args.input.empty() ? args.dim : input_dimension(args.input);
  if (dim != 2 && dim != 3) throw InputError("--dim must be 2 or 3, not " + std::to_string(dim));
  StagedOutputs outputs({args.output});
  const std::string source = args.input.empty() ? "random " + args.distribution + " n=" + std::to_string(args.random) +
                                                      " seed=" + std::to_string(args.seed)
                                                : args.input;
  bool ok = true;
  if (dim == 2) {
    const std::vector<Vec2> points =
        args.input.empty() ? generate_points2d(args.distribution, args.random, args.seed) : read_points2(args.input);
    const std::vector<std::uint32_t> indices = removal_of(args, points.size());
    Delaunay2dRemoval r = numbered_from_one([&] { return delaunay2d_remove(points, indices, {.algorithm = args.algorithm}); });
    std::vector<Vec2> kept;
    survivors_mesh<Vec2, 3>(points, r.removed, r.elements, kept);
    const std::vector<std::array<std::uint32_t, 3>> triangles = canonical_triangle_set(r.elements);
    if (!args.output.empty()) {
      MeshData2 mesh;
      mesh.vertices = kept;
      mesh.vertex_refs.assign(kept.size(), 0);
      mesh.triangles = triangles;
      mesh.triangle_refs.assign(triangles.size(), 0);
      outputs.write(args.output, [&](const std::string& path) { write_mesh2(path, mesh); });
      outputs.commit();
    }
    if (args.verify) {
      const Delaunay2dResult scratch = delaunay2d(kept, {.algorithm = args.algorithm});
      ok = canonical_triangle_set(scratch.triangulation.finite_triangles()) == triangles;
      std::cout << "removal " << (ok ? "equals" : "DIFFERS FROM") << " the survivors' triangulation from scratch ("
                << triangles.size() << " triangles)\n";
    }
    if (args.stats)
      print_stats(args, source, 2, points.size(), indices.size(), triangles.size(), r,
                  "\"ear_tests\":" + std::to_string(r.stats.ear_tests));
  } else {
    const std::vector<Vec3> points =
        args.input.empty() ? generate_points3d(args.distribution, args.random, args.seed) : read_points3(args.input);
    const std::vector<std::uint32_t> indices = removal_of(args, points.size());
    Delaunay3dRemoval r = numbered_from_one([&] { return delaunay3d_remove(points, indices, {.algorithm = args.algorithm}); });
    std::vector<Vec3> kept;
    survivors_mesh<Vec3, 4>(points, r.removed, r.elements, kept);
    const std::vector<std::array<std::uint32_t, 4>> tetrahedra = canonical_tetrahedron_set(r.elements);
    if (!args.output.empty()) {
      MeshData3 mesh;
      mesh.vertices = kept;
      mesh.tetrahedra = tetrahedra;
      outputs.write(args.output, [&](const std::string& path) { write_mesh3(path, mesh); });
      outputs.commit();
    }
    if (args.verify) {
      const Delaunay3dResult scratch = delaunay3d(kept, {.algorithm = args.algorithm});
      ok = canonical_tetrahedron_set(scratch.tetrahedralization) == tetrahedra;
      std::cout << "removal " << (ok ? "equals" : "DIFFERS FROM")
                << " the survivors' tetrahedralization from scratch (" << tetrahedra.size() << " tetrahedra)\n";
    }
    if (args.stats)
      print_stats(args, source, 3, points.size(), indices.size(), tetrahedra.size(), r,
                  "\"link_vertices\":" + std::to_string(r.stats.link_vertices));
  }
  return ok ? 0 : 3;
}

}  // namespace dtlab::cli
