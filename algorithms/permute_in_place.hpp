// Reordering a large array in place by a permutation, and back, with one bit of scratch per
// element: variants that insert points in a spatial order want the coordinates in that order
// (consecutive insertions then touch consecutive memory) but must not hold a second copy of a
// large input (issue 5's memory target: 250 MB for 10^6 points in 3D).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

// order must be a permutation of 0..values.size()-1. Afterwards values[r] is what
// values[order[r]] was. O(n) time, n bits of scratch.
template <class T>
void permute_in_place(std::span<T> values, std::span<const std::uint32_t> order) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(order.size() == n);
  std::vector<bool> done(n, false);
  for (std::size_t start = 0; start < n; ++start) {
    if (done[start]) continue;
    // The cycle start <- order[start] <- order[order[start]] ... back to start.
    T first = std::move(values[start]);
    std::size_t r = start;
    for (std::size_t steps = 0;; ++steps) {
      DTLAB_ASSERT(steps < n);  // order is not a permutation otherwise
      done[r] = true;
      const std::size_t from = order[r];
      if (from == start) {
        values[r] = std::move(first);
        break;
      }
      values[r] = std::move(values[from]);
      r = from;
    }
  }
}

// The inverse of permute_in_place: afterwards values[order[r]] is what values[r] was.
template <class T>
void unpermute_in_place(std::span<T> values, std::span<const std::uint32_t> order) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(order.size() == n);
  std::vector<bool> done(n, false);
  for (std::size_t start = 0; start < n; ++start) {
    if (done[start]) continue;
    // Carry the value at `start` to order[start], whose value goes on to order[order[start]] ...
    T carried = std::move(values[start]);
    std::size_t r = start;
    for (std::size_t steps = 0;; ++steps) {
      DTLAB_ASSERT(steps < n);
      done[r] = true;
      const std::size_t to = order[r];
      std::swap(carried, values[to]);
      if (to == start) break;
      r = to;
    }
  }
}

}  // namespace dtlab
