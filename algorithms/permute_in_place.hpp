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
// caches and its cycles are cheap to follow. With a WorkerTeam the array is first halved by its
// threads together, the halves of the halves next, until there is a part for each thread, which
// then finishes it alone (the result is the same for every thread count).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

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

// Positions [lo, hi) hold the elements whose destinations are in [lo, hi). Swaps the elements
// of [lo, mid) whose destinations are in [mid, hi) with those of [mid, hi) whose destinations are
// in [lo, mid), the k-th of one half with the k-th of the other (as many of each, since the
// destinations are a permutation), on the threads of `team`: each takes a range of k and scans
// its own stretch of both halves, found from per-chunk counts. Two streaming passes, so the first
// split of a large permutation is shared out instead of one thread's deal.
template <class T>
void swap_across_halves(T* values, std::uint32_t* destination, std::size_t lo, std::size_t mid, std::size_t hi,
                        WorkerTeam& team) {
  constexpr std::size_t kChunk = std::size_t{1} << 14;
  const std::size_t lower_chunks = (mid - lo + kChunk - 1) / kChunk, upper_chunks = (hi - mid + kChunk - 1) / kChunk;
  const auto chunk_begin = [&](std::size_t c) { return c < lower_chunks ? lo + c * kChunk : mid + (c - lower_chunks) * kChunk; };
  const auto chunk_end = [&](std::size_t c) { return std::min(c < lower_chunks ? mid : hi, chunk_begin(c) + kChunk); };
  const auto crosses = [&](std::size_t i) { return (i < mid) == (destination[i] >= mid); };
  const std::size_t chunks = lower_chunks + upper_chunks;
  std::vector<std::size_t> before(chunks);  // crossing elements of chunk c, then of c's half before c
  team.run(chunks, [&](std::size_t c, unsigned) {
    std::size_t k = 0;
    for (std::size_t i = chunk_begin(c), e = chunk_end(c); i < e; ++i) k += crosses(i);
    before[c] = k;
  });
  std::size_t lower = 0, upper = 0;
  for (std::size_t c = 0; c < chunks; ++c) {
    std::size_t& half = c < lower_chunks ? lower : upper;
    half += std::exchange(before[c], half);
  }
  DTLAB_ASSERT(lower == upper);  // else not a permutation of [lo, hi)
  // The position of the k-th crossing element of the half whose chunks are [first, last).
  const auto kth = [&](std::size_t k, std::size_t first, std::size_t last) {
    const auto c = static_cast<std::size_t>(std::upper_bound(before.begin() + static_cast<std::ptrdiff_t>(first),
                                                             before.begin() + static_cast<std::ptrdiff_t>(last), k) -
                                            before.begin() - 1);
    std::size_t i = chunk_begin(c);
    for (std::size_t skip = k - before[c]; !crosses(i) || skip-- > 0;) ++i;
    return i;
  };
  // Every thread's start is found before any swap changes what crosses.
  const std::size_t shares = team.threads();
  std::vector<std::array<std::size_t, 2>> start(shares);
  team.run(shares, [&](std::size_t s, unsigned) {
    const std::size_t k = lower * s / shares;
    if (k < lower) start[s] = {kth(k, 0, lower_chunks), kth(k, lower_chunks, chunks)};
  });
  team.run(shares, [&](std::size_t s, unsigned) {
    std::size_t i = start[s][0], j = start[s][1];
    for (std::size_t k = lower * s / shares, end = lower * (s + 1) / shares; k < end; ++k, ++i, ++j) {
      while (!crosses(i)) ++i;
      while (!crosses(j)) ++j;
      std::swap(values[i], values[j]);
      std::swap(destination[i], destination[j]);
    }
  });
}

// move_to_destinations on a team: 2^levels parts by `levels` rounds of swap_across_halves, then
// each part on one thread.
template <class T>
void move_to_destinations_in_parts(T* values, std::uint32_t* destination, std::size_t n, WorkerTeam& team,
                                   unsigned levels) {
  std::vector<std::size_t> cuts = {0, n};  // parts [cuts[p], cuts[p + 1])
  for (unsigned level = 0; level < levels; ++level) {
    std::vector<std::size_t> finer = {0};
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
      const std::size_t lo = cuts[p], hi = cuts[p + 1], mid = lo + (hi - lo) / 2;
      swap_across_halves(values, destination, lo, mid, hi, team);
      finer.push_back(mid);
      finer.push_back(hi);
    }
    cuts = std::move(finer);
  }
  team.run(cuts.size() - 1, [&](std::size_t p, unsigned) {
    move_block_to_destinations(values, destination, cuts[p], cuts[p + 1]);
  });
}

}  // namespace detail

// Moves each values[i] to position destination[i], in place. destination must be a permutation
// of 0..values.size()-1 (an assertion fails otherwise) and is consumed: afterwards it is the
// identity. O(n log_256 n) moves, no scratch. With `team`, the array is first halved on its
// threads until there is a part for each (swap_across_halves), then each part finished on one.
template <class T>
void move_to_destinations(std::span<T> values, std::span<std::uint32_t> destination, WorkerTeam* team = nullptr) {
  const std::size_t n = values.size();
  DTLAB_ASSERT(destination.size() == n);
  if (team == nullptr || team->threads() == 1 || n <= detail::kCycleBlock) {
    detail::move_block_to_destinations(values.data(), destination.data(), 0, n);
    return;
  }
  // As many halvings as make a part for every thread.
  const unsigned levels = static_cast<unsigned>(std::bit_width(team->threads() - 1u));
  detail::move_to_destinations_in_parts(values.data(), destination.data(), n, *team, levels);
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
