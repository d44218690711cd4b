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
  const int digits = (bits + kDigitBits - 1) / kDigitBits;
  // Every digit's histogram in one read of the keys.
  std::vector<std::size_t> count(static_cast<std::size_t>(digits) * kBuckets, 0);
  for (const std::uint64_t k : keys)
    for (int d = 0; d < digits; ++d) ++count[d * kBuckets + ((k >> (d * kDigitBits)) & (kBuckets - 1))];
  std::vector<std::uint64_t> scratch(n);
  for (int d = 0; d < digits; ++d) {
    std::size_t* c = count.data() + d * kBuckets;
    const int shift = d * kDigitBits;
    if (c[(keys[0] >> shift) & (kBuckets - 1)] == n) continue;  // one bucket: nothing moves
    std::size_t sum = 0;
    for (std::size_t b = 0; b < kBuckets; ++b) sum += std::exchange(c[b], sum);
    for (const std::uint64_t k : keys) scratch[c[(k >> shift) & (kBuckets - 1)]++] = k;
    keys.swap(scratch);
  }
}

}  // namespace dtlab
