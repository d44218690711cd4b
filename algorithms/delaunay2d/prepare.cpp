#include "algorithms/delaunay2d/prepare.hpp"

#include <algorithm>

#include "algorithms/spatial_sort.hpp"
#include "kernel/predicates.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {

PreparedPoints2 prepare_points2(std::span<const Vec2> points, std::uint64_t seed) {
  PreparedPoints2 out = prepare_distinct(points, seed, Triangulation2::kMaxPoints, "a 2D triangulation", 3, "triangles",
                                         nullptr, [](std::span<const Vec2> p, WorkerTeam* team) {
                                           return distinct_in_hilbert_order(p, team);
                                         });
  if (!out.degenerate_message.empty()) return out;
  const std::vector<std::uint32_t>& ids = out.distinct;
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
