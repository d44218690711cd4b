// Riemannian metrics of kernel/metric.hpp and the metric qualities of kernel/quality.hpp: exact
// values on axis-aligned and proportional tensors, properties on random rotated ones
// (intersection commutative, contained in both, idempotent; interpolation endpoints and scaling
// laws; rotation equivariance; clipping; powers; gradation), and stretching up to 1e6:1.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "kernel/quality.hpp"

namespace dtlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 full(const Metric3& m) {
  return {{{m.m[0], m.m[1], m.m[3]}, {m.m[1], m.m[2], m.m[4]}, {m.m[3], m.m[4], m.m[5]}}};
}
Mat3 full(const Metric2& m) { return {{{m.m[0], m.m[1], 0.0}, {m.m[1], m.m[2], 0.0}, {0.0, 0.0, 1.0}}}; }

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    }
  }
  return c;
}

Mat3 transpose(const Mat3& a) {
  Mat3 t{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) t[i][j] = a[j][i];
  }
  return t;
}

// Largest entry of |a - I| (or |a - b|).
double distance(const Mat3& a, const Mat3& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d = std::max(d, std::fabs(a[i][j] - b[i][j]));
  }
  return d;
}
const Mat3 kIdentity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

// Agreement of two tensors relative to the larger one's largest component.
template <class M>
::testing::AssertionResult near(const M& got, const M& want, double rel) {
  double scale = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < got.m.size(); ++k) {
    scale = std::max({scale, std::fabs(got.m[k]), std::fabs(want.m[k])});
    diff = std::max(diff, std::fabs(got.m[k] - want.m[k]));
  }
  if (diff <= rel * scale) return ::testing::AssertionSuccess();
  auto& f = ::testing::AssertionFailure() << "components differ by " << diff << " (scale " << scale << "):";
  for (std::size_t k = 0; k < got.m.size(); ++k) f << " " << got.m[k] << "/" << want.m[k];
  return f;
}

::testing::AssertionResult close(double got, double want, double rel) {
  if (std::fabs(got - want) <= rel * std::fabs(want)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << got << " differs from " << want << " by more than " << rel << " relative";
}

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

// Rotation by Euler angles z-y-z; its columns are an orthonormal right-handed frame.
Mat3 rotation(double a, double b, double c) {
  const Mat3 rz1 = {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
  const Mat3 ry = {{{std::cos(b), 0, std::sin(b)}, {0, 1, 0}, {-std::sin(b), 0, std::cos(b)}}};
  const Mat3 rz2 = {{{std::cos(c), -std::sin(c), 0}, {std::sin(c), std::cos(c), 0}, {0, 0, 1}}};
  return mul(mul(rz1, ry), rz2);
}
Vec3 column(const Mat3& r, int k) { return {r[0][k], r[1][k], r[2][k]}; }
Vec3 times(const Mat3& r, const Vec3& v) {
  return {r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z, r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
          r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
}
Metric3 conjugate(const Mat3& r, const Metric3& m) {
  const Mat3 a = mul(mul(r, full(m)), transpose(r));
  return Metric3{{a[0][0], a[0][1], a[1][1], a[0][2], a[1][2], a[2][2]}};
}

// --- Generators: sizes 10^[-1, 1] (stretching up to 100:1, so that v^T M v keeps ~1e-12 of
// relative accuracy in every direction), any orientation. Larger stretching has its own tests.

rc::Gen<double> gen_angle() {
  return rc::gen::map(rc::gen::inRange(0, 1000000), [](int i) { return i * (2 * kPi / 1000000); });
}
rc::Gen<double> gen_size() {
  return rc::gen::map(rc::gen::inRange(-1000, 1001), [](int i) { return std::pow(10.0, i / 1000.0); });
}
rc::Gen<Metric2> gen_metric2() {
  return rc::gen::apply([](double a, double h1, double h2) { return Metric2::from_sizes(direction(a), h1, h2); },
                        gen_angle(), gen_size(), gen_size());
}
rc::Gen<Metric3> gen_metric3() {
  return rc::gen::apply(
      [](double a, double b, double c, double h1, double h2, double h3) {
        const Mat3 r = rotation(a, b, c);
        return Metric3::from_sizes(column(r, 0), column(r, 1), h1, h2, h3);
      },
      gen_angle(), gen_angle(), gen_angle(), gen_size(), gen_size(), gen_size());
}
rc::Gen<Vec2> gen_unit2() { return rc::gen::map(gen_angle(), direction); }
rc::Gen<Vec3> gen_unit3() {
  return rc::gen::apply([](double a, double b) { return Vec3{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)}; },
                        gen_angle(), gen_angle());
}
rc::Gen<double> gen_t() {
  return rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; });
}

// --- Construction and measures -----------------------------------------------------------------

