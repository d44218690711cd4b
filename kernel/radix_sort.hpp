// Sorting 64-bit keys by LSD radix sort, 11 bits a pass over the bits the largest key uses: the
// edge lists of the meshers ((min << 32) | max of two vertex ids, millions of them per pass) sort
// in a few linear passes instead of n log n comparisons. The same order as std::sort.
#pragma once

#include <cstdint>
#include <vector>

namespace dtlab {

void radix_sort(std::vector<std::uint64_t>& keys);

}  // namespace dtlab
