#include "kernel/radix_sort.hpp"

#include <algorithm>
#include <bit>
#include <utility>

namespace dtlab {

void radix_sort(std::vector<std::uint64_t>& keys) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = keys.size();
  if (n < 256) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  // The bits in use: above the highest set bit of every key all digits are zero.
  std::uint64_t any = 0;
  for (const std::uint64_t k : keys) any |= k;
  const int bits = 64 - std::countl_zero(any);
  std::vector<std::uint64_t> scratch(n);
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift < bits; shift += kDigitBits) {
    std::fill(count.begin(), count.end(), 0);
    for (const std::uint64_t k : keys) ++count[(k >> shift) & (kBuckets - 1)];
    if (count[(keys[0] >> shift) & (kBuckets - 1)] == n) continue;  // one bucket: nothing moves
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const std::uint64_t k : keys) scratch[count[(k >> shift) & (kBuckets - 1)]++] = k;
    keys.swap(scratch);
  }
}

}  // namespace dtlab
