// Measures of kernel/constructions.hpp and kernel/quality.hpp on elements with known answers
// (right, 3-4-5, equilateral, regular and corner tetrahedra), on random elements (signs agree
// with the exact orientation, circumcentre equidistant, Q >= 1), and on flat ones.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "kernel/constructions.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Relative agreement for measures (never used for a combinatorial decision).
::testing::AssertionResult close(double got, double want, double rel) {
  if (std::fabs(got - want) <= rel * std::fabs(want)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << got << " differs from " << want << " by more than "
                                       << rel << " relative";
}

rc::Gen<double> gen_unit() {
  return rc::gen::map(rc::gen::inRange(-1000000, 1000001), [](int i) { return i * 1e-6; });
}

// The regular tetrahedron with edge 2 sqrt(2), exactly representable, positively oriented.
const Vec3 kReg[4] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};

TEST(Area, KnownValuesAndSigns) {
  EXPECT_EQ(signed_area({0, 0}, {1, 0}, {0, 1}), 0.5);
  EXPECT_EQ(signed_area({0, 0}, {0, 1}, {1, 0}), -0.5);
  EXPECT_EQ(signed_area({1, 1}, {4, 1}, {1, 5}), 6.0);
  EXPECT_EQ(signed_area({0, 0}, {1, 1}, {2, 2}), 0.0);
}

TEST(Volume, KnownValuesAndSigns) {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(signed_volume(o, x, y, z), 1.0 / 6.0);
  EXPECT_EQ(orient3d(o, x, y, z), Sign::Positive);
  EXPECT_EQ(signed_volume(o, y, x, z), -1.0 / 6.0);
  EXPECT_EQ(signed_volume(o, x, y, Vec3{1, 1, 0}), 0.0);
  // Regular tetrahedron of edge s: s^3 / (6 sqrt 2) = 16 sqrt 2 / (6 sqrt 2) = 8/3.
  EXPECT_TRUE(close(signed_volume(kReg[0], kReg[1], kReg[2], kReg[3]), 8.0 / 3.0, 4 * kEps));
  EXPECT_EQ(orient3d(kReg[0], kReg[1], kReg[2], kReg[3]), Sign::Positive);
}

RC_GTEST_PROP(Area, SignAgreesWithOrient2dAwayFromFlat, ()) {
  const Vec2 a{*gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit()}, c{*gen_unit(), *gen_unit()};
  const double area = signed_area(a, b, c);
  RC_PRE(std::fabs(area) > 1e-9);
  RC_ASSERT(sign_of(area) == orient2d(a, b, c));
  // Swapping two vertices negates the area exactly (the same products, subtracted the other way).
  RC_ASSERT(signed_area(a, c, b) == -area);
}

RC_GTEST_PROP(Volume, SignAgreesWithOrient3dAwayFromFlat, ()) {
  const Vec3 a{*gen_unit(), *gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit(), *gen_unit()};
  const Vec3 c{*gen_unit(), *gen_unit(), *gen_unit()}, d{*gen_unit(), *gen_unit(), *gen_unit()};
  const double v = signed_volume(a, b, c, d);
  RC_PRE(std::fabs(v) > 1e-9);
  RC_ASSERT(sign_of(v) == orient3d(a, b, c, d));
}

TEST(Circumcircle, KnownCentresAndRadii) {
  EXPECT_EQ(circumcenter(Vec2{0, 0}, Vec2{2, 0}, Vec2{0, 2}), (Vec2{1, 1}));
  EXPECT_EQ(circumradius(Vec2{0, 0}, Vec2{2, 0}, Vec2{0, 2}), std::sqrt(2.0));
  // The hypotenuse's midpoint is the centre of a right triangle, far from the origin too.
  const Vec2 o{1e6, -3e6};
  EXPECT_EQ(circumcenter(o, o + Vec2{6, 0}, o + Vec2{0, 8}), (o + Vec2{3, 4}));
  EXPECT_EQ(circumradius(o, o + Vec2{6, 0}, o + Vec2{0, 8}), 5.0);
  EXPECT_EQ(circumcenter(Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, 2}), (Vec3{1, 1, 1}));
  EXPECT_TRUE(close(circumradius(Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, 2}),
                    std::sqrt(3.0), 2 * kEps));
  // Regular tetrahedron centred at the origin, circumradius s sqrt(6) / 4 = sqrt 3.
  const Vec3 cc = circumcenter(kReg[0], kReg[1], kReg[2], kReg[3]);
  EXPECT_EQ(cc, (Vec3{0, 0, 0}));
  EXPECT_TRUE(close(circumradius(kReg[0], kReg[1], kReg[2], kReg[3]), std::sqrt(3.0), 2 * kEps));
}

