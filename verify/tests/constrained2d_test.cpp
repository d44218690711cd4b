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
#include "algorithms/constrained2d/constrained_mesh.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rounding.hpp"
#include "mesh/element_sets2.hpp"
#include "verify/checks_constrained2d.hpp"

namespace dtlab {
namespace {

using Segment = std::array<std::uint32_t, 2>;
using T2 = Triangulation2;

// The shared navigation core (mesh/navigation2*.hpp) as ConstrainedMesh2 uses it: point
// location on a vertex, an edge, inside and outside the hull; the segment walk stopped by a
// vertex on the segment, across an edge, along an edge; a flip carrying the segment ids.
TEST(ConstrainedMesh2, LocateWalkAndFlipOnTheSharedCore) {
  const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}};
  Delaunay2dResult fan = delaunay2d(square);
  ConstrainedMesh2 mesh(fan.triangulation);
  const T2& tri = mesh.tri();
  const std::uint32_t start = T2::triangle_of(mesh.find_half_edge(2, 3));
  ConstrainedMesh2::Location at = mesh.locate({1, 1}, start);
  EXPECT_EQ(at.where, ConstrainedMesh2::Where::Vertex);
  EXPECT_EQ(at.handle, 4u);
  at = mesh.locate({0.5, 0.5}, start);
  ASSERT_EQ(at.where, ConstrainedMesh2::Where::Edge);
  EXPECT_EQ((std::set{tri.origin(at.handle), tri.destination(at.handle)}), (std::set<std::uint32_t>{0, 4}));
  at = mesh.locate({1, 0.25}, start);
  ASSERT_EQ(at.where, ConstrainedMesh2::Where::Triangle);
  EXPECT_EQ((std::set{tri.vertex(at.triangle, 0), tri.vertex(at.triangle, 1), tri.vertex(at.triangle, 2)}),
            (std::set<std::uint32_t>{0, 1, 4}));
  at = mesh.locate({3, 1}, start);
  ASSERT_EQ(at.where, ConstrainedMesh2::Where::Outside);
  EXPECT_TRUE(tri.is_ghost(at.triangle));
  const ConstrainedMesh2::SegmentWalk through = mesh.walk(0, 2);
  EXPECT_TRUE(through.crossed.empty());
  EXPECT_EQ(through.stop, 4u);
  EXPECT_FALSE(mesh.flippable(mesh.find_half_edge(0, 4)));  // 1, 4, 3 collinear

  const std::vector<Vec2> quad{{0, 0}, {2, 0}, {2.5, 1}, {0, 1}};
  Delaunay2dResult two = delaunay2d(quad);
  ConstrainedMesh2 q(two.triangulation);
  const std::uint32_t d = q.find_half_edge(0, 2) != ConstrainedMesh2::kNone ? 0 : 1;  // the diagonal from d
  const std::uint32_t s = 1 - d, e = 3 - d;
  const ConstrainedMesh2::SegmentWalk across = q.walk(s, e);
  ASSERT_EQ(across.crossed.size(), 1u);
  EXPECT_EQ(across.stop, e);
  EXPECT_EQ(orient2d(quad[s], quad[e], quad[q.tri().origin(across.crossed[0])]), Sign::Negative);
  for (std::uint32_t k = 0; k < 4; ++k) q.set_constraint(q.find_half_edge(k, (k + 1) % 4), 10 + k);
  const std::uint32_t g = q.flip(q.find_half_edge(d, d + 2));
  q.tri().check_topology();
  EXPECT_EQ(q.flip_count(), 1u);
  EXPECT_EQ(q.constraint(g), ConstrainedMesh2::kNone);
  EXPECT_EQ(q.find_half_edge(d, d + 2), ConstrainedMesh2::kNone);
  const ConstrainedMesh2::SegmentWalk along = q.walk(s, e);
  EXPECT_TRUE(along.crossed.empty());
  EXPECT_EQ(along.stop, e);
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t h = q.find_half_edge(k, (k + 1) % 4);
    EXPECT_EQ(q.constraint(h), 10 + k);
    EXPECT_EQ(q.constraint(q.tri().twin(h)), 10 + k);
    const std::uint32_t t = q.triangle_of_vertex(k);  // kept current by the flip
    EXPECT_TRUE(q.tri().vertex(t, 0) == k || q.tri().vertex(t, 1) == k || q.tri().vertex(t, 2) == k);
  }
}

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

