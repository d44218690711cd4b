// Bounds-checked reading of binary mesh files held in memory (Medit .meshb/.solb, Gmsh binary
// .msh), shared by their readers, and the little-endian writing that their writers use.
//
// Every read names its byte offset: a ParseError whose line() is the offset and whose message
// says "at byte N", so that a binary file's errors read like a text file's.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "kernel/error.hpp"

namespace dtlab::io {

class BinaryInput {
 public:
  BinaryInput(std::string_view bytes, const std::string& file_name) : bytes_(bytes), file_(file_name) {}

  std::size_t size() const noexcept { return bytes_.size(); }
  std::string_view bytes() const noexcept { return bytes_; }
  const std::string& file_name() const noexcept { return file_; }
  // Words are read in the byte order opposite to the machine's little-endian one when set.
  void set_swapped(bool swapped) noexcept { swap_ = swapped; }
  bool swapped() const noexcept { return swap_; }

  // The n-byte (1 to 8) unsigned word at `at`, in the file's byte order; need() first.
  std::uint64_t load(std::size_t at, std::size_t n) const {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[at + k]));
      v |= byte << (8 * (swap_ ? n - 1 - k : k));
    }
    return v;
  }
  std::int64_t signed32(std::size_t at) const {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(load(at, 4)));
  }
  // A 4- or 8-byte signed integer.
  std::int64_t signed_word(std::size_t at, std::size_t n) const {
    return n == 4 ? signed32(at) : static_cast<std::int64_t>(load(at, 8));
  }
  double real(std::size_t at, std::size_t n) const {
    return n == 4 ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(load(at, 4))))
                  : std::bit_cast<double>(load(at, 8));
  }

  // Throws "file ends in <what> (truncated?)" unless n bytes follow `at`.
  void need(std::size_t at, std::size_t n, const std::string& what) const {
    if (bytes_.size() < at || bytes_.size() - at < n) fail(at, "file ends in " + what + " (truncated?)");
  }
  // Throws unless `count` items of `item_bytes` each fit in what is left after `at`: a count read
  // from a file is checked before anything of that size is allocated.
  void need_items(std::size_t at, std::uint64_t count, std::uint64_t item_bytes, const std::string& what) const {
    const std::uint64_t left = at <= bytes_.size() ? bytes_.size() - at : 0;
    if (item_bytes != 0 && count > left / item_bytes) {
      fail(at, what + ": count " + std::to_string(count) + " needs " + std::to_string(item_bytes) +
                   " bytes each, but the file has " + std::to_string(left) + " left (truncated?)");
    }
  }

  [[noreturn]] void fail(std::size_t at, const std::string& reason) const {
    throw ParseError(file_, at, "at byte " + std::to_string(at) + ": " + reason);
  }

 private:
  std::string_view bytes_;
  const std::string& file_;
  bool swap_ = false;
};

// Appends the n low bytes of v, little-endian.
inline void store_le(std::string& out, std::uint64_t v, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) out += static_cast<char>((v >> (8 * k)) & 0xff);
}
inline void store_le_real(std::string& out, double v) { store_le(out, std::bit_cast<std::uint64_t>(v), 8); }

}  // namespace dtlab::io
