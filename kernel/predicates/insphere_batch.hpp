// Up to four in-sphere tests that share the query point e, decided by the static filter
// (static_filter.hpp) in one pass of vector arithmetic: the cavity search asks about the
// neighbours of a cavity tetrahedron together. Each lane computes the scalar determinant bit for
// bit (semistatic.hpp's insphere_det_translated, no contraction), so a lane decides exactly when
// insphere_semistatic_bounded's static test would; the caller sends the undecided ones through
// insphere_perturbed_bounded. On x86-64 the vectors are AVX2 where the processor has it (chosen
// at run time) and SSE2 pairs otherwise: only speed depends on it.
#pragma once

#include <cstdint>

#include "kernel/vec.hpp"

namespace dtlab {

struct InsphereBatch {
  unsigned positive = 0;   // bit k: test k certified positive
  unsigned undecided = 0;  // bit k: the static bound did not decide test k
};

// Test k is insphere(a, b, c, d, e) with a, b, c, d = points[tests[k][0..3]], for k < count
// (1 to 4) (tests[k]: four vertex ids, as a tetrahedron lists them). The decided tests count as
// semi-static calls in the predicate statistics (kernel/stats.hpp), as one by one would.
InsphereBatch insphere_static_batch(const Vec3* points, const std::uint32_t* const* tests, unsigned count,
                                    const Vec3& e, double static_bound) noexcept;

}  // namespace dtlab
