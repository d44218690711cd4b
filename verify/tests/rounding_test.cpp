// Correct rounding of exact rationals (kernel/rounding.hpp) against a brute-force oracle: the
// rounded double d of q is at least as close to q as both neighbours nextafter(d, +-inf), decided
// in exact rationals, ties going to the even mantissa; directed modes bracket q. Hardware
// arithmetic (one correctly rounded IEEE operation) is a second, independent oracle.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/rounding.hpp"

namespace dtlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool even_mantissa(double d) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1u) == 0;
}

// A neighbour as a rational; the neighbour of DBL_MAX beyond the range is 2^1024, as IEEE's
// overflow rule treats it.
Rational neighbour(double d, double towards) {
  const double n = std::nextafter(d, towards);
  if (std::isinf(n)) return Rational::dyadic(n > 0 ? 1 : -1, 1024);
  return Rational(n);
}

// Brute-force check that d is q rounded to nearest, ties to even.
::testing::AssertionResult is_nearest(const Rational& q, double d) {
  if (std::isinf(d)) {
    // Overflow: |q| >= DBL_MAX + ulp(DBL_MAX)/2 = 2^1024 - 2^970.
    const Rational limit = Rational::dyadic(1, 1024) - Rational::dyadic(1, 970);
    if ((d > 0 && q >= limit) || (d < 0 && -q >= limit)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "overflowed to infinity for " << q.to_string();
  }
  const Rational D(d);
  const Rational err = (q - D).abs();
  for (const double towards : {-kInf, kInf}) {
    const Rational n = neighbour(d, towards);
    const Rational other = (q - n).abs();
    if (other < err) {
      return ::testing::AssertionFailure() << d << " is not nearest to " << q.to_string()
                                           << ": its neighbour towards " << towards << " is closer";
    }
    if (other == err && !even_mantissa(d)) {
      return ::testing::AssertionFailure() << "tie for " << q.to_string() << " went to odd " << d;
    }
  }
  return ::testing::AssertionSuccess();
}

// Directed results bracket q and are adjacent (or equal, exactly when q is a double).
::testing::AssertionResult brackets(const Rational& q) {
  const double lo = round_to_double(q, Rounding::Down);
  const double hi = round_to_double(q, Rounding::Up);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return ::testing::AssertionSuccess();
  if (!(Rational(lo) <= q && q <= Rational(hi))) {
    return ::testing::AssertionFailure() << lo << ", " << hi << " do not bracket " << q.to_string();
  }
  const bool exact = is_double(q);
  if (exact != (lo == hi)) return ::testing::AssertionFailure() << "lo == hi must mean q is a double";
  if (!exact && std::nextafter(lo, kInf) != hi) {
    return ::testing::AssertionFailure() << lo << " and " << hi << " are not adjacent";
  }
  const double n = round_to_double(q);
  if (n != lo && n != hi) return ::testing::AssertionFailure() << "nearest is neither bracket";
  return ::testing::AssertionSuccess();
}

bool ok_is_nearest(const Rational& q, double d) { return static_cast<bool>(is_nearest(q, d)); }
bool ok_brackets(const Rational& q) { return static_cast<bool>(brackets(q)); }

// A double m * 2^e with a 53-bit mantissa m and random sign.
rc::Gen<double> gen_double(int emin, int emax) {
  return rc::gen::map(
      rc::gen::tuple(rc::gen::inRange<std::int64_t>(std::int64_t{1} << 52, std::int64_t{1} << 53),
                     rc::gen::inRange(emin, emax + 1), rc::gen::arbitrary<bool>()),
      [](const std::tuple<std::int64_t, int, bool>& t) {
        const double v = std::ldexp(static_cast<double>(std::get<0>(t)), std::get<1>(t) - 52);
        return std::get<2>(t) ? -v : v;
      });
}

rc::Gen<double> gen_coordinate() {
  return gen_double(kMinCoordinateExponent + 1, kMaxCoordinateExponent - 1);
}

// ---- Rational ------------------------------------------------------------------------------

TEST(Rational, DoubleConvertsExactly) {
  EXPECT_EQ(Rational(0.1).to_string(), "3602879701896397/36028797018963968");
  EXPECT_EQ(Rational(-3.0).to_string(), "-3");
  EXPECT_EQ(Rational(std::numeric_limits<double>::denorm_min()), Rational::dyadic(1, -1074));
  EXPECT_EQ(Rational(DBL_MAX), Rational::dyadic(1, 1024) - Rational::dyadic(1, 971));
  EXPECT_EQ(Rational(6, -4).to_string(), "-3/2");
}

TEST(Rational, ArithmeticAndOrder) {
  const Rational third(1, 3);
  EXPECT_EQ(third + third + third, Rational(1));
  EXPECT_EQ(third * Rational(3), Rational(1));
  EXPECT_EQ(Rational(1) / Rational(3), third);
  EXPECT_EQ(Rational(1) - third, Rational(2, 3));
  EXPECT_EQ(-third, Rational(-1, 3));
  EXPECT_LT(third, Rational(0.3333333333333334));
  EXPECT_GT(third, Rational(0.3333333333333333));
  EXPECT_EQ(third.sign(), Sign::Positive);
  EXPECT_EQ((-third).sign(), Sign::Negative);
  EXPECT_EQ(Rational().sign(), Sign::Zero);
  Rational moved(third);
  Rational target(std::move(moved));
  EXPECT_EQ(target, third);
  EXPECT_TRUE(moved.is_zero());  // NOLINT(bugprone-use-after-move): documented state
}

TEST(Rational, RefusesWhatIsNotRational) {
  EXPECT_THROW(Rational{std::nan("")}, InputError);
  EXPECT_THROW(Rational{kInf}, InputError);
  EXPECT_THROW(Rational(1, 0), InputError);
  EXPECT_THROW(Rational(1) / Rational(), InputError);
}

// ---- round_to_double ----------------------------------------------------------------------

TEST(RoundToDouble, TiesGoToEven) {
  // 1 + 2^-53 lies halfway between 1 and 1 + 2^-52: even is 1.
  EXPECT_EQ(round_to_double(Rational(1) + Rational::dyadic(1, -53)), 1.0);
  // 1 + 3 * 2^-53 lies halfway between 1 + 2^-52 (odd) and 1 + 2^-51 (even).
  EXPECT_EQ(round_to_double(Rational(1) + Rational::dyadic(3, -53)), 1.0 + 0x1p-51);
  // Just above a tie rounds up.
  EXPECT_EQ(round_to_double(Rational(1) + Rational::dyadic(1, -53) + Rational::dyadic(1, -200)),
            1.0 + 0x1p-52);
  EXPECT_EQ(round_to_double(-(Rational(1) + Rational::dyadic(1, -53))), -1.0);
}

TEST(RoundToDouble, Subnormals) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(round_to_double(Rational::dyadic(1, -1075)), 0.0);  // tie with 0, which is even
  EXPECT_EQ(round_to_double(Rational::dyadic(3, -1075)), 2 * tiny);  // tie: 2 is even
  EXPECT_EQ(round_to_double(Rational::dyadic(5, -1075)), 2 * tiny);  // tie: 2, not 3
  EXPECT_EQ(round_to_double(Rational::dyadic(1, -1075) + Rational::dyadic(1, -2000)), tiny);
  EXPECT_EQ(round_to_double(Rational::dyadic(1, -3000)), 0.0);
  // Just above a subnormal tie, by less than 53 bits can see: rounding to 53 bits first and then
  // to the subnormal grid would make it a tie and go to even (double rounding); it must go up.
  const Rational above_tie = Rational::dyadic(1, -1060) + Rational::dyadic(1, -1075) +
                             Rational::dyadic(1, -1140);
  EXPECT_EQ(round_to_double(above_tie), 0x1p-1060 + tiny);
  EXPECT_EQ(round_to_double(above_tie - Rational::dyadic(1, -1139)), 0x1p-1060);
  EXPECT_TRUE(std::signbit(round_to_double(-Rational::dyadic(1, -3000))));
  EXPECT_EQ(round_to_double(Rational::dyadic(1, -3000), Rounding::Up), tiny);
  EXPECT_EQ(round_to_double(Rational::dyadic(1, -3000), Rounding::Down), 0.0);
  EXPECT_EQ(round_to_double(-Rational::dyadic(1, -3000), Rounding::Down), -tiny);
  // 1/3 of the smallest normal: 2^-1022 / 3 sits on the subnormal grid's scale.
  const Rational third_min = Rational(DBL_MIN) / Rational(3);
  EXPECT_TRUE(is_nearest(third_min, round_to_double(third_min)));
  EXPECT_EQ(round_to_double(third_min), DBL_MIN / 3);
  EXPECT_TRUE(brackets(third_min));
  // Rounding up from just below the smallest normal lands on it.
  EXPECT_EQ(round_to_double(Rational(DBL_MIN) - Rational::dyadic(1, -1200)), DBL_MIN);
}

