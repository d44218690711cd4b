// Constrained triangulation in 2D (algorithms/constrained2d): one harness for every registered
// method. On every input the result must be a valid triangulation in doubles (closed structure,
// every finite triangle strictly ccw by exact orient2d, covering the convex hull), every input
// segment a chain of constrained edges (input vertices on it exactly collinear, Steiner points
// within a rounding bound of its line), and have its method's property: "cdt" every
// non-constrained edge locally Delaunay (perturbed incircle), "conforming" every edge.
// Inputs: fixed cases for every bad input the API handles, RapidCheck generators (random polygons
// with holes, random non-crossing segment sets, segment soups on a small grid with crossings and
// overlaps, polygons with many collinear and cocircular vertices), and one large timed case.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rounding.hpp"
#include "mesh/element_sets2.hpp"
#include "verify/checks2d.hpp"

namespace dtlab {
namespace {

using Segment = std::array<std::uint32_t, 2>;
using T2 = Triangulation2;

std::vector<std::string> method_names() {
  std::vector<std::string> out;
  for (const Constrained2dMethod& m : constrained2d_methods()) out.emplace_back(m.name);
  return out;
}

std::set<std::pair<std::uint32_t, std::uint32_t>> constrained_set(const Constrained2dResult& r) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const ConstrainedEdge2& e : r.constrained_edges) out.insert({e.a, e.b});
  return out;
}

bool strictly_inside_box(const Vec2& a, const Vec2& b, const Vec2& p) {
  const bool x = a.x == b.x ? p.x == a.x : (std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x));
  const bool y = a.y == b.y ? p.y == a.y : (std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y));
  return x && y;
}

// Vertex d may lie on the chain of segment ab: exactly on it, or (a Steiner point, whose chain
// bends by rounding) within a few ulps of its line, between a and b.
bool admissible(const Vec2& a, const Vec2& b, const Vec2& d, bool steiner) {
  if (orient2d(a, b, d) == Sign::Zero) return strictly_inside_box(a, b, d);
  if (!steiner) return false;
  const Vec2 ab = b - a, ad = d - a;
  const double length = norm(ab);
  const double along = dot(ab, ad) / length;
  const double off = std::fabs(cross(ab, ad)) / length;
  const double scale = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y)});
  return along > 0 && along < length && off <= 16 * ulp(scale);
}

// Is there a path a -> b of constrained edges, each step forward along ab, through admissible
// vertices? Returns "" or what failed.
using Adjacency = std::map<std::uint32_t, std::vector<std::uint32_t>>;
std::string chain_problem(const Constrained2dResult& r, Adjacency& adj, std::uint32_t a, std::uint32_t b) {
  const auto P = r.triangulation.points();
  const Vec2 A = P[a], B = P[b];
  std::vector<std::uint32_t> stack{a};
  std::set<std::uint32_t> seen{a};
  while (!stack.empty()) {
    const std::uint32_t c = stack.back();
    stack.pop_back();
    for (const std::uint32_t d : adj[c]) {
      if (seen.count(d)) continue;
      if (dot(P[d] - P[c], B - A) <= 0) continue;
      if (d == b) return "";
      if (!admissible(A, B, P[d], d >= r.input_point_count)) continue;
      seen.insert(d);
      stack.push_back(d);
    }
  }
  return "no chain of constrained edges from " + std::to_string(a) + " to " + std::to_string(b);
}

