// The filtered exact predicates of dtlab (book §1): orient2d, incircle, orient3d, insphere.
//
// Each predicate runs up to four stages, and each stage is callable on its own (namespace stage):
//   1. semi-static filter (semistatic.hpp): doubles, error bound from the operands' maxima;
//   2. dynamic filter (adaptive.cpp): the determinant of the exact coordinate differences,
//      estimated in double-word arithmetic and certified against the estimate's error bound, or
//      evaluated exactly in floating-point expansions when the differences are exact;
//   3. exact expansion (exact_expansion.cpp): each difference as an exact two-component
//      expansion, the determinant exactly in expansion arithmetic; reached only when stage 2's
//      estimate is within 2^-89 of Perm from zero with rounded differences;
//   4. exact fallback (exact.cpp): GMP integers, doubles converted exactly; reached only if a
//      stage-3 expansion outgrows its buffer. Kept as the oracle the other stages are tested on.
// Stage counts go to this thread's PredicateStats (stats.hpp).
//
// Sign conventions:
//   orient2d(a,b,c)      > 0  iff a, b, c turn counter-clockwise;
//   incircle(a,b,c,d)    > 0  iff d is inside circle(a,b,c), for a, b, c counter-clockwise;
//   orient3d(a,b,c,d)    > 0  iff det(b-a, c-a, d-a) > 0 (Medit's positive tetrahedron);
//   insphere(a,b,c,d,e)  > 0  iff e is inside sphere(a,b,c,d), for orient3d(a,b,c,d) > 0.
// The *_perturbed variants (perturbation.hpp) never return zero for distinct points in general
// position of the lower dimension (see there).
//
// Precondition: every coordinate is finite and in the supported range (coordinate_range.hpp);
// the entry points of dtlab check it once per input, the predicates do not.
#pragma once

#include <array>

#include "kernel/predicates/semistatic.hpp"
#include "kernel/sign.hpp"
#include "kernel/stats.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

namespace stage {
// Stage 2: decides unless the differences were rounded and the determinant is within 2^-89 of
// its permanent from zero (in practice: zero).
FilteredSign orient2d_adaptive(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
FilteredSign incircle_adaptive(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept;
FilteredSign orient3d_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
FilteredSign insphere_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               const Vec3& e) noexcept;

// Stage 3: decides unless an expansion outgrows its fixed buffer (never seen on the supported
// range; the tests check it on extreme magnitudes).
FilteredSign orient2d_expansion(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
FilteredSign incircle_expansion(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept;
FilteredSign orient3d_expansion(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
FilteredSign insphere_expansion(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                const Vec3& e) noexcept;

// Stage 4: always decides, with GMP.
Sign orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
Sign incircle_exact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept;
Sign orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
Sign insphere_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) noexcept;
}  // namespace stage

namespace detail {
// The signs of the cofactors of the lifted column of incircle / insphere, in argument order (the
// C_p of perturbation.hpp; C_d of incircle is the fourth, the fifth is unused there). Stage 2
// fills them in when it decides Zero from its integer evaluation, which computes them on the way;
// `known` says whether it did.
struct LiftCofactors {
  bool known = false;
  std::array<Sign, 5> sign{};
};

// Stage 2 of incircle and insphere, also reporting the cofactors when it can (cofactors may be null).
FilteredSign incircle_adaptive(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                               LiftCofactors* cofactors) noexcept;
FilteredSign insphere_adaptive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                               LiftCofactors* cofactors) noexcept;

// Stages 2 to 4 with counting, out of line: the filtered predicates' slow path.
Sign orient2d_slow(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
Sign incircle_slow(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                   LiftCofactors* cofactors = nullptr) noexcept;
Sign orient3d_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept;
Sign insphere_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                   LiftCofactors* cofactors = nullptr) noexcept;

inline void count_semistatic(Predicate p) noexcept { ++tls_predicate_stats[p].semistatic; }
}  // namespace detail

inline Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (const FilteredSign s = stage::orient2d_semistatic(a, b, c)) {
    detail::count_semistatic(Predicate::Orient2d);
    return *s;
  }
  return detail::orient2d_slow(a, b, c);
}

inline Sign incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  if (const FilteredSign s = stage::incircle_semistatic(a, b, c, d)) {
    detail::count_semistatic(Predicate::Incircle);
    return *s;
  }
  return detail::incircle_slow(a, b, c, d);
}

// orient3d with a static filter bound valid for these operands (static_filter.hpp) tried first:
// the same sign, only cheaper.
inline Sign orient3d_bounded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                             double static_bound) noexcept {
  if (const FilteredSign s = stage::orient3d_semistatic_bounded(a, b, c, d, static_bound)) {
    detail::count_semistatic(Predicate::Orient3d);
    return *s;
  }
  return detail::orient3d_slow(a, b, c, d);
}
inline Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  return orient3d_bounded(a, b, c, d, stage::kNoStaticBound);
}

inline Sign insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) noexcept {
  if (const FilteredSign s = stage::insphere_semistatic(a, b, c, d, e)) {
    detail::count_semistatic(Predicate::Insphere);
    return *s;
  }
  return detail::insphere_slow(a, b, c, d, e);
}

// The same predicates without the counters, for measuring what counting costs.
namespace uncounted {
inline Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  if (const FilteredSign s = stage::orient2d_semistatic(a, b, c)) return *s;
  if (const FilteredSign s = stage::orient2d_adaptive(a, b, c)) return *s;
  if (const FilteredSign s = stage::orient2d_expansion(a, b, c)) return *s;
  return stage::orient2d_exact(a, b, c);
}
inline Sign incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  if (const FilteredSign s = stage::incircle_semistatic(a, b, c, d)) return *s;
  if (const FilteredSign s = stage::incircle_adaptive(a, b, c, d)) return *s;
  if (const FilteredSign s = stage::incircle_expansion(a, b, c, d)) return *s;
  return stage::incircle_exact(a, b, c, d);
}
inline Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) noexcept {
  if (const FilteredSign s = stage::orient3d_semistatic(a, b, c, d)) return *s;
  if (const FilteredSign s = stage::orient3d_adaptive(a, b, c, d)) return *s;
  if (const FilteredSign s = stage::orient3d_expansion(a, b, c, d)) return *s;
  return stage::orient3d_exact(a, b, c, d);
}
inline Sign insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) noexcept {
  if (const FilteredSign s = stage::insphere_semistatic(a, b, c, d, e)) return *s;
  if (const FilteredSign s = stage::insphere_adaptive(a, b, c, d, e)) return *s;
  if (const FilteredSign s = stage::insphere_expansion(a, b, c, d, e)) return *s;
  return stage::insphere_exact(a, b, c, d, e);
}
}  // namespace uncounted

}  // namespace dtlab

#include "kernel/predicates/perturbation.hpp"