TEST(RoundToDouble, Overflow) {
  const Rational half_ulp_past = Rational::dyadic(1, 1024) - Rational::dyadic(1, 970);
  EXPECT_EQ(round_to_double(half_ulp_past), kInf);  // tie: 2^1024 has the even mantissa
  EXPECT_EQ(round_to_double(half_ulp_past - Rational::dyadic(1, 900)), DBL_MAX);
  EXPECT_EQ(round_to_double(Rational::dyadic(1, 5000), Rounding::Down), DBL_MAX);
  EXPECT_EQ(round_to_double(Rational::dyadic(1, 5000), Rounding::Up), kInf);
  EXPECT_EQ(round_to_double(-Rational::dyadic(1, 5000), Rounding::Up), -DBL_MAX);
  EXPECT_EQ(round_to_double(-Rational::dyadic(1, 5000)), -kInf);
}

// A single IEEE operation in hardware is correctly rounded to nearest: an independent oracle.
RC_GTEST_PROP(RoundToDouble, AgreesWithHardwareOperations, ()) {
  const double a = *gen_double(-600, 600);
  const double b = *gen_double(-600, 600);
  RC_ASSERT(round_to_double(Rational(a) + Rational(b)) == a + b);
  RC_ASSERT(round_to_double(Rational(a) * Rational(b)) == a * b);
  RC_ASSERT(round_to_double(Rational(a) / Rational(b)) == a / b);
  // Products and quotients that land among the subnormals or past DBL_MAX.
  const double s = *gen_double(-1070, -950);
  RC_ASSERT(round_to_double(Rational(s) * Rational(a)) == s * a);
  RC_ASSERT(round_to_double(Rational(b) / Rational(s)) == b / s);
  const double u = *gen_double(-120, 0);
  RC_ASSERT(round_to_double(Rational(s) * Rational(u)) == s * u);
}

