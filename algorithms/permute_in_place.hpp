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
// caches and its cycles are cheap to follow. The blocks of the first deal are independent: with a
// WorkerTeam they are finished on its threads (the result is the same for every thread count).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>

#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/scratch_array.hpp"

namespace dtlab {

namespace detail {

// Blocks this small are finished by following their cycles.
constexpr std::size_t kCycleBlock = 8192;
constexpr std::size_t kDealBlocks = 256;

// Positions [lo, hi), more than kCycleBlock of them, hold the elements whose destinations are in
// [lo, hi). Deals them into blocks of `width` consecutive destinations (the last one shorter):
// block b is [lo + b * width, lo + (b + 1) * width) ∩ [lo, hi), and since the destinations are a
// permutation of [lo, hi), exactly its own elements fill it. Returns width.
template <class T>
std::size_t deal_into_blocks(T* values, std::uint32_t* destination, std::size_t lo, std::size_t hi) {
  const std::size_t n = hi - lo;
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
  return width;
}

// Positions [lo, hi) hold the elements whose destinations are in [lo, hi).
template <class T>
void move_block_to_destinations(T* values, std::uint32_t* destination, std::size_t lo, std::size_t hi) {
  if (hi - lo <= kCycleBlock) {
    // Each swap puts one element where it goes, so at most hi - lo swaps in all.
    for (std::size_t i = lo; i < hi; ++i)
      while (destination[i] != i) {
        const std::size_t to = destination[i];
        DTLAB_ASSERT(lo <= to && to < hi && destination[to] != to);  // a permutation of [lo, hi)
        std::swap(values[i], values[to]);
        std::swap(destination[i], destination[to]);
      }
    return;
  }
  const std::size_t width = deal_into_blocks(values, destination, lo, hi);
  for (std::size_t b = lo; b < hi; b += width) move_block_to_destinations(values, destination, b, std::min(hi, b + width));
}

}  // namespace detail

// Moves each values[i] to position destination[i], in place. destination must be a permutation
// of 0..values.size()-1 (an assertion fails otherwise) and is consumed: afterwards it is the
// identity. O(n log_256 n) moves, no scratch. With `team`, the blocks of the first deal are
// finished on its threads.
template <class T>
void move_to_destinations(std::span<T> values, std::span<std::uint32_t> destination, WorkerTeam* team = nullptr) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(destination.size() == n);
  if (team == nullptr || team->threads() == 1 || n <= detail::kCycleBlock) {
    detail::move_block_to_destinations(values.data(), destination.data(), 0, n);
    return;
  }
  const std::size_t width = detail::deal_into_blocks(values.data(), destination.data(), 0, n);
  team->run((n + width - 1) / width, [&](std::size_t b, unsigned) {
    detail::move_block_to_destinations(values.data(), destination.data(), b * width, std::min(n, (b + 1) * width));
  });
}

// order must be a permutation of 0..values.size()-1. Afterwards values[r] is what
// values[order[r]] was. n 32-bit words of scratch (the inverse of order). With `team`, the
// inverse is made and the blocks finished on its threads.
template <class T>
void permute_in_place(std::span<T> values, std::span<const std::uint32_t> order, WorkerTeam* team = nullptr) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(order.size() == n);
  ScratchArray<std::uint32_t> destination(n);  // zeros: an order that is no permutation fails below
  for_each_share(team, n, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      DTLAB_ASSERT(order[r] < n);
      destination[order[r]] = static_cast<std::uint32_t>(r);
    }
  });
  move_to_destinations(values, destination.span(), team);
}

}  // namespace dtlab