TEST(Metric, IsotropicAndFromSizes) {
  EXPECT_EQ(Metric2::isotropic(2.0), (Metric2{{0.25, 0.0, 0.25}}));
  EXPECT_EQ(Metric3::isotropic(0.5), (Metric3{{4.0, 0.0, 4.0, 0.0, 0.0, 4.0}}));
  EXPECT_EQ(Metric2::from_sizes({1, 0}, 0.5, 4.0), (Metric2{{4.0, 0.0, 0.0625}}));
  EXPECT_EQ(Metric2::from_sizes({0, 1}, 0.5, 4.0), (Metric2{{0.0625, 0.0, 4.0}}));
  EXPECT_EQ(Metric3::from_sizes({0, 1, 0}, {0, 0, 1}, 1.0, 0.5, 0.25), (Metric3{{16.0, 0.0, 1.0, 0.0, 0.0, 4.0}}));
  // Size h along e1: a vector of length h along e1 has unit length.
  const Vec2 e = direction(0.3);
  const Metric2 m = Metric2::from_sizes(e, 0.1, 7.0);
  // (v^T M v loses eps * lambda_max / lambda_min relative across the thin direction: 4900 here.)
  EXPECT_TRUE(close(m.length(0.1 * e), 1.0, 1e-14));
  EXPECT_TRUE(close(m.length(7.0 * Vec2{-e.y, e.x}), 1.0, 1e-12));
  EXPECT_TRUE(close(m.determinant(), 1.0 / (0.01 * 49.0), 1e-13));
  EXPECT_EQ(Metric2::isotropic(0.5).length({3, 4}), 10.0);
  EXPECT_EQ(Metric3::isotropic(0.5).length({2, 3, 6}), 14.0);
  EXPECT_EQ(Metric3::isotropic(0.5).determinant(), 64.0);
}

TEST(Metric, PositiveDefiniteness) {
  EXPECT_TRUE(Metric2{}.is_positive_definite());
  EXPECT_TRUE((Metric2{{2, 1, 1}}).is_positive_definite());
  EXPECT_FALSE((Metric2{{1, 2, 1}}).is_positive_definite());
  EXPECT_FALSE((Metric2{{-1, 0, -1}}).is_positive_definite());
  EXPECT_FALSE((Metric2{{1, 1, 1}}).is_positive_definite());  // singular
  EXPECT_FALSE((Metric2{{std::nan(""), 0, 1}}).is_positive_definite());
  EXPECT_FALSE((Metric2{{kInf, 0, 1}}).is_positive_definite());
  EXPECT_TRUE(Metric3{}.is_positive_definite());
  EXPECT_FALSE((Metric3{{1, 0, -1, 0, 0, 1}}).is_positive_definite());
  EXPECT_FALSE((Metric3{{1, 0, 1, 0, 0, -1}}).is_positive_definite());
  // Positive diagonal, but the eigenvalues of [[1,.9,.9],[.9,1,-.9],[.9,-.9,1]] include -0.8.
  EXPECT_FALSE((Metric3{{1, 0.9, 1, 0.9, -0.9, 1}}).is_positive_definite());
  EXPECT_FALSE((Metric3{{1, 0, 1, 0, std::nan(""), 1}}).is_positive_definite());
}

// Issue 42, item 7: a size of 1e200 gave h^-2 = 0, reported as "not positive definite". The
// representable range keeps the eigenvalues and the 3D determinant normal at both ends.
TEST(Metric, SizesOutOfTheRepresentableRangeAreNamed) {
  for (const double h : {kMinMetricSize, 1.0, kMaxMetricSize}) {
    EXPECT_TRUE(is_representable_size(h)) << h;
    EXPECT_NO_THROW(check_size(h, "--size"));
    const Metric2 m2 = Metric2::isotropic(h);
    const Metric3 m3 = Metric3::isotropic(h);
    EXPECT_TRUE(m2.is_positive_definite()) << h;
    EXPECT_TRUE(m3.is_positive_definite()) << h;
    EXPECT_TRUE(std::isnormal(m3.determinant())) << h;
    EXPECT_EQ(sizes(m3)[0], h);
  }
  for (const double h : {1e200, 1e-200, std::nextafter(kMaxMetricSize, kInf), std::nextafter(kMinMetricSize, 0.0), 0.0,
                         -1.0, kInf, std::nan("")}) {
    EXPECT_FALSE(is_representable_size(h)) << h;
    try {
      check_size(h, "--size");
      ADD_FAILURE() << h << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("--size = ", 0), 0u) << what;
      EXPECT_NE(what.find("[6.68191e-52, 1.49658e+51]"), std::string::npos) << what;
      EXPECT_NE(what.find(h > 0.0 ? "out of the representable range" : "not a positive size"), std::string::npos) << what;
    }
  }
  try {
    check_size(1e200, "--size");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1e+200"), std::string::npos) << e.what();
  }
}

