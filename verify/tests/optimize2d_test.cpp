// 2D mesh optimization (algorithms/optimize2d): each operator on small hand-made meshes (a bad
// rhombus swaps to its short diagonal, an off-centre vertex of a regular hexagon relocates to
// the centre, a needle's short edge collapses, a long edge splits at its metric midpoint), the
// locks (constrained edges, kFixed vertices, boundary splits off by default), and RapidCheck
// properties on random Delaunay meshes of the unit square with random isotropic and anisotropic
// metric fields: after every operator and after the strategy Mesh2::check() passes (links, exact
// orientation: no triangle inverted), the constrained edges and boundary vertices are unchanged,
// the area is preserved, and swaps and relocations never make the worst quality worse; the
// passes that keep their measures (RelocationSweeps, the whole-mesh swap pass) move and swap as
// the passes that measure everything again.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "kernel/error.hpp"
#include "kernel/quality.hpp"
#include "mesh/mesh2_from_data.hpp"

namespace dtlab {
namespace {

// The constrained edges (sorted ends, reference) and the boundary vertices with their positions.
struct Boundary {
  std::vector<std::tuple<std::uint32_t, std::uint32_t, int>> edges;
  std::vector<std::tuple<std::uint32_t, double, double>> vertices;
  friend bool operator==(const Boundary&, const Boundary&) = default;
};

Boundary boundary_of(const Mesh2& mesh) {
  Boundary b;
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.is_alive(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (!mesh.is_constrained(h) || mesh.origin(h) > mesh.destination(h)) continue;
      b.edges.emplace_back(mesh.origin(h), mesh.destination(h), mesh.edge_ref(h));
    }
  }
  std::sort(b.edges.begin(), b.edges.end());
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_dead_vertex(v) && (mesh.flags(v) & (Mesh2::kOnBoundary | Mesh2::kFixed)) != 0)
      b.vertices.emplace_back(v, mesh.point(v).x, mesh.point(v).y);
  }
  return b;
}

double domain_area(const Mesh2& mesh) {
  double area = 0.0;
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const Vec2 &a = mesh.point(mesh.vertex(t, 0)), &b = mesh.point(mesh.vertex(t, 1)), &c = mesh.point(mesh.vertex(t, 2));
    area += 0.5 * cross(b - a, c - a);
  }
  return area;
}

double triangle_q(const Mesh2& mesh, std::uint32_t t) {
  const std::uint32_t a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
  return shape_quality(mesh.point(a), mesh.point(b), mesh.point(c), mesh.metric(a), mesh.metric(b), mesh.metric(c));
}

// Every vertex's metric from the field.
void apply_field(Mesh2& mesh, const MetricField2& field) {
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, field(mesh.point(v)));
}

// The Delaunay triangulation of `points` as a mesh (convex hull constrained, reference 0).
Mesh2 delaunay_mesh(const std::vector<Vec2>& points) {
  const Delaunay2dResult r = delaunay2d(points);
  MeshData2 data;
  data.vertices = points;
  data.triangles = r.triangulation.finite_triangles();
  data.triangle_refs.assign(data.triangles.size(), 0);
  return mesh2_from_data(data);
}

// The rhombus (-2,0), (0,-1), (2,0), (0,1) cut along its long diagonal: angle 127 degrees at
// (0, +-1); the short diagonal gives two triangles of angles 53, 63, 63.
MeshData2 long_rhombus() {
  MeshData2 d;
  d.vertices = {{-2, 0}, {0, -1}, {2, 0}, {0, 1}};
  d.triangles = {{0, 1, 2}, {0, 2, 3}};
  d.triangle_refs = {0, 0};
  return d;
}

std::uint32_t half_edge_between(const Mesh2& mesh, std::uint32_t a, std::uint32_t b) {
  const std::uint32_t h = mesh.find_half_edge(a, b);
  EXPECT_NE(h, Mesh2::kNone);
  return h;
}

