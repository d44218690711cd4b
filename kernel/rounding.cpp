// Correct rounding of exact rationals to binary64 with MPFR, and the exact constructions of
// Steiner points (line intersection, point at a rational parameter, midpoint) of ROADMAP.md
// "Steiner points and rounding". MPFR rounds to a given precision with an unbounded exponent;
// binary64's subnormals are obtained by lowering the precision to the bits left above 2^-1074,
// which avoids touching MPFR's global exponent range (mpfr_set_emin/subnormalize).
#include "kernel/rounding.hpp"

#include <mpfr.h>

#include <cfloat>
#include <cmath>
#include <limits>

namespace dtlab {

namespace {

constexpr int kDoublePrecision = 53;
constexpr long kSubnormalExponent = -1074;  // the least significant bit of every subnormal

mpfr_rnd_t to_mpfr(Rounding mode) {
  switch (mode) {
    case Rounding::Down:
      return MPFR_RNDD;
    case Rounding::Up:
      return MPFR_RNDU;
    case Rounding::NearestEven:
      break;
  }
  return MPFR_RNDN;
}

// An mpfr_t that clears itself.
class Mpfr {
 public:
  explicit Mpfr(mpfr_prec_t prec) { mpfr_init2(x_, prec); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  ~Mpfr() { mpfr_clear(x_); }
  mpfr_ptr get() { return x_; }

 private:
  mpfr_t x_;
};

// |q| < 2^-1074: the result is 0 or the smallest subnormal, with q's sign.
double round_below_smallest_subnormal(const Rational& q, Rounding mode) {
  const bool negative = q.sign() == Sign::Negative;
  const double tiny = std::numeric_limits<double>::denorm_min();
  bool away = false;  // rounds to +-2^-1074 rather than to +-0
  switch (mode) {
    case Rounding::NearestEven:
      // 2^-1075 is the tie; 0 is the even neighbour.
      away = q.abs() > Rational::dyadic(1, kSubnormalExponent - 1);
      break;
    case Rounding::Down:
      away = negative;
      break;
    case Rounding::Up:
      away = !negative;
      break;
  }
  const double m = away ? tiny : 0.0;
  return negative ? -m : m;
}

// TwoSum (Knuth): s = fl(a + b) and the exact error; true iff a + b == s exactly.
bool exact_sum(double a, double b, double& s) {
  s = a + b;
  if (!std::isfinite(s)) return false;
  const double bv = s - a;
  const double av = s - bv;
  return (a - av) + (b - bv) == 0.0;
}

// (a + b) / 2 when it is a double, else nullopt.
std::optional<double> exact_half_sum(double a, double b) {
  double s = 0.0;
  if (!exact_sum(a, b, s)) return std::nullopt;
  const double h = 0.5 * s;
  if (2.0 * h != s) return std::nullopt;
  return h;
}

Rational cross(const Rational& ax, const Rational& ay, const Rational& bx, const Rational& by) {
  return ax * by - ay * bx;
}

}  // namespace

double round_to_double(const Rational& q, Rounding mode) {
  if (q.is_zero()) return 0.0;
  // Truncation never leaves q's binade, so the exponent is q's: 2^(e-1) <= |q| < 2^e.
  Mpfr x(kDoublePrecision);
  mpfr_set_q(x.get(), q.get(), MPFR_RNDZ);
  const long e = mpfr_get_exp(x.get());
  // Bits available between q's leading bit 2^(e-1) and the subnormal grid 2^-1074.
  const long bits = e - kSubnormalExponent;
  if (bits < 1) return round_below_smallest_subnormal(q, mode);
  const mpfr_rnd_t rnd = to_mpfr(mode);
  mpfr_set_prec(x.get(), bits < kDoublePrecision ? bits : kDoublePrecision);
  mpfr_set_q(x.get(), q.get(), rnd);
  // x is now a double, or beyond DBL_MAX with unbounded exponent; mpfr_get_d then returns inf
  // or DBL_MAX as the same mode would, which is IEEE's overflow rule.
  return mpfr_get_d(x.get(), rnd);
}

bool is_double(const Rational& q) {
  const double d = round_to_double(q);
  return std::isfinite(d) && Rational(d) == q;
}

double ulp(double d) noexcept {
  const double a = std::fabs(d);
  if (!std::isfinite(a)) return std::numeric_limits<double>::infinity();
  if (a < DBL_MIN) return std::numeric_limits<double>::denorm_min();
  return std::ldexp(1.0, std::ilogb(a) - (kDoublePrecision - 1));
}

double rounding_bound(double d) noexcept {
  const double u = ulp(d);
  return u > std::numeric_limits<double>::denorm_min() ? 0.5 * u : u;
}

ExactPoint2 to_exact(const Vec2& p) { return {Rational(p.x), Rational(p.y)}; }
ExactPoint3 to_exact(const Vec3& p) { return {Rational(p.x), Rational(p.y), Rational(p.z)}; }

Vec2 round_point(const ExactPoint2& p, Rounding mode) {
  return {round_to_double(p.x, mode), round_to_double(p.y, mode)};
}
Vec3 round_point(const ExactPoint3& p, Rounding mode) {
  return {round_to_double(p.x, mode), round_to_double(p.y, mode), round_to_double(p.z, mode)};
}

RoundedPoint2 round_point_checked(const ExactPoint2& p) {
  const Vec2 r = round_point(p);
  const bool exact = std::isfinite(r.x) && std::isfinite(r.y) && Rational(r.x) == p.x && Rational(r.y) == p.y;
  return {r, exact};
}
RoundedPoint3 round_point_checked(const ExactPoint3& p) {
  const Vec3 r = round_point(p);
  const bool exact = std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) &&
                     Rational(r.x) == p.x && Rational(r.y) == p.y && Rational(r.z) == p.z;
  return {r, exact};
}

namespace {
bool coordinate_within_bound(const Rational& q, double d) {
  if (!std::isfinite(d)) return false;
  const Rational twice_error = Rational(2) * (q - Rational(d)).abs();
  return twice_error <= Rational(ulp(d));
}
}  // namespace

bool within_rounding_bound(const ExactPoint2& exact, const Vec2& rounded) {
  return coordinate_within_bound(exact.x, rounded.x) && coordinate_within_bound(exact.y, rounded.y);
}
bool within_rounding_bound(const ExactPoint3& exact, const Vec3& rounded) {
  return coordinate_within_bound(exact.x, rounded.x) && coordinate_within_bound(exact.y, rounded.y) &&
         coordinate_within_bound(exact.z, rounded.z);
}

bool rounding_box_meets_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double rx = rounding_bound(p.x), ry = rounding_bound(p.y);
  // Boxes apart, in doubles: p.x + 4 rx is rounded by at most ulp(2 p.x) / 2 <= 2 rx, so it
  // stays beyond p.x + rx.
  if (std::min(a.x, b.x) > p.x + 4 * rx || std::max(a.x, b.x) < p.x - 4 * rx) return false;
  if (std::min(a.y, b.y) > p.y + 4 * ry || std::max(a.y, b.y) < p.y - 4 * ry) return false;
  // The line far from p, in doubles: if ab meets the box, |cross| <= |ex| ry + |ey| rx exactly;
  // the computed values are within a few eps of their terms' magnitudes (generous margins).
  const double ex = b.x - a.x, ey = b.y - a.y, dx = p.x - a.x, dy = p.y - a.y;
  const double cross = ex * dy - ey * dx;
  const double reach = std::fabs(ex) * ry + std::fabs(ey) * rx;
  const double error = 16 * DBL_EPSILON * (std::fabs(ex * dy) + std::fabs(ey * dx));
  if (std::fabs(cross) > 4 * reach + error) return false;
  // Exactly: the box [x0, x1] x [y0, y1] meets the closed segment iff the coordinate ranges
  // overlap and the box's corners are not all strictly on one side of the line.
  const Rational Rx(rx), Ry(ry);
  const Rational x0 = Rational(p.x) - Rx, x1 = Rational(p.x) + Rx;
  const Rational y0 = Rational(p.y) - Ry, y1 = Rational(p.y) + Ry;
  if (Rational(std::min(a.x, b.x)) > x1 || Rational(std::max(a.x, b.x)) < x0) return false;
  if (Rational(std::min(a.y, b.y)) > y1 || Rational(std::max(a.y, b.y)) < y0) return false;
  const Rational Ex = Rational(b.x) - Rational(a.x), Ey = Rational(b.y) - Rational(a.y);
  const Rational ax(a.x), ay(a.y);
  int positive = 0, negative = 0;
  for (const Rational* cx : {&x0, &x1})
    for (const Rational* cy : {&y0, &y1}) {
      const Sign s = (Ex * (*cy - ay) - Ey * (*cx - ax)).sign();
      positive += s == Sign::Positive;
      negative += s == Sign::Negative;
    }
  return positive < 4 && negative < 4;
}

