// Tests of the named 3D point distributions (verify/generators/points3d): counts, reproducibility,
// coordinates in range and in each distribution's domain, and the exact degeneracies promised:
// exact_sphere on one sphere x^2 + y^2 + z^2 = R^2 (and its halvings), coplanar on four planes,
// collinear in runs, grid on the lattice, duplicates repeated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab {
namespace {

bool is_integer(double v) { return std::floor(v) == v; }

TEST(Points3d, EveryDistributionGivesNPointsInRangeReproducibly) {
  const auto names = distribution_names3d();
  EXPECT_EQ(names.size(), 13u);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for (const std::string& name : names) {
    EXPECT_FALSE(distribution_description3d(name).empty()) << name;
    for (const std::size_t n : {0, 1, 2, 3, 9, 10, 100, 2500}) {
      const auto P = generate_points3d(name, n, 42);
      ASSERT_EQ(P.size(), n) << name;
      EXPECT_EQ(P, generate_points3d(name, n, 42)) << name << " is not reproducible";
      for (const Vec3& p : P) {
        ASSERT_TRUE(coordinate_in_range(p.x) && coordinate_in_range(p.y) && coordinate_in_range(p.z))
            << name << ": " << p.x << " " << p.y << " " << p.z;
      }
      if (n >= 100) {
        EXPECT_NE(P, generate_points3d(name, n, 43)) << name << " ignores the seed";
        std::set<Vec3> distinct(P.begin(), P.end());
        if (name != "duplicates") {
          EXPECT_GE(distinct.size(), n * 9 / 10) << name;
        }
      }
    }
  }
  EXPECT_THROW(generate_points3d("no-such", 10, 1), InputError);
  EXPECT_EQ(distribution_description3d("no-such"), "");
}

// The first bits are fixed by the standard's mt19937_64 and our own arithmetic: the same on every
// platform. (A change here changes every benchmark's input: do it knowingly.)
TEST(Points3d, FirstUniformPointIsFixed) {
  const auto P = generate_points3d("uniform", 1, 1);
  std::mt19937_64 rng(1);
  const double x = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  EXPECT_EQ(P[0].x, x);
}

TEST(Points3d, Domains) {
  const std::size_t n = 3000;
  for (const Vec3& p : generate_points3d("uniform", n, 1)) {
    for (const double c : {p.x, p.y, p.z}) EXPECT_TRUE(c >= 0.0 && c < 1.0);
  }
  for (const Vec3& p : generate_points3d("scaled_small", n, 1)) {
    for (const double c : {p.x, p.y, p.z}) EXPECT_TRUE(c >= 0.0 && c < 1e-9);
  }
  for (const Vec3& p : generate_points3d("scaled_large", n, 1)) {
    for (const double c : {p.x, p.y, p.z}) EXPECT_TRUE(c >= 0.0 && c < 1e9);
  }
  for (const Vec3& p : generate_points3d("translated", n, 1)) {
    for (const double c : {p.x, p.y, p.z}) EXPECT_TRUE(c >= 1e9 && c <= 1e9 + 1);
  }
  for (const Vec3& p : generate_points3d("multiscale", n, 1)) {
    for (const double c : {p.x, p.y, p.z}) EXPECT_TRUE(c >= 0.0 && c < 1e9);
  }
  for (const Vec3& p : generate_points3d("sphere", n, 1)) {
    EXPECT_NEAR(p.x * p.x + p.y * p.y + p.z * p.z, 1.0, 1e-14);
  }
  double sum = 0, squares = 0;
  for (const Vec3& p : generate_points3d("normal", n, 1)) sum += p.z, squares += p.z * p.z;
  EXPECT_NEAR(sum / n, 0.0, 0.1);
  EXPECT_NEAR(squares / n, 1.0, 0.15);
}

TEST(Points3d, GridIsTheLattice) {
  const auto P = generate_points3d("grid", 1000, 3);
  const std::set<Vec3> distinct(P.begin(), P.end());
  EXPECT_EQ(distinct.size(), 1000u);
  for (const Vec3& p : P) {
    for (const double c : {p.x, p.y, p.z}) {
      EXPECT_TRUE(is_integer(c) && c >= 0 && c < 10);
    }
  }
  EXPECT_NE(P.front(), (Vec3{0, 0, 0}));  // shuffled (for this seed)
}

// x^2 + y^2 + z^2 of integer-valued coordinates, exactly (they stay below 2^26).
std::int64_t norm2(const Vec3& p) {
  const auto x = static_cast<std::int64_t>(p.x), y = static_cast<std::int64_t>(p.y), z = static_cast<std::int64_t>(p.z);
  return x * x + y * y + z * z;
}

TEST(Points3d, ExactSphereIsExactlyOnOneSphere) {
  for (const std::size_t n : {5, 100, 2000, 20000}) {
    const auto P = generate_points3d("exact_sphere", n, 7);
    const std::set<Vec3> distinct(P.begin(), P.end());
    EXPECT_EQ(distinct.size(), n);
    const std::int64_t r2 = norm2(P[0]);
    const auto r = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(r2))));
    EXPECT_EQ(r * r, r2) << "the radius is an integer";
    for (const Vec3& p : P) {
      ASSERT_TRUE(is_integer(p.x) && is_integer(p.y) && is_integer(p.z));
      ASSERT_EQ(norm2(p), r2);
    }
    // Cospherical and not coplanar: every in-sphere test of five of them is an exact zero.
    if (n >= 5) {
      EXPECT_EQ(insphere(P[0], P[1], P[2], P[3], P[4]), Sign::Zero);
    }
  }
}

