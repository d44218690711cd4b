// Reordering in place (algorithms/permute_in_place.hpp) against the obvious out-of-place
// permutation, on sizes that finish by cycles alone, deal once, and deal twice, on random and on
// structured permutations (identity, reversal, one long cycle); and a list that is not a
// permutation raises the named internal error instead of looping or writing out of bounds. With a
// WorkerTeam (the blocks of the first deal finished on its threads) the results are the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "algorithms/permute_in_place.hpp"
#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {
namespace {

struct Value {
  std::uint64_t id;
  double payload;  // a second word, so that a half-moved element shows
};

std::vector<Value> values_of(std::size_t n) {
  std::vector<Value> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = {i, 0.5 * static_cast<double>(i)};
  return v;
}

std::vector<std::vector<std::uint32_t>> permutations_of(std::size_t n, std::mt19937_64& rng) {
  std::vector<std::uint32_t> identity(n);
  std::iota(identity.begin(), identity.end(), 0u);
  std::vector<std::uint32_t> reversal(identity.rbegin(), identity.rend());
  std::vector<std::uint32_t> shuffled = identity;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  std::vector<std::uint32_t> one_cycle(n);  // i -> i + 1 -> ... -> 0: every element moves
  for (std::size_t i = 0; i < n; ++i) one_cycle[i] = static_cast<std::uint32_t>((i + 1) % n);
  // Local: each element moves less than 100 places, as a spatial order moves most points.
  std::vector<std::uint32_t> local = identity;
  for (std::size_t i = 0; i + 100 < n; i += 100) std::shuffle(local.begin() + i, local.begin() + i + 100, rng);
  return {identity, reversal, shuffled, one_cycle, local};
}

TEST(PermuteInPlace, EqualsTheOutOfPlacePermutation) {
  std::mt19937_64 rng(20261206);
  WorkerTeam team(2);
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{1000}, std::size_t{8192},
                              std::size_t{8193}, std::size_t{100003}, std::size_t{3000017}}) {
    for (const std::vector<std::uint32_t>& order : permutations_of(n, rng)) {
      for (WorkerTeam* on : {static_cast<WorkerTeam*>(nullptr), &team}) {
        std::vector<Value> values = values_of(n);
        permute_in_place(std::span<Value>(values), std::span<const std::uint32_t>(order), on);
        for (std::size_t r = 0; r < n; ++r) {
          ASSERT_EQ(values[r].id, order[r]) << "n " << n << ", rank " << r << (on ? ", on a team" : "");
          ASSERT_EQ(values[r].payload, 0.5 * static_cast<double>(order[r]));
        }
      }
    }
  }
}

TEST(PermuteInPlace, MoveToDestinationsUndoesThePermutationAndSpendsIt) {
  std::mt19937_64 rng(7);
  WorkerTeam team(2);
  for (const std::size_t n : {std::size_t{5}, std::size_t{8193}, std::size_t{600001}}) {
    for (const std::vector<std::uint32_t>& permutation : permutations_of(n, rng)) {
      for (WorkerTeam* on : {static_cast<WorkerTeam*>(nullptr), &team}) {
        std::vector<std::uint32_t> order = permutation;
        std::vector<Value> values = values_of(n);
        permute_in_place(std::span<Value>(values), std::span<const std::uint32_t>(order), on);
        move_to_destinations(std::span<Value>(values), std::span<std::uint32_t>(order), on);
        for (std::size_t i = 0; i < n; ++i) {
          ASSERT_EQ(values[i].id, i) << "n " << n << (on ? ", on a team" : "");
          ASSERT_EQ(order[i], i) << "the destinations end as the identity";
        }
      }
    }
  }
}

// Halving on the team before the parts are finished (swap_across_halves), one to three levels
// deep (8 parts on a team of 2: the split does not depend on the team's size), on permutations
// whose crossing elements are all, none, or a random half.
TEST(PermuteInPlace, HalvingOnATeamThenPartsEqualsOneThread) {
  std::mt19937_64 rng(11);
  WorkerTeam team(2);
  for (const std::size_t n : {std::size_t{8193}, std::size_t{50001}, std::size_t{300007}}) {
    for (const std::vector<std::uint32_t>& permutation : permutations_of(n, rng)) {
      for (const unsigned levels : {1u, 2u, 3u}) {
        std::vector<std::uint32_t> destination = permutation;
        std::vector<Value> values = values_of(n);
        detail::move_to_destinations_in_parts(values.data(), destination.data(), n, team, levels);
        for (std::size_t i = 0; i < n; ++i) {
          ASSERT_EQ(permutation[values[i].id], i) << "n " << n << ", levels " << levels;
          ASSERT_EQ(destination[i], i);
        }
      }
    }
  }
}

TEST(PermuteInPlace, NotAPermutationIsAnInternalErrorNotAHang) {
  for (const std::size_t n : {std::size_t{10}, std::size_t{50000}}) {
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::reverse(order.begin(), order.end());
    order[n / 2] = order[n / 3];  // one destination twice, one never
    std::vector<Value> values = values_of(n);
    EXPECT_THROW(move_to_destinations(std::span<Value>(values), std::span<std::uint32_t>(order)), InternalError);
    std::vector<std::uint32_t> beyond(n);
    std::iota(beyond.begin(), beyond.end(), 0u);
    beyond[n - 1] = static_cast<std::uint32_t>(n);  // past the end
    values = values_of(n);
    EXPECT_THROW(permute_in_place(std::span<Value>(values), std::span<const std::uint32_t>(beyond)), InternalError);
    values = values_of(n);
    EXPECT_THROW(move_to_destinations(std::span<Value>(values), std::span<std::uint32_t>(beyond)), InternalError);
    // On a team, a destination twice inside the last block (finished on the last thread) reaches
    // the caller as the same error.
    WorkerTeam team(2);
    std::vector<std::uint32_t> twice(n);
    std::iota(twice.begin(), twice.end(), 0u);
    twice[n - 3] = static_cast<std::uint32_t>(n - 2);
    values = values_of(n);
    EXPECT_THROW(move_to_destinations(std::span<Value>(values), std::span<std::uint32_t>(twice), &team), InternalError);
  }
}

}  // namespace
}  // namespace dtlab
