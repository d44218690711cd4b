// Tests of the 2D triangulation structure, spatial sort, element sets and the "incremental"
// Delaunay variant, with local exact checks (the full checkers live in verify/checks2d).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <set>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_sets2.hpp"
#include "mesh/triangulation2.hpp"

namespace dtlab {
namespace {

using T2 = Triangulation2;
using Tri = std::array<std::uint32_t, 3>;

Delaunay2dResult run(const std::vector<Vec2>& points) {
  return delaunay2d(points, {.algorithm = "incremental"});
}

// Rotated so the smallest id comes first: one name per counter-clockwise triangle.
Tri canonical(Tri t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

std::set<Tri> triangle_set(const T2& tri) {
  std::set<Tri> out;
  for (const Tri& t : tri.finite_triangles()) out.insert(canonical(t));
  return out;
}

// Triangles as coordinate triples, each rotated to start at its lexicographically least point.
std::set<std::array<double, 6>> geometric_set(const T2& tri) {
  std::set<std::array<double, 6>> out;
  const auto P = tri.points();
  for (const Tri& t : tri.finite_triangles()) {
    std::array<Vec2, 3> v = {P[t[0]], P[t[1]], P[t[2]]};
    std::rotate(v.begin(), std::min_element(v.begin(), v.end(), [](const Vec2& x, const Vec2& y) { return x < y; }),
                v.end());
    out.insert({v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y});
  }
  return out;
}

bool between(const Vec2& a, const Vec2& b, const Vec2& p) {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

// Does point d conflict with triangle t (perturbed in-circle; ghosts as triangulation2.hpp says)?
bool in_conflict(const T2& tri, std::uint32_t t, const Vec2& d) {
  const auto P = tri.points();
  if (tri.is_ghost(t)) {
    const Vec2& a = P[tri.vertex(t, 1)];
    const Vec2& b = P[tri.vertex(t, 2)];
    const Sign s = orient2d(a, b, d);
    return s == Sign::Positive || (s == Sign::Zero && between(a, b, d));
  }
  return incircle_perturbed(P[tri.vertex(t, 0)], P[tri.vertex(t, 1)], P[tri.vertex(t, 2)], d) == Sign::Positive;
}

// Topology, orientation, local Delaunay property on every edge (hull convexity through the
// ghosts), Euler's relation, and exactly the kept points used. Empty if all hold, else what broke.
std::string delaunay_violation(const Delaunay2dResult& r) {
  const T2& tri = r.triangulation;
  try {
    tri.check_topology();
  } catch (const InternalError& e) {
    return e.what();
  }
  const auto P = tri.points();
  std::vector<bool> used(P.size(), false);
  std::size_t ghosts = 0;
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    if (tri.is_ghost(t)) {
      ++ghosts;
    } else if (orient2d(P[tri.vertex(t, 0)], P[tri.vertex(t, 1)], P[tri.vertex(t, 2)]) != Sign::Positive) {
      return "triangle " + std::to_string(t) + " is not counter-clockwise";
    }
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t v = tri.vertex(t, i);
      if (v != T2::kInfinite) used[v] = true;
      const std::uint32_t d = tri.vertices()[tri.twin(3 * t + i)];  // opposite across edge i
      if (d != T2::kInfinite && in_conflict(tri, t, P[d]))
        return "edge " + std::to_string(i) + " of triangle " + std::to_string(t) + " is not locally Delaunay";
    }
  }
  std::size_t vertices = 0;
  for (bool u : used) vertices += u;
  if (vertices + r.duplicates.size() != P.size()) return "not every kept point is a vertex";
  for (std::uint32_t d : r.duplicates)
    if (used[d]) return "duplicate " + std::to_string(d) + " is referenced";
  // A triangulated convex polygon with h hull vertices: F = 2V - 2 - h, E = 3V - 3 - h.
  if (tri.finite_triangle_count() != 2 * vertices - 2 - ghosts) return "Euler: wrong number of triangles";
  if (edges(tri).size() != 3 * vertices - 3 - ghosts) return "Euler: wrong number of edges";
  if (tri.triangle_count() != 2 * vertices - 2) return "wrong number of ghosts";
  return "";
}

void expect_delaunay(const Delaunay2dResult& r) { EXPECT_EQ(delaunay_violation(r), ""); }

// Brute force, independent of any structure: every counter-clockwise triple of distinct points
// whose perturbed circle holds none of the others.
std::set<Tri> brute_force(const std::vector<Vec2>& P) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    bool first = true;
    for (std::uint32_t j = 0; j < i; ++j) first = first && !(P[j] == P[i]);
    if (first) ids.push_back(i);
  }
  std::set<Tri> out;
  for (std::uint32_t a : ids)
    for (std::uint32_t b : ids)
      for (std::uint32_t c : ids) {
        if (!(a < b && a < c) || b == c || orient2d(P[a], P[b], P[c]) != Sign::Positive) continue;
        bool empty = true;
        for (std::uint32_t d : ids)
          if (d != a && d != b && d != c && incircle_perturbed(P[a], P[b], P[c], P[d]) == Sign::Positive) empty = false;
        if (empty) out.insert({a, b, c});
      }
  return out;
}