TEST(Points3d, ExactSphereBeyondTheLargestRadiusUsesHalvedSpheres) {
  // The base sphere R = 15015 has fewer points than this: the rest lie on R/2 (exactly).
  const auto P = generate_points3d("exact_sphere", 300'000, 1);
  std::set<std::int64_t> radii;
  for (const Vec3& p : P) {
    const Vec3 q = 2.0 * p;  // exact
    ASSERT_TRUE(is_integer(q.x) && is_integer(q.y) && is_integer(q.z));
    const double x = q.x, y = q.y, z = q.z;
    // 4 R^2 < 2^30: the sum of squares of these integers is exact in doubles.
    radii.insert(static_cast<std::int64_t>(x * x + y * y + z * z));
  }
  EXPECT_EQ(radii, (std::set<std::int64_t>{4 * 15015ll * 15015, 15015ll * 15015}));
}

// The largest number of points on one plane through p[a], p[b] and a third point, exactly.
std::size_t largest_plane(const std::vector<Vec3>& P, std::size_t a, std::size_t b) {
  std::size_t best = 0;
  for (std::size_t c = 0; c < P.size(); ++c) {
    std::size_t on = 0;
    for (const Vec3& q : P) on += orient3d(P[a], P[b], P[c], q) == Sign::Zero;
    // Collinear a, b, c put everything "on" the degenerate plane: skip them.
    if (on < P.size()) best = std::max(best, on);
  }
  return best;
}

TEST(Points3d, CoplanarLiesOnFourPlanes) {
  const auto P = generate_points3d("coplanar", 200, 5);  // 20 off the planes, 45 on each plane
  for (const Vec3& p : P) ASSERT_TRUE(is_integer(p.x) && is_integer(p.y) && is_integer(p.z));
  // Points on one of the planes see a plane of >= 45 points through themselves and a neighbour
  // on it; count the points that do.
  std::size_t on_big_plane = 0;
  for (std::size_t a = 0; a < 40; ++a) {
    std::size_t best = 0;
    for (std::size_t b = 0; b < P.size() && best < 45; ++b)
      if (b != a) best = std::max(best, largest_plane(P, a, b));
    on_big_plane += best >= 45;
  }
  EXPECT_GE(on_big_plane, 28u);  // about 90% of 40
  EXPECT_LT(on_big_plane, 40u + 1);
}

TEST(Points3d, CollinearHasRunsOnLines) {
  const auto P = generate_points3d("collinear", 100, 5);  // 90 in runs of 9, 10 off the lines
  for (const Vec3& p : P) ASSERT_TRUE(is_integer(p.x) && is_integer(p.y) && is_integer(p.z));
  const auto collinear = [](const Vec3& a, const Vec3& b, const Vec3& c) {
    return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::Zero &&
           orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::Zero &&
           orient2d({a.x, a.z}, {b.x, b.z}, {c.x, c.z}) == Sign::Zero;
  };
  std::size_t lines = 0;
  std::set<std::size_t> covered;
  for (std::size_t a = 0; a < P.size(); ++a)
    for (std::size_t b = a + 1; b < P.size(); ++b) {
      std::vector<std::size_t> on;
      for (std::size_t c = 0; c < P.size(); ++c)
        if (collinear(P[a], P[b], P[c])) on.push_back(c);
      if (on.size() >= 9 && on[0] == a && on[1] == b) {  // each line once, from its first two points
        ++lines;
        covered.insert(on.begin(), on.end());
      }
    }
  EXPECT_EQ(lines, 10u);
  EXPECT_EQ(covered.size(), 90u);
}

TEST(Points3d, DuplicatesRepeatTenPercent) {
  const auto P = generate_points3d("duplicates", 1000, 2);
  const std::set<Vec3> distinct(P.begin(), P.end());
  EXPECT_EQ(distinct.size(), 900u);
}

}  // namespace
}  // namespace dtlab
