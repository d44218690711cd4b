// The "sweep" 2D Delaunay variant (radial sweep-hull + Lawson flips): on every input, degenerate
// ones included, exactly the triangles of "incremental", and a valid Delaunay triangulation by the
// exact checkers of verify/checks2d.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/sweep_order.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

std::vector<TriangleIds> triangles_of(const Delaunay2dResult& r) { return r.triangulation.finite_triangles(); }

// Sweep and incremental give the same triangles, the sweep's pass every exact check, and its
// structure is closed. Returns the number of finite triangles.
std::size_t expect_same_as_incremental(const std::vector<Vec2>& P, const std::string& what) {
  const Delaunay2dResult s = delaunay2d(P, {.algorithm = "sweep"});
  const Delaunay2dResult i = delaunay2d(P, {.algorithm = "incremental"});
  EXPECT_EQ(s.degenerate_message, i.degenerate_message) << what;
  EXPECT_EQ(s.duplicates, i.duplicates) << what;
  EXPECT_NO_THROW(s.triangulation.check_topology()) << what;
  const auto st = triangles_of(s);
  EXPECT_TRUE(canonical_triangle_set(st) == canonical_triangle_set(triangles_of(i))) << what;
  if (s.degenerate_message.empty()) {
    const CheckReport2 report = verify_delaunay2d(P, st, s.duplicates);
    EXPECT_TRUE(report.ok) << what << ": " << to_text(report);
  }
  EXPECT_EQ(s.triangulation.points().size(), P.size());
  for (std::size_t k = 0; k < P.size(); ++k) {
    if (!(s.triangulation.points()[k] == P[k])) {
      ADD_FAILURE() << what << ": point " << k << " not restored";
      break;
    }
  }
  return st.size();
}

std::vector<Vec2> grid(int side) {
  std::vector<Vec2> P;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) P.push_back({static_cast<double>(i), static_cast<double>(j)});
  return P;
}

std::vector<Vec2> pythagorean_circle(std::int64_t R) {
  std::vector<Vec2> P;
  for (std::int64_t x = -R; x <= R; ++x)
    for (std::int64_t y = -R; y <= R; ++y)
      if (x * x + y * y == R * R) P.push_back({static_cast<double>(x), static_cast<double>(y)});
  return P;
}

std::vector<std::uint32_t> all_ids(std::size_t n) {
  std::vector<std::uint32_t> ids(n);
  for (std::size_t k = 0; k < n; ++k) ids[k] = static_cast<std::uint32_t>(k);
  return ids;
}

TEST(Delaunay2dSweep, HandCases) {
  const std::vector<std::vector<Vec2>> cases = {
      {{0, 0}, {1, 0}, {0, 1}},                                  // one triangle
      {{0, 0}, {0, 1}, {1, 0}},                                  // given clockwise
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                          // square: 4 cocircular
      {{0, 0}, {2, 0}, {1, 1}, {1, 3}, {1, -2}},                 // two fans
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}},                  // collinear hull edge
      {{0, 0}, {4, 0}, {2, 0}, {1, 0}, {3, 0}, {2, 5}, {2, -5}},  // points on an interior edge
      {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4},
       {4, 3}, {-4, 3}, {4, -3}, {-4, -3}, {0, 0}},               // 12 exactly cocircular + centre
      {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}},          // vertical run, one apex
      {{0, 0}, {1, 1}, {2, 2}, {-1, -1}, {-2, -2}, {0, 1}},      // diagonal run through the centre
  };
  for (std::size_t k = 0; k < cases.size(); ++k) expect_same_as_incremental(cases[k], "case " + std::to_string(k));
}

TEST(Delaunay2dSweep, FourCocircularPointsInEveryOrder) {
  std::vector<Vec2> P = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  std::vector<std::size_t> perm = {0, 1, 2, 3};
  do {
    std::vector<Vec2> Q;
    for (std::size_t k : perm) Q.push_back(P[k]);
    EXPECT_EQ(expect_same_as_incremental(Q, "square"), 2u);
  } while (std::next_permutation(perm.begin(), perm.end()));
}