TEST(Triangulation2, NavigationFollowsTheDrawing) {
  static_assert(T2::next(0) == 1 && T2::next(2) == 0 && T2::prev(0) == 2 && T2::prev(4) == 3);
  static_assert(T2::triangle_of(7) == 2 && T2::index_in_triangle(7) == 1 && T2::half_edge(2, 1) == 7);
  T2 tri({{0, 0}, {1, 0}, {0, 1}});
  EXPECT_EQ(tri.add_triangle(0, 1, 2), 0u);
  EXPECT_EQ(tri.origin(2), 0u);       // edge 2 runs v0 -> v1
  EXPECT_EQ(tri.destination(2), 1u);
  EXPECT_EQ(tri.origin(0), 1u);       // edge 0 runs v1 -> v2
  EXPECT_THROW(tri.check_topology(), InternalError);  // no twins yet
  EXPECT_EQ(tri.add_triangle(1, T2::kInfinite, 0), 1u);  // rotated: infinite vertex first
  EXPECT_EQ(tri.vertex(1, 0), T2::kInfinite);
  EXPECT_EQ(tri.vertex(1, 1), 0u);
  EXPECT_TRUE(tri.is_ghost(1));
}

TEST(Triangulation2, CheckTopologyCatchesBrokenTwins) {
  auto r = run({{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.3, 0.4}});
  ASSERT_NO_THROW(r.triangulation.check_topology());
  auto& n = r.triangulation.mutable_neighbours();
  std::swap(n[0], n[1]);
  EXPECT_THROW(r.triangulation.check_topology(), InternalError);
}

TEST(SpatialSort, HilbertIndexIsAContinuousCurve) {
  // The first 4^k cells of the curve fill the 2^k square at the origin, each next to the last.
  constexpr std::uint32_t side = 32;
  std::vector<std::array<std::uint32_t, 2>> cell(side * side);
  std::vector<bool> seen(side * side, false);
  for (std::uint32_t x = 0; x < side; ++x)
    for (std::uint32_t y = 0; y < side; ++y) {
      const std::uint32_t d = hilbert_index2(x, y);
      ASSERT_LT(d, side * side);
      ASSERT_FALSE(seen[d]);
      seen[d] = true;
      cell[d] = {x, y};
    }
  for (std::size_t d = 1; d < cell.size(); ++d) {
    const int dx = static_cast<int>(cell[d][0]) - static_cast<int>(cell[d - 1][0]);
    const int dy = static_cast<int>(cell[d][1]) - static_cast<int>(cell[d - 1][1]);
    EXPECT_EQ(std::abs(dx) + std::abs(dy), 1) << "at " << d;
  }
  EXPECT_EQ(hilbert_index2(0xFFFF, 0), 0xFFFFFFFFu);  // ends at the bottom-right corner
}