// The checks every result must pass (verify/checks_constrained2d.hpp), and what the test knows
// of the input: `exact_chains`, no crossings in it, so no crossing Steiner points.
void expect_valid(const std::vector<Vec2>& points, const std::vector<Segment>& segments, const std::string& method,
                  const Constrained2dResult& r, bool exact_chains, std::span<const int> markers = {},
                  bool keep_exterior = false) {
  SCOPED_TRACE("method " + method);
  ASSERT_TRUE(r.degenerate_message.empty()) << r.degenerate_message;
  const ConstrainedInput2 in{.points = points, .segments = segments, .segment_markers = markers, .holes = {}, .regions = {}};
  const ConstrainedCheckReport2 report =
      verify_constrained2d(in, r, {.method = method, .keep_exterior = keep_exterior, .first_number = 0});
  ASSERT_TRUE(report.ok) << to_text(report);
  EXPECT_EQ(report.segments, segments.size());
  if (exact_chains) {
    EXPECT_EQ(r.crossing_steiner_points, 0u);
  }
  if (method == "swap" || method == "cdt") {
    EXPECT_EQ(r.split_steiner_points, 0u);
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
std::size_t non_delaunay_edges(const Constrained2dResult& r) { return check_locally_delaunay2(r, true).problem_count; }

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
    const std::vector<int> markers = {7, 8, 9, 10};
    const auto r = run(kSquare, segs, m, markers);
    expect_valid(kSquare, segs, m, r, false, markers);
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
    const std::vector<int> markers = {5, 7};
    const auto r = run(pts, {{0, 2}, {1, 3}}, m, markers);
    expect_valid(pts, {{0, 2}, {1, 3}}, m, r, true, markers);
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
    const std::vector<int> markers = {1, 2};
    const auto r = run(pts, {{0, 1}, {2, 3}}, m, markers);
    expect_valid(pts, {{0, 1}, {2, 3}}, m, r, false, markers);
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
  expect_valid(pts, segs, "cdt", inner, true);
  expect_valid(pts, segs, "cdt", all, true, {}, true);
  // The kept exterior ends at hull edges that are not constrained: only valid when declared.
  const ConstrainedInput2 in{.points = pts, .segments = segs, .segment_markers = {}, .holes = {}, .regions = {}};
  EXPECT_FALSE(verify_constrained2d(in, all, {.method = "cdt", .keep_exterior = false}).ok);
}

// --- the checker rejects each kind of broken result ------------------------------------------------

struct Broken {
  std::vector<Vec2> points = {{0, 0}, {6, 0}, {6, 6}, {0, 6}, {1, 2}, {5, 4}, {2, 5}, {4, 0.5}, {3, 3.5}};
  // 4-5 crosses 6-7 at (32/11, 65/22), not a double point.
  std::vector<Segment> segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {6, 7}};
  std::vector<int> markers = {1, 1, 2, 2, 3, 4};
  ConstrainedInput2 input() const {
    return {.points = points, .segments = segments, .segment_markers = markers, .holes = {}, .regions = {}};
  }
  Constrained2dResult result(const std::string& method) const { return run(points, segments, method, markers); }
};

std::string problems_of(const Broken& b, const Constrained2dResult& r, const std::string& method) {
  const ConstrainedCheckReport2 report = verify_constrained2d(b.input(), r, {.method = method});
  EXPECT_FALSE(report.ok);
  EXPECT_EQ(report.problem_count, report.problems.size());
  return to_text(report);
}

TEST(Constrained2dChecks, AcceptTheUnbrokenResults) {
  const Broken b;
  for (const std::string& m : method_names()) {
    const auto r = b.result(m);
    ASSERT_EQ(r.crossing_steiner_points, 1u);
    const ConstrainedCheckReport2 report = verify_constrained2d(b.input(), r, {.method = m});
    EXPECT_TRUE(report.ok) << to_text(report);
    EXPECT_EQ(report.rounding_checks, 1u);
    EXPECT_NE(to_json(report).find("\"ok\":true"), std::string::npos);
  }
}

TEST(Constrained2dChecks, RejectAMissingConstrainedEdge) {
  const Broken b;
  auto r = b.result("cdt");
  r.constrained_edges.erase(r.constrained_edges.begin());
  // The domain's boundary lost a constrained edge (validity), and a segment its chain.
  EXPECT_NE(problems_of(b, r, "cdt").find("is not a constrained edge"), std::string::npos);
  const ConstrainedCheckReport2 chains = check_constrained_chains2(b.input(), r);
  EXPECT_FALSE(chains.ok);
  EXPECT_NE(to_text(chains).find("no chain of constrained edges"), std::string::npos) << to_text(chains);
}

TEST(Constrained2dChecks, RejectAWrongMarkerAndAnUnknownSegment) {
  const Broken b;
  auto r = b.result("swap");
  r.constrained_edges[0].marker = 99;
  EXPECT_NE(problems_of(b, r, "swap").find("has marker 99"), std::string::npos);
  r = b.result("swap");
  r.constrained_edges[0].segment = 17;
  EXPECT_NE(problems_of(b, r, "swap").find("segment 17, which does not exist"), std::string::npos);
}

TEST(Constrained2dChecks, RejectAWrongSlotRegionAndHalfEdge) {
  const Broken b;
  auto r = b.result("cdt");
  r.slot_regions[r.constrained_edges[0].half_edge / 3] = 5;
  EXPECT_NE(problems_of(b, r, "cdt").find("slot_regions are not"), std::string::npos);
  r = b.result("cdt");
  r.constrained_edges[0].half_edge = r.constrained_edges[1].half_edge;
  EXPECT_NE(problems_of(b, r, "cdt").find("has a half-edge elsewhere"), std::string::npos);
}

TEST(Constrained2dChecks, RejectAMovedSteinerPoint) {
  // The crossing point moved by two ulps in x and y: still a valid triangulation, but off its
  // rounding bound.
  const Broken b;
  auto r = b.result("cdt");
  Vec2& x = r.triangulation.mutable_points().back();
  const auto exact = line_intersection_exact(b.points[4], b.points[5], b.points[6], b.points[7]);
  ASSERT_TRUE(exact && within_rounding_bound(*exact, x));
  x.x = std::nextafter(x.x, 10.0);
  x.y = std::nextafter(x.y, 10.0);
  x.x = std::nextafter(x.x, 10.0);
  x.y = std::nextafter(x.y, 10.0);
  ASSERT_FALSE(within_rounding_bound(*exact, x));
  const std::string text = problems_of(b, r, "cdt");
  EXPECT_NE(text.find("is not within its rounding bound of their exact intersection"), std::string::npos) << text;
  EXPECT_NE(text.find("is not within its rounding bound of the segment nor of a piece"), std::string::npos) << text;
}

