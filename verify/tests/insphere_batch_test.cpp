// The batched static in-sphere filter (kernel/predicates/insphere_batch.hpp) against the scalar
// filter it must equal lane for lane: a lane decides exactly when insphere_semistatic_bounded's
// static test does, with the same sign, and the exact predicate agrees with every decided lane.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "kernel/predicates.hpp"
#include "kernel/predicates/insphere_batch.hpp"
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

// Returns how many tests the batches left undecided.
int check_batches(const std::vector<Vec3>& points, double bound, std::mt19937_64& rng, int rounds) {
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(points.size() - 1));
  int undecided_count = 0;
  for (int round = 0; round < rounds; ++round) {
    const unsigned count = 1 + round % 4;
    std::array<std::array<std::uint32_t, 4>, 4> ids;
    std::array<const std::uint32_t*, 4> tests;
    for (unsigned k = 0; k < count; ++k) {
      for (std::uint32_t& v : ids[k]) v = pick(rng);
      tests[k] = ids[k].data();
    }
    const Vec3& e = points[pick(rng)];
    const std::uint64_t before = predicate_stats()[Predicate::Insphere].semistatic;
    const InsphereBatch batch = insphere_static_batch(points.data(), tests.data(), count, e, bound);
    const std::uint64_t counted = predicate_stats()[Predicate::Insphere].semistatic - before;
    unsigned decided = 0;
    for (unsigned k = 0; k < count; ++k) {
      const auto& q = ids[k];
      const int expected = scalar_static(points[q[0]], points[q[1]], points[q[2]], points[q[3]], e, bound);
      const bool undecided = (batch.undecided >> k) & 1u, positive = (batch.positive >> k) & 1u;
      EXPECT_EQ(undecided, expected == 0) << "round " << round << " lane " << k;
      if (expected == 0) {
        ++undecided_count;
        continue;
      }
      ++decided;
      EXPECT_EQ(positive, expected > 0) << "round " << round << " lane " << k;
      EXPECT_EQ(insphere(points[q[0]], points[q[1]], points[q[2]], points[q[3]], e),
                positive ? Sign::Positive : Sign::Negative)
          << "round " << round << " lane " << k;
    }
    EXPECT_EQ((batch.positive | batch.undecided) >> count, 0u) << "bits beyond the tests";
    EXPECT_EQ(counted, decided);
  }
  return undecided_count;
}

TEST(InsphereBatch, EqualsTheScalarStaticFilterOnRandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points(64);
  for (Vec3& p : points) p = {u(rng), u(rng), u(rng)};
  const StaticBounds3 bounds = static_bounds3(points);
  // (random picks repeat points or take e among them now and then: those tests are zero)
  EXPECT_LT(check_batches(points, bounds.insphere, rng, 4000), 3000);
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
  EXPECT_GT(check_batches(points, bounds.insphere, rng, 4000), 500);
  // Without a static bound nothing is decided.
  EXPECT_EQ(check_batches(points, stage::kNoStaticBound, rng, 100), 250);
}

}  // namespace
}  // namespace dtlab
