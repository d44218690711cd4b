#include "mesh/scratch_array.hpp"

#include <cstring>
#include <new>

#if defined(__unix__)
#include <sys/mman.h>
#endif

namespace dtlab {

void* acquire_scratch_pages(std::size_t bytes) {
#if defined(__unix__) && defined(MAP_ANONYMOUS)
  void* pages = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (pages == MAP_FAILED) throw std::bad_alloc();
  return pages;
#else
  void* pages = ::operator new(bytes);
  std::memset(pages, 0, bytes);
  return pages;
#endif
}

void release_scratch_pages(void* pages, std::size_t bytes) noexcept {
#if defined(__unix__) && defined(MAP_ANONYMOUS)
  static_cast<void>(munmap(pages, bytes));
#else
  static_cast<void>(bytes);
  ::operator delete(pages);
#endif
}

}  // namespace dtlab