TEST(Optimize2dSwap, BadRhombusSwapsToItsShortDiagonal) {
  Mesh2 mesh = mesh2_from_data(long_rhombus());
  const double before = std::max(triangle_q(mesh, 0), triangle_q(mesh, 1));
  ASSERT_TRUE(try_swap(mesh, half_edge_between(mesh, 0, 2)));
  mesh.check();
  EXPECT_EQ(mesh.find_half_edge(0, 2), Mesh2::kNone);
  EXPECT_NE(mesh.find_half_edge(1, 3), Mesh2::kNone);
  EXPECT_LT(std::max(triangle_q(mesh, 0), triangle_q(mesh, 1)), before);
  // Swapping back would make it worse again.
  EXPECT_FALSE(try_swap(mesh, half_edge_between(mesh, 1, 3)));
  EXPECT_EQ(swap_pass(mesh).swaps, 0u);
}

TEST(Optimize2dSwap, ConstrainedDiagonalAndHullEdgesStay) {
  MeshData2 d = long_rhombus();
  d.edges = {{0, 2}};
  d.edge_refs = {5};
  Mesh2 mesh = mesh2_from_data(d);
  EXPECT_FALSE(try_swap(mesh, half_edge_between(mesh, 0, 2)));
  EXPECT_FALSE(try_swap(mesh, half_edge_between(mesh, 0, 1)));  // a hull edge: a ghost beside it
  EXPECT_EQ(swap_pass(mesh).swaps, 0u);
  mesh.check();
}

TEST(Optimize2dSwap, DifferentRegionsAreNotMerged) {
  MeshData2 d = long_rhombus();
  d.triangle_refs = {1, 2};
  Mesh2 mesh = mesh2_from_data(d);
  EXPECT_FALSE(try_swap(mesh, half_edge_between(mesh, 0, 2)));
}

// A regular hexagon of radius 1 around the origin with its centre vertex moved to `centre`.
MeshData2 hexagon(Vec2 centre) {
  MeshData2 d;
  for (int i = 0; i < 6; ++i) {
    const double a = std::numbers::pi * i / 3;
    d.vertices.push_back({std::cos(a), std::sin(a)});
  }
  d.vertices.push_back(centre);
  for (std::uint32_t i = 0; i < 6; ++i) d.triangles.push_back({6, i, (i + 1) % 6});
  d.triangle_refs.assign(6, 0);
  return d;
}

TEST(Optimize2dRelocate, OffCentreVertexOfHexagonGoesToTheCentre) {
  for (const Metric2& m : {Metric2{}, Metric2::isotropic(0.7)}) {
    Mesh2 mesh = mesh2_from_data(hexagon({0.31, -0.17}), m);
    ASSERT_TRUE(try_relocate(mesh, 6, {}));
    mesh.check();
    EXPECT_NEAR(mesh.point(6).x, 0.0, 1e-12);
    EXPECT_NEAR(mesh.point(6).y, 0.0, 1e-12);
    // At the optimum no move improves any more.
    EXPECT_FALSE(try_relocate(mesh, 6, {}));
  }
}

TEST(Optimize2dRelocate, MetricIsReEvaluatedAtTheNewPoint) {
  Mesh2 mesh = mesh2_from_data(hexagon({0.2, 0.1}));
  const MetricField2 field = [](const Vec2& p) { return Metric2::isotropic(1.0 + 0.1 * p.x); };
  ASSERT_TRUE(try_relocate(mesh, 6, field));
  EXPECT_EQ(mesh.metric(6), field(mesh.point(6)));
}

TEST(Optimize2dRelocate, FixedAndBoundaryVerticesStay) {
  Mesh2 mesh = mesh2_from_data(hexagon({0.31, -0.17}));
  mesh.set_flags(6, Mesh2::kFixed);
  EXPECT_FALSE(try_relocate(mesh, 6, {}));
  EXPECT_FALSE(try_relocate(mesh, 0, {}));  // on the hull: kOnBoundary
  EXPECT_EQ(relocate_sweep(mesh, {}), 0u);
  EXPECT_EQ(mesh.point(6), (Vec2{0.31, -0.17}));
}

