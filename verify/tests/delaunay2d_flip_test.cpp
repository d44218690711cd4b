// Tests of the "flip" 2D Delaunay variant (Lawson flips from a lexicographic fan sweep): the
// sweep alone gives a valid triangulation of the hull, Lawson's flips leave a Delaunay
// triangulation untouched, and the variant yields exactly the triangles of "incremental" and
// passes the exact checker on degenerate and random inputs.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/flip_lawson.hpp"
#include "algorithms/delaunay2d/flip_sweep.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "kernel/error.hpp"
#include "mesh/triangulation2.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

using T2 = Triangulation2;

// "flip" and "incremental" on the same points: the same message, or the same triangles, and
// those pass the exact checker. Returns the flip run's Lawson statistics.
LawsonFlipStats expect_same_as_incremental(const std::vector<Vec2>& P, const std::string& what) {
  const Delaunay2dResult f = delaunay2d(P, {.algorithm = "flip"});
  const LawsonFlipStats stats = last_lawson_flip2_stats();
  const Delaunay2dResult inc = delaunay2d(P, {.algorithm = "incremental"});
  EXPECT_EQ(f.degenerate_message, inc.degenerate_message) << what;
  EXPECT_EQ(f.duplicates, inc.duplicates) << what;
  if (!f.degenerate_message.empty()) {
    EXPECT_EQ(f.triangulation.triangle_count(), 0u) << what;
    return {};
  }
  EXPECT_NO_THROW(f.triangulation.check_topology()) << what;
  EXPECT_EQ(f.triangulation.triangle_count(), inc.triangulation.triangle_count()) << what;  // same hull
  const auto ft = f.triangulation.finite_triangles();
  const auto it = inc.triangulation.finite_triangles();
  EXPECT_TRUE(canonical_triangle_set(ft) == canonical_triangle_set(it)) << what << ": triangles differ";
  const CheckReport2 report = verify_delaunay2d(P, ft, f.duplicates);
  EXPECT_TRUE(report.ok) << what << ": " << to_text(report);
  EXPECT_TRUE(std::equal(P.begin(), P.end(), f.triangulation.points().begin(), f.triangulation.points().end()))
      << what << ": points not restored";
  const std::uint64_t m = P.size() - f.duplicates.size();
  EXPECT_LE(stats.flips, m * (m - 1) / 2) << what;
  return stats;
}

std::vector<Vec2> grid(int nx, int ny) {
  std::vector<Vec2> P;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) P.push_back({static_cast<double>(i), static_cast<double>(j)});
  return P;
}

// The sweep on its own, on lexicographically sorted distinct points: a triangulation of the
// hull (the checker's topology, orientation and hull coverage), with no in-circle test at all.
void expect_sweep_triangulates(std::vector<Vec2> P, const std::string& what) {
  std::sort(P.begin(), P.end());
  P.erase(std::unique(P.begin(), P.end()), P.end());
  const std::size_t m = P.size();
  T2 tri(P);
  tri.mutable_vertices().assign(3 * (2 * m - 2), T2::kNone);
  tri.mutable_neighbours().assign(3 * (2 * m - 2), T2::kNone);
  const PredicateStats before = predicate_stats();
  sweep_triangulate2(P.data(), m, tri.mutable_vertices().data(), tri.mutable_neighbours().data());
  EXPECT_EQ((predicate_stats() - before)[Predicate::Incircle].calls(), 0u) << what;
  EXPECT_NO_THROW(tri.check_topology()) << what;
  const auto t = tri.finite_triangles();
  CheckReport2 report = check_topology2(P, t);
  report.merge(check_orientation2(P, t));
  report.merge(check_hull_coverage2(P, t));
  report.merge(check_unreferenced(P, t, {}));
  EXPECT_TRUE(report.ok) << what << ": " << to_text(report);
}

TEST(Delaunay2dFlip, IsRegistered) {
  const Delaunay2dVariant* v = delaunay2d_variants().find("flip");
  ASSERT_NE(v, nullptr);
  EXPECT_NE(v->run, nullptr);
}

TEST(Delaunay2dFlip, SweepAloneTriangulatesTheHull) {
  expect_sweep_triangulates({{0, 0}, {1, 0}, {0, 1}}, "one triangle");
  expect_sweep_triangulates({{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 5}}, "vertical run, apex to the right");
  expect_sweep_triangulates({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 0}}, "run, apex below");
  expect_sweep_triangulates({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 9}, {5, 5}, {6, 6}}, "run, apex, run again");
  expect_sweep_triangulates(grid(10, 10), "grid: collinear hull sides and columns");
  expect_sweep_triangulates(grid(2, 50), "two columns");
  expect_sweep_triangulates(grid(50, 2), "two rows");
  for (const std::string& name : distribution_names2d())
    expect_sweep_triangulates(generate_points2d(name, 3000, 11), name);
}

TEST(Delaunay2dFlip, LawsonLeavesADelaunayTriangulationAlone) {
  const std::vector<Vec2> P = generate_points2d("grid", 2500, 3);  // cocircular everywhere
  Delaunay2dResult r = delaunay2d(P, {.algorithm = "incremental"});
  ASSERT_TRUE(r.degenerate_message.empty());
  const auto before = r.triangulation.vertices();
  const LawsonFlipStats s =
      lawson_flip2(r.triangulation.points().data(), P.size(), r.triangulation.mutable_vertices().data(),
                   r.triangulation.mutable_neighbours().data(), r.triangulation.triangle_count());
  EXPECT_EQ(s.flips, 0u);
  EXPECT_GT(s.edge_tests, P.size());
  EXPECT_EQ(r.triangulation.vertices(), before);
}

