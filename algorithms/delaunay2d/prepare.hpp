// The preprocessing every 2D Delaunay variant shares: coordinate check, duplicate detection
// (by a Hilbert sort, which puts equal points side by side), degeneracy detection (fewer than
// three distinct points, all points collinear). Variants receive only distinct points that are
// not all collinear.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct PreparedPoints2 {
  // The input, in input order: vertex ids are indices into it.
  std::span<const Vec2> points;
  // One id per distinct coordinate pair (the smallest index holding it), in Hilbert order
  // (spatial_sort.hpp). A variant that wants another order sorts a copy.
  std::vector<std::uint32_t> distinct;
  // Dropped duplicates, ascending, and for each the kept index with the same coordinates.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why no triangle can be made ("fewer than 3 distinct points ...", "all points
  // collinear ..."); variants are not run then.
  std::string degenerate_message;
  // For randomised steps (BRIO), so that runs are reproducible.
  std::uint64_t seed = 0;
};

// Throws InputError naming the first point with a coordinate that is NaN, infinite or outside
// the supported range (coordinate_range.hpp), or when there are more than
// Triangulation2::kMaxPoints points.
PreparedPoints2 prepare_points2(std::span<const Vec2> points, std::uint64_t seed);

}  // namespace dtlab