TEST(Metric, EigenOfKnownTensors) {
  const MetricEigen2 e = eigen(Metric2{{2, 1, 2}});
  EXPECT_TRUE(close(e.values[0], 1.0, 1e-15));
  EXPECT_TRUE(close(e.values[1], 3.0, 1e-15));
  EXPECT_TRUE(close(std::fabs(e.vectors[0].x), std::sqrt(0.5), 1e-15));
  EXPECT_TRUE(close(-e.vectors[0].x * e.vectors[0].y, 0.5, 1e-15));  // (1, -1) / sqrt 2, up to sign
  // Already diagonal: exact, ascending.
  const MetricEigen3 d = eigen(Metric3{{9, 0, 1, 0, 0, 4}});
  EXPECT_EQ(d.values, (std::array<double, 3>{1, 4, 9}));
  EXPECT_EQ(std::fabs(d.vectors[0].y), 1.0);
  EXPECT_EQ(std::fabs(d.vectors[2].x), 1.0);
  EXPECT_EQ(sizes(Metric3{{9, 0, 1, 0, 0, 4}}), (std::array<double, 3>{1.0, 0.5, 1.0 / 3.0}));
  EXPECT_EQ(sizes(Metric2::from_sizes({1, 0}, 0.5, 4.0)), (std::array<double, 2>{4.0, 0.5}));
  // A repeated eigenvalue: any orthonormal basis, the values exact.
  const MetricEigen3 i = eigen(Metric3::isotropic(0.5));
  EXPECT_EQ(i.values, (std::array<double, 3>{4, 4, 4}));
}

RC_GTEST_PROP(Metric, EigenRoundTripAndOrthonormal3d, ()) {
  const Metric3 m = *gen_metric3();
  const MetricEigen3 e = eigen(m);
  RC_ASSERT(e.values[0] <= e.values[1] && e.values[1] <= e.values[2]);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      RC_ASSERT(std::fabs(dot(e.vectors[i], e.vectors[j]) - (i == j ? 1.0 : 0.0)) <= 1e-14);
    }
    // M v = lambda v, relative to the largest eigenvalue.
    const Vec3 mv = times(full(m), e.vectors[i]);
    RC_ASSERT(norm(mv - e.values[i] * e.vectors[i]) <= 1e-13 * e.values[2]);
  }
  RC_ASSERT(near(from_eigen(e), m, 1e-14));
  // The smallest eigenvalue to high relative accuracy (stretching 100:1 is 1e4 in eigenvalues).
  const std::array<double, 3> h = sizes(m);
  RC_ASSERT(close(h[0] * h[0] * e.values[0], 1.0, 1e-14));
}

RC_GTEST_PROP(Metric, EigenRoundTrip2d, ()) {
  const Metric2 m = *gen_metric2();
  const MetricEigen2 e = eigen(m);
  RC_ASSERT(e.values[0] <= e.values[1]);
  RC_ASSERT(std::fabs(dot(e.vectors[0], e.vectors[1])) <= 1e-15);
  RC_ASSERT(std::fabs(norm(e.vectors[0]) - 1.0) <= 1e-15);
  RC_ASSERT(near(from_eigen(e), m, 1e-14));
}

RC_GTEST_PROP(Metric, PowerMinusHalfSquaredIsTheInverse, ()) {
  const Metric3 m = *gen_metric3();
  const Metric3 s = power(m, -0.5);
  const Mat3 sms = mul(mul(full(s), full(m)), full(s));
  RC_ASSERT(distance(sms, kIdentity) <= 1e-12);
  const Metric2 m2 = *gen_metric2();
  const Metric2 s2 = power(m2, -0.5);
  RC_ASSERT(distance(mul(mul(full(s2), full(s2)), full(m2)), kIdentity) <= 1e-12);
  // M^1/2 maps v to a vector whose Euclidean length is the metric length.
  const Vec3 v = *gen_unit3();
  RC_ASSERT(close(norm(transform(power(m, 0.5), v)), m.length(v), 1e-13));
  const Vec2 v2 = *gen_unit2();
  RC_ASSERT(close(norm(transform(power(m2, 0.5), v2)), m2.length(v2), 1e-13));
  RC_ASSERT(power(m, 1.0) == m);
}

RC_GTEST_PROP(Metric, LengthsInvariantUnderRotatingMetricAndVector, ()) {
  const double a = *gen_angle(), phi = *gen_angle();
  const double h1 = *gen_size(), h2 = *gen_size();
  const Vec2 v = *gen_unit2();
  const Metric2 m = Metric2::from_sizes(direction(a), h1, h2);
  const Metric2 rotated = Metric2::from_sizes(direction(a + phi), h1, h2);
  const Vec2 rv{std::cos(phi) * v.x - std::sin(phi) * v.y, std::sin(phi) * v.x + std::cos(phi) * v.y};
  RC_ASSERT(close(rotated.length(rv), m.length(v), 1e-12));
  // 3D, and the intersection commutes with the rotation.
  const Metric3 p = *gen_metric3(), q = *gen_metric3();
  const Mat3 r = rotation(*gen_angle(), *gen_angle(), *gen_angle());
  const Vec3 w = *gen_unit3();
  RC_ASSERT(close(conjugate(r, p).length(times(r, w)), p.length(w), 1e-12));
  RC_ASSERT(close(intersect(conjugate(r, p), conjugate(r, q)).length(times(r, w)), intersect(p, q).length(w), 1e-10));
}

