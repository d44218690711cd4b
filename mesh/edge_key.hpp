// The key of an undirected edge between vertex ids: the smaller id in the high 32 bits, so that
// {a, b} and {b, a} have one key and sorting keys groups the edges by their smaller end.
#pragma once

#include <cstdint>

namespace dtlab {

constexpr std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) noexcept {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

}  // namespace dtlab