TEST(Optimize2dRelocate, AnisotropicOptimumIsEquilateralInTheMetric) {
  // The hexagon stretched by 3 along x is regular in the metric diag(1/9, 1): its centre is the
  // optimum there too.
  MeshData2 d = hexagon({0.5, 0.2});
  for (Vec2& p : d.vertices) p.x *= 3;
  Mesh2 mesh = mesh2_from_data(d, Metric2::from_sizes({1, 0}, 3.0, 1.0));
  ASSERT_TRUE(try_relocate(mesh, 6, {}));
  EXPECT_NEAR(mesh.point(6).x, 0.0, 1e-9);
  EXPECT_NEAR(mesh.point(6).y, 0.0, 1e-9);
}

// The unit square with two interior points 0.01 apart near its centre.
Mesh2 square_with_short_edge(const Metric2& metric) {
  Mesh2 mesh = delaunay_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.51, 0.505}});
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.set_metric(v, metric);
  return mesh;
}

// A patch cut out of a front mesh of the square minus a disc (h = 0.01, scaled by 100): the
// straight boundary vertex 1 = (0, 16) has only two triangles, both with a 32-degree angle at the
// free vertex 7. No swap of the bad triangle's edges and no relocation of 7 improves it; the swap
// of 7-2 followed by the relocation of 7 does (1 then has three triangles).
MeshData2 boundary_vertex_with_two_triangles() {
  MeshData2 d;
  d.vertices = {{0, 18}, {0, 16}, {0, 14}, {2.21, 13.92}, {3.18, 15.69}, {2.23, 17.49}, {1.73, 19.0}, {1.32, 15.89}};
  d.triangles = {{5, 6, 0}, {0, 1, 7}, {5, 7, 4}, {2, 3, 7}, {7, 5, 0}, {3, 4, 7}, {7, 1, 2}};
  d.triangle_refs.assign(d.triangles.size(), 0);
  return d;
}

double worst_q(const Mesh2& mesh) { return summarize_quality(mesh).worst; }

TEST(Optimize2dSwapRelocate, CuresABoundaryVertexWithTwoTriangles) {
  Mesh2 mesh = mesh2_from_data(boundary_vertex_with_two_triangles());
  const double before = worst_q(mesh);
  // Neither operator alone helps.
  Mesh2 copy = mesh;
  const std::uint32_t bad = Mesh2::triangle_of(half_edge_between(copy, 0, 1));
  for (std::uint32_t i = 0; i < 3; ++i) EXPECT_FALSE(try_swap(copy, Mesh2::half_edge(bad, i)));
  EXPECT_FALSE(try_relocate(copy, 7, {}));
  EXPECT_TRUE(try_swap_relocate(mesh, half_edge_between(mesh, 7, 2), {}));
  mesh.check();
  EXPECT_NE(mesh.find_half_edge(1, 3), Mesh2::kNone);  // the new diagonal
  EXPECT_LT(worst_q(mesh), 0.97 * before);  // 1.58 -> 1.49: the rest of the patch is fixed
}

TEST(Optimize2dSwapRelocate, RestoresTheMeshWhenNothingImproves) {
  Mesh2 mesh = mesh2_from_data(long_rhombus());  // no free vertex: refused before any change
  EXPECT_FALSE(try_swap_relocate(mesh, half_edge_between(mesh, 0, 2), {}));
  EXPECT_NE(mesh.find_half_edge(0, 2), Mesh2::kNone);
}

TEST(Optimize2dCollapse, ShortEdgeCollapses) {
  Mesh2 mesh = square_with_short_edge(Metric2::isotropic(0.8));
  const double area = domain_area(mesh);
  const Boundary boundary = boundary_of(mesh);
  ASSERT_NE(mesh.find_half_edge(4, 5), Mesh2::kNone);
  EXPECT_EQ(collapse_pass(mesh), 1u);
  mesh.check();
  EXPECT_EQ(mesh.live_vertex_count(), 5u);
  EXPECT_TRUE(mesh.is_dead_vertex(4) != mesh.is_dead_vertex(5));
  EXPECT_EQ(boundary_of(mesh), boundary);
  EXPECT_NEAR(domain_area(mesh), area, 1e-15);
  EXPECT_EQ(collapse_pass(mesh), 0u);
}

TEST(Optimize2dCollapse, NothingToCollapseWhenEdgesAreUnit) {
  // In a metric of size 0.01 the short edge is 1 long.
  Mesh2 mesh = square_with_short_edge(Metric2::isotropic(0.01));
  EXPECT_EQ(collapse_pass(mesh), 0u);
  EXPECT_EQ(mesh.live_vertex_count(), 6u);
}