// --- Intersection ------------------------------------------------------------------------------

TEST(MetricIntersection, KnownValues) {
  // The book's example shape: a circle and an ellipse crossing it.
  const Metric2 i = intersect(Metric2::isotropic(1.0), Metric2::from_sizes({1, 0}, 0.1, 10.0));
  EXPECT_TRUE(near(i, Metric2{{100.0, 0.0, 1.0}}, 1e-14));
  const std::array<double, 2> h = sizes(i);
  EXPECT_TRUE(close(h[0], 1.0, 1e-14));
  EXPECT_TRUE(close(h[1], 0.1, 1e-14));
  // Diagonal tensors: the larger eigenvalue on each axis.
  EXPECT_TRUE(near(intersect(Metric3{{1, 0, 9, 0, 0, 4}}, Metric3{{3, 0, 2, 0, 0, 5}}), Metric3{{3, 0, 9, 0, 0, 5}}, 1e-15));
  // Proportional (every direction an eigenvector of Ma^-1 Mb): the finer one, exactly.
  EXPECT_EQ(intersect(Metric2::isotropic(1.0), Metric2::isotropic(0.5)), Metric2::isotropic(0.5));
  const Metric3 m = Metric3::from_sizes(column(rotation(0.1, 0.2, 0.3), 0), column(rotation(0.1, 0.2, 0.3), 1), 1, 2, 3);
  Metric3 half = m;
  for (double& c : half.m) c *= 4.0;
  EXPECT_EQ(intersect(m, half), half);
  EXPECT_EQ(intersect(half, m), half);
  // One inside the other, rotated: the inner unit ball wins.
  const Metric2 fine = Metric2::from_sizes(direction(0.7), 0.01, 0.02);
  const Metric2 coarse = Metric2::from_sizes(direction(2.0), 0.5, 3.0);
  EXPECT_EQ(intersect(fine, coarse), fine);
}

RC_GTEST_PROP(MetricIntersection, CommutativeAndContainedInBoth2d, ()) {
  const Metric2 a = *gen_metric2(), b = *gen_metric2();
  const Metric2 i = intersect(a, b);
  // The base of the reduction is chosen by conditioning, not by argument order: bit for bit.
  RC_ASSERT(i == intersect(b, a));
  RC_ASSERT(i.is_positive_definite());
  for (int k = 0; k < 4; ++k) {
    const Vec2 v = *gen_unit2();
    RC_ASSERT(i.length(v) >= std::max(a.length(v), b.length(v)) * (1 - 1e-9));
  }
  // The largest such ellipse: in the basis that reduces both, I = diag(max(1, mu_i)) where mu_i
  // are the eigenvalues of A^-1 B, here the roots of mu^2 - tr(A^-1 B) mu + det B / det A.
  const double da = a.determinant();
  const double tr = (a.m[2] * b.m[0] - 2 * a.m[1] * b.m[1] + a.m[0] * b.m[2]) / da;
  const double pr = b.determinant() / da;
  const double disc = std::sqrt(std::max(0.0, tr * tr / 4 - pr));
  const double mu1 = tr / 2 + disc, mu2 = pr / mu1;
  RC_ASSERT(close(i.determinant(), da * std::max(1.0, mu1) * std::max(1.0, mu2), 1e-6));
}

RC_GTEST_PROP(MetricIntersection, CommutativeAndContainedInBoth3d, ()) {
  const Metric3 a = *gen_metric3(), b = *gen_metric3();
  const Metric3 i = intersect(a, b);
  RC_ASSERT(i == intersect(b, a));
  RC_ASSERT(i.is_positive_definite());
  for (int k = 0; k < 4; ++k) {
    const Vec3 v = *gen_unit3();
    RC_ASSERT(i.length(v) >= std::max(a.length(v), b.length(v)) * (1 - 1e-9));
  }
  // Not finer than needed: max(1, mu) <= 1 + mu in the reducing basis, so I <= A + B.
  for (int k = 0; k < 4; ++k) {
    const Vec3 v = *gen_unit3();
    const double li = i.length(v), la = a.length(v), lb = b.length(v);
    RC_ASSERT(li * li <= (la * la + lb * lb) * (1 + 1e-9));
  }
}

RC_GTEST_PROP(MetricIntersection, Idempotent, ()) {
  const Metric3 m = *gen_metric3();
  RC_ASSERT(intersect(m, m) == m);
  // With a copy that differs in the last bits (through a decomposition): still m.
  const Metric3 copy = from_eigen(eigen(m));
  RC_ASSERT(near(intersect(m, copy), m, 1e-13));
  const Metric2 m2 = *gen_metric2();
  RC_ASSERT(near(intersect(m2, from_eigen(eigen(m2))), m2, 1e-13));
}

