// The preprocessing every 3D Delaunay variant shares (algorithms/common/prepared_points.hpp):
// coordinate check, duplicate detection, degeneracy detection (fewer than four distinct points,
// all points collinear or coplanar). Variants receive only distinct points that are not all
// coplanar.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "algorithms/common/prepared_points.hpp"
#include "kernel/vec.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {

using PreparedPoints3 = PreparedPoints<Vec3>;

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