RC_GTEST_PROP(Circumcircle, CentreIsEquidistant2d, ()) {
  const Vec2 a{*gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit()}, c{*gen_unit(), *gen_unit()};
  // Well-shaped enough that the centre is well-conditioned.
  RC_PRE(shape_quality(a, b, c) < 20.0);
  const Vec2 m = circumcenter(a, b, c);
  const double r = circumradius(a, b, c);
  RC_ASSERT(close(norm(m - a), r, 1e-12));
  RC_ASSERT(close(norm(m - b), r, 1e-12));
  RC_ASSERT(close(norm(m - c), r, 1e-12));
}

RC_GTEST_PROP(Circumcircle, CentreIsEquidistant3d, ()) {
  const Vec3 a{*gen_unit(), *gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit(), *gen_unit()};
  const Vec3 c{*gen_unit(), *gen_unit(), *gen_unit()}, d{*gen_unit(), *gen_unit(), *gen_unit()};
  RC_PRE(shape_quality(a, b, c, d) < 20.0);
  const Vec3 m = circumcenter(a, b, c, d);
  const double r = circumradius(a, b, c, d);
  for (const Vec3& p : {a, b, c, d}) RC_ASSERT(close(norm(m - p), r, 1e-12));
}

// FacetQuality3 prepares the facet's terms once: the same value as shape_quality_nonflat, bit for
// bit (optimize3d's relocation relies on it for identical results), flat apexes included.
RC_GTEST_PROP(FacetQuality3, SameBitsAsShapeQualityNonflat, ()) {
  const Vec3 a{*gen_unit(), *gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit(), *gen_unit()};
  const Vec3 c{*gen_unit(), *gen_unit(), *gen_unit()};
  const FacetQuality3 facet(a, b, c);
  for (int k = 0; k < 4; ++k) {
    const Vec3 d{*gen_unit(), *gen_unit(), *gen_unit()};
    const double want = shape_quality_nonflat(a, b, c, d), got = facet.with_apex(d);
    RC_ASSERT(std::memcmp(&want, &got, sizeof want) == 0);
  }
  const double flat = facet.with_apex(0.25 * a + 0.75 * b);
  const double want_flat = shape_quality_nonflat(a, b, c, 0.25 * a + 0.75 * b);
  RC_ASSERT(std::memcmp(&want_flat, &flat, sizeof flat) == 0);
}

// Q_K is taken from the square roots of the squared norms where those keep their precision and
// from hypot's norms outside: the same tetrahedron scaled by powers of two (exactly) gives the
// same value within rounding on both sides of the switch, and FacetQuality3 follows it bit for bit.
RC_GTEST_PROP(ShapeQuality3, ScaleInvariantAcrossTheHypotFallback, ()) {
  const Vec3 a{*gen_unit(), *gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit(), *gen_unit()};
  const Vec3 c{*gen_unit(), *gen_unit(), *gen_unit()}, d{*gen_unit(), *gen_unit(), *gen_unit()};
  const double q = shape_quality_nonflat(a, b, c, d);
  RC_PRE(std::isfinite(q) && q < 1e6);
  for (const int e : {-300, -100, 0, 100, 300}) {
    const auto s = [e](const Vec3& p) { return std::ldexp(1.0, e) * p; };
    const double scaled = shape_quality_nonflat(s(a), s(b), s(c), s(d));
    RC_ASSERT(std::fabs(scaled - q) <= 1e-9 * q);
    const double facet = FacetQuality3(s(a), s(b), s(c)).with_apex(s(d));
    RC_ASSERT(std::memcmp(&facet, &scaled, sizeof facet) == 0);
  }
}

