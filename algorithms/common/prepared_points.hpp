// The preprocessing every Delaunay variant shares in 2D and 3D (algorithms/delaunay2d/prepare.hpp,
// algorithms/delaunay3d/prepare.hpp): the size and coordinate checks, duplicate detection by a
// Hilbert sort (which puts equal points side by side), and the message for too few distinct
// points. The dimension adds its own degeneracy (collinear, coplanar).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"

namespace dtlab {

template <class Vec>
struct PreparedPoints {
  // The input, in input order: vertex ids are indices into it.
  std::span<const Vec> points;
  // One id per distinct coordinate tuple (the smallest index holding it), in Hilbert order
  // (spatial_sort.hpp). A variant that wants another order sorts a copy, and may then release
  // this one (release_distinct) to lower its peak memory: no caller reads it after the run.
  std::vector<std::uint32_t> distinct;
  // Dropped duplicates, ascending, and for each the kept index with the same coordinates.
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
  // Empty, or why no element can be made ("fewer than 3 distinct points ...", "all points
  // collinear ..."); variants are not run then.
  std::string degenerate_message;
  // For randomised steps (BRIO), so that runs are reproducible.
  std::uint64_t seed = 0;

  void release_distinct() { std::vector<std::uint32_t>().swap(distinct); }
};

// Throws InputError for more than `max_points` points (`structure` names what cannot index them,
// "a 2D triangulation") or naming the first bad coordinate (coordinate_range.hpp); `split` is
// spatial_sort.hpp's distinct_in_hilbert_order. Fewer than `min_distinct` distinct points: the
// degenerate message, "... : no <elements>".
template <class Vec, class Split>
PreparedPoints<Vec> prepare_distinct(std::span<const Vec> points, std::uint64_t seed, std::size_t max_points,
                                     std::string_view structure, std::size_t min_distinct, std::string_view elements,
                                     WorkerTeam* team, const Split& split) {
  if (points.size() > max_points)
    throw InputError(std::to_string(points.size()) + " points: more than the " + std::to_string(max_points) + " " +
                     std::string(structure) + " can index");
  check_coordinates(points, "point", team);

  PreparedPoints<Vec> out;
  out.points = points;
  out.seed = seed;
  auto distinct = split(points, team);
  out.distinct = std::move(distinct.distinct);
  out.duplicates = std::move(distinct.duplicates);
  out.duplicate_of = std::move(distinct.duplicate_of);
  if (out.distinct.size() < min_distinct) {
    out.degenerate_message = "fewer than " + std::to_string(min_distinct) + " distinct points (" +
                             std::to_string(out.distinct.size()) + " distinct among " + std::to_string(points.size()) +
                             "): no " + std::string(elements);
  }
  return out;
}

}  // namespace dtlab