RC_GTEST_PROP(RoundToDouble, NearestByBruteForceAndDirectedBracket, ()) {
  // num / den with numerators and denominators of up to ~120 bits and wide exponents.
  const Rational den = Rational(*gen_double(-40, 40)) + Rational(*gen_double(-40, 40));
  RC_PRE(!den.is_zero());
  const Rational q = Rational(*gen_double(-1100, 1000)) * Rational(*gen_double(-60, 60)) / den;
  RC_PRE(!q.is_zero());
  RC_ASSERT(ok_is_nearest(q, round_to_double(q)));
  RC_ASSERT(ok_brackets(q));
}

RC_GTEST_PROP(RoundToDouble, NearTiesAreDecidedExactly, ()) {
  // d + ulp(d)/2 (a tie), and ties nudged by far less than an ulp either way.
  const double d = *gen_double(-1070, 1020);
  const int nudge = *rc::gen::inRange(-1, 2);
  Rational q = Rational(d) + Rational(ulp(d)) / Rational(2);
  q += Rational::dyadic(nudge, -1500);
  const double r = round_to_double(q);
  RC_ASSERT(ok_is_nearest(q, r));
  RC_ASSERT(ok_brackets(q));
}

TEST(RoundToDouble, ExactValuesComeBackUnchanged) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> exp(-1074, 1023);
  for (int i = 0; i < 2000; ++i) {
    const double d = std::ldexp(static_cast<double>(rng() >> 11), exp(rng) - 53);
    const Rational q(d);
    for (const Rounding mode : {Rounding::NearestEven, Rounding::Down, Rounding::Up}) {
      ASSERT_EQ(round_to_double(q, mode), d) << d;
    }
    ASSERT_TRUE(is_double(q));
  }
  EXPECT_FALSE(is_double(Rational(1, 3)));
  EXPECT_FALSE(is_double(Rational::dyadic(1, 1024)));
}

// ---- ulp and the rounding bound -----------------------------------------------------------