TEST(Optimize2dCollapse, BoundaryVerticesAreNeverRemoved) {
  // Every vertex on the hull: the square's diagonal is short in a huge size, but both ends are
  // kOnBoundary.
  MeshData2 d;
  d.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.triangles = {{0, 1, 2}, {0, 2, 3}};
  Mesh2 mesh = mesh2_from_data(d, Metric2::isotropic(100.0));
  EXPECT_FALSE(try_collapse(mesh, half_edge_between(mesh, 0, 2)));
  EXPECT_EQ(collapse_pass(mesh), 0u);
}

TEST(Optimize2dSplit, MetricMidpointHalvesTheLength) {
  const Vec2 a{0, 0}, b{1, 0};
  const double ha = 1.0, hb = 0.25;
  const Vec2 p = metric_midpoint(a, Metric2::isotropic(ha), b, Metric2::isotropic(hb));
  // The sizes vary geometrically along the edge: h(s) = ha^(1-s) hb^s.
  const double s = p.x;
  const Metric2 mp = Metric2::isotropic(std::pow(ha, 1 - s) * std::pow(hb, s));
  const double first = edge_length(a, Metric2::isotropic(ha), p, mp);
  const double second = edge_length(p, mp, b, Metric2::isotropic(hb));
  EXPECT_NEAR(first, second, 1e-12 * first);
  EXPECT_GT(s, 0.5);  // closer to the fine end
  EXPECT_EQ(metric_midpoint(a, Metric2{}, b, Metric2{}).x, 0.5);
}

MeshData2 unit_square(int ref) {
  MeshData2 d;
  d.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.triangles = {{0, 1, 2}, {0, 2, 3}};
  d.triangle_refs = {0, 0};
  d.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  d.edge_refs.assign(4, ref);
  return d;
}

TEST(Optimize2dSplit, InteriorEdgeSplitsAtItsMidpoint) {
  Mesh2 mesh = mesh2_from_data(unit_square(7), Metric2::isotropic(0.4));
  const std::uint32_t v = try_split(mesh, half_edge_between(mesh, 0, 2), {});
  ASSERT_NE(v, Mesh2::kNone);
  mesh.check();
  EXPECT_EQ(mesh.point(v), (Vec2{0.5, 0.5}));
  EXPECT_EQ(mesh.flags(v), 0);
  EXPECT_EQ(summarize_quality(mesh).triangles, 4u);
  EXPECT_NEAR(domain_area(mesh), 1.0, 1e-15);
}

TEST(Optimize2dSplit, BoundarySplitOnlyWhenAllowedAndCarriesTheConstraint) {
  Mesh2 mesh = mesh2_from_data(unit_square(7), Metric2::isotropic(0.4));
  EXPECT_EQ(try_split(mesh, half_edge_between(mesh, 0, 1), {}), Mesh2::kNone);
  SplitOptions options;
  options.boundary = true;
  const std::uint32_t v = try_split(mesh, half_edge_between(mesh, 0, 1), {}, options);
  ASSERT_NE(v, Mesh2::kNone);
  mesh.check();
  EXPECT_EQ(mesh.flags(v), Mesh2::kOnBoundary);
  for (const std::uint32_t end : {0u, 1u}) {
    const std::uint32_t h = half_edge_between(mesh, end, v);
    EXPECT_TRUE(mesh.is_constrained(h));
    EXPECT_EQ(mesh.edge_ref(h), 7);
    EXPECT_TRUE(mesh.is_ghost(Mesh2::triangle_of(h)) || mesh.is_ghost(Mesh2::triangle_of(mesh.twin(h))));
  }
  EXPECT_EQ(mesh.domain().edges.size(), 5u);
}

// The unit square triangulated on its boundary points only, each side cut into n pieces.
Mesh2 square_boundary_mesh(int n) {
  std::vector<Vec2> points;
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      points.push_back(s == 0 ? Vec2{t, 0} : s == 1 ? Vec2{1, t} : s == 2 ? Vec2{1 - t, 1} : Vec2{0, 1 - t});
    }
  }
  return delaunay_mesh(points);
}

