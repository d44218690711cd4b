// A large temporary array in pages of its own, straight from the system and given back when it
// goes. Through malloc, freeing a block of a few MB raises glibc's dynamic mmap threshold to its
// size, and later allocations below that size then stay on the heap: after a 4 MB permutation
// scratch, the 3D Delaunay kernel's peak memory at 10^6 points grew by 2.7 MB (issue 23), and
// its target is 240 MB.
#pragma once

#include <cstddef>
#include <span>
#include <type_traits>

namespace dtlab {

// `bytes` of zeroed memory, page aligned (mmap where there is one, else operator new); throws
// std::bad_alloc when refused.
void* acquire_scratch_pages(std::size_t bytes);
void release_scratch_pages(void* pages, std::size_t bytes) noexcept;

template <class T>
class ScratchArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  explicit ScratchArray(std::size_t n) : n_(n), data_(n == 0 ? nullptr : static_cast<T*>(acquire_scratch_pages(n * sizeof(T)))) {}
  ~ScratchArray() {
    if (data_ != nullptr) release_scratch_pages(data_, n_ * sizeof(T));
  }
  ScratchArray(const ScratchArray&) = delete;
  ScratchArray& operator=(const ScratchArray&) = delete;

  T& operator[](std::size_t i) noexcept { return data_[i]; }
  std::span<T> span() noexcept { return {data_, n_}; }

 private:
  std::size_t n_;
  T* data_;
};

}  // namespace dtlab