TEST(ShapeQuality3, RegularTetrahedronAtExtremeScales) {
  for (const double scale : {1.0, 0x1p-300, 0x1p300}) {
    const auto s = [scale](const Vec3& p) { return scale * p; };
    EXPECT_TRUE(close(shape_quality_nonflat(s(kReg[0]), s(kReg[1]), s(kReg[2]), s(kReg[3])), 1.0, 8 * kEps)) << scale;
  }
}

TEST(Inradius, KnownValues) {
  // 3-4-5 triangle: r = area / semi-perimeter = 6 / 6.
  EXPECT_EQ(inradius(Vec2{0, 0}, Vec2{3, 0}, Vec2{0, 4}), 1.0);
  // Corner tetrahedron: r = 3V / A = (1/2) / (3/2 + sqrt(3)/2) = 1 / (3 + sqrt 3).
  EXPECT_TRUE(close(inradius(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}),
                    1.0 / (3.0 + std::sqrt(3.0)), 4 * kEps));
  // Regular tetrahedron of edge s: s / (2 sqrt 6) = 1 / sqrt 3.
  EXPECT_TRUE(close(inradius(kReg[0], kReg[1], kReg[2], kReg[3]), 1.0 / std::sqrt(3.0), 4 * kEps));
  // Orientation does not matter.
  EXPECT_EQ(inradius(Vec2{0, 0}, Vec2{0, 4}, Vec2{3, 0}), 1.0);
}

TEST(EdgeLengths, DocumentedOrder) {
  // Triangle: edge i is opposite vertex i: (bc, ca, ab).
  const std::array<double, 3> t = edge_lengths(Vec2{0, 0}, Vec2{3, 0}, Vec2{0, 4});
  EXPECT_EQ(t, (std::array<double, 3>{5, 4, 3}));
  // Tetrahedron: (ab, ac, ad, bc, bd, cd).
  const std::array<double, 6> e =
      edge_lengths(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, 3});
  EXPECT_EQ(e[0], 1.0);
  EXPECT_EQ(e[1], 2.0);
  EXPECT_EQ(e[2], 3.0);
  EXPECT_TRUE(close(e[3], std::sqrt(5.0), kEps));
  EXPECT_TRUE(close(e[4], std::sqrt(10.0), kEps));
  EXPECT_TRUE(close(e[5], std::sqrt(13.0), kEps));
}

TEST(Quality, EquilateralAndRegularAreOne) {
  const double h = std::sqrt(3.0) / 2.0;
  const double q2 = shape_quality(Vec2{0, 0}, Vec2{1, 0}, Vec2{0.5, h});
  EXPECT_LE(std::fabs(q2 - 1.0), 4 * kEps) << q2 - 1.0;
  // Far from the origin and at other scales, within the supported range.
  for (const double s : {0x1p-120, 1e-9, 1e9, 0x1p120}) {
    const Vec2 o{3 * s, -7 * s};
    const double q = shape_quality(o, o + Vec2{s, 0}, o + Vec2{0.5 * s, h * s});
    EXPECT_LE(std::fabs(q - 1.0), 8 * kEps) << "scale " << s << ": " << q - 1.0;
  }
  const double q3 = shape_quality(kReg[0], kReg[1], kReg[2], kReg[3]);
  EXPECT_LE(std::fabs(q3 - 1.0), 4 * kEps) << q3 - 1.0;
  for (const double s : {0x1p-120, 0x1p120}) {
    const auto sc = [s](const Vec3& p) { return Vec3{p.x * s + 5 * s, p.y * s, p.z * s - 2 * s}; };
    const double q = shape_quality(sc(kReg[0]), sc(kReg[1]), sc(kReg[2]), sc(kReg[3]));
    EXPECT_LE(std::fabs(q - 1.0), 8 * kEps) << "scale " << s << ": " << q - 1.0;
  }
}

