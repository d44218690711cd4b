// The static filter (kernel/predicates/static_filter.hpp): its bounds are never below the
// semi-static bound of any call on the set, so the bounded predicates give the same sign as the
// unbounded ones and as the rational reference, on random, near-degenerate and exactly
// degenerate sets at every scale and far from the origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel/predicates.hpp"
#include "kernel/predicates/static_filter.hpp"
#include "verify/exact_reference.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace dtlab {
namespace {

// The semi-static bounds of one call, as semistatic.hpp computes them.
double orient3d_semistatic_bound(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 r[3] = {b - a, c - a, d - a};
  double mx = 0, my = 0, mz = 0;
  for (const Vec3& v : r) mx = std::max(mx, std::fabs(v.x)), my = std::max(my, std::fabs(v.y)), mz = std::max(mz, std::fabs(v.z));
  return stage::semistatic_bound::kOrient3d * mx * my * mz;
}
double insphere_semistatic_bound(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  const Vec3 r[4] = {a - e, b - e, c - e, d - e};
  double m = 0;
  for (const Vec3& v : r) m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  const double m2 = m * m;
  return stage::semistatic_bound::kInsphere * m2 * m2 * m;
}

// Calls on `points` with `draws` random choices of five distinct operands (the perturbation
// needs distinct points).
void check_set(std::vector<Vec3> points, gen::Rng& rng, int draws, const std::string& what) {
  // (scaling to the extremes of the range may merge points)
  std::sort(points.begin(), points.end(), [](const Vec3& p, const Vec3& q) {
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  ASSERT_GE(points.size(), 10u) << what;
  const StaticBounds3 bounds = static_bounds3(points);
  const std::int64_t n = static_cast<std::int64_t>(points.size());
  for (int k = 0; k < draws; ++k) {
    // Five distinct indices: a partial Fisher-Yates shuffle of the first five.
    std::vector<std::size_t> order(points.size());
    for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
    for (std::int64_t j = 0; j < 5; ++j) std::swap(order[j], order[gen::integer(rng, j, n - 1)]);
    const std::size_t* i = order.data();
    const Vec3 &a = points[i[0]], &b = points[i[1]], &c = points[i[2]], &d = points[i[3]], &e = points[i[4]];
    ASSERT_GE(bounds.orient3d, orient3d_semistatic_bound(a, b, c, d)) << what;
    ASSERT_GE(bounds.insphere, insphere_semistatic_bound(a, b, c, d, e)) << what;
    const Sign o = orient3d_bounded(a, b, c, d, bounds.orient3d);
    ASSERT_EQ(o, orient3d(a, b, c, d)) << what;
    ASSERT_EQ(o, reference::orient3d(a, b, c, d)) << what;
    const Sign s = insphere_perturbed_bounded(a, b, c, d, e, bounds.insphere);
    ASSERT_EQ(s, insphere_perturbed(a, b, c, d, e)) << what;
    ASSERT_EQ(s, reference::insphere_perturbed(a, b, c, d, e)) << what;
  }
}

TEST(StaticFilter, BoundedPredicatesAgreeWithTheReferenceOnEveryKindOfSet) {
  gen::Rng rng(gen::kDefaultSeed);
  struct Set {
    std::string name;
    std::vector<Vec3> points;
  };
  std::vector<Set> sets = {
      {"uniform", gen::uniform_box(rng, 40, {0, 0, 0}, {1, 1, 1})},
      {"flat box", gen::uniform_box(rng, 40, {0, 0, 0}, {1e3, 1e3, 1e-6})},
      {"coplanar", gen::exact_coplanar3(rng, 40)},
      {"collinear", gen::exact_collinear3(rng, 40)},
      {"cospherical", gen::exact_cospherical3(rng, 40)},
      {"near coplanar", gen::near_coplanar3(rng, 40, 4)},
      {"near cospherical", gen::near_cospherical3(rng, 40, 4)},
  };
  for (const Set& s : sets) {
    check_set(s.points, rng, 400, s.name);
    check_set(gen::scaled(s.points, gen::kLargeExponent), rng, 200, s.name + ", large");
    // (2^-90: the unit-box sets scaled by kSmallExponent would fall below the supported range)
    check_set(gen::scaled(s.points, -90), rng, 200, s.name + ", small");
    check_set(gen::translated(s.points, {gen::kFarOffset, gen::kFarOffset, gen::kFarOffset}), rng, 200,
              s.name + ", far");
  }
}

// The bound decides most calls on well-spread points: it is a filter, not a formality.
TEST(StaticFilter, DecidesMostCallsOnUniformPoints) {
  gen::Rng rng(7);
  const std::vector<Vec3> points = gen::uniform_box(rng, 1000, {0, 0, 0}, {1, 1, 1});
  const StaticBounds3 bounds = static_bounds3(points);
  int decided = 0;
  for (int k = 0; k < 1000; ++k) {
    const Vec3& a = points[k % 1000];
    const Vec3& b = points[(k * 7 + 1) % 1000];
    const Vec3& c = points[(k * 13 + 2) % 1000];
    const Vec3& d = points[(k * 31 + 3) % 1000];
    decided += stage::orient3d_semistatic_bounded(a, b, c, d, bounds.orient3d).has_value() &&
               std::fabs(((b - a).x * ((c - a).y * (d - a).z - (c - a).z * (d - a).y) -
                          (c - a).x * ((b - a).y * (d - a).z - (b - a).z * (d - a).y)) +
                         (d - a).x * ((b - a).y * (c - a).z - (b - a).z * (c - a).y)) > bounds.orient3d;
  }
  EXPECT_GT(decided, 900);
}

TEST(StaticFilter, EmptySetHasNoBound) {
  const StaticBounds3 none = static_bounds3({});
  EXPECT_TRUE(std::isinf(none.orient3d));
  EXPECT_TRUE(std::isinf(none.insphere));
}

}  // namespace
}  // namespace dtlab