// The checks every result must pass; `exact_chains`: no crossings in the input, so chains run
// through input vertices exactly on their segment only.
void expect_valid(const std::vector<Vec2>& points, const std::vector<Segment>& segments, const std::string& method,
                  const Constrained2dResult& r, bool exact_chains) {
  SCOPED_TRACE("method " + method);
  const Triangulation2& tri = r.triangulation;
  ASSERT_TRUE(r.degenerate_message.empty()) << r.degenerate_message;
  ASSERT_NO_THROW(tri.check_topology());
  const auto P = tri.points();
  ASSERT_EQ(P.size(), points.size() + r.crossing_steiner_points + r.split_steiner_points);
  for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(P[i], points[i]);
  const std::vector<TriangleIds> all = tri.finite_triangles();
  CheckReport2 report = check_orientation2(P, all);
  report.merge(check_topology2(P, all));
  report.merge(check_hull_coverage2(P, all));
  ASSERT_TRUE(report.ok) << to_text(report);
  for (const auto& t : r.triangles) ASSERT_EQ(orient2d(P[t[0]], P[t[1]], P[t[2]]), Sign::Positive);
  ASSERT_EQ(r.triangles.size(), r.triangle_region.size());
  EXPECT_EQ(r.rounding_checks_failed, 0u);
  if (exact_chains) {
    EXPECT_EQ(r.crossing_steiner_points, 0u);
  }
  if (method == "swap" || method == "cdt") {
    EXPECT_EQ(r.split_steiner_points, 0u);
  }

  // Every constrained edge is an edge, once.
  const auto cons = constrained_set(r);
  ASSERT_EQ(cons.size(), r.constrained_edges.size());
  std::set<std::pair<std::uint32_t, std::uint32_t>> mesh_edges;
  for (const auto& e : edges(tri)) mesh_edges.insert({e[0], e[1]});
  for (const auto& e : cons) ASSERT_TRUE(mesh_edges.count(e)) << "constrained edge " << e.first << "-" << e.second << " missing";
  // Chains.
  Adjacency adj;
  for (const ConstrainedEdge2& e : r.constrained_edges) adj[e.a].push_back(e.b), adj[e.b].push_back(e.a);
  for (const Segment& s : segments) {
    if (P[s[0]] == P[s[1]]) continue;
    // Duplicate points: the first copy carries the chain.
    std::uint32_t a = s[0], b = s[1];
    a = static_cast<std::uint32_t>(std::find(P.begin(), P.end(), P[a]) - P.begin());
    b = static_cast<std::uint32_t>(std::find(P.begin(), P.end(), P[b]) - P.begin());
    const std::string problem = chain_problem(r, adj, a, b);
    ASSERT_TRUE(problem.empty()) << problem;
  }
  // Method properties on the whole triangulation.
  if (method == "swap") return;
  const auto& V = tri.vertices();
  for (std::uint32_t h = 0; h < V.size(); ++h) {
    const std::uint32_t g = tri.twin(h);
    if (h > g || tri.is_ghost(T2::triangle_of(h)) || tri.is_ghost(T2::triangle_of(g))) continue;
    const std::uint32_t u = tri.origin(h), v = tri.destination(h);
    if (method == "cdt" && cons.count({std::min(u, v), std::max(u, v)})) continue;
    const std::uint32_t t = T2::triangle_of(h);
    ASSERT_NE(incircle_perturbed(P[V[3 * t]], P[V[3 * t + 1]], P[V[3 * t + 2]], P[V[g]]), Sign::Positive)
        << "edge " << u << "-" << v << " is not locally Delaunay";
  }
}

Constrained2dResult run(const std::vector<Vec2>& points, const std::vector<Segment>& segments, const std::string& method,
                        std::vector<int> markers = {}, std::vector<Vec2> holes = {}, std::vector<RegionSeed2> regions = {},
                        bool keep_exterior = false) {
  ConstrainedInput2 in{.points = points, .segments = segments, .segment_markers = markers, .holes = holes, .regions = regions};
  return constrained2d(in, {.method = method, .keep_exterior = keep_exterior});
}

// Twice the area of the domain's triangles (exact for small integer coordinates).
double area2(const Constrained2dResult& r) {
  const auto P = r.triangulation.points();
  double s = 0;
  for (const auto& t : r.triangles) s += cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]);
  return s;
}

const ConstrainedEdge2* find_edge(const Constrained2dResult& r, std::uint32_t a, std::uint32_t b) {
  for (const ConstrainedEdge2& e : r.constrained_edges)
    if (e.a == std::min(a, b) && e.b == std::max(a, b)) return &e;
  return nullptr;
}

