// The radial sweep order of the "sweep" variant (Sinclair's s-hull, 2010): points by increasing
// distance from a centre, compared exactly. Exactness is what the sweep relies on: the point
// farthest from the centre among those so far is a vertex of their hull (a disc is strictly
// convex), so every point in this order lies strictly outside the hull of the points before it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

// `ids` (indices of distinct points) sorted by the exact squared distance of their point to
// `center`, ties by lexicographic (x, y). The centre's coordinates must be in the supported range
// (coordinate_range.hpp), as the points' are (sweep_center gives one).
std::vector<std::uint32_t> radial_sweep_order(std::span<const Vec2> points, std::span<const std::uint32_t> ids,
                                              const Vec2& center);

// The middle of the bounding box of `ids`' points, each coordinate rounded to 0 or into the
// supported range: a centre inside the hull of most inputs, so that the growing hull stays round
// around it (the hull search is fast when the centre is inside the hull; any centre is correct).
Vec2 sweep_center(std::span<const Vec2> points, std::span<const std::uint32_t> ids);

}  // namespace dtlab
