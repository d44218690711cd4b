// The preprocessing every 2D Delaunay variant shares (algorithms/common/prepared_points.hpp):
// coordinate check, duplicate detection, degeneracy detection (fewer than three distinct points,
// all points collinear). Variants receive only distinct points that are not all collinear.
#pragma once

#include <cstdint>
#include <span>

#include "algorithms/common/prepared_points.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

using PreparedPoints2 = PreparedPoints<Vec2>;

// Throws InputError naming the first point with a coordinate that is NaN, infinite or outside
// the supported range (coordinate_range.hpp), or when there are more than
// Triangulation2::kMaxPoints points.
PreparedPoints2 prepare_points2(std::span<const Vec2> points, std::uint64_t seed);

}  // namespace dtlab
