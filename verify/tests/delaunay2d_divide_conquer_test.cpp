// The "divide-conquer" 2D Delaunay variant against "incremental": the same set of triangles on
// every input (the perturbed Delaunay triangulation is unique), and a valid Delaunay
// triangulation by the exact checkers of verify/checks2d. The inputs aim at the merge's traps:
// halves that are all collinear (grid columns and rows cut by both axes), collinear hull runs on
// the common tangents, cocircular sets everywhere, duplicates, extreme scales.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/points2d.hpp"

namespace dtlab {
namespace {

constexpr const char* kVariant = "divide-conquer";

std::vector<TriangleIds> triangles_of(const Delaunay2dResult& r) {
  const auto t = r.triangulation.finite_triangles();
  return {t.begin(), t.end()};
}

// Empty if the variant's output is valid and equal to incremental's, else what differs.
std::string compare_with_incremental(const std::vector<Vec2>& points) {
  const Delaunay2dResult mine = delaunay2d(points, {.algorithm = kVariant});
  const Delaunay2dResult reference = delaunay2d(points, {.algorithm = "incremental"});
  if (mine.degenerate_message != reference.degenerate_message) return "degenerate messages differ";
  if (mine.duplicates != reference.duplicates) return "duplicates differ";
  const auto out = mine.triangulation.points();
  if (!std::equal(out.begin(), out.end(), points.begin(), points.end(),
                  [](const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }))
    return "points not restored to the input";
  if (!mine.degenerate_message.empty()) {
    return mine.triangulation.triangle_count() == 0 ? "" : "triangles on degenerate input";
  }
  try {
    mine.triangulation.check_topology();
  } catch (const InternalError& e) {
    return e.what();
  }
  const std::vector<TriangleIds> tris = triangles_of(mine);
  if (canonical_triangle_set(tris) != canonical_triangle_set(triangles_of(reference)))
    return "triangle sets differ (" + std::to_string(tris.size()) + " vs " +
           std::to_string(reference.triangulation.finite_triangle_count()) + ")";
  const CheckReport2 report = verify_delaunay2d(points, tris, mine.duplicates);
  if (!report.ok) return to_text(report).substr(0, 2000);
  return "";
}

std::vector<Vec2> grid(int columns, int rows, double step = 1.0) {
  std::vector<Vec2> P;
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < rows; ++j) P.push_back({i * step, j * step});
  return P;
}

// Brute force, independent of any structure: every counter-clockwise triple of distinct points
// whose perturbed circle holds none of the others, as a canonical set.
std::vector<TriangleIds> brute_force(const std::vector<Vec2>& P) {
  std::vector<TriangleIds> out;
  const auto n = static_cast<std::uint32_t>(P.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = a + 1; c < n; ++c) {
        if (b == c || orient2d(P[a], P[b], P[c]) != Sign::Positive) continue;
        bool empty = true;
        for (std::uint32_t d = 0; d < n && empty; ++d)
          if (d != a && d != b && d != c && incircle_perturbed(P[a], P[b], P[c], P[d]) == Sign::Positive)
            empty = false;
        if (empty) out.push_back({a, b, c});
      }
  return canonical_triangle_set(out);
}

TEST(Delaunay2dDivideConquer, HandCasesMatchBruteForce) {
  const std::vector<std::vector<Vec2>> cases = {
      {{0, 0}, {1, 0}, {0, 1}},                                   // one triangle
      {{0, 0}, {0, 1}, {1, 0}},                                   // given clockwise
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                           // square: 4 cocircular
      {{0, 0}, {2, 0}, {1, 1}, {1, 3}, {1, -2}},                  // two fans
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}},                   // collinear hull edge
      {{0, 0}, {4, 0}, {2, 0}, {1, 0}, {3, 0}, {2, 5}, {2, -5}},  // points on an interior edge
      {{0, 0}, {0, 1}, {0, 2}, {1, 0}},                           // column then a point: tangent on the column
      {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 0}},           // all of the left half on x = 0
      {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}, {-1, 7}},  // a column, then a point above-left of it
      {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {3, 0}},           // collinear bottom bridge
      {{0, 0}, {1, 0}, {0, 1}, {2, 1}, {2, 2}, {3, 0}},           // bridge descends in the right half
      {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4},
       {4, 3}, {-4, 3}, {4, -3}, {-4, -3}, {0, 0}},                // 12 exactly cocircular + centre
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& P = cases[k];
    EXPECT_EQ(compare_with_incremental(P), "") << "case " << k;
    const auto r = delaunay2d(P, {.algorithm = kVariant});
    EXPECT_EQ(canonical_triangle_set(triangles_of(r)), brute_force(P)) << "case " << k;
  }
}

TEST(Delaunay2dDivideConquer, FourCocircular) {
  // Several squares and a rectangle, in every input order: the tie is always broken the same way.
  std::vector<Vec2> P = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  std::sort(P.begin(), P.end(), [](const Vec2& a, const Vec2& b) { return a < b; });
  do {
    EXPECT_EQ(compare_with_incremental(P), "");
  } while (std::next_permutation(P.begin(), P.end(), [](const Vec2& a, const Vec2& b) { return a < b; }));
}

TEST(Delaunay2dDivideConquer, Grids) {
  for (const auto& [c, r] : std::vector<std::pair<int, int>>{
           {10, 10}, {100, 100}, {300, 300}, {2, 2}, {2, 50}, {50, 2}, {3, 1000}, {1000, 3}, {7, 13}}) {
    const auto P = grid(c, r);
    EXPECT_EQ(compare_with_incremental(P), "") << c << " x " << r;
  }
}