double longest_interior_edge(const Mesh2& mesh) {
  double longest = 0.0;
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (mesh.is_constrained(h)) continue;
      const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
      longest = std::max(longest, edge_length(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b)));
    }
  }
  return longest;
}

double shortest_edge(const Mesh2& mesh) {
  double shortest = std::numeric_limits<double>::infinity();
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
      shortest = std::min(shortest, edge_length(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b)));
    }
  }
  return shortest;
}

TEST(Optimize2dSplit, PassRefinesTowardUnitEdges) {
  // Boundary edges of length 1 in the metric (size 0.1, sides cut in 10): the interior fills in.
  Mesh2 mesh = square_boundary_mesh(10);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) mesh.set_metric(v, Metric2::isotropic(0.1));
  EXPECT_GT(longest_interior_edge(mesh), 5.0);
  const SplitPassResult r = split_pass(mesh, {});
  mesh.check();
  EXPECT_GT(r.splits, 30u);
  EXPECT_LT(mesh.live_vertex_count(), 400u);
  EXPECT_LE(longest_interior_edge(mesh), 2.0);
  EXPECT_NEAR(domain_area(mesh), 1.0, 1e-12);
}

TEST(Optimize2dSplit, PassStopsBesideALongBoundaryEdge) {
  // The boundary edges are 10 long in the metric and may not be split: refinement near them
  // stops at the unit scale instead of flattening triangles without end.
  Mesh2 mesh = mesh2_from_data(unit_square(1), Metric2::isotropic(0.1));
  const SplitPassResult r = split_pass(mesh, {});
  mesh.check();
  EXPECT_FALSE(r.limit_reached);
  EXPECT_LT(mesh.live_vertex_count(), 1000u);
}

TEST(Optimize2dStrategy, ImprovesAPerturbedGridAndCounts) {
  // A 6x6 grid with its interior vertices shaken: relocation and swaps must bring the worst down.
  std::vector<Vec2> points;
  for (int j = 0; j <= 6; ++j) {
    for (int i = 0; i <= 6; ++i) {
      Vec2 p{i / 6.0, j / 6.0};
      if (i > 0 && i < 6 && j > 0 && j < 6) p = p + Vec2{0.06 * std::sin(7.0 * i + 3.0 * j), 0.06 * std::cos(5.0 * i * j)};
      points.push_back(p);
    }
  }
  Mesh2 mesh = delaunay_mesh(points);
  const Boundary boundary = boundary_of(mesh);
  Optimize2dOptions options;
  options.collapses = options.splits = false;
  const MetricField2 field = [](const Vec2&) { return Metric2::isotropic(1.0 / 6.0); };
  apply_field(mesh, field);
  const Optimize2dStats stats = optimize2d(mesh, options, field);
  mesh.check();
  EXPECT_EQ(boundary_of(mesh), boundary);
  EXPECT_LT(stats.worst_after, stats.worst_before);
  EXPECT_LT(stats.mean_after, stats.mean_before);
  EXPECT_GT(stats.relocations, 0u);
  EXPECT_GE(stats.rounds, 1u);
  EXPECT_LE(stats.rounds, options.max_rounds);
  EXPECT_EQ(stats.vertices_after, stats.vertices_before);
  EXPECT_NEAR(domain_area(mesh), 1.0, 1e-12);
  // Deterministic: the same input gives the same mesh.
  Mesh2 again = delaunay_mesh(points);
  apply_field(again, field);
  optimize2d(again, options, field);
  EXPECT_EQ(again.domain(), mesh.domain());
}

TEST(Optimize2dStrategy, SizesMoveTowardAUnitMesh) {
  Mesh2 mesh = mesh2_from_data(unit_square(3), Metric2::isotropic(0.1));
  const MetricField2 field = [](const Vec2&) { return Metric2::isotropic(0.1); };
  const Optimize2dStats stats = optimize2d(mesh, {}, field);
  mesh.check();
  EXPECT_GT(stats.splits, 0u);
  EXPECT_EQ(stats.vertices_after, stats.vertices_before + stats.splits - stats.collapses);
  EXPECT_EQ(mesh.domain().edges.size(), 4u);  // the boundary discretisation is the input's
  EXPECT_NEAR(domain_area(mesh), 1.0, 1e-12);
  // Beside the four sides (10 long in the metric, not split) the triangles are flat, but no
  // split flattened them without end (it once left edges 1e-40 long there).
  EXPECT_GT(shortest_edge(mesh), 0.2);
}

