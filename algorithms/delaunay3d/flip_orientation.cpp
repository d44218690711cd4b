// Orientation with the infinite vertex (flip_orientation.hpp).
#include "algorithms/delaunay3d/flip_orientation.hpp"

#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

namespace {
constexpr std::uint32_t kInf = Tetrahedralization3::kInfinite;
}  // namespace

FlipOrientation::FlipOrientation(const Vec3* points, std::array<std::uint32_t, 4> first) noexcept
    : p_(points), first_{points[first[0]], points[first[1]], points[first[2]], points[first[3]]} {}

Sign FlipOrientation::from_interior(std::uint32_t a, std::uint32_t b, std::uint32_t c) const noexcept {
  for (const Vec3& v : first_) {
    const Sign s = orient3d(v, p_[a], p_[b], p_[c]);
    if (s != Sign::Zero) return s;
  }
  return Sign::Zero;
}

// With c0 in place of kInfinite at position k, orient3d(..) equals +-orient3d(c0, the other
// three in order): + for k = 0 and 2 (a 3-cycle), - for k = 1 and 3 (a swap, a 4-cycle); the
// infinite vertex negates that once more.
Sign FlipOrientation::orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const noexcept {
  if (a == kInf) return -from_interior(b, c, d);
  if (b == kInf) return from_interior(a, c, d);
  if (c == kInf) return -from_interior(a, b, d);
  if (d == kInf) return from_interior(a, b, c);
  return orient3d(p_[a], p_[b], p_[c], p_[d]);
}

}  // namespace dtlab