TEST(Delaunay2dDivideConquer, ColumnsAndRowsWithAFewPointsOff) {
  // One long collinear run: every half at the bottom of the recursion is collinear.
  for (int n : {3, 4, 5, 7, 8, 16, 33, 1000}) {
    for (const Vec2 off : {Vec2{1, 0}, Vec2{-1, 0}, Vec2{0.5, 1e9}, Vec2{1, 3.5}, Vec2{-2, -1}}) {
      std::vector<Vec2> column, row, diagonal;
      for (int k = 0; k < n; ++k) {
        column.push_back({0, static_cast<double>(k)});
        row.push_back({static_cast<double>(k), 0});
        diagonal.push_back({static_cast<double>(k), static_cast<double>(2 * k)});
      }
      column.push_back(off);
      row.push_back({off.y, off.x});
      diagonal.push_back(off);
      EXPECT_EQ(compare_with_incremental(column), "") << n << " column";
      EXPECT_EQ(compare_with_incremental(row), "") << n << " row";
      EXPECT_EQ(compare_with_incremental(diagonal), "") << n << " diagonal";
      // Two parallel runs, and a run with points on both sides.
      std::vector<Vec2> two = column, sides = column;
      for (int k = 0; k < n; ++k) two.push_back({3, static_cast<double>(k)});
      sides.push_back({-off.x, off.y});
      EXPECT_EQ(compare_with_incremental(two), "") << n << " two columns";
      EXPECT_EQ(compare_with_incremental(sides), "") << n << " sides";
    }
  }
}

TEST(Delaunay2dDivideConquer, ExactCircles) {
  // Integer points on x^2 + y^2 = 5^2 * 13^2 * 17^2 (many Pythagorean pairs), with and without
  // the centre.
  const long long R2 = 5LL * 5 * 13 * 13 * 17 * 17;
  std::vector<Vec2> P;
  for (long long x = -1105; x <= 1105; ++x) {
    const long long y2 = R2 - x * x;
    const auto y = static_cast<long long>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    P.push_back({static_cast<double>(x), static_cast<double>(y)});
    if (y != 0) P.push_back({static_cast<double>(x), static_cast<double>(-y)});
  }
  ASSERT_GT(P.size(), 40u);
  EXPECT_EQ(compare_with_incremental(P), "");
  P.push_back({0, 0});
  EXPECT_EQ(compare_with_incremental(P), "");
}

TEST(Delaunay2dDivideConquer, EveryGeneratorAtSeveralSizes) {
  for (const std::string& name : distribution_names2d())
    for (std::size_t n : {3u, 4u, 5u, 6u, 7u, 10u, 17u, 100u, 1000u, 20000u})
      for (std::uint64_t seed : {1u, 2u}) {
        const auto P = generate_points2d(name, n, seed);
        EXPECT_EQ(compare_with_incremental(P), "") << name << " n=" << n << " seed=" << seed;
      }
}

TEST(Delaunay2dDivideConquer, CollinearRunsPlusOffLinePoints) {
  auto P = generate_points2d("collinear", 5000, 9);
  const auto U = generate_points2d("uniform", 20, 9);
  for (const Vec2& u : U) P.push_back({u.x * 100, u.y * 100});
  EXPECT_EQ(compare_with_incremental(P), "");
}

TEST(Delaunay2dDivideConquer, ScaledAndTranslatedGrids) {
  for (const double scale : {1e-9, 1e9}) {
    auto P = grid(40, 40, scale);
    EXPECT_EQ(compare_with_incremental(P), "") << scale;
  }
  auto P = grid(40, 40);
  for (Vec2& p : P) p = {p.x + 1e9, p.y + 1e9};
  EXPECT_EQ(compare_with_incremental(P), "");
}

TEST(Delaunay2dDivideConquer, Random100k) {
  for (const char* name : {"uniform", "normal", "clustered"}) {
    const auto P = generate_points2d(name, 100000, 3);
    EXPECT_EQ(compare_with_incremental(P), "") << name;
  }
}

TEST(Delaunay2dDivideConquer, DegenerateInputGivesTheSameMessage) {
  std::vector<Vec2> P;
  for (int k = 0; k < 50; ++k) P.push_back({1.0 + 3 * k, -2.0 + 7 * k});
  EXPECT_EQ(compare_with_incremental(P), "");
  EXPECT_EQ(compare_with_incremental({{1, 1}, {1, 1}, {2, 2}}), "");
}

// Small inputs on a coarse integer grid (many duplicates, collinear and cocircular subsets).
RC_GTEST_PROP(Delaunay2dDivideConquer, SmallGridInputsMatchIncremental, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 60);
  const int half = *rc::gen::inRange(1, 6);
  std::vector<Vec2> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({static_cast<double>(*rc::gen::inRange(-half, half + 1)),
                 static_cast<double>(*rc::gen::inRange(-half, half + 1))});
  RC_ASSERT(compare_with_incremental(P) == "");
}

// Skewed integer lattices (a i + b j, c i + d j): collinear runs along many directions and
// cocircular sets, in random subsets, so that halves fall on lattice lines of every slope.
RC_GTEST_PROP(Delaunay2dDivideConquer, SkewedLatticeSubsetsMatchIncremental, ()) {
  const int a = *rc::gen::inRange(-3, 4), b = *rc::gen::inRange(-3, 4);
  const int c = *rc::gen::inRange(-3, 4), d = *rc::gen::inRange(-3, 4);
  const int side = *rc::gen::inRange(2, 25);
  const int keep = *rc::gen::inRange(30, 101);  // percent of lattice points kept
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  std::mt19937 rng(seed);
  std::vector<Vec2> P;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      if (static_cast<int>(rng() % 100) < keep)
        P.push_back({static_cast<double>(a * i + b * j), static_cast<double>(c * i + d * j)});
  RC_ASSERT(compare_with_incremental(P) == "");
}

}  // namespace
}  // namespace dtlab