TEST(Optimize2dStrategy, BoundarySplitsGiveAUnitMesh) {
  Mesh2 mesh = mesh2_from_data(unit_square(3), Metric2::isotropic(0.1));
  const MetricField2 field = [](const Vec2&) { return Metric2::isotropic(0.1); };
  Optimize2dOptions options;
  options.split.boundary = true;
  const Optimize2dStats stats = optimize2d(mesh, options, field);
  mesh.check();
  EXPECT_LT(stats.worst_after, 2.0);
  EXPECT_GT(shortest_edge(mesh), 0.5);
  EXPECT_LT(longest_interior_edge(mesh), 1.5);
  for (const auto& e : boundary_of(mesh).edges) EXPECT_EQ(std::get<2>(e), 3);
  EXPECT_NEAR(domain_area(mesh), 1.0, 1e-12);
}

// --- Random meshes ---------------------------------------------------------------------------

// A random Delaunay mesh of the unit square (corners included; interior points on a 1/1024 grid,
// so duplicates and collinear runs occur) and a random metric field: isotropic with a size that
// grows along x, or anisotropic with directions turning along y.
struct RandomCase {
  Mesh2 mesh;
  MetricField2 field;
};

RandomCase random_case() {
  const int n = *rc::gen::inRange(0, 40);
  std::vector<Vec2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < n; ++i) {
    const int x = *rc::gen::inRange(1, 1024), y = *rc::gen::inRange(1, 1024);
    points.push_back({x / 1024.0, y / 1024.0});
  }
  const double h0 = *rc::gen::inRange(10, 50) / 100.0;
  const double grow = *rc::gen::inRange(0, 30) / 10.0;
  const bool anisotropic = *rc::gen::arbitrary<bool>();
  const double ratio = *rc::gen::inRange(2, 10) / 10.0;
  const double turn = *rc::gen::inRange(0, 30) / 10.0;
  MetricField2 field;
  if (anisotropic) {
    field = [h0, ratio, turn](const Vec2& p) {
      const double a = turn * p.y;
      return Metric2::from_sizes({std::cos(a), std::sin(a)}, h0, h0 * ratio);
    };
  } else {
    field = [h0, grow](const Vec2& p) { return Metric2::isotropic(h0 * (1.0 + grow * p.x)); };
  }
  RandomCase c{delaunay_mesh(points), field};
  apply_field(c.mesh, c.field);
  return c;
}

// What every operator keeps: validity (exact orientation: no triangle inverted), the boundary,
// the area.
void expect_kept(const Mesh2& mesh, const Boundary& boundary, double area) {
  mesh.check();
  RC_ASSERT(boundary_of(mesh) == boundary);
  RC_ASSERT(std::fabs(domain_area(mesh) - area) <= 1e-12 * area);
}

RC_GTEST_PROP(Optimize2dProperties, SwapPassNeverWorsens, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  const QualitySummary2 before = summarize_quality(c.mesh);
  const SwapPassResult r = swap_pass(c.mesh);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(!r.limit_reached);
  RC_ASSERT(summarize_quality(c.mesh).worst <= before.worst);
  // Converged: a second pass finds nothing.
  RC_ASSERT(swap_pass(c.mesh).swaps == 0u);
}

RC_GTEST_PROP(Optimize2dProperties, EachSwapImprovesItsPair, ()) {
  RandomCase c = random_case();
  const std::uint32_t h = *rc::gen::inRange<std::uint32_t>(0, 3 * c.mesh.triangle_capacity());
  if (!c.mesh.in_domain(Mesh2::triangle_of(h))) return;
  const std::uint32_t t1 = Mesh2::triangle_of(h), t2 = Mesh2::triangle_of(c.mesh.twin(h));
  const bool beside_domain = c.mesh.in_domain(t2);
  const double before = beside_domain ? std::max(triangle_q(c.mesh, t1), triangle_q(c.mesh, t2)) : 0.0;
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  if (!try_swap(c.mesh, h)) return;
  RC_ASSERT(beside_domain);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(std::max(triangle_q(c.mesh, t1), triangle_q(c.mesh, t2)) < before);
}