// Non-constrained edges between finite triangles that fail the perturbed empty-circle test.
std::size_t non_delaunay_edges(const Constrained2dResult& r) {
  const Triangulation2& tri = r.triangulation;
  const auto P = tri.points();
  const auto& V = tri.vertices();
  const auto cons = constrained_set(r);
  std::size_t count = 0;
  for (std::uint32_t h = 0; h < V.size(); ++h) {
    const std::uint32_t g = tri.twin(h), t = T2::triangle_of(h);
    if (h > g || tri.is_ghost(t) || tri.is_ghost(T2::triangle_of(g))) continue;
    const std::uint32_t u = tri.origin(h), v = tri.destination(h);
    if (cons.count({std::min(u, v), std::max(u, v)})) continue;
    count += incircle_perturbed(P[V[3 * t]], P[V[3 * t + 1]], P[V[3 * t + 2]], P[V[g]]) == Sign::Positive;
  }
  return count;
}

// --- bad and awkward input, one test each --------------------------------------------------------

const std::vector<Vec2> kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}, {1, 3}};

TEST(Constrained2d, UnknownMethodIsRefused) {
  EXPECT_THROW(run(kSquare, {{0, 1}}, "nope"), InputError);
}

TEST(Constrained2d, EndpointOutOfRangeNamesTheSegment) {
  try {
    run(kSquare, {{0, 1}, {2, 6}}, "cdt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{1});
    EXPECT_NE(std::string(e.what()).find("segment 1"), std::string::npos);
  }
}

TEST(Constrained2d, ZeroLengthSegmentsAreRefused) {
  for (const Segment s : {Segment{3, 3}, Segment{3, 6}}) {
    std::vector<Vec2> pts = kSquare;
    pts.push_back(pts[3]);  // point 6 = point 3
    try {
      run(pts, {{0, 1}, s}, "cdt");
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.items(), std::vector<std::uint64_t>{1});
      EXPECT_NE(std::string(e.what()).find("zero length"), std::string::npos);
    }
  }
}

TEST(Constrained2d, MarkerCountMustMatch) {
  EXPECT_THROW(run(kSquare, {{0, 1}, {1, 2}}, "cdt", {1}), InputError);
}

TEST(Constrained2d, DuplicateSegmentsKeepOne) {
  for (const std::string& m : method_names()) {
    const std::vector<Segment> segs = {{0, 2}, {2, 0}, {1, 4}, {0, 2}};
    const auto r = run(kSquare, segs, m, {7, 8, 9, 10});
    expect_valid(kSquare, segs, m, r, false);
    const ConstrainedEdge2* e = find_edge(r, 0, 2);
    if (m != "conforming") {
      ASSERT_NE(e, nullptr);
      EXPECT_EQ(e->marker, 7);
    }
    int dup_messages = 0;
    for (const std::string& s : r.messages) dup_messages += s.find("duplicates segment 0") != std::string::npos;
    EXPECT_EQ(dup_messages, 2);
  }
}

TEST(Constrained2d, SegmentThroughVertexIsSplitThere) {
  const std::vector<Vec2> pts = {{0, 0}, {1, 1}, {2, 2}, {2, 0}, {0, 2}, {1, -1}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, {{0, 2}}, m);
    expect_valid(pts, {{0, 2}}, m, r, true);
    EXPECT_NE(find_edge(r, 0, 1), nullptr);
    EXPECT_NE(find_edge(r, 1, 2), nullptr);
    EXPECT_EQ(find_edge(r, 0, 2), nullptr);
  }
}

