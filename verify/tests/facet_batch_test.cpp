// The batched static filters of one tetrahedron's facets (kernel/predicates/facet_batch.hpp)
// against the scalar filters they must equal test for test: a test decides exactly when the
// scalar static test on the same rows does, with the same sign, the exact predicate agrees with
// every decided test, the rows list each facet and each neighbour as documented, and the
// portable version (no AVX2) says the same as the one the processor runs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "kernel/predicates.hpp"
#include "kernel/predicates/facet_batch.hpp"
#include "kernel/predicates/semistatic.hpp"
#include "kernel/predicates/static_filter.hpp"
#include "kernel/stats.hpp"

namespace dtlab {
namespace {

// What the scalar static test says of one test: +1 / -1 decided, 0 undecided.
int scalar_static(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e, double bound) {
  const double det = stage::insphere_det_translated(a.x - e.x, a.y - e.y, a.z - e.z, b.x - e.x, b.y - e.y,
                                                    b.z - e.z, c.x - e.x, c.y - e.y, c.z - e.z, d.x - e.x,
                                                    d.y - e.y, d.z - e.z);
  return det > bound ? 1 : (det < -bound ? -1 : 0);
}

// Random positive tetrahedra of `points` and random apexes and query points, every subset of the
// four tests; how many tests there were and how many the batches left undecided.
struct Counts {
  int tests = 0, undecided = 0;
};
Counts check_batches(const std::vector<Vec3>& points, double bound, std::mt19937_64& rng, int rounds) {
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(points.size() - 1));
  Counts counts;
  for (int round = 0; round < rounds; ++round) {
    std::array<std::uint32_t, 4> v, apex;
    for (std::uint32_t& x : v) x = pick(rng);
    if (orient3d(points[v[0]], points[v[1]], points[v[2]], points[v[3]]) != Sign::Positive) std::swap(v[2], v[3]);
    for (std::uint32_t& x : apex) x = pick(rng);
    const unsigned tests = 1 + round % 15;
    const Vec3& e = points[pick(rng)];
    const std::uint64_t before = predicate_stats()[Predicate::Insphere].semistatic;
    const InsphereBatch batch = insphere_static_across_facets(points.data(), v, apex, tests, e, bound);
    const std::uint64_t counted = predicate_stats()[Predicate::Insphere].semistatic - before;
    // The version for processors without AVX2 says the same.
    const InsphereBatch portable =
        detail::insphere_static_across_facets_portable(points.data(), v, apex, tests, e, bound);
    EXPECT_EQ(portable.positive, batch.positive) << "round " << round;
    EXPECT_EQ(portable.undecided, batch.undecided) << "round " << round;
    unsigned decided = 0;
    for (unsigned i = 0; i < 4; ++i) {
      if (!(tests & (1u << i))) continue;
      ++counts.tests;
      const auto& rows = kAcrossFacetRows[i];
      const Vec3 &a = points[v[rows[0]]], &b = points[v[rows[1]]], &c = points[v[rows[2]]], &d = points[apex[i]];
      const int expected = scalar_static(a, b, c, d, e, bound);
      const bool undecided = (batch.undecided >> i) & 1u, positive = (batch.positive >> i) & 1u;
      EXPECT_EQ(undecided, expected == 0) << "round " << round << " test " << i;
      if (expected == 0) {
        ++counts.undecided;
        continue;
      }
      ++decided;
      EXPECT_EQ(positive, expected > 0) << "round " << round << " test " << i;
      EXPECT_EQ(insphere(a, b, c, d, e), positive ? Sign::Positive : Sign::Negative)
          << "round " << round << " test " << i;
      // The rows list the neighbour positive when its apex is across the facet from v_i.
      if (orient3d(a, b, c, points[v[i]]) != Sign::Zero) {
        EXPECT_EQ(orient3d(a, b, c, points[v[i]]), Sign::Negative) << "round " << round << " test " << i;
      }
    }
    EXPECT_EQ((batch.positive | batch.undecided) & ~tests, 0u) << "bits of tests not asked for";
    EXPECT_EQ(counted, decided);
  }
  return counts;
}

// What the scalar static orientation test says: +1 / -1 decided, 0 undecided.
int scalar_static_orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double bound) {
  const double det = stage::orient3d_det_translated(b.x - a.x, b.y - a.y, b.z - a.z, c.x - a.x, c.y - a.y,
                                                    c.z - a.z, d.x - a.x, d.y - a.y, d.z - a.z);
  return det > bound ? 1 : (det < -bound ? -1 : 0);
}