TEST(Constrained2dChecks, RejectAClockwiseTriangleAndABadDomain) {
  const Broken b;
  auto r = b.result("cdt");
  std::swap(r.triangulation.mutable_vertices()[r.triangulation.is_ghost(0) ? 4 : 1],
            r.triangulation.mutable_vertices()[r.triangulation.is_ghost(0) ? 5 : 2]);
  EXPECT_FALSE(verify_constrained2d(b.input(), r, {.method = "cdt"}).ok);
  r = b.result("cdt");
  r.triangles.push_back({0, 1, 8});  // no triangle of the mesh
  r.triangle_region.push_back(0);
  EXPECT_NE(problems_of(b, r, "cdt").find("not triangles of the triangulation"), std::string::npos);
  r = b.result("cdt");
  r.triangles.pop_back();  // a hole with unconstrained boundary
  r.triangle_region.pop_back();
  EXPECT_NE(problems_of(b, r, "cdt").find("is not a constrained edge"), std::string::npos);
}

TEST(Constrained2dChecks, RejectNonDelaunayEdgesByMethod) {
  // swap leaves non-Delaunay edges: checked as cdt or conforming it fails; cdt's constrained
  // edges are not Delaunay: checked as conforming it fails.
  std::vector<Vec2> pts = {{0, 0}, {1, 1}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 300; ++i) pts.push_back({u(rng), u(rng)});
  const std::vector<Segment> segs = {{0, 1}};
  const ConstrainedInput2 in{.points = pts, .segments = segs, .segment_markers = {}, .holes = {}, .regions = {}};
  const auto s = run(pts, segs, "swap", {}, {}, {}, true);
  const auto c = run(pts, segs, "cdt", {}, {}, {}, true);
  EXPECT_TRUE(verify_constrained2d(in, s, {.method = "swap", .keep_exterior = true}).ok);
  const auto as_cdt = verify_constrained2d(in, s, {.method = "cdt", .keep_exterior = true});
  EXPECT_FALSE(as_cdt.ok);
  EXPECT_NE(to_text(as_cdt).find("not locally Delaunay"), std::string::npos);
  EXPECT_FALSE(verify_constrained2d(in, c, {.method = "conforming", .keep_exterior = true}).ok);
  EXPECT_TRUE(verify_constrained2d(in, c, {.method = "cdt", .keep_exterior = true}).ok);
}