std::optional<ExactPoint2> line_intersection_exact(const Vec2& a, const Vec2& b, const Vec2& c,
                                                   const Vec2& d) {
  const ExactPoint2 ea = to_exact(a);
  const ExactPoint2 ec = to_exact(c);
  // a + t (b - a) = c + s (d - c);  t = cross(c - a, d - c) / cross(b - a, d - c).
  const Rational ux = Rational(b.x) - ea.x, uy = Rational(b.y) - ea.y;
  const Rational vx = Rational(d.x) - ec.x, vy = Rational(d.y) - ec.y;
  const Rational den = cross(ux, uy, vx, vy);
  if (den.is_zero()) return std::nullopt;
  const Rational t = cross(ec.x - ea.x, ec.y - ea.y, vx, vy) / den;
  return ExactPoint2{ea.x + t * ux, ea.y + t * uy};
}

std::optional<RoundedPoint2> line_intersection(const Vec2& a, const Vec2& b, const Vec2& c,
                                               const Vec2& d) {
  const std::optional<ExactPoint2> p = line_intersection_exact(a, b, c, d);
  if (!p) return std::nullopt;
  return round_point_checked(*p);
}

ExactPoint2 point_on_segment_exact(const Vec2& a, const Vec2& b, const Rational& t) {
  const ExactPoint2 ea = to_exact(a);
  return {ea.x + t * (Rational(b.x) - ea.x), ea.y + t * (Rational(b.y) - ea.y)};
}
ExactPoint3 point_on_segment_exact(const Vec3& a, const Vec3& b, const Rational& t) {
  const ExactPoint3 ea = to_exact(a);
  return {ea.x + t * (Rational(b.x) - ea.x), ea.y + t * (Rational(b.y) - ea.y),
          ea.z + t * (Rational(b.z) - ea.z)};
}
RoundedPoint2 point_on_segment(const Vec2& a, const Vec2& b, const Rational& t) {
  return round_point_checked(point_on_segment_exact(a, b, t));
}
RoundedPoint3 point_on_segment(const Vec3& a, const Vec3& b, const Rational& t) {
  return round_point_checked(point_on_segment_exact(a, b, t));
}

RoundedPoint2 midpoint(const Vec2& a, const Vec2& b) {
  const std::optional<double> x = exact_half_sum(a.x, b.x);
  const std::optional<double> y = exact_half_sum(a.y, b.y);
  if (x && y) return {{*x, *y}, true};
  return point_on_segment(a, b, Rational(1, 2));
}
RoundedPoint3 midpoint(const Vec3& a, const Vec3& b) {
  const std::optional<double> x = exact_half_sum(a.x, b.x);
  const std::optional<double> y = exact_half_sum(a.y, b.y);
  const std::optional<double> z = exact_half_sum(a.z, b.z);
  if (x && y && z) return {{*x, *y, *z}, true};
  return point_on_segment(a, b, Rational(1, 2));
}

}  // namespace dtlab