TEST(RoundingBound, UlpAndHalfUlp) {
  EXPECT_EQ(ulp(1.0), 0x1p-52);
  EXPECT_EQ(ulp(-1.5), 0x1p-52);
  EXPECT_EQ(ulp(std::nextafter(1.0, 0.0)), 0x1p-53);
  EXPECT_EQ(ulp(DBL_MAX), 0x1p971);
  EXPECT_EQ(ulp(0.0), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(ulp(kInf), kInf);
  EXPECT_EQ(rounding_bound(1.0), 0x1p-53);
  EXPECT_EQ(rounding_bound(kMinCoordinateMagnitude), std::ldexp(1.0, kMinCoordinateExponent - 53));
  EXPECT_EQ(rounding_bound(kMaxCoordinateMagnitude), std::ldexp(1.0, kMaxCoordinateExponent - 53));
  EXPECT_EQ(rounding_bound(DBL_MIN), std::numeric_limits<double>::denorm_min());  // twice too large
}

RC_GTEST_PROP(RoundingBound, RoundedPointIsWithinAndNeighbourIsNot, ()) {
  const ExactPoint2 p{Rational(*gen_coordinate()) / Rational(*gen_double(-20, 20)),
                      Rational(*gen_coordinate()) / Rational(*gen_double(-20, 20))};
  const Vec2 r = round_point(p);
  RC_ASSERT(within_rounding_bound(p, r));
  // Step x one double away from p.x: no longer within the bound unless p.x is r.x itself.
  RC_PRE(!(Rational(r.x) == p.x));
  const double away = Rational(r.x) < p.x ? -kInf : kInf;
  RC_ASSERT(!within_rounding_bound(p, Vec2{std::nextafter(r.x, away), r.y}));
  RC_ASSERT(!within_rounding_bound(p, Vec2{kInf, r.y}));
}

// ---- Constructions: line intersection, point on segment, midpoint --------------------------

// The exact point lies on both lines: cross(b - a, p - a) == 0 and cross(d - c, p - c) == 0.
bool on_line(const ExactPoint2& p, const Vec2& a, const Vec2& b) {
  const Rational ux = Rational(b.x) - Rational(a.x), uy = Rational(b.y) - Rational(a.y);
  return (ux * (p.y - Rational(a.y)) - uy * (p.x - Rational(a.x))).is_zero();
}

RC_GTEST_PROP(LineIntersection, ExactOnBothLinesAndCorrectlyRounded, ()) {
  const Vec2 a{*gen_double(-3, 3), *gen_double(-3, 3)}, b{*gen_double(-3, 3), *gen_double(-3, 3)};
  const Vec2 c{*gen_double(-3, 3), *gen_double(-3, 3)}, d{*gen_double(-3, 3), *gen_double(-3, 3)};
  const std::optional<ExactPoint2> p = line_intersection_exact(a, b, c, d);
  RC_PRE(p.has_value());
  RC_ASSERT(on_line(*p, a, b));
  RC_ASSERT(on_line(*p, c, d));
  const std::optional<RoundedPoint2> r = line_intersection(a, b, c, d);
  RC_ASSERT(r.has_value());
  RC_ASSERT(ok_is_nearest(p->x, r->point.x));
  RC_ASSERT(ok_is_nearest(p->y, r->point.y));
  RC_ASSERT(within_rounding_bound(*p, r->point));
  RC_ASSERT(r->exact == (is_double(p->x) && is_double(p->y)));
}

RC_GTEST_PROP(LineIntersection, IntegerCrossingComesBackExact, ()) {
  // Lines through an integer point p along integer directions meet exactly at p.
  const auto coord = rc::gen::inRange<std::int64_t>(-1000000, 1000001);
  const Vec2 p{static_cast<double>(*coord), static_cast<double>(*coord)};
  const auto step = rc::gen::inRange<std::int64_t>(-1000, 1001);
  const Vec2 u{static_cast<double>(*step), static_cast<double>(*step)};
  const Vec2 v{static_cast<double>(*step), static_cast<double>(*step)};
  RC_PRE(cross(u, v) != 0.0);
  const std::optional<RoundedPoint2> r = line_intersection(p - u, p + 2.0 * u, p + 3.0 * v, p - v);
  RC_ASSERT(r.has_value());
  RC_ASSERT(r->exact);
  RC_ASSERT(r->point == p);
}

TEST(LineIntersection, KnownPoints) {
  const auto r = line_intersection({0, 0}, {2, 2}, {0, 2}, {2, 0});
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->exact);
  EXPECT_EQ(r->point, (Vec2{1, 1}));
  // y = x and x + 2y = 1 meet at (1/3, 1/3): not a double.
  const auto e = line_intersection_exact({0, 0}, {1, 1}, {1, 0}, {0, 0.5});
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->x, Rational(1, 3));
  EXPECT_EQ(e->y, Rational(1, 3));
  const auto t = line_intersection({0, 0}, {1, 1}, {1, 0}, {0, 0.5});
  ASSERT_TRUE(t.has_value());
  EXPECT_FALSE(t->exact);
  EXPECT_EQ(t->point, (Vec2{1.0 / 3.0, 1.0 / 3.0}));
}

