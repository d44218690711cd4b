// Only this file passes vectors of doubles around (to semistatic.hpp's inlined determinant): no
// ABI is crossed, so the warning that the AVX2 clone's vectors are passed differently is moot.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "kernel/predicates/facet_batch.hpp"

#include <bit>

#include "kernel/predicates/semistatic.hpp"
#include "kernel/stats.hpp"

namespace dtlab {

namespace {

typedef double Lanes __attribute__((vector_size(4 * sizeof(double))));

// Row r of the four tests, lane i = vertex kAcrossFacetRows[i][r]: the shuffles below,
//   row 0: (1, 0, 0, 0)   row 1: (2, 3, 1, 2)   row 2: (3, 2, 3, 1).
static_assert(kAcrossFacetRows[0] == std::array<unsigned, 3>{1, 2, 3} && kAcrossFacetRows[1] == std::array<unsigned, 3>{0, 3, 2} &&
              kAcrossFacetRows[2] == std::array<unsigned, 3>{0, 1, 3} && kAcrossFacetRows[3] == std::array<unsigned, 3>{0, 2, 1});

// The facet rows of the orientation lanes, encoded in facets()'s shuffles below.
static_assert(kFacetRows[0] == std::array<unsigned, 3>{1, 3, 2} && kFacetRows[1] == std::array<unsigned, 3>{0, 2, 3} &&
              kFacetRows[2] == std::array<unsigned, 3>{0, 3, 1} && kFacetRows[3] == std::array<unsigned, 3>{0, 1, 2});

// Coordinate `axis` of the tetrahedron's four vertices, one lane each.
[[gnu::always_inline]] inline Lanes vertex_lanes(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                                 double Vec3::*axis) noexcept {
  return Lanes{points[v[0]].*axis, points[v[1]].*axis, points[v[2]].*axis, points[v[3]].*axis};
}

// The tests asked for in `tests` as the scalar static filter decides them: bit i of `sign` set
// when lane i is certified of the sign asked for (`negative`: below -bound, else above bound),
// of `undecided` when |det| <= bound; the decided ones counted as semi-static calls of `p`.
struct Decided {
  unsigned sign = 0, undecided = 0;
};
[[gnu::always_inline]] inline Decided decide(Lanes det, unsigned tests, double static_bound, bool negative,
                                             Predicate p) noexcept {
  Decided out;
  for (unsigned i = 0; i < 4; ++i) {
    if (!(tests & (1u << i))) continue;
    if (negative ? det[i] < -static_bound : det[i] > static_bound) {
      out.sign |= 1u << i;
    } else if (!(negative ? det[i] > static_bound : det[i] < -static_bound)) {
      out.undecided |= 1u << i;
    }
  }
  detail::tls_predicate_stats[p].semistatic += std::popcount(tests) - std::popcount(out.undecided);
  return out;
}

// The bodies, compiled once per vector unit below.
[[gnu::always_inline]] inline OrientBatch facets(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                                 unsigned tests, const Vec3& e, double static_bound) noexcept {
  // As orient3d_semistatic_bounded(a, b, c, e): rows b - a, c - a, e - a, a, b, c = facet rows
  //   a: (1, 0, 0, 0)   b: (3, 2, 3, 1)   c: (2, 3, 1, 2)   (kFacetRows by lane).
  const Lanes x = vertex_lanes(points, v, &Vec3::x), y = vertex_lanes(points, v, &Vec3::y),
              z = vertex_lanes(points, v, &Vec3::z);
  const Lanes ax = __builtin_shufflevector(x, x, 1, 0, 0, 0), ay = __builtin_shufflevector(y, y, 1, 0, 0, 0),
              az = __builtin_shufflevector(z, z, 1, 0, 0, 0);
  const Lanes bx = __builtin_shufflevector(x, x, 3, 2, 3, 1), by = __builtin_shufflevector(y, y, 3, 2, 3, 1),
              bz = __builtin_shufflevector(z, z, 3, 2, 3, 1);
  const Lanes cx = __builtin_shufflevector(x, x, 2, 3, 1, 2), cy = __builtin_shufflevector(y, y, 2, 3, 1, 2),
              cz = __builtin_shufflevector(z, z, 2, 3, 1, 2);
  const Lanes ex = {e.x, e.x, e.x, e.x}, ey = {e.y, e.y, e.y, e.y}, ez = {e.z, e.z, e.z, e.z};
  const Lanes det = stage::orient3d_det_translated(bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az, ex - ax,
                                                   ey - ay, ez - az);
  const Decided d = decide(det, tests, static_bound, true, Predicate::Orient3d);
  return {d.sign, d.undecided};
}

[[gnu::always_inline]] inline InsphereBatch across_facets(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                                         const std::array<std::uint32_t, 4>& apex, unsigned tests,
                                                         const Vec3& e, double static_bound) noexcept {
  // The lanes are assembled in registers: filling them through memory one double at a time and
  // reading them back whole stalls on store forwarding. An untested lane's apex is replaced by a
  // vertex, so that nothing unread is loaded.
  const Lanes ex = {e.x, e.x, e.x, e.x}, ey = {e.y, e.y, e.y, e.y}, ez = {e.z, e.z, e.z, e.z};
  const Lanes tx = vertex_lanes(points, v, &Vec3::x) - ex;
  const Lanes ty = vertex_lanes(points, v, &Vec3::y) - ey;
  const Lanes tz = vertex_lanes(points, v, &Vec3::z) - ez;
  const Vec3& a0 = points[(tests & 1u) ? apex[0] : v[0]];
  const Vec3& a1 = points[(tests & 2u) ? apex[1] : v[0]];
  const Vec3& a2 = points[(tests & 4u) ? apex[2] : v[0]];
  const Vec3& a3 = points[(tests & 8u) ? apex[3] : v[0]];
  const Lanes dx = Lanes{a0.x, a1.x, a2.x, a3.x} - ex;
  const Lanes dy = Lanes{a0.y, a1.y, a2.y, a3.y} - ey;
  const Lanes dz = Lanes{a0.z, a1.z, a2.z, a3.z} - ez;
  const Lanes det = stage::insphere_det_translated(
      __builtin_shufflevector(tx, tx, 1, 0, 0, 0), __builtin_shufflevector(ty, ty, 1, 0, 0, 0),
      __builtin_shufflevector(tz, tz, 1, 0, 0, 0), __builtin_shufflevector(tx, tx, 2, 3, 1, 2),
      __builtin_shufflevector(ty, ty, 2, 3, 1, 2), __builtin_shufflevector(tz, tz, 2, 3, 1, 2),
      __builtin_shufflevector(tx, tx, 3, 2, 3, 1), __builtin_shufflevector(ty, ty, 3, 2, 3, 1),
      __builtin_shufflevector(tz, tz, 3, 2, 3, 1), dx, dy, dz);
  const Decided d = decide(det, tests, static_bound, false, Predicate::Insphere);
  return {d.sign, d.undecided};
}

}  // namespace

// The public entry points come in an AVX2 and a default version, chosen once when the program
// is loaded (GNU ifunc); the portable ones below are the default bodies, for the tests.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__)
#define DTLAB_FACET_BATCH_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define DTLAB_FACET_BATCH_CLONES
#endif

DTLAB_FACET_BATCH_CLONES
OrientBatch orient3d_static_facets(const Vec3* points, const std::array<std::uint32_t, 4>& v, unsigned tests,
                                   const Vec3& e, double static_bound) noexcept {
  return facets(points, v, tests, e, static_bound);
}

DTLAB_FACET_BATCH_CLONES
InsphereBatch insphere_static_across_facets(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                            const std::array<std::uint32_t, 4>& apex, unsigned tests,
                                            const Vec3& e, double static_bound) noexcept {
  return across_facets(points, v, apex, tests, e, static_bound);
}

namespace detail {
OrientBatch orient3d_static_facets_portable(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                            unsigned tests, const Vec3& e, double static_bound) noexcept {
  return facets(points, v, tests, e, static_bound);
}
InsphereBatch insphere_static_across_facets_portable(const Vec3* points, const std::array<std::uint32_t, 4>& v,
                                                     const std::array<std::uint32_t, 4>& apex, unsigned tests,
                                                     const Vec3& e, double static_bound) noexcept {
  return across_facets(points, v, apex, tests, e, static_bound);
}
}  // namespace detail

}  // namespace dtlab
