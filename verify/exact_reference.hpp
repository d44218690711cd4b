// An independent oracle for the predicates: exact signs over the rationals (GMP mpq).
//
// Deliberately a different road from kernel/predicates/exact.cpp (scaled GMP integers, the
// translated determinants): each coordinate becomes an mpq exactly (mpq_set_d), each predicate
// is the determinant of its homogeneous matrix (rows (p, 1), lifted (p, |p|^2, 1) for the
// in-circle/in-sphere tests), and the sign comes from Gaussian elimination with exact pivots.
// Slow (microseconds per call) and meant for tests, fuzzers and checkers only.
//
// Sign conventions are those of kernel/predicates.hpp:
//   orient2d  = +det[(p, 1)]           over a, b, c
//   incircle  = +det[(p, |p|^2, 1)]    over a, b, c, d
//   orient3d  = -det[(p, 1)]           over a, b, c, d
//   insphere  = -det[(p, |p|^2, 1)]    over a, b, c, d, e
// Inputs may be any finite doubles (no range precondition); NaN or infinity throws InputError.
#pragma once

#include <span>
#include <vector>

#include "kernel/exact_rational.hpp"
#include "kernel/sign.hpp"
#include "kernel/vec.hpp"

namespace dtlab::reference {

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);
Sign incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
Sign insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

// The perturbation scheme documented in kernel/predicates/perturbation.hpp, evaluated from its
// definition: the lifted coordinate of the point of rank r (rank 1 = lexicographically largest)
// gets + eps^r; since the determinant is linear in the lifted column, the perturbed sign is the
// sign of det, else that of the first non-zero cofactor of that column in rank order. Every
// cofactor is computed here as its own minor, not via orient2d/orient3d. Duplicate points have
// no rank order: they throw InputError.
Sign incircle_perturbed(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
Sign insphere_perturbed(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

// True iff all points lie on one line (2D) / one plane (3D), exactly; fewer than 3 (4) points
// are trivially so.
bool all_collinear(std::span<const Vec2> points);
bool all_coplanar(std::span<const Vec3> points);

// The sign of the determinant of a square rational matrix, by Gaussian elimination with exact
// pivots: the engine of every function above, for tests that build their own matrices.
Sign determinant_sign(std::vector<std::vector<Rational>> m);

}  // namespace dtlab::reference