TEST(MetricIntersection, StretchingOfAMillion) {
  // Two boundary-layer metrics, 1e6:1, at 30 degrees from each other.
  const Vec2 e1 = direction(0.2), e2 = direction(0.2 + kPi / 6);
  const Metric2 a = Metric2::from_sizes(e1, 1e-6, 1.0);
  const Metric2 b = Metric2::from_sizes(e2, 1e-6, 1.0);
  const Metric2 i = intersect(a, b);
  ASSERT_TRUE(i.is_positive_definite());
  EXPECT_EQ(i, intersect(b, a));
  // Both thin directions are kept (within the accuracy the stored components allow).
  EXPECT_GE(i.length(e1), a.length(e1) * (1 - 1e-6));
  EXPECT_GE(i.length(e2), b.length(e2) * (1 - 1e-6));
  // Both thin: the intersection is nearly isotropic at ~1e-6.
  const std::array<double, 2> h = sizes(i);
  EXPECT_LT(h[0], 3e-6);
  EXPECT_GT(h[1], 0.5e-6);
  // Axis-aligned 1e6:1 against isotropic: exact.
  const Metric2 layer = Metric2::from_sizes({1, 0}, 1e-6, 1.0);
  EXPECT_TRUE(near(intersect(layer, Metric2::isotropic(1e-3)), Metric2{{1e12, 0, 1e6}}, 1e-15));
  // 3D: a layer and a nearly isotropic metric (eigenvalues 1 +- 1e-12). The rotated layer's
  // unit eigenvalues are only defined to ~eps * 1e12 = 2e-4 by its rounded components (and so
  // are the result's): they agree with max(1, lambda) to that, the large one to ulps.
  const Metric3 layer3 = Metric3::from_sizes(column(rotation(0.3, 0.4, 0.5), 0), column(rotation(0.3, 0.4, 0.5), 1),
                                             1e-6, 1.0, 1.0);
  const Metric3 almost = Metric3{{1.0 + 1e-12, 1e-13, 1.0, -1e-13, 0.0, 1.0 - 1e-12}};
  const Metric3 i3 = intersect(layer3, almost);
  ASSERT_TRUE(i3.is_positive_definite());
  const MetricEigen3 got = eigen(i3), layer_e = eigen(layer3);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(got.values[k], std::max(1.0, layer_e.values[k]), 1e-3) << k;
  EXPECT_TRUE(close(got.values[2], 1e12, 1e-12));
  // Axis-aligned, where the components are exact: sizes 1e-6, 1, 1 to a few ulps.
  const Metric3 i4 = intersect(Metric3{{1e12, 0, 1, 0, 0, 1}}, almost);
  const std::array<double, 3> h4 = sizes(i4);
  EXPECT_TRUE(close(h4[0], 1.0, 1e-11));
  EXPECT_TRUE(close(h4[1], 1.0, 1e-11));
  EXPECT_TRUE(close(h4[2], 1e-6, 1e-14));
}

// --- Interpolation -----------------------------------------------------------------------------

TEST(MetricInterpolation, KnownValues) {
  // Sizes 1 and 3: the size halfway is 2 (linear in size), the log-Euclidean one sqrt 3.
  const Metric2 a = Metric2::isotropic(1.0), b = Metric2::isotropic(3.0);
  EXPECT_TRUE(near(interpolate(a, b, 0.5), Metric2::isotropic(2.0), 1e-15));
  EXPECT_TRUE(near(interpolate(a, b, 0.5, MetricInterpolation::LogEuclidean), Metric2::isotropic(std::sqrt(3.0)), 1e-15));
  // Axis-aligned: each axis on its own.
  const Metric3 p{{1, 0, 1.0 / 9, 0, 0, 1.0 / 16}}, q{{1.0 / 9, 0, 1, 0, 0, 1.0 / 16}};
  EXPECT_TRUE(near(interpolate(p, q, 0.25), Metric3{{1.0 / (1.5 * 1.5), 0, 1.0 / (2.5 * 2.5), 0, 0, 1.0 / 16}}, 1e-15));
  // A simplex with weights (1/2, 1/4, 1/4) of sizes 1, 2, 4: size 2.
  const std::vector<Metric2> ms = {Metric2::isotropic(1), Metric2::isotropic(2), Metric2::isotropic(4)};
  const std::vector<double> w = {0.5, 0.25, 0.25};
  EXPECT_TRUE(near(interpolate(ms, w), Metric2::isotropic(2.0), 1e-15));
  EXPECT_TRUE(near(interpolate(ms, w, MetricInterpolation::LogEuclidean), Metric2::isotropic(std::pow(2.0, 0.75)), 1e-14));
  // At a vertex: that vertex's metric, bit for bit.
  EXPECT_EQ(interpolate(ms, std::vector<double>{0, 1, 0}), ms[1]);
}