TEST(Delaunay2dSweep, Grids) {
  for (const int side : {10, 100, 300})
    EXPECT_EQ(expect_same_as_incremental(grid(side), "grid " + std::to_string(side)),
              2u * (side - 1) * (side - 1));
}

// All integer points on x^2 + y^2 = 1105^2 (1105 = 5 * 13 * 17 has many representations), with
// and without the centre, and shifted so that the bounding box is not centred on the circle.
TEST(Delaunay2dSweep, PointsOnAnExactCircle) {
  std::vector<Vec2> P = pythagorean_circle(1105);
  ASSERT_GT(P.size(), 20u);
  EXPECT_EQ(expect_same_as_incremental(P, "exact circle"), P.size() - 2);
  std::vector<Vec2> half;  // the upper half: the bounding box's centre is off the circle's
  for (const Vec2& p : P)
    if (p.y >= 0) half.push_back(p);
  EXPECT_EQ(expect_same_as_incremental(half, "upper half circle"), half.size() - 2);
  P.push_back({0, 0});
  expect_same_as_incremental(P, "exact circle and centre");
}

TEST(Delaunay2dSweep, GeneratedDistributions) {
  struct Case {
    const char* name;
    std::size_t n;
  };
  // collinear is the sweep's slow case (see sweep.cpp): kept small.
  for (const Case c : {Case{"uniform", 20000}, Case{"normal", 20000}, Case{"grid", 20000}, Case{"circle", 20000},
                       Case{"exact_circle", 20000}, Case{"clustered", 20000}, Case{"collinear", 10000},
                       Case{"duplicates", 20000}, Case{"scaled_small", 20000}, Case{"scaled_large", 20000},
                       Case{"multiscale", 20000}, Case{"translated", 20000}})
    for (std::uint64_t seed : {1u, 2u})
      expect_same_as_incremental(generate_points2d(c.name, c.n, seed),
                                 std::string(c.name) + " seed " + std::to_string(seed));
}

// Collinear runs plus a few points off the line; the run through the bounding box's centre makes
// the first points of the sweep collinear (the fan start).
TEST(Delaunay2dSweep, CollinearRunsWithOffLinePoints) {
  std::vector<Vec2> P;
  for (int k = -200; k <= 200; ++k) P.push_back({static_cast<double>(k), 3.0 * k + 1});
  P.push_back({5, -300});
  P.push_back({-7, 400});
  P.push_back({100, 0});
  expect_same_as_incremental(P, "one line");
  for (int k = 0; k < 100; ++k) P.push_back({0.5, static_cast<double>(k)});  // a vertical run
  expect_same_as_incremental(P, "two lines");
  std::vector<Vec2> Q;
  for (int k = -100; k <= 100; ++k) Q.push_back({0, static_cast<double>(k)});
  Q.push_back({1e-9, 0.5});
  expect_same_as_incremental(Q, "vertical run and one near point");
}

TEST(Delaunay2dSweep, DegenerateInputsGiveTheSameMessage) {
  std::vector<Vec2> line;
  for (int k = 0; k < 30; ++k) line.push_back({1.0 + 3 * k, -2.0 + 7 * k});
  expect_same_as_incremental(line, "collinear");
  expect_same_as_incremental({{1, 1}, {2, 2}, {1, 1}}, "two distinct");
  expect_same_as_incremental({}, "empty");
}

TEST(Delaunay2dSweep, Random100k) {
  expect_same_as_incremental(generate_points2d("uniform", 100000, 7), "uniform 1e5");
}

// The hull search on near-cocircular points, where the hull holds nearly every point (a one-way
// walk from a fixed-size angle hash took over 600 s at 10^6), and exactly cocircular points off
// the bounding box's middle (quadratic in flips before the centre was the circle's).
TEST(Delaunay2dSweep, LargeCircles) {
  expect_same_as_incremental(generate_points2d("circle", 200000, 3), "circle 2e5");
  expect_same_as_incremental(generate_points2d("exact_circle", 100000, 3), "exact_circle 1e5");
}