TEST(LineIntersection, ParallelIdenticalAndDegenerateAreEmpty) {
  EXPECT_FALSE(line_intersection({0, 0}, {1, 1}, {0, 1}, {1, 2}).has_value());   // parallel
  EXPECT_FALSE(line_intersection({0, 0}, {1, 1}, {2, 2}, {5, 5}).has_value());   // same line
  EXPECT_FALSE(line_intersection({0, 0}, {0, 0}, {0, 1}, {1, 0}).has_value());   // a == b
  EXPECT_FALSE(line_intersection({0, 0}, {1, 0}, {3, 3}, {3, 3}).has_value());   // c == d
  // Nearly parallel: a single point far away, reported, correctly rounded.
  const auto far = line_intersection({0, 0}, {1, 0}, {0, 1}, {1, 1.0 - 0x1p-50});
  ASSERT_TRUE(far.has_value());
  EXPECT_EQ(far->point, (Vec2{0x1p50, 0}));
}

RC_GTEST_PROP(LineIntersection, ScalesByPowersOfTwoAcrossTheRange, ()) {
  // Scaling by 2^k is exact on inputs and exact point, so the rounded point scales exactly too,
  // from about 2^-140 to 2^140 (inside the supported range, far from subnormals and overflow).
  const Vec2 a{*gen_double(-2, 2), *gen_double(-2, 2)}, b{*gen_double(-2, 2), *gen_double(-2, 2)};
  const Vec2 c{*gen_double(-2, 2), *gen_double(-2, 2)}, d{*gen_double(-2, 2), *gen_double(-2, 2)};
  const std::optional<RoundedPoint2> r = line_intersection(a, b, c, d);
  // RapidCheck's && does not short-circuit: test has_value on its own.
  RC_PRE(r.has_value());
  RC_PRE(std::fabs(r->point.x) < 1e6 && std::fabs(r->point.y) < 1e6 &&
         std::fabs(r->point.x) > 1e-6 && std::fabs(r->point.y) > 1e-6);
  const int k = *rc::gen::element(-120, -100, 100, 120);
  const auto s = [k](const Vec2& v) { return Vec2{std::ldexp(v.x, k), std::ldexp(v.y, k)}; };
  const std::optional<RoundedPoint2> rs = line_intersection(s(a), s(b), s(c), s(d));
  RC_ASSERT(rs.has_value());
  RC_ASSERT(rs->point == s(r->point));
  RC_ASSERT(rs->exact == r->exact);
  RC_ASSERT(coordinate_in_range(rs->point.x) && coordinate_in_range(rs->point.y));
  RC_ASSERT(within_rounding_bound(*line_intersection_exact(s(a), s(b), s(c), s(d)), rs->point));
}

RC_GTEST_PROP(PointOnSegment, ExactEndsAndCorrectRounding, ()) {
  const Vec3 a{*gen_coordinate(), *gen_coordinate(), *gen_coordinate()};
  const Vec3 b{*gen_coordinate(), *gen_coordinate(), *gen_coordinate()};
  const RoundedPoint3 at0 = point_on_segment(a, b, Rational(0));
  const RoundedPoint3 at1 = point_on_segment(a, b, Rational(1));
  RC_ASSERT(at0.exact && at0.point == a);
  RC_ASSERT(at1.exact && at1.point == b);
  const std::int64_t den = *rc::gen::inRange<std::int64_t>(2, 1000);
  const Rational t(*rc::gen::inRange<std::int64_t>(0, den + 1), den);
  const ExactPoint3 p = point_on_segment_exact(a, b, t);
  const RoundedPoint3 r = point_on_segment(a, b, t);
  RC_ASSERT(ok_is_nearest(p.x, r.point.x) && ok_is_nearest(p.y, r.point.y) &&
            ok_is_nearest(p.z, r.point.z));
  RC_ASSERT(within_rounding_bound(p, r.point));
  RC_ASSERT(r.exact == (is_double(p.x) && is_double(p.y) && is_double(p.z)));
}

