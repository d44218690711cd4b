// Reordering a large array in place by a permutation, and back: variants that insert points in a
// spatial order want the coordinates in that order (consecutive insertions then touch consecutive
// memory) but must not hold a second copy of a large input (issue 5's memory target: 250 MB for
// 10^6 points in 3D).
//
// Following the permutation's cycles one element at a time is a chain of dependent loads, each a
// cache and TLB miss once the array outgrows the caches: 12 % of the 3D kernel's time at 10^7
// points (issue 23). Instead the elements are first dealt into 256 blocks of destinations in
// place, as American flag sort deals keys into buckets (McIlroy, Bostic, McIlroy, "Engineering
// radix sort", Computing Systems 1993): 256 write positions that each advance through memory,
// which the caches and prefetchers follow; then again inside each block, until a block fits the
// caches and its cycles are cheap to follow.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>

#include "kernel/error.hpp"
#include "mesh/scratch_array.hpp"

namespace dtlab {

namespace detail {

// Blocks this small are finished by following their cycles.
constexpr std::size_t kCycleBlock = 8192;
constexpr std::size_t kDealBlocks = 256;

// Positions [lo, hi) hold the elements whose destinations are in [lo, hi).
template <class T>
void move_block_to_destinations(T* values, std::uint32_t* destination, std::size_t lo, std::size_t hi) {
  const std::size_t n = hi - lo;
  if (n <= kCycleBlock) {
    // Each swap puts one element where it goes, so at most n swaps in all.
    for (std::size_t i = lo; i < hi; ++i)
      while (destination[i] != i) {
        const std::size_t to = destination[i];
        DTLAB_ASSERT(lo <= to && to < hi && destination[to] != to);  // a permutation of [lo, hi)
        std::swap(values[i], values[to]);
        std::swap(destination[i], destination[to]);
      }
    return;
  }
  // Block b is [lo + b * width, lo + (b + 1) * width) ∩ [lo, hi): since the destinations are a
  // permutation of [lo, hi), exactly its own elements fill it.
  const std::size_t width = (n + kDealBlocks - 1) / kDealBlocks;
  const std::size_t blocks = (n + width - 1) / width;
  std::array<std::size_t, kDealBlocks> next{};  // block b's first position not yet dealt
  for (std::size_t b = 0; b < blocks; ++b) next[b] = lo + b * width;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t end = std::min(hi, lo + (b + 1) * width);
    // Each pass puts one element in its block, so at most n passes in all.
    while (next[b] < end) {
      const std::size_t i = next[b];
      DTLAB_ASSERT(lo <= destination[i] && destination[i] < hi);
      const std::size_t to = (destination[i] - lo) / width;
      if (to == b) {
        ++next[b];
        continue;
      }
      const std::size_t j = next[to]++;
      DTLAB_ASSERT(j < std::min(hi, lo + (to + 1) * width));  // block `to` overfull: not a permutation
      std::swap(values[i], values[j]);
      std::swap(destination[i], destination[j]);
    }
  }
  for (std::size_t b = 0; b < blocks; ++b)
    move_block_to_destinations(values, destination, lo + b * width, std::min(hi, lo + (b + 1) * width));
}

}  // namespace detail

// Moves each values[i] to position destination[i], in place. destination must be a permutation
// of 0..values.size()-1 (an assertion fails otherwise) and is consumed: afterwards it is the
// identity. O(n log_256 n) moves, no scratch.
template <class T>
void move_to_destinations(std::span<T> values, std::span<std::uint32_t> destination) {
  DTLAB_ASSERT(destination.size() == values.size());
  detail::move_block_to_destinations(values.data(), destination.data(), 0, values.size());
}

// order must be a permutation of 0..values.size()-1. Afterwards values[r] is what
// values[order[r]] was. n 32-bit words of scratch (the inverse of order).
template <class T>
void permute_in_place(std::span<T> values, std::span<const std::uint32_t> order) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(order.size() == n);
  ScratchArray<std::uint32_t> destination(n);  // zeros: an order that is no permutation fails below
  for (std::size_t r = 0; r < n; ++r) {
    DTLAB_ASSERT(order[r] < n);
    destination[order[r]] = static_cast<std::uint32_t>(r);
  }
  move_to_destinations(values, destination.span());
}

}  // namespace dtlab
