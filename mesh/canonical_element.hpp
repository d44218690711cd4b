// One written form per oriented element, so that two triangulations can be compared as sets and
// written byte for byte alike whatever order and rotation a variant, a thread count or a tile
// count left them in: the lowest id first, the orientation kept.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace dtlab {

// A triangle: the rotation that puts its lowest id first.
inline std::array<std::uint32_t, 3> canonical_triangle(const std::array<std::uint32_t, 3>& t) {
  const auto k = static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

// A tetrahedron: an even permutation (orientation kept) putting the lowest id first and the
// lowest of the other three second.
inline std::array<std::uint32_t, 4> canonical_tetrahedron(std::array<std::uint32_t, 4> t) {
  // Double transpositions moving the lowest id to position 0.
  switch (std::min_element(t.begin(), t.end()) - t.begin()) {
    case 1: t = {t[1], t[0], t[3], t[2]}; break;
    case 2: t = {t[2], t[3], t[0], t[1]}; break;
    case 3: t = {t[3], t[2], t[1], t[0]}; break;
    default: break;
  }
  // A 3-cycle of the last three (even), at most twice, until the lowest of them comes first.
  for (int k = 0; k < 2 && (t[1] > t[2] || t[1] > t[3]); ++k) t = {t[0], t[2], t[3], t[1]};
  return t;
}

}  // namespace dtlab
