#include "algorithms/delaunay2d/delaunay2d.hpp"

#include <chrono>

#include "algorithms/delaunay2d/prepare.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "kernel/error.hpp"

namespace dtlab {

Delaunay2dResult delaunay2d(std::span<const Vec2> points, const Delaunay2dOptions& options) {
  const Delaunay2dVariant* variant = &(options.variants ? *options.variants : delaunay2d_variants()).at(options.algorithm);
  const PredicateStats before = predicate_stats();
  const auto start = std::chrono::steady_clock::now();

  PreparedPoints2 prepared = prepare_points2(points, options.seed);
  Delaunay2dResult result;
  std::vector<Vec2> copy;
  copy.reserve(points.size());
  advise_huge_pages(copy.data(), points.size() * sizeof(Vec2));
  copy.assign(points.begin(), points.end());
  result.triangulation = Triangulation2(std::move(copy));
  if (prepared.degenerate_message.empty()) variant->run(prepared, result.triangulation);
  result.duplicates = std::move(prepared.duplicates);
  result.duplicate_of = std::move(prepared.duplicate_of);
  result.degenerate_message = std::move(prepared.degenerate_message);

  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.predicate_stats = predicate_stats() - before;
  return result;
}

}  // namespace dtlab