RC_GTEST_PROP(MetricInterpolation, EndpointsAndConstantField, ()) {
  const Metric3 a = *gen_metric3(), b = *gen_metric3();
  for (const MetricInterpolation mode : {MetricInterpolation::Sizes, MetricInterpolation::LogEuclidean}) {
    RC_ASSERT(interpolate(a, b, 0.0, mode) == a);
    RC_ASSERT(interpolate(a, b, 1.0, mode) == b);
    // Continuous at the ends.
    RC_ASSERT(near(interpolate(a, b, 1e-13, mode), a, 1e-10));
    RC_ASSERT(near(interpolate(a, b, 1.0 - 1e-13, mode), b, 1e-10));
    // Identical metrics, one of them through a decomposition: the same metric all along.
    const double t = *gen_t();
    RC_ASSERT(near(interpolate(a, from_eigen(eigen(a)), t, mode), a, 1e-12));
    const std::vector<Metric3> three = {a, from_eigen(eigen(a)), a};
    const std::vector<double> w = {0.2, 0.5, 0.3};
    RC_ASSERT(near(interpolate(three, w, mode), a, 1e-12));
    RC_ASSERT(interpolate(a, b, t, mode).is_positive_definite());
  }
}

RC_GTEST_PROP(MetricInterpolation, ScalingLaws, ()) {
  // b = a / k^2 has sizes k times a's: on sizes the size is (1 - t + t k) times a's; log-Euclidean
  // gives k^t times.
  const Metric2 a = *gen_metric2();
  const double k = *gen_size(), t = *gen_t();
  Metric2 b = a;
  for (double& c : b.m) c /= k * k;
  Metric2 sizes_law = a, log_law = a;
  for (double& c : sizes_law.m) c /= (1 - t + t * k) * (1 - t + t * k);
  for (double& c : log_law.m) c /= std::pow(k, 2 * t);
  RC_ASSERT(near(interpolate(a, b, t), sizes_law, 1e-12));
  RC_ASSERT(near(interpolate(a, b, t, MetricInterpolation::LogEuclidean), log_law, 1e-12));
  // The edge version is the simplex version with weights (1 - t, t).
  const Metric2 c = *gen_metric2();
  const std::vector<Metric2> ends = {a, c};
  const std::vector<double> w = {1 - t, t};
  RC_ASSERT(near(interpolate(ends, w), interpolate(a, c, t), 1e-13));
}

// --- Clipping, lengths, growth -----------------------------------------------------------------

RC_GTEST_PROP(Metric, ClipBoundsTheSizes, ()) {
  const Metric3 m = *gen_metric3();
  const double h_min = *gen_size(), h_max = h_min * (1 + *rc::gen::inRange(0, 100));
  const std::array<double, 3> h = sizes(clip(m, h_min, h_max));
  const std::array<double, 3> before = sizes(m);
  for (int k = 0; k < 3; ++k) {
    RC_ASSERT(h[k] >= h_min * (1 - 1e-12) && h[k] <= h_max * (1 + 1e-12));
    RC_ASSERT(close(h[k], std::clamp(before[k], h_min, h_max), 1e-12));
  }
  // Already inside the bounds: untouched.
  RC_ASSERT(clip(m, 1e-3, 1e3) == m);
  const Metric2 m2 = *gen_metric2();
  const std::array<double, 2> h2 = sizes(clip(m2, h_min, h_max));
  RC_ASSERT(h2[1] >= h_min * (1 - 1e-12) && h2[0] <= h_max * (1 + 1e-12));
}

TEST(Metric, EdgeLengthKnownValues) {
  // Sizes 1 at p and 2 at q along an edge of length 2: la = 2, lb = 1, l = 1 / ln 2.
  const Vec2 p{0, 0}, q{2, 0};
  EXPECT_TRUE(close(edge_length(p, Metric2::isotropic(1), q, Metric2::isotropic(2)), 1.0 / std::log(2.0), 1e-15));
  EXPECT_TRUE(close(edge_length(q, Metric2::isotropic(2), p, Metric2::isotropic(1)), 1.0 / std::log(2.0), 1e-15));
  EXPECT_EQ(edge_length(p, Metric2::isotropic(0.5), p, Metric2::isotropic(2)), 0.0);
  EXPECT_EQ(edge_length(Vec3{0, 0, 0}, Metric3::isotropic(0.5), Vec3{2, 3, 6}, Metric3::isotropic(0.5)), 14.0);
  // grow: (1 + l ln beta)^-2 m.
  const Metric2 g = grow(Metric2::isotropic(1.0), 2.0, std::exp(0.5));
  EXPECT_TRUE(near(g, Metric2::isotropic(2.0), 1e-15));
  EXPECT_EQ(grow(Metric3::isotropic(0.5), 3.0, 1.0), Metric3::isotropic(0.5));
}

RC_GTEST_PROP(Metric, EdgeLengthBetweenTheEndLengths, ()) {
  const Metric3 a = *gen_metric3(), b = *gen_metric3();
  const Vec3 p{0.5, -1, 2}, q = p + *gen_unit3();
  const double l = edge_length(p, a, q, b);
  // Equal metrics: the plain metric length, bit for bit.
  RC_ASSERT(edge_length(p, a, q, a) == a.length(q - p));
  const double la = a.length(q - p), lb = b.length(q - p);
  RC_ASSERT(l >= std::min(la, lb) * (1 - 1e-12) && l <= std::max(la, lb) * (1 + 1e-12));
  RC_ASSERT(close(edge_length(q, b, p, a), l, 1e-12));
  // No jump where the two lengths become equal.
  const Metric3 a2 = grow(a, 1e-10, 2.0);
  RC_ASSERT(close(edge_length(p, a, q, a2), la, 1e-9));
}