RC_GTEST_PROP(Midpoint, ExactFlagMatchesRationalsAndInexactIsRoundedToNearest, ()) {
  // Exponents close together give exact sums, far apart give inexact ones.
  const int e = *rc::gen::inRange(-140, 140);
  const auto near = [e] { return *gen_double(e - 3, e + 3); };
  const auto any = [] { return *gen_coordinate(); };
  const bool close = *rc::gen::arbitrary<bool>();
  const Vec2 a{close ? near() : any(), close ? near() : any()};
  const Vec2 b{close ? near() : any(), close ? near() : any()};
  const ExactPoint2 exact = point_on_segment_exact(a, b, Rational(1, 2));
  const RoundedPoint2 m = midpoint(a, b);
  RC_ASSERT(m.exact == (is_double(exact.x) && is_double(exact.y)));
  RC_ASSERT(ok_is_nearest(exact.x, m.point.x) && ok_is_nearest(exact.y, m.point.y));
}

TEST(Midpoint, KnownCases) {
  EXPECT_TRUE(midpoint(Vec2{0, 0}, Vec2{1, 3}).exact);
  EXPECT_EQ(midpoint(Vec2{0, 0}, Vec2{1, 3}).point, (Vec2{0.5, 1.5}));
  // 1 + 2^-52 and 1 + 2^-51: the sum 2 + 3 * 2^-52 needs 54 bits (TwoSum error non-zero), and
  // the midpoint 1 + 1.5 * 2^-52 is rounded.
  const RoundedPoint2 m = midpoint(Vec2{1.0 + 0x1p-52, 0}, Vec2{1.0 + 0x1p-51, 0});
  EXPECT_FALSE(m.exact);
  EXPECT_EQ(m.point.x, 1.0 + 0x1p-51);  // tie between 1 + 2^-52 (odd) and 1 + 2^-51 (even)
  // Halving an odd multiple of 2^-1074 is inexact: detected by 2 * h != s.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const RoundedPoint2 t = midpoint(Vec2{tiny, 0}, Vec2{2 * tiny, 0});
  EXPECT_FALSE(t.exact);
  EXPECT_EQ(t.point.x, 2 * tiny);  // 1.5 * 2^-1074: tie, 2 is even
  const RoundedPoint3 m3 = midpoint(Vec3{0, 0, kMaxCoordinateMagnitude}, Vec3{1, 2, kMaxCoordinateMagnitude});
  EXPECT_TRUE(m3.exact);
  EXPECT_EQ(m3.point, (Vec3{0.5, 1, kMaxCoordinateMagnitude}));
}

}  // namespace
}  // namespace dtlab

namespace dtlab {
namespace {

// The hot-pixel test of snap rounding: any exact point of a segment, rounded, has a box that
// meets the segment (so the double filter never rejects a true case); one ulp off an
// axis-parallel segment, outside the box, it does not.
TEST(RoundingBox, MeetsTheSegmentItsPointsRoundFrom) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 a{u(rng), u(rng)}, b{u(rng) * (trial % 7 == 0 ? 1e-9 : 1.0), u(rng)};
    const Rational t(std::ldexp(static_cast<double>(rng() % (1u << 20)), -20));
    const RoundedPoint2 p = point_on_segment(a, b, t);
    EXPECT_TRUE(rounding_box_meets_segment(p.point, a, b)) << trial;
  }
  const Vec2 a{0.0, 1.0}, b{4.0, 1.0};
  EXPECT_TRUE(rounding_box_meets_segment({2.0, 1.0}, a, b));
  EXPECT_FALSE(rounding_box_meets_segment({2.0, std::nextafter(1.0, 2.0)}, a, b));
  EXPECT_FALSE(rounding_box_meets_segment({5.0, 1.0}, a, b));  // on the line, past the end
  // The next double past the end: its box starts half an ulp beyond the end.
  EXPECT_FALSE(rounding_box_meets_segment({std::nextafter(4.0, 5.0), 1.0}, a, b));
}

}  // namespace
}  // namespace dtlab