TEST(SpatialSort, SortGroupsDuplicatesAndBrioIsAPermutation) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(0, 30);
  std::vector<Vec2> P(5000);
  for (Vec2& p : P) p = {static_cast<double>(coord(rng)), coord(rng) * 1e-9};
  std::vector<std::uint32_t> ids(P.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  hilbert_sort(P, ids);
  std::set<std::pair<double, double>> closed;  // coordinates whose group has ended
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (k > 0 && P[ids[k]] == P[ids[k - 1]]) {
      EXPECT_LT(ids[k - 1], ids[k]);
      continue;
    }
    if (k > 0) closed.insert({P[ids[k - 1]].x, P[ids[k - 1]].y});
    EXPECT_FALSE(closed.count({P[ids[k]].x, P[ids[k]].y})) << "group split at " << k;
  }
  // Dropping duplicates on the way: the first index of each coordinate pair stays.
  std::map<std::pair<double, double>, std::uint32_t> first;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    const auto [it, fresh] = first.emplace(std::pair{P[i].x, P[i].y}, i);
    if (!fresh) expected.emplace_back(i, it->second);
  }
  std::vector<std::uint32_t> unique(P.size());
  for (std::uint32_t i = 0; i < unique.size(); ++i) unique[i] = i;
  EXPECT_EQ(hilbert_sort_unique(P, unique), expected);
  ASSERT_EQ(unique.size(), first.size());
  for (std::uint32_t id : unique) EXPECT_EQ(first.at({P[id].x, P[id].y}), id);
  const auto a = brio_order_of_sorted(ids, 42), b = brio_order_of_sorted(ids, 42), c = brio_order_of_sorted(ids, 43);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  auto sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
}

TEST(Delaunay2dIncremental, SingleTriangleComesOutCounterClockwise) {
  const auto r = run({{0, 0}, {0, 1}, {1, 0}});  // given clockwise
  ASSERT_TRUE(r.degenerate_message.empty());
  EXPECT_EQ(triangle_set(r.triangulation), (std::set<Tri>{{0, 2, 1}}));
  EXPECT_EQ(r.triangulation.triangle_count(), 4u);  // one finite, three ghosts
  expect_delaunay(r);
}

TEST(Delaunay2dIncremental, HandCasesMatchBruteForce) {
  const std::vector<std::vector<Vec2>> cases = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                          // square: 4 cocircular
      {{0, 0}, {2, 0}, {1, 1}, {1, 3}, {1, -2}},                 // two fans
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}},                  // collinear hull edge
      {{0, 0}, {4, 0}, {2, 0}, {1, 0}, {3, 0}, {2, 5}, {2, -5}},  // points on an interior edge
      {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4},
       {4, 3}, {-4, 3}, {4, -3}, {-4, -3}, {0, 0}},               // 12 exactly cocircular + centre
  };
  for (const auto& P : cases) {
    const auto r = run(P);
    ASSERT_TRUE(r.degenerate_message.empty());
    expect_delaunay(r);
    EXPECT_EQ(triangle_set(r.triangulation), brute_force(P));
  }
}

TEST(Delaunay2dIncremental, RegularGrid100x100) {
  std::vector<Vec2> P;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) P.push_back({static_cast<double>(i), static_cast<double>(j)});
  const auto r = run(P);
  expect_delaunay(r);
  EXPECT_EQ(r.triangulation.finite_triangle_count(), 2u * 99 * 99);
  EXPECT_GT(r.predicate_stats[Predicate::Incircle].perturbed, 0u);  // cocircular quads were met
}

TEST(Delaunay2dIncremental, PointsOnACircle) {
  std::vector<Vec2> P;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    P.push_back({std::cos(a), std::sin(a)});
  }
  const auto r = run(P);
  expect_delaunay(r);
  EXPECT_EQ(r.triangulation.finite_triangle_count(), static_cast<std::size_t>(n - 2));
}

TEST(Delaunay2dIncremental, ExactlyCocircularLatticePointsAndTheirCentre) {
  // x^2 + y^2 = (5*13*17*29)^2 has 324 integer solutions: exactly cocircular doubles. The centre
  // conflicts with every triangle present when it arrives: a cavity far above the usual size.
  const std::int64_t r = 5 * 13 * 17 * 29;
  std::vector<Vec2> P;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t y2 = r * r - x * x;
    const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    P.push_back({static_cast<double>(x), static_cast<double>(y)});
    if (y != 0) P.push_back({static_cast<double>(x), static_cast<double>(-y)});
  }
  ASSERT_EQ(P.size(), 324u);
  const auto ring = run(P);
  expect_delaunay(ring);
  EXPECT_EQ(ring.triangulation.finite_triangle_count(), P.size() - 2);
  P.push_back({0, 0});
  const auto r2 = run(P);
  expect_delaunay(r2);
  EXPECT_EQ(r2.triangulation.finite_triangle_count(), P.size() - 1);  // 2V - 2 - h, h = V - 1
}