// --- Gradation ---------------------------------------------------------------------------------

RC_GTEST_PROP(MetricGradation, BoundsTheSizeRatioAlongEdges, ()) {
  // A chain of points with random isotropic sizes: afterwards h_j <= h_i + |pq| ln beta on every
  // edge (book §9.5's H-variation), up to the stopping tolerance, and no size grew.
  const int n = *rc::gen::inRange(2, 40);
  const double beta = 1.0 + *rc::gen::inRange(1, 100) / 50.0;
  std::vector<Vec2> points;
  std::vector<Metric2> metrics;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<double> before;
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    points.push_back({x, 0.0});
    x += 0.01 + *rc::gen::inRange(0, 1000) / 1000.0;
    const double h = *gen_size();
    before.push_back(h);
    metrics.push_back(Metric2::isotropic(h));
    if (i > 0) edges.push_back({static_cast<std::uint32_t>(i - 1), static_cast<std::uint32_t>(i)});
  }
  const std::uint32_t passes = apply_gradation(points, edges, metrics, beta);
  RC_ASSERT(passes >= 1u && passes < 100u);
  for (const auto& e : edges) {
    const double hi = sizes(metrics[e[0]])[0], hj = sizes(metrics[e[1]])[0];
    const double d = points[e[1]].x - points[e[0]].x;
    RC_ASSERT(hj <= (hi + d * std::log(beta)) * (1 + 2e-3));
    RC_ASSERT(hi <= (hj + d * std::log(beta)) * (1 + 2e-3));
  }
  for (int i = 0; i < n; ++i) {
    RC_ASSERT(sizes(metrics[static_cast<std::size_t>(i)])[0] <= before[static_cast<std::size_t>(i)] * (1 + 1e-12));
  }
}

RC_GTEST_PROP(MetricGradation, AnisotropicGrownMetricIsContained, ()) {
  // A triangle fan in 3D with random anisotropic metrics: afterwards every M_q contains
  // grow(M_p, l_p(pq), beta) in every direction, up to the stopping tolerance.
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const std::vector<std::array<std::uint32_t, 2>> edges = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}, {3, 1}, {4, 1}, {4, 2}, {4, 3}};
  std::vector<Metric3> metrics;
  for (std::size_t i = 0; i < points.size(); ++i) metrics.push_back(*gen_metric3());
  const double beta = 1.5;
  apply_gradation(points, edges, metrics, beta);
  for (const auto& e : edges) {
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t p = e[side], q = e[1 - side];
      const Metric3 g = grow(metrics[p], metrics[p].length(points[q] - points[p]), beta);
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = *gen_unit3();
        RC_ASSERT(metrics[q].length(v) >= g.length(v) * (1 - 1e-2));
      }
    }
  }
}

TEST(MetricGradation, RefusesBadInput) {
  std::vector<Vec2> points = {{0, 0}, {1, 0}};
  std::vector<Metric2> metrics(2);
  const std::vector<std::array<std::uint32_t, 2>> edges = {{0, 1}};
  EXPECT_THROW(apply_gradation(points, edges, metrics, 0.5), InputError);
  const std::vector<std::array<std::uint32_t, 2>> bad = {{0, 1}, {1, 2}};
  try {
    apply_gradation(points, bad, metrics, 1.5);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 1 has vertex 2 out of range"), std::string::npos) << e.what();
    EXPECT_EQ(e.items(), (std::vector<std::uint64_t>{1}));
  }
  std::vector<Metric2> one(1);
  EXPECT_THROW(apply_gradation(points, edges, one, 1.5), InputError);
  // beta = 1: sizes may not grow at all along an edge, so the coarser end takes the finer size.
  metrics = {Metric2::isotropic(1.0), Metric2::isotropic(0.1)};
  EXPECT_EQ(apply_gradation(points, edges, metrics, 1.0), 2u);  // one pass that changes, one that checks
  EXPECT_EQ(metrics[0], Metric2::isotropic(0.1));
  EXPECT_EQ(apply_gradation(points, edges, metrics, 1.0, 0), 0u);
}

// --- Quality in a metric -----------------------------------------------------------------------

TEST(MetricQuality, IdentityMetricGivesThePlainMeasures) {
  const Vec2 a{0, 0}, b{3, 0}, c{1, 2};
  EXPECT_TRUE(close(shape_quality(a, b, c, Metric2{}), shape_quality(a, b, c), 1e-15));
  const Vec3 p{0, 0, 0}, q{1, 0, 0}, r{0.2, 1, 0}, s{0.1, 0.3, 2};
  EXPECT_TRUE(close(shape_quality(p, q, r, s, Metric3{}), shape_quality(p, q, r, s), 1e-15));
  // Scaling the metric scales every length alike: Q and the mean ratio do not change.
  EXPECT_TRUE(close(shape_quality(a, b, c, Metric2::isotropic(0.01)), shape_quality(a, b, c), 1e-14));
  EXPECT_TRUE(close(mean_ratio(p, q, r, s, Metric3::isotropic(7.0)), mean_ratio(p, q, r, s, Metric3{}), 1e-14));
}