TEST(Constrained2d, CollinearOverlapsMergeLowestSegmentWins) {
  // Segment 0 = [0,2] on the x axis, segment 1 = [1,3] overlapping it on [1,2].
  const std::vector<Vec2> pts = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1.5, 1}, {1.5, -1}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, {{0, 2}, {1, 3}}, m, {5, 7});
    expect_valid(pts, {{0, 2}, {1, 3}}, m, r, true);
    ASSERT_NE(find_edge(r, 0, 1), nullptr);
    ASSERT_NE(find_edge(r, 1, 2), nullptr);
    ASSERT_NE(find_edge(r, 2, 3), nullptr);
    EXPECT_EQ(find_edge(r, 0, 1)->marker, 5);
    EXPECT_EQ(find_edge(r, 1, 2)->marker, 5);  // the overlap: lowest-numbered segment
    EXPECT_EQ(find_edge(r, 2, 3)->marker, 7);
    EXPECT_EQ(r.constrained_edges.size(), 3u);
  }
}

TEST(Constrained2d, CrossingAtARepresentablePoint) {
  const std::vector<Vec2> pts = {{0, 0}, {2, 2}, {0, 2}, {2, 0}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, {{0, 1}, {2, 3}}, m, {1, 2});
    expect_valid(pts, {{0, 1}, {2, 3}}, m, r, false);
    ASSERT_EQ(r.crossing_steiner_points, 1u);
    EXPECT_EQ(r.triangulation.points()[4], (Vec2{1, 1}));
    EXPECT_EQ(find_edge(r, 0, 4)->marker, 1);
    EXPECT_EQ(find_edge(r, 4, 3)->marker, 2);
  }
}

TEST(Constrained2d, CrossingAtARoundedPointStaysWithinItsBound) {
  // y = x/5 meets x + y = 1 at (5/6, 1/6): not a double; the chains bend there by < ulp/2.
  const std::vector<Vec2> pts = {{0, 0}, {5, 1}, {1, 0}, {0, 1}, {3, 3}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, {{0, 1}, {2, 3}}, m);
    expect_valid(pts, {{0, 1}, {2, 3}}, m, r, false);
    ASSERT_EQ(r.crossing_steiner_points, 1u);
    const Vec2 x = r.triangulation.points()[5];
    const auto exact = line_intersection_exact(pts[0], pts[1], pts[2], pts[3]);
    ASSERT_TRUE(exact);
    EXPECT_TRUE(within_rounding_bound(*exact, x));
    EXPECT_FALSE(is_double(exact->x));
    if (m == "conforming") continue;  // splits the pieces further
    EXPECT_NE(find_edge(r, 0, 5), nullptr);
    EXPECT_NE(find_edge(r, 5, 1), nullptr);
    EXPECT_NE(find_edge(r, 2, 5), nullptr);
    EXPECT_NE(find_edge(r, 5, 3), nullptr);
  }
}

TEST(Constrained2d, ManySegmentsThroughOnePoint) {
  // Four segments through (0, 0), which is not an input point: one Steiner vertex, shared.
  const std::vector<Vec2> pts = {{-2, 0}, {2, 0}, {0, -2}, {0, 2}, {-2, -2}, {2, 2}, {-2, 2}, {2, -2}};
  const std::vector<Segment> segs = {{0, 1}, {2, 3}, {4, 5}, {6, 7}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, segs, m);
    expect_valid(pts, segs, m, r, false);
    EXPECT_EQ(r.crossing_steiner_points, 1u);
  }
}

TEST(Constrained2d, DanglingSegmentsAndHolesAndRegions) {
  // Outer square 0..8, inner square 3..5 (a hole), a dangling segment, two regions split by a
  // vertical wall at x = 1.
  const std::vector<Vec2> pts = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 3}, {5, 3}, {5, 5}, {3, 5},
                                 {1, 0}, {1, 8}, {6, 6}, {7, 7}};
  const std::vector<Segment> segs = {{0, 8}, {8, 1}, {1, 2}, {2, 9}, {9, 3}, {3, 0}, {4, 5},
                                     {5, 6}, {6, 7}, {7, 4}, {8, 9}, {10, 11}};
  for (const std::string& m : method_names()) {
    const auto r = run(pts, segs, m, {}, {{4, 4}}, {{{0.5, 4}, 3}, {{6, 1}, 9}});
    expect_valid(pts, segs, m, r, true);
    EXPECT_EQ(area2(r), 2 * (64.0 - 4.0));
    double area_by_region[2] = {0, 0};
    const auto P = r.triangulation.points();
    for (std::size_t k = 0; k < r.triangles.size(); ++k) {
      const auto& t = r.triangles[k];
      const double a = cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]);
      ASSERT_TRUE(r.triangle_region[k] == 3 || r.triangle_region[k] == 9);
      area_by_region[r.triangle_region[k] == 9] += a;
    }
    EXPECT_EQ(area_by_region[0], 2 * 8.0);
    EXPECT_EQ(area_by_region[1], 2 * (56.0 - 4.0));
  }
}