TEST(SweepOrder, ExactDistanceOrderWithNearTies) {
  // Squared distances to the origin, exactly: A = C = 1 + 2^-51 + 2^-104, B = D = A + 2^-104. The
  // rounded keys are all equal (1 + 2^-51); the exact order puts A and C first, each tie by (x, y).
  const double e = 0x1p-52;
  const std::vector<Vec2> P = {{e, -(1 + e)}, {1 + e, -e}, {1 + e, 0}, {-(1 + e), 0}};  // B, D, A, C
  const std::vector<std::uint32_t> ids = {0, 1, 2, 3};
  EXPECT_EQ(radial_sweep_order(P, ids, {0, 0}), (std::vector<std::uint32_t>{3, 2, 0, 1}));
  EXPECT_TRUE(bounding_box_middle(P, ids) == (Vec2{0, -(1 + e) / 2}));
}

// On an exact circle whose centre is a pair of doubles the sweep centre is that centre exactly,
// wherever the bounding box's middle is: every point then ties (see sweep_order.hpp).
TEST(SweepOrder, CentreOfAnExactCircleIsExact) {
  std::vector<Vec2> P;
  for (const Vec2& p : pythagorean_circle(1105))
    if (p.x > -600 && p.y < 900) P.push_back({p.x + 0.5, p.y - 3.25});
  const auto ids = all_ids(P.size());
  EXPECT_FALSE(bounding_box_middle(P, ids) == (Vec2{0.5, -3.25}));
  EXPECT_TRUE(sweep_center(P, ids) == (Vec2{0.5, -3.25}));
  Vec2 c;
  EXPECT_TRUE(rounded_circumcenter({0, 0}, {3, 0}, {0, 1}, c));
  EXPECT_TRUE(c == (Vec2{1.5, 0.5}));
  EXPECT_TRUE(rounded_circumcenter({0, 0}, {1, 0}, {0, 3}, c));  // (1/2, 3/2): exact
  EXPECT_TRUE(c == (Vec2{0.5, 1.5}));
  EXPECT_TRUE(rounded_circumcenter({0, 0}, {3, 0}, {1, 1}, c));  // (3/2, -1/2)
  EXPECT_TRUE(c == (Vec2{1.5, -0.5}));
  EXPECT_TRUE(rounded_circumcenter({0, 0}, {2, 0}, {1, 3}, c));  // (1, 4/3): rounded to nearest
  EXPECT_TRUE(c == (Vec2{1, 4.0 / 3.0}));
  EXPECT_FALSE(rounded_circumcenter({0, 0}, {1, 1}, {3, 3}, c));
}

// A seed triangle whose circumcentre lies outside the bounding box leaves the box's middle.
TEST(SweepOrder, FarCircumcentreFallsBackToTheMiddle) {
  const std::vector<Vec2> P = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {2.5, 0.002}};
  const auto ids = all_ids(P.size());
  EXPECT_TRUE(sweep_center(P, ids) == bounding_box_middle(P, ids));
  EXPECT_TRUE(bounding_box_middle(P, ids) == (Vec2{2, 0.001}));
}

// Small inputs on a coarse integer grid: full of duplicates, collinear and cocircular subsets.
RC_GTEST_PROP(Delaunay2dSweep, SmallDegenerateInputsMatchIncremental, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 60);
  const int half = *rc::gen::inRange(1, 6);
  std::vector<Vec2> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({static_cast<double>(*rc::gen::inRange(-half, half + 1)),
                 static_cast<double>(*rc::gen::inRange(-half, half + 1))});
  const auto s = delaunay2d(P, {.algorithm = "sweep"});
  const auto i = delaunay2d(P, {.algorithm = "incremental"});
  RC_ASSERT(s.degenerate_message == i.degenerate_message);
  RC_ASSERT(canonical_triangle_set(triangles_of(s)) == canonical_triangle_set(triangles_of(i)));
  if (s.degenerate_message.empty()) RC_ASSERT(verify_delaunay2d(P, triangles_of(s), s.duplicates).ok);
}

}  // namespace
}  // namespace dtlab