TEST(MetricQuality, EquilateralInTheMetric) {
  // The image under M^-1/2 of an equilateral triangle / regular tetrahedron is perfect in M.
  const Metric2 m = Metric2::from_sizes(direction(0.4), 1e-3, 1.0);
  const Metric2 s = power(m, -0.5);
  const Vec2 a = transform(s, {0, 0}), b = transform(s, {1, 0}), c = transform(s, {0.5, std::sqrt(3.0) / 2});
  EXPECT_TRUE(close(shape_quality(a, b, c, m), 1.0, 1e-9));
  EXPECT_TRUE(close(mean_ratio(a, b, c, m), 1.0, 1e-9));
  EXPECT_GT(shape_quality(a, b, c), 100.0);  // badly shaped in the Euclidean plane
  EXPECT_TRUE(close(mean_ratio(a, c, b, m), -1.0, 1e-9));  // inverted
  const Mat3 r = rotation(0.3, 1.1, -0.4);
  const Metric3 m3 = Metric3::from_sizes(column(r, 0), column(r, 1), 0.01, 1.0, 0.1);
  const Metric3 s3 = power(m3, -0.5);
  const Vec3 reg[4] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
  Vec3 t[4];
  for (int k = 0; k < 4; ++k) t[k] = transform(s3, reg[k]);
  EXPECT_TRUE(close(shape_quality(t[0], t[1], t[2], t[3], m3), 1.0, 1e-10));
  EXPECT_TRUE(close(mean_ratio(t[0], t[1], t[2], t[3], m3), 1.0, 1e-10));
  EXPECT_TRUE(close(mean_ratio(t[1], t[0], t[2], t[3], m3), -1.0, 1e-10));
  // The vertex-metric version is the worst of the three (four).
  const Metric2 other = Metric2::isotropic(1.0);
  EXPECT_EQ(shape_quality(a, b, c, m, other, m), std::max(shape_quality(a, b, c, m), shape_quality(a, b, c, other)));
  EXPECT_EQ(shape_quality(t[0], t[1], t[2], t[3], m3, m3, Metric3{}, m3),
            std::max(shape_quality(t[0], t[1], t[2], t[3], m3), shape_quality(t[0], t[1], t[2], t[3], Metric3{})));
}

TEST(MetricQuality, FlatElements) {
  const Metric2 m = Metric2::from_sizes(direction(0.4), 0.1, 1.0);
  EXPECT_EQ(shape_quality(Vec2{0, 0}, Vec2{1, 1}, Vec2{3, 3}, m), kInf);
  EXPECT_EQ(mean_ratio(Vec2{0, 0}, Vec2{1, 1}, Vec2{3, 3}, m), 0.0);
  const Metric3 m3 = Metric3::isotropic(0.3);
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, xy{1, 1, 0};
  EXPECT_EQ(shape_quality(o, x, y, xy, m3), kInf);
  EXPECT_EQ(mean_ratio(o, x, y, xy, m3), 0.0);
  EXPECT_EQ(shape_quality(o, x, y, xy, m3, m3, m3, m3), kInf);
}

RC_GTEST_PROP(MetricQuality, ImageUnderSquareRootAgrees, ()) {
  // Q in M equals the plain Q of the image under M^1/2 (header), here computed the long way.
  const Metric3 m = *gen_metric3();
  const Metric3 root = power(m, 0.5);
  Vec3 v[4];
  for (auto& p : v) p = Vec3{*gen_angle(), *gen_angle(), *gen_angle()};
  const double plain = shape_quality(transform(root, v[0]), transform(root, v[1]), transform(root, v[2]), transform(root, v[3]));
  RC_PRE(plain < 1e3);
  RC_ASSERT(close(shape_quality(v[0], v[1], v[2], v[3], m), plain, 1e-9));
  const double q = shape_quality(v[0], v[1], v[2], v[3], m);
  RC_ASSERT(q >= 1.0 - 1e-12);
  const double r = mean_ratio(v[0], v[1], v[2], v[3], m);
  RC_ASSERT(std::fabs(r) <= 1.0 + 1e-12 && std::fabs(r) > 0.0);
  const Metric2 m2 = *gen_metric2();
  const Metric2 root2 = power(m2, 0.5);
  const Vec2 a{*gen_angle(), *gen_angle()}, b{*gen_angle(), *gen_angle()}, c{*gen_angle(), *gen_angle()};
  const double plain2 = shape_quality(transform(root2, a), transform(root2, b), transform(root2, c));
  RC_PRE(plain2 < 1e3);
  RC_ASSERT(close(shape_quality(a, b, c, m2), plain2, 1e-9));
}

}  // namespace
}  // namespace dtlab