TEST(Constrained2dChecks, NumbersProblemsFromTheGivenFirstNumber) {
  const Broken b;
  auto r = b.result("cdt");
  r.constrained_edges[0].marker = 99;
  const auto e = r.constrained_edges[0];
  const std::string text = to_text(verify_constrained2d(b.input(), r, {.method = "cdt", .first_number = 1}));
  EXPECT_NE(text.find("edge " + std::to_string(e.a + 1) + "-" + std::to_string(e.b + 1)), std::string::npos) << text;
  EXPECT_NE(text.find("segment " + std::to_string(e.segment + 1) + " has"), std::string::npos) << text;
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

// Nudged half-integers whose crossings round off their segments, onto input vertices: the chains
// bend through those vertices (within their rounding bound of the segment, not exactly on it).
// These were taken for an algorithm bug ("no chain of constrained edges") until the checker
// admitted such vertices; every method, every check.
void expect_chains_everywhere(const std::vector<Vec2>& pts, const std::vector<Segment>& segs) {
  std::vector<int> markers;  // as the fuzz target numbers them
  for (std::size_t k = 0; k < segs.size(); ++k) markers.push_back(static_cast<int>((k + 1) % 5));
  for (const std::string& method : method_names()) {
    const auto r = run(pts, segs, method, markers);
    expect_valid(pts, segs, method, r, false, markers);
  }
}

// Found by SegmentSoupsWithCrossingsAndOverlaps (random seed): segment 4 (1,6)-(5,2) passes
// exactly through vertex 0 (3,4) and crosses segment 1 at a rounded point; its piece from that
// point to (5,2), bent by half an ulp, missed vertex 0 by as much, and "conforming" split it
// towards vertex 0 until the Steiner limit. A bent segment keeps the vertices exactly on it.
TEST(Constrained2dRegression, BentSegmentKeepsTheVerticesOnIt) {
  const std::vector<Vec2> pts = {{3, 4}, {0, 1}, {1, 6}, {5, 2}, {1, 4}, {4, 0}, {4, 4}, {0, 6}, {5, 1},
                                 {3, 2}, {5, 2}, {5, 2}, {2, 4}, {6, 6}, {5, 0}, {0, 5}, {3, 1}, {1, 6},
                                 {2, 4}, {3, 1}, {4, 5}, {6, 3}, {2, 3}, {3, 6}, {5, 6}};
  const std::vector<Segment> segs = {{14, 4}, {4, 13}, {22, 5}, {11, 0}, {2, 11}, {13, 17}};
  for (const std::string& method : method_names()) {
    const auto r = run(pts, segs, method);
    expect_valid(pts, segs, method, r, false);
    EXPECT_LT(r.split_steiner_points, 50u) << method;
  }
}

// fuzz/constrained2d_fuzz input (base64, CI run of 2026-11-23)
// AhgABAD/////////JwH7AgD4/wMkBP////8nAfsCAPj/AyQEAv8C+S8ABABHAAL/AvkvAAQARwAAAEUAAAD9AgAJEwYCFQsCEg8CDgkNBAAARwAAAEUAAAC1/QIACRMCAgYLFQ8CARYQBQwHFAAI
// Segment 2-1 crosses segment 5-12 half an ulp from vertex 5, and their exact intersection
// rounds onto vertex 5 itself: the chain of 2-1 bends through input vertex 5, which is not
// exactly on 2-1 but within its rounding bound of it. The checker refused that chain ("no chain
// of constrained edges from point 2 to point 1") though no Steiner point was made.
TEST(Constrained2dRegression, CrossingRoundsOntoAnInputVertex) {
  const double tiny = std::ldexp(1.0, -142);
  const std::vector<Vec2> pts = {
      {0x1p+1, -0x1.0000000000001p-1}, {-0x1.0000000000001p-1, -0x1.0000000000001p-1},
      {-0x1.ffffffffffffdp-2, 0x1.fffffffffffffp-2}, {0x1p+0, -0x1.0000000000001p+2},
      {0x1.8p+0, 0x1.fffffffffffffp+0}, {-0x1.0000000000001p-1, -0x1.ffffffffffffdp-2},
      {0x1.fffffffffffffp-2, 0x1p+0}, {-0x1.0000000000001p+2, 0x1.8p+0},
      {0x1.0000000000002p+1, -0x1.ffffffffffffep-2}, {-0x1.bfffffffffffdp+1, 0},
      {tiny, tiny}, {-0x1.ffffffffffffep-2, -0x1.bfffffffffffdp+1},
      {0, tiny}, {0, tiny}, {0, -tiny}, {0x1p+0, 0x1.2000000000003p+2},
      {0x1.8000000000002p+1, 0x1.5000000000003p+3}, {0x1.0000000000002p+0, 0x1.e000000000002p+2},
      {0x1.c000000000001p+2, 0x1.ap+2}, {0, 0x1.1cp+5}, {0, 0x1.14p+5}, {0, -0x1.2c00000000003p+5},
      {0x1p+0, 0x1.2000000000003p+2}, {0x1.0000000000002p+0, 0x1.8000000000003p+1}};
  const std::vector<Segment> segs = {{21, 15}, {2, 1}, {22, 16}, {5, 12}, {7, 20}, {0, 8}};
  for (const std::string& method : method_names()) {
    expect_valid(pts, segs, method, run(pts, segs, method), true);
    expect_valid(pts, segs, method, run(pts, segs, method, {}, {}, {}, true), true, {}, true);
  }
}

// fuzz/constrained2d_fuzz input (corpus: regression-shared-pieces). Segments 2-4 and 8-4 run from
// near the origin to vertex 4 near (2e30, 3e36), within an ulp of each other over most of their
// length: "conforming" splits both by concentric shells, and a rounded split point of one lies
// exactly on a piece of the other, so the two chains share pieces. Each shared edge kept only
// the lower segment, and the checker found no chain for segment 3 (2-4) and its shell points on
// no chain: an edge now carries every segment that covers it (Constrained2dResult::shared_edges).
TEST(Constrained2dRegression, ChainsSharingPiecesKeepEverySegment) {
  const std::vector<Vec2> pts = {
      {0x1.6974f162d388p-8, -0x1.480d51ae4f299p-33}, {0x1.4feb67188d137p-11, 0x1.ac4b6b7fc6a2p-6},
      {0x1.fa86f75a8a8ecp-2, 0x1.62472e512fa8p-4}, {0x1.593aa335b8148p-1, -0x1.f00040018021p+0},
      {0x1.c800000174p+100, 0x1.3fff800000085p+121}, {-0x1.127f8ffffff04p+93, 0x1.42403fff80002p-139},
      {0x1.004002ff902ffp+113, 0x1.02ff9020200ffp-107}, {0x1.140000011cp+108, 0x1.045000002fdp+129},
      {0x1p+9, 0x1p-11}, {0x1.20f2f150b0602p+129, 0x1.014070c051016p-43},
      {0x1.1e5d92a213087p-1, 0x1.dbb60abe4828p+107}, {-0x1p+109, 0x1.01813090002fdp-107},
      {0x1.8083fffffcp+108, -0x1.ff00300010ap-127}, {-0x1.9340101006669p-94, 0x1.50400030302f3p-91},
      {0x1.210080e0e0c0cp+113, 0x1.63bff0f02p+95}, {0x1.10100f3039699p-139, 0x1.5050400030302p+137},
      {0x1.210080e0e0c0cp+113, -0x1.1p-115}, {-0x1.f1309fe9c5fe2p-100, 0x1.feae84ed19786p+124},
      {0x1.fe132b03bb924p-48, 0x1.babb37a05a579p-1}, {0x1.5699581423254p-1, 0x1.ce97285111b9cp-2}};
  const std::vector<Segment> segs = {{0, 8}, {8, 4}, {8, 19}, {2, 4}, {11, 2}, {19, 6}, {10, 1}, {12, 17}};
  std::vector<int> markers;  // as the fuzz target numbers them
  for (std::size_t k = 0; k < segs.size(); ++k) markers.push_back(static_cast<int>((k + 1) % 5));
  const auto r = run(pts, segs, "conforming", markers);
  expect_valid(pts, segs, "conforming", r, false, markers);
  EXPECT_GT(r.shared_edges.size(), 0u);
}

// fuzz/constrained2d_fuzz input (corpus: regression-bent-crossings; its hole left out). Segment
// 57 crosses segment 14 (and its duplicate 30) and 16 near x = 1, where the rounding boxes change
// size: chains bent by snap rounding still cross there, and enforcement splits them at the
// rounded intersection of the two pieces' lines, a point no pair of input segments explains.
// The result records such points (Constrained2dResult::bent_crossings) and the checker takes
// their exact point from the recorded pieces.
TEST(Constrained2dRegression, BentChainsCrossAtRecordedPieces) {
  const std::vector<Vec2> pts = {
      {0x1.8p+3, -0x1.fffffffffffffp+1}, {-0x1.ffffffffffffep+1, -0x1.4p+1}, {0x1.0000000000002p+0,
      -0x1.4p+1}, {0x1p-1, 0x1.fffffffffffffp-1}, {-0x1.0000000000001p-1, -0x1.0000000000001p-1},
      {-0x1.0000000000001p-1, -0x1.0000000000001p-1}, {-0x1.ffffffffffffep-2, 0x1.4000000000002p+1}, {0,
      -0x1.ffffffffffffep-2}, {-0x1.bfffffffffffep+1, 0x1.8p+3}, {-0x1.fffffffffffffp+1, -0x1p+2}, {-0x1.4p+1,
      0x1p+0}, {0x1p+0, -0x1.3fffffffffffep+1}, {0x1p-1, 0x1.e800000000003p+5}, {-0x1.ffffffffffffep-2, 0},
      {-0x1.ffffffffffffep-2, -0x1.bffffffffffffp+1}, {0, 0x1p-142}, {0x1.7fffffffffffdp+0,
      0x1.ffffffffffffdp-1}, {0x1p-1, -0x1.4fffffffffffep+5}, {0x1p-142, 0x1p-142}, {0x1.6c00000000002p+5,
      0x1.8p+0}, {0x1.0000000000002p-1, -0x1.fffffffffffffp+1}, {-0x1p+2, -0x1.14p+5}, {0x1p+0, 0x1p+0},
      {-0x1.3fffffffffffep+1, 0x1p-1}};
  const std::vector<Segment> segs = {
      {7, 9}, {2, 4}, {2, 3}, {15, 9}, {2, 4}, {2, 3}, {15, 0}, {15, 3}, {9, 2}, {6, 0}, {1, 4}, {6, 0}, {1,
      0}, {13, 19}, {6, 11}, {2, 1}, {8, 2}, {3, 15}, {2, 0}, {4, 15}, {2, 9}, {3, 9}, {2, 0}, {15, 3}, {9,
      2}, {6, 0}, {1, 4}, {6, 0}, {1, 0}, {13, 19}, {6, 11}, {2, 1}, {8, 2}, {3, 15}, {2, 0}, {4, 15}, {2, 9},
      {3, 9}, {2, 13}, {1, 4}, {4, 6}, {0, 1}, {0, 13}, {19, 6}, {3, 0}, {8, 1}, {8, 0}, {2, 0}, {2, 0}, {11,
      2}, {1, 8}, {22, 7}, {9, 2}, {4, 2}, {3, 15}, {0, 15}, {3, 9}, {2, 6}, {0, 1}, {4, 6}, {0, 1}, {0, 13},
      {19, 6}, {11, 2}};
  std::vector<int> markers;  // as the fuzz target numbers them
  for (std::size_t k = 0; k < segs.size(); ++k) markers.push_back(static_cast<int>((k + 1) % 5));
  for (const std::string& method : method_names()) {
    if (method == "conforming") {  // refuses: the pieces near x = 1 split down to its Steiner limit
      EXPECT_THROW(run(pts, segs, method, markers), InputError);
      continue;
    }
    const auto r = run(pts, segs, method, markers);
    expect_valid(pts, segs, method, r, false, markers);
    EXPECT_GT(r.bent_crossings.size(), 0u) << method;
  }
}

// fuzz/constrained2d_fuzz input (corpus: regression-crossing-vertex-behind), cut down to the four
// segments that fail. Segments 0 and 2 end a few ulps apart, at (1, -2.5 + ulp) and (1 + 2 ulps,
// -2.5), across x = 1 where the rounding boxes change size; segment 1 runs into the second
// end and segment 3 crosses all three. Their chains, bent by snap rounding, cross again a few
// ulps from the rounded crossing of segments 0 and 1, and enforcement routed a piece of segment 1
// back through that vertex, which its chain had passed already: the chain looped, stepping back
// along the segment, and two crossing points were left on no chain. A crossing vertex must now
// lie between the ends of both pieces along their segments, else the pieces' own crossing is
// taken.
TEST(Constrained2dRegression, CrossingVertexBehindAChainIsNotReused) {
  const std::vector<Vec2> pts = {{0x1.8p+3, -0x1.fffffffffffffp+1},        {0x1.0000000000002p+0, -0x1.4p+1},
                                 {-0x1.ffffffffffffep-2, 0x1.4000000000002p+1}, {-0x1.bfffffffffffep+1, 0x1.8p+3},
                                 {0x1p+0, -0x1.3fffffffffffep+1},            {-0x1.ffffffffffffep-2, 0}};
  const std::vector<Segment> segs = {{2, 4}, {3, 1}, {2, 1}, {0, 5}};
  for (const std::string& method : method_names()) {
    const auto r = run(pts, segs, method);
    expect_valid(pts, segs, method, r, false);
  }
}

// fuzz/constrained2d_fuzz input (corpus: regression-duplicate-chains; its hole left out). Segment 3,
// (1, 2.5)-(1 + 2 ulps, -2.5), has five duplicates (15, 19, 31, 51, 63), dropped with a message.
// "conforming" bends its chain through input vertex 22, a little more than its rounding bound
// off the segment; the kept segment's own edges admit it, the duplicates had none and found no
// chain. A dropped duplicate now covers the kept segment's edges (shared_edges).
TEST(Constrained2dRegression, DroppedDuplicatesCoverTheKeptChain) {
  const std::vector<Vec2> pts = {
      {0x1.8p+3, -0x1.fffffffffffffp+1}, {-0x1.ffffffffffffep+1, -0x1.4p+1}, {0x1.0000000000002p+0,
      -0x1.4p+1}, {0x1p-1, 0x1.fffffffffffffp-1}, {-0x1.0000000000001p-1, 0x1.4000000000002p+1}, {0,
      -0x1.ffffffffffffep-2}, {-0x1.bfffffffffffep+1, 0x1.8p+3}, {-0x1.fffffffffffffp+1, -0x1p+2}, {-0x1.4p+1,
      0x1p+0}, {0x1p+0, 0x1.4p+1}, {0x1p-1, 0x1.e800000000003p+5}, {-0x1.ffffffffffffep-2, 0},
      {-0x1.ffffffffffffep-2, -0x1.bffffffffffffp+1}, {0, 0x1p-142}, {0x1.7fffffffffffdp+0,
      0x1.ffffffffffffdp-1}, {0x1p-1, -0x1.4fffffffffffep+5}, {-0x1.fffffffffffffp+5, 0x1p-142},
      {0x1.6c00000000002p+5, 0x1.8p+0}, {-0x1.fffffffffffffp+1, -0x1p+2}, {-0x1.4p+1, 0x1p+0}, {0x1p+0,
      -0x1.3fffffffffffep+1}, {0x1p-1, 0x1.bfffffffffffdp+1}, {0x1p+0, 0x1.0000000000003p+0},
      {-0x1.0000000000003p-1, 0x1p+0}};
  const std::vector<Segment> segs = {
      {2, 3}, {15, 0}, {15, 3}, {9, 2}, {6, 0}, {1, 4}, {6, 0}, {1, 0}, {13, 19}, {6, 11}, {2, 1}, {8, 2}, {3,
      15}, {2, 0}, {4, 15}, {2, 9}, {3, 9}, {2, 0}, {15, 3}, {9, 2}, {6, 0}, {1, 4}, {7, 0}, {1, 0}, {13, 19},
      {6, 11}, {2, 1}, {8, 2}, {3, 15}, {2, 0}, {4, 15}, {2, 9}, {3, 9}, {2, 13}, {1, 4}, {4, 6}, {0, 1}, {0,
      13}, {19, 6}, {3, 0}, {8, 1}, {8, 0}, {2, 0}, {2, 0}, {11, 2}, {1, 8}, {7, 9}, {2, 4}, {2, 3}, {15, 0},
      {15, 3}, {9, 2}, {6, 0}, {1, 4}, {6, 0}, {1, 0}, {13, 19}, {6, 11}, {2, 1}, {8, 2}, {3, 15}, {0, 15},
      {1, 2}, {2, 9}};
  std::vector<int> markers;  // as the fuzz target numbers them
  for (std::size_t k = 0; k < segs.size(); ++k) markers.push_back(static_cast<int>((k + 1) % 5));
  for (const std::string& method : method_names()) {
    const auto r = run(pts, segs, method, markers);
    expect_valid(pts, segs, method, r, false, markers);
    EXPECT_TRUE(std::any_of(r.shared_edges.begin(), r.shared_edges.end(),
                            [](const ConstrainedEdge2& e) { return e.segment == 63; }))
        << method;
  }
}


// fuzz/constrained2d_fuzz input (CI run of 2026-11-23, reduced to its two segments):
// AhgA+AH4APsAAnsAAAAC+QP5Av0BBKwGAAIAAwIGAwIC+QD/AQUA+AD9UAAAAFMAAABcAAAAAvsAAwH4AfoD/gEGAfgA+gEFAPwC+gEFAgEBAAMEAAQD/QIACRMCBwYLFQ8DAA4JDQQBFhAFDAcUAAg=
// Segment 3 ends at vertex 3, an ulp left of the vertical segment 0, which it crosses just
// before: the crossing rounds onto segment 0's line beside vertex 3, and vertex 3's rounding box
// touches segment 0 too. Both stops lie at the same place along segment 0, so its chain steps
// across it between them; the checker wanted every step strictly forward and found no chain.
TEST(Constrained2dRegression, TwoStopsAtTheSamePlaceAlongASegment) {
  const std::vector<Vec2> pts = {{-0x1.fffffffffffffp+1, -4},
                                 {-0x1.fffffffffffffp+1, -0x1.7fffffffffffdp+1},
                                 {0x1.3000000000002p+3, 0x1.c000000000002p+1},
                                 {-4, -0x1.7ffffffffffffp+1}};
  const std::vector<Segment> segs = {{0, 1}, {2, 3}};
  for (const std::string& method : method_names()) {
    const auto r = run(pts, segs, method);
    expect_valid(pts, segs, method, r, false);
    EXPECT_EQ(r.crossing_steiner_points, 1u) << method;
  }
}

// fuzz/constrained2d_fuzz input (base64)
// AhgA+AH4APsAAgACAPsCAQD4A/8ABAL/AvkD+QL9AQQABgACAAMCBgMCAvkBAgEFAPgA/QP7AgIC+wIGAQACBQL7AAMB+AH6A/4BBgH4APoBBQD8AvoBBQIBAQIDBAAEA/0CAAkTAgIGCxUPAhIOCQ0EARYQBQwHFAAI
// failed on conforming: segment 4 (15-2) had no chain, Steiner point 45 on no chain.
TEST(Constrained2dRegression, ChainsThroughRoundedCrossingsConforming) {
  const std::vector<Vec2> pts = {
      {-0x1.fffffffffffffp+1, -0x1.0000000000000p+2},
      {-0x1.4000000000000p+1, 0x1.0000000000000p+0},
      {0x1.0000000000000p+0, -0x1.3fffffffffffep+1},
      {0x1.0000000000000p-1, -0x1.ffffffffffffdp+1},
      {-0x1.0000000000000p-1, 0x1.0000000000002p+1},
      {-0x1.ffffffffffffep-2, -0x1.bfffffffffffdp+1},
      {-0x1.bfffffffffffep+1, -0x1.7ffffffffffffp+0},
      {0x1.0000000000000p+1, 0x1.8000000000000p+1},
      {0x1.0000000000000p+0, 0x1.8000000000002p+0},
      {0x1.8000000000003p+1, 0x1.0000000000002p+0},
      {-0x1.bffffffffffffp+1, 0x1.0000000000001p+0},
      {0x1.4000000000000p+1, -0x1.0000000000000p+2},
      {-0x1.7fffffffffffdp+0, -0x1.3fffffffffffep+1},
      {0x1.0000000000002p+0, -0x1.3fffffffffffep+1},
      {0x1.8000000000001p+1, std::ldexp(1.0, -142)},
      {0x1.4000000000002p+1, -0x1.4000000000000p+1},
      {0x1.8000000000001p+0, -0x1.fffffffffffffp+1},
      {-0x1.7fffffffffffdp+1, -0x1.fffffffffffffp-1},
      {0x1.8000000000001p+1, -0x1.0000000000000p+2},
      {-0x1.7ffffffffffffp+1, 0x1.4000000000000p+1},
      {-0x1.ffffffffffffep+0, -0x1.7ffffffffffffp+1},
      {0x1.4000000000002p+1, 0x1.0000000000001p-1},
      {0x1.0000000000003p+0, 0x1.0000000000000p+1},
      {0x1.0000000000003p+1, -0x1.7fffffffffffep+0}};
  const std::vector<Segment> segs = {{0, 9}, {19, 2}, {2, 6}, {11, 21}, {15, 2}, {18, 14}, {9, 13}, {4, 1}, {22, 16}, {5, 12}, {7, 20}, {0, 8}};
  expect_chains_everywhere(pts, segs);
}

// fuzz/constrained2d_fuzz input (base64)
// AhgA+AH4APsACAACAPsCAQD4A/8ABAL/AvkD+QL9AQQABgACAAMCBgMCAgL5BQABAfgA/QP7AgIC+wIGAQACBQL7AAMB+AH6A/4BBgH4APoBBQD8AvoBBQIBAQIDBAAEA/0CAAkTAgIKCxUPAhIOCQ0EARYQBQwHFAAI
// failed on every method (cdt, swap, conforming): segment 4 (15-2) had
// no chain.
TEST(Constrained2dRegression, ChainsThroughRoundedCrossingsEveryMethod) {
  const std::vector<Vec2> pts = {
      {-0x1.fffffffffffffp+1, -0x1.0000000000000p+2},
      {-0x1.4000000000000p+1, 0x1.0000000000000p+2},
      {0x1.0000000000000p+0, -0x1.3fffffffffffep+1},
      {0x1.0000000000000p-1, -0x1.ffffffffffffdp+1},
      {-0x1.0000000000000p-1, 0x1.0000000000002p+1},
      {-0x1.ffffffffffffep-2, -0x1.bfffffffffffdp+1},
      {-0x1.bfffffffffffep+1, -0x1.7ffffffffffffp+0},
      {0x1.0000000000000p+1, 0x1.8000000000000p+1},
      {0x1.0000000000000p+0, 0x1.8000000000002p+0},
      {0x1.8000000000003p+1, 0x1.0000000000002p+0},
      {0x1.ffffffffffffdp-1, 0x1.4000000000000p+1},
      {0x1.0000000000001p-1, -0x1.0000000000000p+2},
      {-0x1.7fffffffffffdp+0, -0x1.3fffffffffffep+1},
      {0x1.0000000000002p+0, -0x1.3fffffffffffep+1},
      {0x1.8000000000001p+1, std::ldexp(1.0, -142)},
      {0x1.4000000000002p+1, -0x1.4000000000000p+1},
      {0x1.8000000000001p+0, -0x1.fffffffffffffp+1},
      {-0x1.7fffffffffffdp+1, -0x1.fffffffffffffp-1},
      {0x1.8000000000001p+1, -0x1.0000000000000p+2},
      {-0x1.7ffffffffffffp+1, 0x1.4000000000000p+1},
      {-0x1.ffffffffffffep+0, -0x1.7ffffffffffffp+1},
      {0x1.4000000000002p+1, 0x1.0000000000001p-1},
      {0x1.0000000000003p+0, 0x1.0000000000000p+1},
      {0x1.0000000000003p+1, -0x1.7fffffffffffep+0}};
  const std::vector<Segment> segs = {{0, 9}, {19, 2}, {2, 10}, {11, 21}, {15, 2}, {18, 14}, {9, 13}, {4, 1}, {22, 16}, {5, 12}, {7, 20}, {0, 8}};
  expect_chains_everywhere(pts, segs);
}

// fuzz/constrained2d_fuzz (corpus: regression-conforming-two-chains-a-hair-apart): segments
// 0-9 and 0-14 leave vertex 0 a hair apart, and "conforming" splits both on the same shells, so
// their chains share pieces (labelled 0) and run side by side. The chain check, free to change
// label, followed segment 0's chain for segment 5 and left segment 5's own Steiner points on no
// chain found; it now tries a segment's own edges first.
TEST(Constrained2dRegression, ChainsAHairApartKeepTheirOwnPoints) {
  const std::vector<Vec2> pts = {
      {-0x1.fffffffffffffp+1, -0x1p+2}, {-0x1.4p+1, 0x1p+0},
      {0x1p+0, -0x1.3fffffffffffep+1}, {0x1p-1, 0x1.c000000000003p+1},
      {-0x1.ffffffffffffep-2, 0x0p+0}, {-0x1.ffffffffffffep-2, -0x1.bfffffffffffdp+1},
      {-0x1.bfffffffffffep+1, -0x1.7ffffffffffffp+0}, {0x1p+1, 0x1.8p+1},
      {0x1p+0, 0x1.8000000000002p+0}, {0x1.8000000000003p+1, 0x1.0000000000002p+0},
      {-0x1.cp+1, -0x1.fffffffffffffp-2}, {0x1.4p+1, -0x1p+2},
      {-0x1.7fffffffffffdp+0, -0x1.3fffffffffffep+1}, {0x1.0000000000002p+0, std::ldexp(1.0, -142)},
      {0x1.7ffffffffffffp+1, 0x1.0000000000002p+0}, {0x1.4000000000002p+1, -0x1.4p+1},
      {0x1.8000000000001p+0, -0x1.fffffffffffffp+1}, {-0x1.7fffffffffffdp+1, -0x1.fffffffffffffp-1},
      {0x1.8000000000001p+1, -0x1p+2}, {-0x1.7ffffffffffffp+1, 0x1.4p+1},
      {-0x1.ffffffffffffep+0, -0x1.7ffffffffffffp+1}, {0x1.4000000000002p+1, 0x1.0000000000001p-1},
      {std::ldexp(1.0, -142), 0x1p+1}, {0x1.0000000000003p+1, -0x1.7fffffffffffep+0}
  };
  const std::vector<Segment> segs = {{0, 9}, {19, 2}, {7, 6}, {11, 21}, {15, 3}, {0, 14}, {9, 13}, {4, 1}, {22, 16}, {5, 12}, {7, 20}, {0, 8}};
  expect_chains_everywhere(pts, segs);
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

RC_GTEST_PROP(Constrained2dProperties, RandomSwapOrder, ()) {
  // Swapping crossed edges in random order (book §3.3.3) enforces every segment too; for "cdt"
  // the result is the same triangulation as with Sloan's queue (the CDT is unique), for "swap"
  // it is valid and contains the same constrained edges.
  auto rng = seeded_rng();
  const int n = uniform(rng, 5, 200);
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) pts.push_back({double(uniform(rng, 0, 40)), double(uniform(rng, 0, 40))});
  RC_PRE(delaunay2d(pts).degenerate_message.empty());
  std::vector<Segment> segs;
  for (int i = uniform(rng, 1, 30); i > 0; --i) {
    const auto a = static_cast<std::uint32_t>(uniform(rng, 0, n));
    const auto b = static_cast<std::uint32_t>(uniform(rng, 0, n));
    if (pts[a] != pts[b]) segs.push_back({a, b});
  }
  const std::uint64_t seed = rng();
  const ConstrainedInput2 in{.points = pts, .segments = segs, .segment_markers = {}, .holes = {}, .regions = {}};
  for (const std::string m : {"cdt", "swap"}) {
    const auto queue = constrained2d(in, {.method = m, .keep_exterior = true});
    const auto random = constrained2d(in, {.method = m, .keep_exterior = true, .seed = seed, .random_swaps = true});
    expect_valid(pts, segs, m, random, false, {}, true);
    RC_ASSERT(!::testing::Test::HasFailure());
    RC_ASSERT(constrained_set(random) == constrained_set(queue));
    if (m == "cdt") {
      auto a = queue.triangles, b = random.triangles;
      for (auto* list : {&a, &b}) {
        for (auto& t : *list) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        std::sort(list->begin(), list->end());
      }
      RC_ASSERT(a == b);
    }
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
