// Exact constructions of Steiner points and their correct rounding to double (MPFR).
//
// The rule (ROADMAP.md, "Steiner points and rounding"): a point an algorithm creates (segment
// intersection, split point) is COMPUTED EXACTLY (Rational), ROUNDED CORRECTLY to double, coordinate
// by coordinate, and from then on THE ROUNDED POINT IS THE TRUTH: predicates, mesh and output
// all use the double point; the exact one is kept only to check (verify/) that the rounded point
// is within its rounding bound. An algorithm that sees rounding fold an element must merge or
// re-place points, never emit the folded mesh. Split points that are exactly representable are
// preferred: every result below says whether it is exact (`RoundedPoint2::exact`).
//
// Rounding is IEEE-754 binary64 rounding of the exact value, subnormals and overflow included:
// nearest with ties to even (the default), or directed down (towards -inf) / up (towards +inf).
// The rounded point of an in-range construction need not be in the supported coordinate range
// (coordinate_range.hpp): two nearly parallel lines meet far away, a line may cross an axis at a
// tiny coordinate, and nearest rounding overflows to infinity past DBL_MAX. Callers check the
// result with coordinate_in_range before using it as an input point.
#pragma once

#include <optional>

#include "kernel/exact_rational.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

enum class Rounding { NearestEven, Down, Up };

// The double that IEEE-754 rounding of q in `mode` gives (±0 or a subnormal for tiny q, ±inf
// or ±DBL_MAX past the range, as IEEE specifies; a negative q rounding to zero gives -0.0).
double round_to_double(const Rational& q, Rounding mode = Rounding::NearestEven);
// True iff q is exactly a double (then round_to_double(q, any mode) == q).
bool is_double(const Rational& q);

// ulp(d): the distance from |d| to the next larger double in magnitude; 2^-1074 for zero and
// subnormals, 2^971 for DBL_MAX, +inf for infinite d. Always an exact double for finite d.
double ulp(double d) noexcept;
// The per-coordinate rounding bound of nearest rounding: if d = round_to_double(q) then
// |q - d| <= ulp(d) / 2 (the gap on the side of q is at most ulp(d)). Returned exactly when
// |d| >= 2^-1021; below that ulp(d)/2 = 2^-1075 is not a double, and 2^-1074 is returned, a bound
// twice too large (the supported coordinate range, |x| >= 2^-142, never reaches it).
double rounding_bound(double d) noexcept;

struct ExactPoint2 {
  Rational x, y;
  friend bool operator==(const ExactPoint2&, const ExactPoint2&) = default;
};
struct ExactPoint3 {
  Rational x, y, z;
  friend bool operator==(const ExactPoint3&, const ExactPoint3&) = default;
};

ExactPoint2 to_exact(const Vec2& p);
ExactPoint3 to_exact(const Vec3& p);

// A rounded construction: the double point, and whether it equals the exact point (no rounding).
struct RoundedPoint2 {
  Vec2 point;
  bool exact = false;
};
struct RoundedPoint3 {
  Vec3 point;
  bool exact = false;
};

Vec2 round_point(const ExactPoint2& p, Rounding mode = Rounding::NearestEven);
Vec3 round_point(const ExactPoint3& p, Rounding mode = Rounding::NearestEven);
RoundedPoint2 round_point_checked(const ExactPoint2& p);
RoundedPoint3 round_point_checked(const ExactPoint3& p);

// True iff every coordinate of `rounded` is finite and within ulp/2 of the exact coordinate,
// decided exactly (2|q - d| <= ulp(d) in rationals). This is what verify/ checks of each
// Steiner point; it holds for round_point(p) whenever no coordinate overflows.
bool within_rounding_bound(const ExactPoint2& exact, const Vec2& rounded);
bool within_rounding_bound(const ExactPoint3& exact, const Vec3& rounded);

// Does the closed segment ab meet the box of half-widths rounding_bound(p.x), rounding_bound(p.y)
// around p, i.e. is p within its rounding bound of some exact point of ab? This is p's "hot
// pixel" in snap rounding: the reals that round to p lie in that box. Decided exactly (a double
// filter, then rationals on the separating axes: the two coordinate axes and ab's normal).
bool rounding_box_meets_segment(const Vec2& p, const Vec2& a, const Vec2& b);

// The intersection of the supporting lines of segments ab and cd, exactly. Empty (std::nullopt)
// when the lines are parallel or identical, or a segment has zero length: then there is no
// single intersection point, and the caller decides from orient2d what the configuration is.
std::optional<ExactPoint2> line_intersection_exact(const Vec2& a, const Vec2& b, const Vec2& c,
                                                   const Vec2& d);
// The same, correctly rounded to nearest; `exact` tells whether the intersection is a double point.
std::optional<RoundedPoint2> line_intersection(const Vec2& a, const Vec2& b, const Vec2& c,
                                               const Vec2& d);

// a + t (b - a), exactly: t in [0, 1] gives a point of segment ab, other t the supporting line.
ExactPoint2 point_on_segment_exact(const Vec2& a, const Vec2& b, const Rational& t);
ExactPoint3 point_on_segment_exact(const Vec3& a, const Vec3& b, const Rational& t);
RoundedPoint2 point_on_segment(const Vec2& a, const Vec2& b, const Rational& t);
RoundedPoint3 point_on_segment(const Vec3& a, const Vec3& b, const Rational& t);

// The midpoint of ab, the preferred split point. Detection of the exact case, in doubles, per
// coordinate: s = a + b is computed with TwoSum, and the sum is exact iff the TwoSum error is
// zero and s is finite; then h = s / 2 is exact iff 2 * h == s (halving only loses a bit when s
// is an odd multiple of 2^-1074). When both hold for every coordinate the midpoint is returned
// with exact = true and no rational arithmetic; otherwise it is computed exactly and rounded to
// nearest. (An inexact midpoint may still lie on the segment, e.g. on an axis-aligned one: ask
// orient2d of the rounded point.)
RoundedPoint2 midpoint(const Vec2& a, const Vec2& b);
RoundedPoint3 midpoint(const Vec3& a, const Vec3& b);

}  // namespace dtlab