TEST(Delaunay2dFlip, HandCases) {
  const std::vector<std::vector<Vec2>> cases = {
      {{0, 0}, {1, 0}, {0, 1}},
      {{0, 0}, {0, 1}, {1, 0}},
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                          // square: 4 cocircular
      {{1, 0}, {0, 1}, {-1, 0}, {0, -1}},                        // diamond: 4 cocircular, run of one
      {{0, 0}, {2, 0}, {1, 1}, {1, 3}, {1, -2}},                 // two fans
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}},                  // collinear hull edge
      {{0, 0}, {4, 0}, {2, 0}, {1, 0}, {3, 0}, {2, 5}, {2, -5}},  // points on an interior edge
      {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4},
       {4, 3}, {-4, 3}, {4, -3}, {-4, -3}, {0, 0}},               // 12 exactly cocircular + centre
      {{0, 0}, {1, 0}, {2, 0}, {3, 1}, {4, 2}, {5, 3}},          // later points on a hull edge's line
  };
  for (std::size_t k = 0; k < cases.size(); ++k) expect_same_as_incremental(cases[k], "case " + std::to_string(k));
}

TEST(Delaunay2dFlip, Grids) {
  expect_same_as_incremental(grid(10, 10), "10x10");
  const LawsonFlipStats s = expect_same_as_incremental(grid(100, 100), "100x100");
  EXPECT_GT(s.flips, 0u);
  expect_same_as_incremental(grid(300, 300), "300x300");
  expect_same_as_incremental(grid(3, 400), "3x400");
  expect_same_as_incremental(grid(400, 3), "400x3");
}

TEST(Delaunay2dFlip, ExactlyCocircularPoints) {
  // Every integer point on x^2 + y^2 = (5 * 13 * 17)^2: Pythagorean points, exactly cocircular.
  const long long r = 5 * 13 * 17;
  std::vector<Vec2> P;
  for (long long x = -r; x <= r; ++x)
    for (long long y = -r; y <= r; ++y)
      if (x * x + y * y == r * r) P.push_back({static_cast<double>(x), static_cast<double>(y)});
  ASSERT_GT(P.size(), 20u);
  expect_same_as_incremental(P, "Pythagorean circle");
  P.push_back({0, 0});
  P.push_back({1, 2});
  expect_same_as_incremental(P, "Pythagorean circle and two inner points");
  expect_same_as_incremental(generate_points2d("exact_circle", 5000, 4), "exact_circle generator");
  expect_same_as_incremental(generate_points2d("circle", 20000, 5), "circle generator");
}

TEST(Delaunay2dFlip, CollinearRunsAndOffLinePoints) {
  std::vector<Vec2> P;
  for (int k = 0; k < 1000; ++k) P.push_back({1.0 + 3 * k, -2.0 + 7 * k});
  EXPECT_NE(delaunay2d(P, {.algorithm = "flip"}).degenerate_message.find("collinear"), std::string::npos);
  P.push_back({5, 100});
  expect_same_as_incremental(P, "a run and one point off it");
  P.push_back({2000, -50});
  P.push_back({-7, 3});
  expect_same_as_incremental(P, "a run and three points off it");
  std::vector<Vec2> Q;
  for (int k = 0; k < 500; ++k) Q.push_back({0.0, static_cast<double>(k)});  // vertical: the sweep's first run
  Q.push_back({-1, 250.5});
  expect_same_as_incremental(Q, "vertical run, off point first in the order");
  Q.push_back({1, 600});
  expect_same_as_incremental(Q, "vertical run, off points on both sides");
  expect_same_as_incremental(generate_points2d("collinear", 20000, 6), "collinear generator");
}

TEST(Delaunay2dFlip, GeneratedDistributions) {
  for (const char* name : {"clustered", "duplicates", "scaled_small", "scaled_large", "translated", "multiscale",
                           "normal", "grid"})
    expect_same_as_incremental(generate_points2d(name, 30000, 7), name);
}

TEST(Delaunay2dFlip, Random100k) {
  const LawsonFlipStats s = expect_same_as_incremental(generate_points2d("uniform", 100000, 8), "uniform 1e5");
  // The fan sweep is far from Delaunay (long thin fans at the hull), but not quadratic on
  // random input: flips stay within a small multiple of n.
  EXPECT_GT(s.flips, 100000u);
  EXPECT_LT(s.flips, 100u * 100000u);
  std::printf("uniform 1e5: %llu flips, %llu edge tests\n", static_cast<unsigned long long>(s.flips),
              static_cast<unsigned long long>(s.edge_tests));
}

// Small inputs on a coarse integer grid (cocircular and collinear subsets, duplicates):
// exactly the triangles of "incremental".
RC_GTEST_PROP(Delaunay2dFlip, SmallDegenerateInputsMatchIncremental, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 60);
  const int half = *rc::gen::inRange(1, 6);
  std::vector<Vec2> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({static_cast<double>(*rc::gen::inRange(-half, half + 1)),
                 static_cast<double>(*rc::gen::inRange(-half, half + 1))});
  const Delaunay2dResult f = delaunay2d(P, {.algorithm = "flip"});
  const Delaunay2dResult inc = delaunay2d(P, {.algorithm = "incremental"});
  RC_ASSERT(f.degenerate_message == inc.degenerate_message);
  if (!f.degenerate_message.empty()) return;
  f.triangulation.check_topology();
  const auto ft = f.triangulation.finite_triangles();
  RC_ASSERT(canonical_triangle_set(ft) == canonical_triangle_set(inc.triangulation.finite_triangles()));
  RC_ASSERT(verify_delaunay2d(P, ft, f.duplicates).ok);
}

}  // namespace
}  // namespace dtlab