TEST(Constrained2d, KeepExteriorKeepsTheHull) {
  // A triangle domain inside a larger point set.
  const std::vector<Vec2> pts = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {8, 2}, {5, 8}};
  const std::vector<Segment> segs = {{4, 5}, {5, 6}, {6, 4}};
  const auto inner = run(pts, segs, "cdt");
  EXPECT_EQ(area2(inner), 6.0 * 6.0);
  const auto all = run(pts, segs, "cdt", {}, {}, {}, true);
  EXPECT_EQ(area2(all), 200.0);
}

TEST(Constrained2d, CollinearInputHasNoTriangles) {
  const std::vector<Vec2> pts = {{0, 0}, {1, 0}, {2, 0}};
  const auto r = run(pts, {{0, 2}}, "cdt");
  EXPECT_FALSE(r.degenerate_message.empty());
  EXPECT_TRUE(r.triangles.empty());
}

TEST(Constrained2d, SwapIsNotDelaunayButCdtIs) {
  // A long segment across a fan: swap leaves non-Delaunay edges, cdt none; the same edges
  // constrained in both.
  std::vector<Vec2> pts = {{0, 0}, {1, 1}};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) pts.push_back({u(rng), u(rng)});
  const auto s = run(pts, {{0, 1}}, "swap");
  const auto c = run(pts, {{0, 1}}, "cdt");
  expect_valid(pts, {{0, 1}}, "swap", s, true);
  expect_valid(pts, {{0, 1}}, "cdt", c, true);
  EXPECT_EQ(constrained_set(s), constrained_set(c));
  EXPECT_GT(non_delaunay_edges(s), 0u);
  EXPECT_EQ(non_delaunay_edges(c), 0u);
}

TEST(Constrained2d, ConformingSplitsSmallAngles) {
  // Two segments at a tiny angle from a shared vertex, points near them: concentric shells end it.
  const std::vector<Vec2> pts = {{0, 0}, {100, 1}, {100, -1}, {50, 3}, {50, -3}, {30, 0}};
  const std::vector<Segment> segs = {{0, 1}, {0, 2}};
  const auto r = run(pts, segs, "conforming");
  expect_valid(pts, segs, "conforming", r, false);
  EXPECT_GT(r.split_steiner_points, 0u);
  EXPECT_LT(r.split_steiner_points, 200u);
}

// --- generators ---------------------------------------------------------------------------------

// A random star-shaped polygon around c (angles sorted, radii random), optionally with a
// smaller star-shaped hole around c.
struct PolygonInput {
  std::vector<Vec2> points;
  std::vector<Segment> segments;
  std::vector<Vec2> holes;
};

void add_ring(PolygonInput& in, const std::vector<Vec2>& ring) {
  const auto base = static_cast<std::uint32_t>(in.points.size());
  const auto k = static_cast<std::uint32_t>(ring.size());
  for (std::uint32_t i = 0; i < k; ++i) {
    in.points.push_back(ring[i]);
    in.segments.push_back({base + i, base + (i + 1) % k});
  }
}

// RapidCheck's inRange scales with the test size (small sizes give near-equal values, so
// degenerate sets); coordinates come from a generator seeded by RapidCheck instead.
std::mt19937_64 seeded_rng() { return std::mt19937_64(*rc::gen::arbitrary<std::uint64_t>()); }

int uniform(std::mt19937_64& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi - 1)(rng); }

