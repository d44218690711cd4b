// Exact convex hull of a 2D point set that keeps the points lying on hull edges: Andrew's
// monotone chain (A. M. Andrew, "Another efficient algorithm for convex hulls in two
// dimensions", IPL 1979) with the exact orient2d, popping only on a strict clockwise turn.
// The checkers compare a triangulation's boundary with it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct Hull2 {
  // Counter-clockwise hull vertices (indices into the points), starting at the
  // lexicographically smallest, every point on a hull edge included. Empty if the points are
  // all collinear (or fewer than three distinct ones): `collinear` is then true.
  std::vector<std::uint32_t> cycle;
  bool collinear = false;
};

// Hull of points[ids]. Points at equal coordinates count once (the first id in `ids` order
// among them stands for the location). Coordinates must be in the supported range.
Hull2 convex_hull_with_collinear(std::span<const Vec2> points, std::span<const std::uint32_t> ids);

}  // namespace dtlab
