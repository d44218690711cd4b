// The named 2D point distributions: deterministic (same seed, same bits), the right size, in
// the supported range, and with the structure each name promises.
#include <algorithm>
#include <bit>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

std::vector<std::pair<std::uint64_t, std::uint64_t>> bits(const std::vector<Vec2>& p) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> b;
  for (const Vec2& q : p) b.emplace_back(std::bit_cast<std::uint64_t>(q.x), std::bit_cast<std::uint64_t>(q.y));
  return b;
}

std::size_t distinct(const std::vector<Vec2>& p) {
  std::set<std::pair<double, double>> s;
  for (const Vec2& q : p) s.insert({q.x, q.y});
  return s.size();
}

TEST(Points2d, NamesAreKnownAndDescribed) {
  const std::vector<std::string> names = distribution_names2d();
  EXPECT_EQ(names.size(), 12u);
  for (const std::string& name : names) {
    EXPECT_FALSE(distribution_description2d(name).empty()) << name;
    EXPECT_NO_THROW(generate_points2d(name, 5, 1)) << name;
  }
  EXPECT_TRUE(distribution_description2d("nope").empty());
}

TEST(Points2d, UnknownNameListsTheKnownOnes) {
  try {
    generate_points2d("unifrom", 10, 1);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'unifrom'"), std::string::npos) << what;
    for (const std::string& name : distribution_names2d()) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}

TEST(Points2d, SameSeedSameBitsOtherSeedOtherPoints) {
  for (const std::string& name : distribution_names2d()) {
    const std::vector<Vec2> a = generate_points2d(name, 500, 42);
    const std::vector<Vec2> b = generate_points2d(name, 500, 42);
    const std::vector<Vec2> c = generate_points2d(name, 500, 43);
    EXPECT_EQ(bits(a), bits(b)) << name;
    EXPECT_NE(bits(a), bits(c)) << name;  // grid and exact_circle differ at least in order
  }
}

TEST(Points2d, SizesAndRange) {
  for (const std::string& name : distribution_names2d()) {
    for (std::size_t n : {0u, 1u, 2u, 3u, 4u, 5u, 10u, 99u, 1000u}) {
      const std::vector<Vec2> p = generate_points2d(name, n, 7);
      ASSERT_EQ(p.size(), n) << name;
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(coordinate_in_range(p[i].x) && coordinate_in_range(p[i].y))
            << name << " point " << i << ": " << p[i].x << " " << p[i].y;
      }
    }
  }
}

TEST(Points2d, BoxesOfTheScaledAndTranslatedOnes) {
  const auto inside = [](const std::vector<Vec2>& p, double lo, double hi) {
    return std::all_of(p.begin(), p.end(), [&](const Vec2& q) { return q.x >= lo && q.x <= hi && q.y >= lo && q.y <= hi; });
  };
  EXPECT_TRUE(inside(generate_points2d("uniform", 1000, 3), 0.0, std::nextafter(1.0, 0.0)));
  EXPECT_TRUE(inside(generate_points2d("scaled_small", 1000, 3), 0.0, 1e-9));
  EXPECT_TRUE(inside(generate_points2d("scaled_large", 1000, 3), 0.0, 1e9));
  EXPECT_TRUE(inside(generate_points2d("translated", 1000, 3), 1e9, 1e9 + 1.0));
  const std::vector<Vec2> m = generate_points2d("multiscale", 2000, 3);
  EXPECT_TRUE(inside(m, 0.0, 1e9));
  EXPECT_TRUE(std::any_of(m.begin(), m.end(), [](const Vec2& q) { return q.x > 1e7; }));
  EXPECT_TRUE(std::any_of(m.begin(), m.end(), [](const Vec2& q) { return q.x > 0 && q.x < 1e-7; }));
}

