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

// The sweep centre (after Delaunator's seed): the circumcentre of a small triangle near the middle
// of the bounding box of `ids`' points, correctly rounded, so exact whenever it is a pair of
// doubles; the bounding box's middle when that circumcentre falls outside the box. On exactly
// cocircular input whose circle has a representable centre every point then ties, and ties go in
// (x, y) order, the order in which the perturbation adds each point as an ear without a flip
// (sweep.cpp). On near-cocircular input the distances spread along the circle instead of nearly
// tying around a centre a rounding away from the circle's. Any centre is correct; this one only
// makes the sweep fast. Coordinates are rounded to 0 or into the supported range.
Vec2 sweep_center(std::span<const Vec2> points, std::span<const std::uint32_t> ids);

// The middle of the bounding box of `ids`' points, each coordinate rounded to 0 or into the
// supported range.
Vec2 bounding_box_middle(std::span<const Vec2> points, std::span<const std::uint32_t> ids);

// The circumcentre of (a, b, c) rounded to nearest, coordinate by coordinate (exact rationals);
// false when the three are collinear (exact orient2d zero).
bool rounded_circumcenter(const Vec2& a, const Vec2& b, const Vec2& c, Vec2& center);

}  // namespace dtlab