TEST(Quality, KnownNonRegularValues) {
  // Right isosceles triangle with legs 1: h_max = sqrt 2, rho = (2 - sqrt 2) / 2, so
  // Q = (sqrt(3)/6) sqrt(2) * 2 / (2 - sqrt 2) = sqrt(6) / (3 (2 - sqrt 2)) ~ 1.3938.
  const double want = std::sqrt(6.0) / (3.0 * (2.0 - std::sqrt(2.0)));
  EXPECT_TRUE(close(shape_quality(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}), want, 8 * kEps));
  EXPECT_GT(shape_quality(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}), 1.3);
  // Corner tetrahedron: h_max = sqrt 2, rho = 1 / (3 + sqrt 3).
  const double want3 = kQualityAlpha3d * std::sqrt(2.0) * (3.0 + std::sqrt(3.0));
  EXPECT_TRUE(close(shape_quality(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}), want3,
                    8 * kEps));
  // A sliver: four nearly coplanar points, all edges of similar length, Q very large.
  const double q = shape_quality(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 1e-8}, Vec3{0, 1, 0});
  EXPECT_GT(q, 1e7);
  EXPECT_TRUE(std::isfinite(q));
}

RC_GTEST_PROP(Quality, AtLeastOneAndOrientationFree, ()) {
  const Vec2 a{*gen_unit(), *gen_unit()}, b{*gen_unit(), *gen_unit()}, c{*gen_unit(), *gen_unit()};
  RC_PRE(orient2d(a, b, c) != Sign::Zero);
  const double q = shape_quality(a, b, c);
  RC_ASSERT(q >= 1.0 - 8 * kEps);
  // The area's rounding error relative to the area grows like Q: so does the tolerance.
  RC_ASSERT(close(shape_quality(b, a, c), q, 16 * kEps * q));
  const Vec3 p{*gen_unit(), *gen_unit(), *gen_unit()}, r{*gen_unit(), *gen_unit(), *gen_unit()};
  const Vec3 s{*gen_unit(), *gen_unit(), *gen_unit()}, t{*gen_unit(), *gen_unit(), *gen_unit()};
  RC_PRE(orient3d(p, r, s, t) != Sign::Zero);
  const double q3 = shape_quality(p, r, s, t);
  RC_ASSERT(q3 >= 1.0 - 8 * kEps);
  RC_ASSERT(close(shape_quality(r, p, s, t), q3, 64 * kEps * q3));
}

TEST(Flat, InfiniteRadiusAndQualityZeroInradius) {
  // Collinear, including points whose coordinate differences are rounded (0.1 steps).
  const Vec2 flat[][3] = {{{0, 0}, {1, 1}, {2, 2}},
                          {{0.1, 0.3}, {0.2, 0.6}, {0.4, 1.2}},
                          {{1, 1}, {1, 1}, {5, -2}},
                          {{7, 7}, {7, 7}, {7, 7}}};
  for (const auto& f : flat) {
    ASSERT_EQ(orient2d(f[0], f[1], f[2]), Sign::Zero);
    EXPECT_EQ(shape_quality(f[0], f[1], f[2]), kInf);
    EXPECT_EQ(circumradius(f[0], f[1], f[2]), kInf);
    EXPECT_EQ(inradius(f[0], f[1], f[2]), 0.0);
    const Vec2 m = circumcenter(f[0], f[1], f[2]);
    EXPECT_FALSE(std::isfinite(m.x) && std::isfinite(m.y));
  }
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0.3, 0.7, 0};
  EXPECT_EQ(shape_quality(a, b, c, d), kInf);
  EXPECT_EQ(circumradius(a, b, c, d), kInf);
  EXPECT_EQ(inradius(a, b, c, d), 0.0);
  EXPECT_EQ(shape_quality(a, a, c, d), kInf);
  const Vec3 m = circumcenter(a, b, c, d);
  EXPECT_FALSE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z));
  // Nearly flat is not flat: finite, large.
  EXPECT_TRUE(std::isfinite(shape_quality(Vec2{0, 0}, Vec2{1, 0}, Vec2{0.5, 1e-12})));
  EXPECT_GT(shape_quality(Vec2{0, 0}, Vec2{1, 0}, Vec2{0.5, 1e-12}), 1e11);
}

}  // namespace
}  // namespace dtlab