PolygonInput polygon_with_hole() {
  auto rng = seeded_rng();
  const int k = uniform(rng, 4, 31);
  const bool hole = uniform(rng, 0, 2) == 1;
  PolygonInput in;
  std::vector<Vec2> outer;
  // Vertex i at angle (i + jitter) / k turns, jitter in [0.1, 0.9]: gaps under half a turn, so
  // the polygon is star-shaped around the origin, far enough from it for the hole.
  for (int i = 0; i < k; ++i) {
    const double turn = (i + 0.1 + 0.8 * uniform(rng, 0, 1001) / 1000.0) / k;
    const double r = uniform(rng, 40, 101);
    outer.push_back({std::round(r * std::cos(turn * 6.283185307179586)), std::round(r * std::sin(turn * 6.283185307179586))});
  }
  const std::vector<Vec2> inner = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (std::size_t i = 0; i < outer.size(); ++i) {
    const Vec2 a = outer[i], b = outer[(i + 1) % outer.size()];
    RC_PRE(orient2d({0, 0}, a, b) == Sign::Positive);
    for (const Vec2& c : inner) RC_PRE(orient2d(a, b, c) == Sign::Positive);
  }
  add_ring(in, outer);
  if (hole) {
    add_ring(in, inner);
    in.holes.push_back({0, 0});
  }
  const int extra = uniform(rng, 0, 30);
  for (int i = 0; i < extra; ++i) in.points.push_back({double(uniform(rng, -100, 100)), double(uniform(rng, -100, 100))});
  return in;
}

RC_GTEST_PROP(Constrained2dProperties, RandomPolygonsWithHoles, ()) {
  const PolygonInput in = polygon_with_hole();
  for (const std::string& m : method_names()) {
    ConstrainedInput2 ci{.points = in.points, .segments = in.segments, .segment_markers = {}, .holes = in.holes, .regions = {}};
    const auto r = constrained2d(ci, {.method = m});
    expect_valid(in.points, in.segments, m, r, true);
    RC_ASSERT(!::testing::Test::HasFailure());
  }
}

RC_GTEST_PROP(Constrained2dProperties, RandomNonCrossingSegments, ()) {
  // Segments: random edges of the Delaunay triangulation of a random subset (they never cross),
  // inserted into the triangulation of all the points.
  auto rng = seeded_rng();
  const int n = uniform(rng, 10, 300);
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) pts.push_back({double(uniform(rng, 0, 64)), double(uniform(rng, 0, 64))});
  std::vector<std::uint32_t> subset;
  for (std::uint32_t i = 0; i < pts.size(); ++i)
    if (uniform(rng, 0, 3) == 0) subset.push_back(i);
  std::vector<Vec2> sub;
  for (auto i : subset) sub.push_back(pts[i]);
  std::vector<Segment> segs;
  const auto d = delaunay2d(sub);
  if (d.degenerate_message.empty())
    for (const auto& e : edges(d.triangulation))
      if (uniform(rng, 0, 2) == 0) segs.push_back({subset[e[0]], subset[e[1]]});
  RC_PRE(delaunay2d(pts).degenerate_message.empty());
  for (const std::string& m : method_names()) {
    const auto r = run(pts, segs, m);
    expect_valid(pts, segs, m, r, true);
    RC_ASSERT(!::testing::Test::HasFailure());
  }
}

RC_GTEST_PROP(Constrained2dProperties, SegmentSoupsWithCrossingsAndOverlaps, ()) {
  // A small grid: many collinear triples (overlaps, segments through vertices) and crossings
  // at points that are not doubles.
  auto rng = seeded_rng();
  const int n = uniform(rng, 5, 30);
  const int g = uniform(rng, 3, 9);
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) pts.push_back({double(uniform(rng, 0, g)), double(uniform(rng, 0, g))});
  RC_PRE(delaunay2d(pts).degenerate_message.empty());
  const int s = uniform(rng, 1, 25);
  std::vector<Segment> segs;
  for (int i = 0; i < s; ++i) {
    const auto a = static_cast<std::uint32_t>(uniform(rng, 0, n));
    const auto b = static_cast<std::uint32_t>(uniform(rng, 0, n));
    if (pts[a] != pts[b]) segs.push_back({a, b});
  }
  for (const std::string& m : method_names()) {
    const auto r = run(pts, segs, m);
    expect_valid(pts, segs, m, r, false);
    RC_ASSERT(!::testing::Test::HasFailure());
  }
}

