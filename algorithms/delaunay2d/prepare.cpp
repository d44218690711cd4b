#include "algorithms/delaunay2d/prepare.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "algorithms/spatial_sort.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

PreparedPoints2 prepare_points2(std::span<const Vec2> points, std::uint64_t seed) {
  if (points.size() > Triangulation2::kMaxPoints)
    throw InputError(std::to_string(points.size()) + " points: more than the " +
                     std::to_string(Triangulation2::kMaxPoints) + " a 2D triangulation can index");
  check_coordinates(points, "point");

  PreparedPoints2 out;
  out.points = points;
  out.seed = seed;
  DistinctPoints split = distinct_in_hilbert_order(points);
  out.distinct = std::move(split.distinct);
  out.duplicates = std::move(split.duplicates);
  out.duplicate_of = std::move(split.duplicate_of);
  std::vector<std::uint32_t>& ids = out.distinct;

  if (ids.size() < 3) {
    out.degenerate_message = "fewer than 3 distinct points (" + std::to_string(ids.size()) + " distinct among " +
                             std::to_string(points.size()) + "): no triangles";
    return out;
  }
  const Vec2& a = points[ids[0]];
  const Vec2& b = points[ids[1]];
  const bool collinear = std::all_of(ids.begin() + 2, ids.end(),
                                     [&](std::uint32_t c) { return orient2d(a, b, points[c]) == Sign::Zero; });
  if (collinear)
    out.degenerate_message =
        "all points collinear (" + std::to_string(ids.size()) + " distinct points on one line): no triangles";
  return out;
}

}  // namespace dtlab
