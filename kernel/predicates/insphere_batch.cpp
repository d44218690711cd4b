// Only this file passes vectors of doubles around (to semistatic.hpp's inlined determinant): no
// ABI is crossed, so the warning that the AVX2 clone's vectors are passed differently is moot.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "kernel/predicates/insphere_batch.hpp"

#include <bit>

#include "kernel/predicates/semistatic.hpp"
#include "kernel/stats.hpp"

namespace dtlab {

namespace {

typedef double Lanes __attribute__((vector_size(4 * sizeof(double))));

}  // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
InsphereBatch insphere_static_batch(const Vec3* points, const std::uint32_t* const* tests, unsigned count,
                                    const Vec3& e, double static_bound) noexcept {
  // Missing tests repeat test 0. The lanes are assembled in registers: filling them through
  // memory one double at a time and reading them back whole stalls on store forwarding.
  const std::uint32_t* t0 = tests[0];
  const std::uint32_t* t1 = tests[count > 1 ? 1 : 0];
  const std::uint32_t* t2 = tests[count > 2 ? 2 : 0];
  const std::uint32_t* t3 = tests[count > 3 ? 3 : 0];
  const Lanes ex = {e.x, e.x, e.x, e.x}, ey = {e.y, e.y, e.y, e.y}, ez = {e.z, e.z, e.z, e.z};
  Lanes c[12];
  for (unsigned j = 0; j < 4; ++j) {
    const Vec3 &q0 = points[t0[j]], &q1 = points[t1[j]], &q2 = points[t2[j]], &q3 = points[t3[j]];
    c[3 * j] = Lanes{q0.x, q1.x, q2.x, q3.x} - ex;
    c[3 * j + 1] = Lanes{q0.y, q1.y, q2.y, q3.y} - ey;
    c[3 * j + 2] = Lanes{q0.z, q1.z, q2.z, q3.z} - ez;
  }
  const Lanes det = stage::insphere_det_translated(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9],
                                                   c[10], c[11]);
  InsphereBatch out;
  for (unsigned k = 0; k < count; ++k) {
    // As insphere_semistatic_bounded: decided when |det| > bound.
    if (det[k] > static_bound) {
      out.positive |= 1u << k;
    } else if (!(det[k] < -static_bound)) {
      out.undecided |= 1u << k;
    }
  }
  detail::tls_predicate_stats[Predicate::Insphere].semistatic += count - std::popcount(out.undecided);
  return out;
}

}  // namespace dtlab
