// The walk of the solution transfer (book §9.8, §12.2.6), written once for 2D and 3D: each new
// vertex, in the caller's order (Hilbert: each walk starts where the previous one ended), placed
// in the old mesh with its P1 weights by the dimension's `Walk` (its mesh's walk, the bucket grid
// for walks lost through a concavity, else the nearest old boundary point: an error farther than
// outside_limit x the size of the nearest boundary element).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab::transfer_detail {

// Rescanned: the walk left through a concavity, the grid found the point. Outside: its distance
// to the nearest old boundary point and that element's size (the message names it Walk::kSize).
enum class Placed { Walked, Rescanned, Outside };
template <class Weights>
struct Placement {
  Weights weights;
  Placed how = Placed::Walked;
  double distance = 0.0, size = 0.0;
};

// `Walk` provides `Placement<Weights> place(const Point& p)` and `kSize`. `Stats` (TransferStats,
// adapt/transfer.hpp) is zeroed, then counts located, rescanned and snapped vertices and the
// largest distance outside; null: not kept.
template <class Walk, class Point, class Stats>
auto transfer_walk(Walk& walk, std::span<const Point> points, std::span<const std::uint32_t> order,
                   double outside_limit, Stats* stats) {
  Stats local;
  Stats& st = stats ? *stats : local;
  st = Stats{};
  std::vector<decltype(walk.place(points[0]).weights)> out(points.size());
  for (const std::uint32_t v : order) {
    const auto at = walk.place(points[v]);
    if (at.how != Placed::Outside) {
      ++st.located;
      st.rescanned += at.how == Placed::Rescanned;
    } else if (at.distance > outside_limit * at.size) {
      throw InputError("new vertex " + std::to_string(v + 1) + " lies " + std::to_string(at.distance) +
                           " outside the old mesh, more than " + std::to_string(outside_limit) + " x " + Walk::kSize +
                           " (" + std::to_string(at.size) + ")",
                       {std::uint64_t{v} + 1});
    } else {
      ++st.snapped;
      st.max_outside_distance = std::max(st.max_outside_distance, at.distance);
    }
    out[v] = at.weights;
  }
  return out;
}

}  // namespace dtlab::transfer_detail