TEST(Delaunay2dIncremental, CollinearInputGivesAMessage) {
  std::vector<Vec2> P;
  for (int k = 0; k < 50; ++k) P.push_back({1.0 + 3 * k, -2.0 + 7 * k});
  const auto r = run(P);
  EXPECT_NE(r.degenerate_message.find("collinear"), std::string::npos);
  EXPECT_EQ(r.triangulation.triangle_count(), 0u);
}

TEST(Delaunay2dIncremental, FewerThanThreeDistinctPoints) {
  for (const std::vector<Vec2>& P : std::vector<std::vector<Vec2>>{
           {}, {{1, 1}}, {{1, 1}, {2, 2}}, {{1, 1}, {2, 2}, {1, 1}, {2, 2}}}) {
    const auto r = run(P);
    EXPECT_NE(r.degenerate_message.find("fewer than 3 distinct"), std::string::npos) << P.size();
    EXPECT_EQ(r.triangulation.triangle_count(), 0u);
    EXPECT_EQ(r.triangulation.points().size(), P.size());
  }
}

TEST(Delaunay2dIncremental, DuplicatesAreReportedAndUnreferenced) {
  const std::vector<Vec2> P = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {0.0, -0.0}, {1, 1}, {1, 0}, {0.5, 0.5}};
  const auto r = run(P);
  EXPECT_EQ(r.duplicates, (std::vector<std::uint32_t>{3, 4, 6}));
  EXPECT_EQ(r.duplicate_of, (std::vector<std::uint32_t>{1, 0, 1}));
  expect_delaunay(r);
  EXPECT_EQ(triangle_set(r.triangulation), brute_force(P));
}

TEST(Delaunay2dIncremental, BadInputIsRefusedByName) {
  std::vector<Vec2> P = {{0, 0}, {1, 0}, {0, std::numeric_limits<double>::quiet_NaN()}};
  try {
    run(P);
    ADD_FAILURE() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.items(), (std::vector<std::uint64_t>{2}));
  }
  try {
    delaunay2d(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}, {.algorithm = "no-such"});
    ADD_FAILURE() << "unknown algorithm accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("incremental"), std::string::npos);
  }
}

TEST(Delaunay2dIncremental, Random100kIsDelaunay) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> P(100000);
  for (Vec2& p : P) p = {u(rng), u(rng)};
  const auto r = run(P);
  expect_delaunay(r);
  EXPECT_GT(r.seconds, 0.0);
  EXPECT_GT(r.predicate_stats[Predicate::Incircle].calls(), P.size());
}

TEST(ElementSets2, BallEdgesAndPipeOnAGrid) {
  std::vector<Vec2> P;
  const int side = 10;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) P.push_back({static_cast<double>(i), static_cast<double>(j)});
  const auto r = run(P);
  const T2& tri = r.triangulation;
  const auto vt = vertex_triangles(tri);
  // Degree from the ball equals degree from the edge list (plus 2 ghosts on the hull).
  std::vector<std::size_t> degree(P.size(), 0);
  for (const auto& e : edges(tri)) ++degree[e[0]], ++degree[e[1]];
  for (std::uint32_t v = 0; v < P.size(); ++v) {
    const auto b = ball(tri, vt[v], v);
    std::size_t ghosts = 0;
    for (std::uint32_t t : b) {
      ghosts += tri.is_ghost(t);
      EXPECT_TRUE(tri.vertex(t, 0) == v || tri.vertex(t, 1) == v || tri.vertex(t, 2) == v);
    }
    EXPECT_EQ(b.size() - ghosts + (ghosts > 0 ? 1 : 0), degree[v]) << "vertex " << v;
  }
  // The diagonal runs through every grid vertex on it.
  const Pipe2 diagonal = pipe(tri, vt[0], 0, side * side - 1);
  ASSERT_EQ(diagonal.through.size(), static_cast<std::size_t>(side - 2));
  for (int k = 1; k + 1 < side; ++k) EXPECT_EQ(diagonal.through[k - 1], static_cast<std::uint32_t>(k * side + k));
  // An edge has an empty pipe.
  EXPECT_TRUE(pipe(tri, vt[0], 0, 1).triangles.empty());
}

