// kernel/radix_sort: the same order as std::sort on random keys of every width (a few bits to all
// 64), with duplicates, below and above the size where it hands over to std::sort, and on the
// meshers' edge keys ((min << 32) | max).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "kernel/radix_sort.hpp"

namespace dtlab {
namespace {

TEST(RadixSort, SameOrderAsStdSortForEveryWidth) {
  std::mt19937_64 rng(7);
  for (const int bits : {1, 5, 11, 12, 22, 33, 40, 63, 64}) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{255}, std::size_t{256}, std::size_t{5000}}) {
      std::vector<std::uint64_t> keys(n);
      for (auto& k : keys) k = bits == 64 ? rng() : rng() & ((std::uint64_t{1} << bits) - 1);
      std::vector<std::uint64_t> expected = keys;
      std::sort(expected.begin(), expected.end());
      radix_sort(keys);
      EXPECT_EQ(keys, expected) << bits << " bits, " << n << " keys";
    }
  }
}

TEST(RadixSort, EdgeKeysWithDuplicates) {
  std::mt19937_64 rng(11);
  std::vector<std::uint64_t> keys;
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t a = rng() % 3000, b = rng() % 3000;
    keys.push_back(std::min(a, b) << 32 | std::max(a, b));
    keys.push_back(keys.back());
  }
  std::vector<std::uint64_t> expected = keys;
  std::sort(expected.begin(), expected.end());
  radix_sort(keys);
  EXPECT_EQ(keys, expected);
}

RC_GTEST_PROP(RadixSort, AgreesWithStdSort, ()) {
  // Past the hand-over size, keys of a random width.
  const auto n = *rc::gen::inRange<std::size_t>(256, 4000);
  const auto bits = *rc::gen::inRange(1, 65);
  const auto raw = *rc::gen::container<std::vector<std::uint64_t>>(n, rc::gen::arbitrary<std::uint64_t>());
  std::vector<std::uint64_t> keys;
  for (const std::uint64_t k : raw) keys.push_back(bits == 64 ? k : k & ((std::uint64_t{1} << bits) - 1));
  std::vector<std::uint64_t> expected = keys;
  std::sort(expected.begin(), expected.end());
  radix_sort(keys);
  RC_ASSERT(keys == expected);
}

}  // namespace
}  // namespace dtlab
