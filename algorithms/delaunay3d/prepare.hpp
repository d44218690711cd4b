// The preprocessing every 3D Delaunay variant shares: coordinate check, duplicate detection
// (by a Hilbert sort, which puts equal points side by side), degeneracy detection (fewer than
// four distinct points, all points collinear or coplanar). Variants receive only distinct points
// that are not all coplanar.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {

struct PreparedPoints3 {
  // The input, in input order: vertex ids are indices into it.
  std::span<const Vec3> points;
  // One id per distinct coordinate triple (the smallest index holding it), in Hilbert order
  // (spatial_sort.hpp). A variant that wants another order sorts a copy, and may then release
  // this one (release_distinct) to lower its peak memory: no caller reads it after the run.
  std::vector<std::uint32_t> distinct;
  // Dropped duplicates, ascending, and for each the kept index with the same coordinates.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why no tetrahedron can be made ("fewer than 4 distinct points ...", "all points
  // collinear ...", "all points coplanar ..."); variants are not run then.
  std::string degenerate_message;
  // For randomised steps (BRIO), so that runs are reproducible.
  std::uint64_t seed = 0;

  void release_distinct() { std::vector<std::uint32_t>().swap(distinct); }
};

// Throws InputError naming the first point with a coordinate that is NaN, infinite or outside
// the supported range (coordinate_range.hpp), or when there are more than
// Tetrahedralization3::kMaxPoints points. With `team`, the Hilbert sort runs on its threads (same
// result).
PreparedPoints3 prepare_points3(std::span<const Vec3> points, std::uint64_t seed, WorkerTeam* team = nullptr);

// Positions in `ids` of four points spanning space: the first two, the first point off their
// line, the first point off the plane of those three. Positions equal ids.size() where no such
// point exists (ids.size() < 2 for the first two).
std::array<std::size_t, 4> first_simplex(std::span<const Vec3> points, std::span<const std::uint32_t> ids);

}  // namespace dtlab
