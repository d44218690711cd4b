#include "mesh/memory_hints.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dtlab {

namespace {

// [first, last): the whole blocks of `block` bytes inside [begin, end).
struct Inner {
  std::uintptr_t first, last;
};
Inner inner_blocks(const void* begin, const void* end, std::uintptr_t block) noexcept {
  const auto b = reinterpret_cast<std::uintptr_t>(begin), e = reinterpret_cast<std::uintptr_t>(end);
  return {(b + block - 1) & ~(block - 1), e & ~(block - 1)};
}

}  // namespace

void advise_huge_pages(const void* data, std::size_t bytes) noexcept {
#if defined(MADV_HUGEPAGE)
  const Inner in = inner_blocks(data, static_cast<const char*>(data) + bytes, std::uintptr_t{1} << 21);
  if (in.last > in.first) static_cast<void>(madvise(reinterpret_cast<void*>(in.first), in.last - in.first, MADV_HUGEPAGE));
#else
  static_cast<void>(data), static_cast<void>(bytes);
#endif
}

void populate_for_writing(const void* begin, const void* end) noexcept {
#if defined(__linux__)
  // The constant of Linux's uapi (older C libraries do not name it); an older kernel answers
  // EINVAL and the pages fault in one by one, as without the hint.
  constexpr int kPopulateWrite = 23;
  const Inner in = inner_blocks(begin, end, std::uintptr_t{4096});
  if (in.last > in.first) static_cast<void>(madvise(reinterpret_cast<void*>(in.first), in.last - in.first, kPopulateWrite));
#else
  static_cast<void>(begin), static_cast<void>(end);
#endif
}

}  // namespace dtlab
