// The tests across the four facets of one tetrahedron against one query point, decided by the
// static filter (static_filter.hpp) in one pass of vector arithmetic, one lane a facet: the
// orientation of the point to each facet (the walk of point location asks which facets it lies
// beyond) and the in-sphere test of each neighbour across a facet (the cavity search asks about
// the neighbours of a cavity tetrahedron together). The lanes are the tetrahedron's four
// vertices permuted in registers, plus one apex each for the neighbours: 4 or 8 points loaded
// instead of 12 or 16. Each lane computes the scalar determinant of its rows bit for bit
// (semistatic.hpp's *_det_translated, no contraction), so a lane decides exactly when the
// scalar static test on those rows would; the caller sends the undecided ones through the full
// predicate. On x86-64 the vectors are AVX2 where the processor has it (chosen at run time),
// SSE2 pairs otherwise: only speed depends on it.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/vec.hpp"

namespace dtlab {

// The facets of a positive tetrahedron (v0, v1, v2, v3): facet i, opposite v_i, listed so that
// (facet, v_i) is positive (mesh/tetrahedralization3.hpp's kFacetVertex, checked where both
// are used).
inline constexpr std::array<std::array<unsigned, 3>, 4> kFacetRows = {{{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

struct OrientBatch {
  unsigned negative = 0;   // bit i: e certified strictly beyond facet i (orient3d(facet i, e) < 0)
  unsigned undecided = 0;  // bit i: the static bound did not decide test i
};

// orient3d(v[kFacetRows[i][0]], v[kFacetRows[i][1]], v[kFacetRows[i][2]], e) for each bit i of
// `tests` (at least one); v = four vertex ids indexing `points`, the tetrahedron positive. The
// decided tests count as semi-static orient3d calls in the predicate statistics.
OrientBatch orient3d_static_facets(const Vec3* points, const std::array<std::uint32_t, 4>& v, unsigned tests,
                                   const Vec3& e, double static_bound) noexcept;

struct InsphereBatch {
  unsigned positive = 0;   // bit i: test i certified positive
  unsigned undecided = 0;  // bit i: the static bound did not decide test i
};

// The rows of test i, for a positive tetrahedron (v0, v1, v2, v3) and the apex a_i of the
// tetrahedron across the facet opposite v_i: that neighbour listed positive,
//   test 0: (v1, v2, v3, a0)   test 1: (v0, v3, v2, a1)   test 2: (v0, v1, v3, a2)   test 3: (v0, v2, v1, a3)
// and e last: insphere(rows, e) > 0 iff e lies inside the neighbour's circumsphere.
inline constexpr std::array<std::array<unsigned, 3>, 4> kAcrossFacetRows = {
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

// Tests i with bit i of `tests` set (at least one); v = the four vertex ids of the tetrahedron,
// apex[i] the apex id of test i (ignored, not read, for the others); ids index `points`. The
// decided tests count as semi-static in-sphere calls in the predicate statistics
// (kernel/stats.hpp), as one by one would.
InsphereBatch insphere_static_across_facets(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                            const std::array<std::uint32_t, 4>& apex, unsigned tests,
                                            const Vec3& e, double static_bound) noexcept;

namespace detail {
// The same without the AVX2 version, whatever the processor: for the tests.
OrientBatch orient3d_static_facets_portable(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                            unsigned tests, const Vec3& e, double static_bound) noexcept;
InsphereBatch insphere_static_across_facets_portable(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                                     const std::array<std::uint32_t, 4>& apex, unsigned tests,
                                                     const Vec3& e, double static_bound) noexcept;
}  // namespace detail

}  // namespace dtlab