// Random positive tetrahedra and query points, every subset of the four facets; how many tests
// there were and how many the batches left undecided.
Counts check_orient_batches(const std::vector<Vec3>& points, double bound, std::mt19937_64& rng, int rounds) {
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(points.size() - 1));
  Counts counts;
  for (int round = 0; round < rounds; ++round) {
    std::array<std::uint32_t, 4> v;
    for (std::uint32_t& x : v) x = pick(rng);
    if (orient3d(points[v[0]], points[v[1]], points[v[2]], points[v[3]]) != Sign::Positive) std::swap(v[2], v[3]);
    const unsigned tests = 1 + round % 15;
    const Vec3& e = points[pick(rng)];
    const std::uint64_t before = predicate_stats()[Predicate::Orient3d].semistatic;
    const OrientBatch batch = orient3d_static_facets(points.data(), v, tests, e, bound);
    const std::uint64_t counted = predicate_stats()[Predicate::Orient3d].semistatic - before;
    const OrientBatch portable = detail::orient3d_static_facets_portable(points.data(), v, tests, e, bound);
    EXPECT_EQ(portable.negative, batch.negative) << "round " << round;
    EXPECT_EQ(portable.undecided, batch.undecided) << "round " << round;
    unsigned decided = 0;
    for (unsigned i = 0; i < 4; ++i) {
      if (!(tests & (1u << i))) continue;
      ++counts.tests;
      const auto& rows = kFacetRows[i];
      const Vec3 &a = points[v[rows[0]]], &b = points[v[rows[1]]], &c = points[v[rows[2]]];
      const int expected = scalar_static_orient(a, b, c, e, bound);
      EXPECT_EQ(((batch.undecided >> i) & 1u) != 0, expected == 0) << "round " << round << " facet " << i;
      if (expected == 0) {
        ++counts.undecided;
        continue;
      }
      ++decided;
      const bool negative = (batch.negative >> i) & 1u;
      EXPECT_EQ(negative, expected < 0) << "round " << round << " facet " << i;
      EXPECT_EQ(orient3d(a, b, c, e), negative ? Sign::Negative : Sign::Positive) << "round " << round;
      // The facet listed so that it and its opposite vertex make a positive tetrahedron.
      if (orient3d(a, b, c, points[v[i]]) != Sign::Zero) {
        EXPECT_EQ(orient3d(a, b, c, points[v[i]]), Sign::Positive) << "round " << round << " facet " << i;
      }
    }
    EXPECT_EQ((batch.negative | batch.undecided) & ~tests, 0u) << "bits of tests not asked for";
    EXPECT_EQ(counted, decided);
  }
  return counts;
}

TEST(OrientBatch, EqualsTheScalarStaticFilter) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points(64);
  for (Vec3& p : points) p = {u(rng), u(rng), u(rng)};
  const Counts random = check_orient_batches(points, static_bounds3(points).orient3d, rng, 4000);
  EXPECT_LT(random.undecided, random.tests / 4);
  // A 3 x 3 x 3 grid: many coplanar quadruples, which must come out undecided.
  std::vector<Vec3> grid;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) grid.push_back({double(x), double(y), double(z)});
  EXPECT_GT(check_orient_batches(grid, static_bounds3(grid).orient3d, rng, 4000).undecided, 500);
  const Counts unbounded = check_orient_batches(points, stage::kNoStaticBound, rng, 100);
  EXPECT_EQ(unbounded.undecided, unbounded.tests);
}

TEST(InsphereBatch, EqualsTheScalarStaticFilterOnRandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points(64);
  for (Vec3& p : points) p = {u(rng), u(rng), u(rng)};
  const StaticBounds3 bounds = static_bounds3(points);
  // (random picks repeat points or take e among them now and then: those tests are zero)
  const Counts counts = check_batches(points, bounds.insphere, rng, 4000);
  EXPECT_LT(counts.undecided, counts.tests / 4);
}

// Points on a sphere and on a small grid: many tests the static bound cannot decide, and exact
// zeros, which must come out undecided.
TEST(InsphereBatch, LeavesNearDegenerateTestsUndecided) {
  std::mt19937_64 rng(11);
  std::vector<Vec3> points;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) points.push_back({double(x), double(y), double(z)});
  std::normal_distribution<double> g;
  for (int k = 0; k < 27; ++k) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    points.push_back({1 + v.x / n, 1 + v.y / n, 1 + v.z / n});
  }
  const StaticBounds3 bounds = static_bounds3(points);
  EXPECT_GT(check_batches(points, bounds.insphere, rng, 4000).undecided, 500);
  // Without a static bound nothing is decided.
  const Counts unbounded = check_batches(points, stage::kNoStaticBound, rng, 100);
  EXPECT_EQ(unbounded.undecided, unbounded.tests);
}

}  // namespace
}  // namespace dtlab