TEST(Points2d, GridIsTheFirstLatticePoints) {
  for (std::size_t n : {16u, 17u, 100u}) {
    const std::vector<Vec2> p = generate_points2d("grid", n, 5);
    std::size_t k = 0;
    while (k * k < n) ++k;
    EXPECT_EQ(distinct(p), n);
    for (const Vec2& q : p) {
      EXPECT_EQ(q.x, std::floor(q.x));
      EXPECT_EQ(q.y, std::floor(q.y));
      EXPECT_TRUE(q.x >= 0 && q.x < static_cast<double>(k) && q.y >= 0 && q.y < static_cast<double>(k));
      EXPECT_LT(q.y * static_cast<double>(k) + q.x, static_cast<double>(n));
    }
  }
}

TEST(Points2d, CircleIsAsCloseAsDoublesAllowButExactCircleIsExact) {
  const std::vector<Vec2> c = generate_points2d("circle", 2000, 9);
  for (const Vec2& q : c) EXPECT_NEAR(q.x * q.x + q.y * q.y, 1.0, 8e-16);

  for (std::size_t n : {4u, 5u, 108u, 1000u}) {
    const std::vector<Vec2> p = generate_points2d("exact_circle", n, 9);
    EXPECT_EQ(distinct(p), n);
    // Every four points are exactly cocircular (exact incircle zero), none three collinear.
    for (std::size_t i = 0; i + 3 < n; i += 3) {
      EXPECT_EQ(incircle(p[i], p[i + 1], p[i + 2], p[i + 3]), Sign::Zero) << n << " " << i;
      EXPECT_NE(orient2d(p[i], p[i + 1], p[i + 2]), Sign::Zero);
    }
  }
}

TEST(Points2d, ExactCircleBeyondOneCircleGoesToConcentricOnes) {
  const std::size_t n = 4 * 59049 + 100;  // one more prime would pass 2^53
  const std::vector<Vec2> p = generate_points2d("exact_circle", n, 1);
  EXPECT_EQ(distinct(p), n);
  std::set<double> radii_squared;
  for (const Vec2& q : p) radii_squared.insert(q.x * q.x + q.y * q.y);  // rounded, enough to tell 2 apart
  EXPECT_GE(radii_squared.size(), 2u);
}

TEST(Points2d, CollinearRunsAreExactlyCollinear) {
  const std::vector<Vec2> p = generate_points2d("collinear", 50, 11);  // 7 runs of 7, one single point
  std::size_t on_a_line = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p[i].x, std::floor(p[i].x));
    bool found = false;
    for (std::size_t j = 0; j < p.size() && !found; ++j) {
      for (std::size_t k = j + 1; k < p.size() && !found; ++k) {
        found = j != i && k != i && orient2d(p[i], p[j], p[k]) == Sign::Zero;
      }
    }
    on_a_line += found ? 1 : 0;
  }
  EXPECT_GE(on_a_line, 49u);
}

TEST(Points2d, DuplicatesRepeatATenth) {
  const std::vector<Vec2> p = generate_points2d("duplicates", 1000, 13);
  EXPECT_EQ(distinct(p), 900u);
  EXPECT_EQ(distinct(generate_points2d("duplicates", 5, 13)), 4u);
  EXPECT_EQ(distinct(generate_points2d("uniform", 1000, 13)), 1000u);
}

TEST(Points2d, NormalAndClusteredLookRight) {
  const std::vector<Vec2> p = generate_points2d("normal", 20000, 17);
  double mean = 0, var = 0;
  for (const Vec2& q : p) mean += q.x + q.y;
  mean /= 2.0 * static_cast<double>(p.size());
  for (const Vec2& q : p) var += (q.x - mean) * (q.x - mean) + (q.y - mean) * (q.y - mean);
  var /= 2.0 * static_cast<double>(p.size());
  EXPECT_NEAR(mean, 0.0, 0.03);
  EXPECT_NEAR(var, 1.0, 0.05);

  // 20 clusters of sigma 0.05/sqrt(20): most points near one of few centres, so a coarse
  // 100 x 100 histogram is far from uniform.
  const std::vector<Vec2> c = generate_points2d("clustered", 20000, 17);
  std::set<std::pair<int, int>> cells;
  for (const Vec2& q : c) cells.insert({static_cast<int>(std::floor(q.x * 100)), static_cast<int>(std::floor(q.y * 100))});
  EXPECT_LT(cells.size(), 2000u);
}

}  // namespace
}  // namespace dtlab
