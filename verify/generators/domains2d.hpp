// Planar domains for the 2D mesher's tests and fuzzers: loops of segments with markers, holes,
// regions, and the benchmark's unit square minus a disc.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/problems/constrained2.hpp"

namespace dtlab::gen {

struct Domain2 {
  std::vector<Vec2> points;
  std::vector<std::array<std::uint32_t, 2>> segments;
  std::vector<int> markers;
  std::vector<Vec2> holes;
  std::vector<RegionSeed2> regions;
  ConstrainedInput2 input() const { return {points, segments, markers, holes, regions}; }
};

// Appends the closed polygon `loop` (its vertices in order) as segments with `marker`.
void add_loop(Domain2& d, const std::vector<Vec2>& loop, int marker);
// The n vertices of the regular polygon inscribed in the circle (c, r), counter-clockwise.
std::vector<Vec2> circle_polygon(const Vec2& c, double r, int n);
// The boundary of the unit square, each side cut into n pieces, counter-clockwise from (0, 0).
std::vector<Vec2> unit_square_loop(int n);
// The unit square, each side cut into n pieces, all with `marker`.
Domain2 unit_square(int n, int marker = 1);
// The unit square, each side cut into n pieces (marker 1), minus the disc of radius 0.2 at its
// centre cut at the same spacing (marker 2, a hole).
Domain2 square_minus_disc(int n);

}  // namespace dtlab::gen