RC_GTEST_PROP(Constrained2dProperties, CollinearAndCocircularPolygons, ()) {
  // A square with many points on each side (collinear) or the lattice points of the circle
  // x^2 + y^2 = 65^2 (exactly cocircular), as a polygon, with a few interior points.
  auto rng = seeded_rng();
  const bool circle = uniform(rng, 0, 2) == 1;
  PolygonInput in;
  std::vector<Vec2> ring;
  if (circle) {
    std::vector<std::pair<double, Vec2>> on;
    for (int x = -65; x <= 65; ++x)
      for (int y = -65; y <= 65; ++y)
        if (x * x + y * y == 65 * 65) on.push_back({std::atan2(double(y), double(x)), {double(x), double(y)}});
    std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [angle, p] : on) ring.push_back(p);
  } else {
    const int k = uniform(rng, 2, 12);
    for (int i = 0; i < k; ++i) ring.push_back({double(i), 0});
    for (int i = 0; i < k; ++i) ring.push_back({double(k), double(i)});
    for (int i = 0; i < k; ++i) ring.push_back({double(k - i), double(k)});
    for (int i = 0; i < k; ++i) ring.push_back({0, double(k - i)});
  }
  add_ring(in, ring);
  const int extra = uniform(rng, 0, 10);
  for (int i = 0; i < extra; ++i) in.points.push_back({uniform(rng, 1, 40) / 4.0, uniform(rng, 1, 40) / 4.0});
  // Chords between ring vertices (non-crossing: a fan from vertex 0).
  const auto m_ring = static_cast<std::uint32_t>(ring.size());
  for (std::uint32_t j = 2; j + 1 < m_ring; j += uniform(rng, 1, 5)) in.segments.push_back({0, j});
  for (const std::string& m : method_names()) {
    const auto r = run(in.points, in.segments, m);
    expect_valid(in.points, in.segments, m, r, true);
    RC_ASSERT(!::testing::Test::HasFailure());
  }
}

// --- a large case, timed -----------------------------------------------------------------------

TEST(Constrained2dLarge, HundredThousandPointsTenThousandSegments) {
  // 10^5 uniform points; 10^4 segments: edges of the Delaunay triangulation of a 2*10^4-point
  // subset, so they do not cross each other but cross many edges of the full triangulation.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 100000;
  std::vector<Vec2> pts(n);
  for (Vec2& p : pts) p = {u(rng), u(rng)};
  std::vector<Vec2> sub(pts.begin(), pts.begin() + 20000);
  const auto d = delaunay2d(sub);
  auto sub_edges = edges(d.triangulation);
  std::shuffle(sub_edges.begin(), sub_edges.end(), rng);
  std::vector<Segment> segs;
  for (std::size_t i = 0; i < 10000; ++i) segs.push_back({sub_edges[i][0], sub_edges[i][1]});
  const auto t0 = std::chrono::steady_clock::now();
  const auto plain = delaunay2d(pts);
  const double plain_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ figures  ] delaunay2d incremental, 1e5 points: %.3f s\n", plain_s);
  for (const std::string& m : method_names()) {
    const auto r = run(pts, segs, m);
    std::printf("[ figures  ] constrained2d %-10s 1e5 points + 1e4 segments: %.3f s, %zu flips, %u split points, %zu domain triangles\n",
                m.c_str(), r.seconds, std::size_t(r.flips), r.split_steiner_points, r.triangles.size());
    expect_valid(pts, segs, m, r, true);
  }
}

}  // namespace
}  // namespace dtlab