// Kept: valid, boundary and area unchanged, the worst Q_K over the mesh not worse (the balls it
// judges hold every triangle it changed). Refused: the same points and triangles as before.
RC_GTEST_PROP(Optimize2dProperties, SwapRelocateImprovesOrRestores, ()) {
  RandomCase c = random_case();
  const std::uint32_t h = *rc::gen::inRange<std::uint32_t>(0, 3 * c.mesh.triangle_capacity());
  if (!c.mesh.in_domain(Mesh2::triangle_of(h))) return;
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  const double before = worst_q(c.mesh);
  const MeshData2 old = c.mesh.domain();
  if (try_swap_relocate(c.mesh, h, c.field)) {
    expect_kept(c.mesh, boundary, area);
    RC_ASSERT(worst_q(c.mesh) <= before);
  } else {
    c.mesh.check();
    const MeshData2 now = c.mesh.domain();
    RC_ASSERT(now.vertices == old.vertices);
    auto sorted = [](std::vector<std::array<std::uint32_t, 3>> t) {
      for (auto& x : t) std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
      std::sort(t.begin(), t.end());
      return t;
    };
    RC_ASSERT(sorted(now.triangles) == sorted(old.triangles));
  }
}

RC_GTEST_PROP(Optimize2dProperties, RelocationImprovesEachBall, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < c.mesh.vertex_capacity(); ++v) {
    if (c.mesh.is_dead_vertex(v)) continue;
    auto worst = [&] {
      c.mesh.ball(v, ring);
      double w = 0.0;
      for (const std::uint32_t h : ring)
        if (c.mesh.in_domain(Mesh2::triangle_of(h))) w = std::max(w, triangle_q(c.mesh, Mesh2::triangle_of(h)));
      return w;
    };
    const double before = worst();
    const Vec2 at = c.mesh.point(v);
    const bool moved = try_relocate(c.mesh, v, c.field);
    if (moved) {
      RC_ASSERT(worst() < before);
      RC_ASSERT((c.mesh.flags(v) & (Mesh2::kFixed | Mesh2::kOnBoundary)) == 0);
    } else {
      RC_ASSERT(c.mesh.point(v) == at);
    }
  }
  expect_kept(c.mesh, boundary, area);
}

RC_GTEST_PROP(Optimize2dProperties, CollapsePassKeepsTheMeshValid, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  const std::uint32_t vertices = c.mesh.live_vertex_count();
  const std::uint64_t collapses = collapse_pass(c.mesh);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(c.mesh.live_vertex_count() + collapses == vertices);
}

RC_GTEST_PROP(Optimize2dProperties, SplitPassKeepsTheMeshValid, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  const std::uint32_t vertices = c.mesh.live_vertex_count();
  const SplitPassResult r = split_pass(c.mesh, c.field);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(c.mesh.live_vertex_count() == vertices + r.splits);
}

RC_GTEST_PROP(Optimize2dProperties, BoundarySplitsKeepTheBoundaryLine, ()) {
  RandomCase c = random_case();
  const double area = domain_area(c.mesh);
  SplitOptions options;
  options.boundary = true;
  split_pass(c.mesh, c.field, options);
  c.mesh.check();
  RC_ASSERT(std::fabs(domain_area(c.mesh) - area) <= 1e-12 * area);
  // Every constrained edge lies on the square's sides, and the sides' total length is 4.
  double length = 0.0;
  for (std::uint32_t t = 0; t < c.mesh.triangle_capacity(); ++t) {
    if (!c.mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (!c.mesh.is_constrained(h)) continue;
      const Vec2 &a = c.mesh.point(c.mesh.origin(h)), &b = c.mesh.point(c.mesh.destination(h));
      RC_ASSERT((a.x == b.x && (a.x == 0.0 || a.x == 1.0)) || (a.y == b.y && (a.y == 0.0 || a.y == 1.0)));
      length += norm(b - a);
    }
  }
  RC_ASSERT(std::fabs(length - 4.0) <= 1e-12);
}

