// Symbolic perturbation of the in-circle and in-sphere tests: one tie-break for every algorithm.
//
// Scheme (a lexicographic lifting perturbation, in the spirit of Devillers and Teillaud,
// "Perturbations for Delaunay and weighted Delaunay 3D triangulations", CGTA 2011): each point p
// is lifted to |p|^2 + eps^r(p), where r(p) is the rank of p in decreasing lexicographic order
// of its coordinates (x, then y, then z) among the points of the call, and eps is infinitely
// small. The lifted determinant becomes det + sum_p eps^r(p) * C_p, where C_p is the cofactor
// of p's lifted entry, an orientation of the other points:
//   incircle(a,b,c,d):   C_a = +orient2d(b,c,d)   C_b = -orient2d(a,c,d)
//                        C_c = +orient2d(a,b,d)   C_d = -orient2d(a,b,c)
//   insphere(a,b,c,d,e): C_a = -orient3d(b,c,d,e) C_b = +orient3d(a,c,d,e)
//                        C_c = -orient3d(a,b,d,e) C_d = +orient3d(a,b,c,e)
//                        C_e = -orient3d(a,b,c,d)
// When det is zero, the sign is that of the first non-zero cofactor, taking the points from the
// lexicographically largest down. Because the rank depends only on coordinates, the result is
// a pure function of the points, the same for every algorithm and every input order; it is the
// sign of a genuine perturbation, so it induces one triangulation (the lower hull of the
// perturbed lifting) even on cocircular or cospherical sets.
//
// Zero is returned only when every cofactor vanishes: all points collinear (coplanar in 3D),
// which no Delaunay algorithm asks about a non-degenerate simplex (C_d or C_e is then non-zero).
//
// Cost on cospherical input: the exact zero is usually certified by stage 2's integer evaluation
// (grids, lattices), which hands over the cofactors it computed on the way; only otherwise are
// they evaluated as orientations (semi-static filter first), and only until the first non-zero.
#pragma once

#include "kernel/predicates.hpp"
#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

namespace detail {
// The sign of the perturbed determinant when the unperturbed one is zero; `known` cofactors (may
// be null, or not known) are used instead of evaluating orientations.
Sign incircle_perturbation(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                           const LiftCofactors* known = nullptr) noexcept;
Sign insphere_perturbation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                           const LiftCofactors* known = nullptr) noexcept;

// Stages 2 to 4, then the perturbation: out of line, as for the predicates themselves.
Sign incircle_perturbed_slow(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept;
Sign insphere_perturbed_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                             const Vec3& e) noexcept;
}  // namespace detail

// The semi-static filter never certifies Zero, so what it decides needs no perturbation.
inline Sign incircle_perturbed(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) noexcept {
  if (const FilteredSign s = stage::incircle_semistatic(a, b, c, d)) {
    detail::count_semistatic(Predicate::Incircle);
    return *s;
  }
  return detail::incircle_perturbed_slow(a, b, c, d);
}

// With a static filter bound valid for these operands (static_filter.hpp) tried first.
inline Sign insphere_perturbed_bounded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                                       double static_bound) noexcept {
  if (const FilteredSign s = stage::insphere_semistatic_bounded(a, b, c, d, e, static_bound)) {
    detail::count_semistatic(Predicate::Insphere);
    return *s;
  }
  return detail::insphere_perturbed_slow(a, b, c, d, e);
}
inline Sign insphere_perturbed(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               const Vec3& e) noexcept {
  return insphere_perturbed_bounded(a, b, c, d, e, stage::kNoStaticBound);
}

}  // namespace dtlab
