// Hints to the operating system about large arrays (Linux madvise; no effect elsewhere). Only
// speed depends on them: a refused hint changes nothing else.
#pragma once

#include <cstddef>

namespace dtlab {

// Back an array about to be filled with transparent huge pages where the system offers them,
// which cuts the TLB misses of the random accesses of point location and cavity search. Call it
// before first writing the memory; no effect on small arrays.
void advise_huge_pages(const void* data, std::size_t bytes) noexcept;

// Fault in, for writing, the whole pages inside [begin, end) in one call (MADV_POPULATE_WRITE,
// Linux 5.14) instead of one page fault each when first written: for memory about to be written
// anyway. Where a page fault is dear (a virtual machine's, measured on the 3D Delaunay kernel's
// tetrahedra: issue 23), this is most of the first touch's cost.
void populate_for_writing(const void* begin, const void* end) noexcept;

}  // namespace dtlab