RC_GTEST_PROP(Optimize2dProperties, ValencePassNeverWorsens, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  const double before = summarize_quality(c.mesh).worst;
  valence_pass(c.mesh);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(summarize_quality(c.mesh).worst <= before);
}

RC_GTEST_PROP(Optimize2dProperties, StrategyKeepsTheMeshValid, ()) {
  RandomCase c = random_case();
  const Boundary boundary = boundary_of(c.mesh);
  const double area = domain_area(c.mesh);
  Optimize2dOptions options;
  options.valence = *rc::gen::arbitrary<bool>();
  const bool sizes = *rc::gen::arbitrary<bool>();
  options.collapses = options.splits = sizes;
  options.max_rounds = 4;
  const Optimize2dStats stats = optimize2d(c.mesh, options, c.field);
  expect_kept(c.mesh, boundary, area);
  RC_ASSERT(stats.vertices_after == stats.vertices_before + stats.splits - stats.collapses);
  RC_ASSERT(stats.rounds >= 1u && stats.rounds <= options.max_rounds);
  if (!sizes) RC_ASSERT(stats.worst_after <= stats.worst_before);
  const QualitySummary2 after = summarize_quality(c.mesh);
  RC_ASSERT(after.worst == stats.worst_after);
}

// --- The passes' caches give the uncached passes' results, bit for bit -------------------------

// relocate_sweep as it was written before its measures were kept (every ball measured for the
// order, every attempt measuring its ball again): the reference for RelocationSweeps.
std::uint64_t reference_relocate_sweep(Mesh2& mesh, const MetricField2& field) {
  std::vector<std::pair<double, std::uint32_t>> order;
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!optimize2d_detail::is_free(mesh, v, ring)) continue;
    double worst = 0.0;
    for (const std::uint32_t h : ring)
      worst = std::max(worst, optimize2d_detail::quality(mesh, v, mesh.origin(h), mesh.destination(h)));
    order.emplace_back(worst, v);
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::uint64_t moved = 0;
  for (const auto& entry : order) moved += try_relocate(mesh, entry.second, field) ? 1 : 0;
  return moved;
}

std::vector<std::array<double, 5>> points_and_metrics(const Mesh2& mesh) {
  std::vector<std::array<double, 5>> out;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    const Metric2& m = mesh.metric(v);
    out.push_back({mesh.point(v).x, mesh.point(v).y, m.m[0], m.m[1], m.m[2]});
  }
  return out;
}

RC_GTEST_PROP(Optimize2dProperties, RelocationSweepsMoveAsFreshSweeps, ()) {
  RandomCase c = random_case();
  Mesh2 reference = c.mesh;
  RelocationSweeps sweeps(c.mesh, c.field, {});
  for (int k = 0; k < 3; ++k) {
    const std::uint64_t expected = reference_relocate_sweep(reference, c.field);
    RC_ASSERT(sweeps.sweep() == expected);
    RC_ASSERT(points_and_metrics(c.mesh) == points_and_metrics(reference));
  }
}

// The whole-mesh pass (its triangles' Q_K kept until flipped) against the seeded pass (measured
// each time) given the same edges in the same order.
RC_GTEST_PROP(Optimize2dProperties, SwapPassKeptQualitiesSwapAsMeasuredOnes, ()) {
  RandomCase c = random_case();
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t t = 0; t < c.mesh.triangle_capacity(); ++t) {
    if (!c.mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (optimize2d_detail::is_locked(c.mesh, h) || c.mesh.twin(h) < h) continue;
      order.emplace_back(std::max(optimize2d_detail::triangle_quality(c.mesh, t),
                                  optimize2d_detail::triangle_quality(c.mesh, Mesh2::triangle_of(c.mesh.twin(h)))),
                         h);
    }
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::vector<std::uint32_t> seeds;
  for (const auto& e : order) seeds.push_back(e.second);
  Mesh2 reference = c.mesh;
  const SwapPassResult expected = swap_pass(reference, kImprovementMargin, seeds);
  const SwapPassResult r = swap_pass(c.mesh);
  RC_ASSERT(r.swaps == expected.swaps);
  RC_ASSERT(c.mesh.domain().triangles == reference.domain().triangles);
}

}  // namespace
}  // namespace dtlab