TEST(ElementSets2, PipeCrossesConsecutiveTriangles) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> P(3000);
  for (Vec2& p : P) p = {u(rng), u(rng)};
  const auto r = run(P);
  const T2& tri = r.triangulation;
  const auto vt = vertex_triangles(tri);
  for (std::uint32_t k = 0; k < 50; ++k) {
    const std::uint32_t p = k, q = 2999 - k;
    const Pipe2 pp = pipe(tri, vt[p], p, q);
    ASSERT_TRUE(pp.through.empty());
    ASSERT_GE(pp.triangles.size(), 1u);
    auto has = [&](std::uint32_t t, std::uint32_t v) {
      return tri.vertex(t, 0) == v || tri.vertex(t, 1) == v || tri.vertex(t, 2) == v;
    };
    EXPECT_TRUE(has(pp.triangles.front(), p));
    EXPECT_TRUE(has(pp.triangles.back(), q));
    for (std::size_t j = 0; j < pp.triangles.size(); ++j) {
      const std::uint32_t t = pp.triangles[j];
      int left = 0, right = 0;
      for (std::uint32_t i = 0; i < 3; ++i) {
        const Sign s = orient2d(P[p], P[q], P[tri.vertex(t, i)]);
        left += s == Sign::Positive, right += s == Sign::Negative;
      }
      EXPECT_TRUE(left > 0 && right > 0) << "triangle " << t << " does not straddle the segment";
      if (j > 0) {
        bool adjacent = false;
        for (std::uint32_t i = 0; i < 3; ++i) adjacent = adjacent || tri.adjacent(t, i) == pp.triangles[j - 1];
        EXPECT_TRUE(adjacent);
      }
    }
  }
}

// Small inputs on a coarse integer grid: full of cocircular and collinear subsets and
// duplicates. Same triangles as the brute force, and independent of the input order.
RC_GTEST_PROP(Delaunay2dIncremental, SmallDegenerateInputsMatchBruteForce, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 24);
  std::vector<Vec2> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({static_cast<double>(*rc::gen::inRange(-3, 4)), static_cast<double>(*rc::gen::inRange(-3, 4))});
  const auto r = run(P);
  if (!r.degenerate_message.empty()) {
    RC_ASSERT(r.triangulation.triangle_count() == 0u);
    RC_ASSERT(brute_force(P).empty());
    return;
  }
  r.triangulation.check_topology();
  RC_ASSERT(triangle_set(r.triangulation) == brute_force(P));
  // Reversed input: the same triangles, as triangles of points.
  const std::vector<Vec2> Q(P.rbegin(), P.rend());
  RC_ASSERT(geometric_set(r.triangulation) == geometric_set(run(Q).triangulation));
}

// Larger inputs on a small grid (many duplicates, cocircular and collinear sets) under random
// BRIO seeds: always the Delaunay triangulation, and the same one for every insertion order.
RC_GTEST_PROP(Delaunay2dIncremental, GridInputsUnderRandomSeeds, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 400);
  const int half = *rc::gen::inRange(1, 9);
  std::vector<Vec2> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({static_cast<double>(*rc::gen::inRange(-half, half + 1)),
                 static_cast<double>(*rc::gen::inRange(-half, half + 1))});
  const auto r = delaunay2d(P, {.algorithm = "incremental", .seed = *rc::gen::arbitrary<std::uint64_t>()});
  const auto s = delaunay2d(P, {.algorithm = "incremental", .seed = *rc::gen::arbitrary<std::uint64_t>()});
  if (!r.degenerate_message.empty()) {
    RC_ASSERT(r.triangulation.triangle_count() == 0u);
    return;
  }
  RC_ASSERT(delaunay_violation(r) == "");
  RC_ASSERT(triangle_set(r.triangulation) == triangle_set(s.triangulation));
}

TEST(Delaunay2dRegistry, EveryVariantHasANameAndARunFunction) {
  ASSERT_FALSE(delaunay2d_variants().empty());
  std::set<std::string_view> names;
  for (const auto& v : delaunay2d_variants()) {
    EXPECT_FALSE(v.name.empty());
    EXPECT_NE(v.run, nullptr);
    EXPECT_TRUE(names.insert(v.name).second) << "duplicate name " << v.name;
    EXPECT_EQ(delaunay2d_variants().find(v.name), &v);
  }
  EXPECT_EQ(delaunay2d_variants().find("no-such"), nullptr);
}

}  // namespace
}  // namespace dtlab
