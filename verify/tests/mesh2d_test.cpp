// 2D mesh generation (algorithms/mesh2d) and the shared mesh it builds on (mesh/mesh2.hpp): the
// structure's operations keep it valid (Mesh2::check: links, exact orientation, free lists); the
// Delaunay kernel keeps an isotropic mesh constrained Delaunay and an anisotropic one valid; the
// generator's output passes the exact checks (verify/checks_mesh2d.hpp) on fixed domains and on
// random polygons with holes, thin strips and small angles, with uniform, classical and
// anisotropic sizes; it is deterministic; bad input is refused by name.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/mesh2d/delaunay_kernel.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "kernel/interrupt.hpp"
#include "kernel/predicates.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "mesh/mesh_quality.hpp"
#include "verify/checks_mesh2d.hpp"
#include "verify/generators/domains2d.hpp"
#include "verify/tests/interrupt_stops.hpp"

namespace dtlab {
namespace {

using Segment = std::array<std::uint32_t, 2>;

using gen::add_loop;
using gen::square_minus_disc;
using Domain = gen::Domain2;

void expect_valid(const Domain& d, const Mesh2dResult& r) {
  r.mesh.check();
  const MeshCheckReport2 report = check_mesh2d(d.input(), constrained2d(d.input()), r.output);
  EXPECT_TRUE(report.ok) << to_text(report);
}

TEST(Mesh2, FromDataBuildsAClosedStructure) {
  MeshData2 data;
  data.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  data.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  data.triangle_refs = {1, 1, 2, 2};
  data.edges = {{0, 1}};
  data.edge_refs = {7};
  const Mesh2 mesh = mesh2_from_data(data);
  mesh.check();
  EXPECT_EQ(mesh.live_triangle_count(), 8u);  // 4 triangles, 4 ghosts
  EXPECT_EQ(mesh.flags(4), 0);
  EXPECT_EQ(mesh.flags(0), Mesh2::kFixed | Mesh2::kOnBoundary);
  const std::uint32_t h = mesh.find_half_edge(0, 1);
  ASSERT_NE(h, Mesh2::kNone);
  EXPECT_TRUE(mesh.is_constrained(h));
  EXPECT_EQ(mesh.edge_ref(h), 7);
  EXPECT_EQ(mesh.edge_ref(mesh.find_half_edge(1, 2)), 0);
  EXPECT_TRUE(mesh.is_constrained(mesh.find_half_edge(1, 2)));
  EXPECT_FALSE(mesh.is_constrained(mesh.find_half_edge(0, 4)));
  std::vector<std::uint32_t> ring;
  mesh.ball(4, ring);
  EXPECT_EQ(ring.size(), 4u);
  const MeshData2 back = mesh.domain();
  EXPECT_EQ(back.triangles.size(), 4u);
  EXPECT_EQ(back.edges.size(), 4u);
}

TEST(Mesh2, FromDataRefusesBadMeshes) {
  MeshData2 cw;
  cw.vertices = {{0, 0}, {1, 0}, {0, 1}};
  cw.triangles = {{0, 2, 1}};
  EXPECT_THROW(mesh2_from_data(cw), InputError);
  MeshData2 pinched;  // two triangles touching at vertex 0 only
  pinched.vertices = {{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  pinched.triangles = {{0, 1, 2}, {0, 3, 4}};
  try {
    mesh2_from_data(pinched);
    FAIL() << "a pinched vertex was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos) << e.what();
  }
}

TEST(Mesh2, FlipKeepsTheStructureValid) {
  MeshData2 data;
  data.vertices = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  data.triangles = {{0, 1, 2}, {0, 2, 3}};
  data.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  data.edge_refs = {7, 8, 9, 10};
  Mesh2 mesh = mesh2_from_data(data);
  const std::uint32_t h = mesh.find_half_edge(0, 2);
  const std::uint32_t g = mesh.flip(h);
  mesh.check();
  EXPECT_TRUE((mesh.origin(g) == 1 && mesh.destination(g) == 3) || (mesh.origin(g) == 3 && mesh.destination(g) == 1));
  EXPECT_FALSE(mesh.is_constrained(g));
  EXPECT_EQ(mesh.find_half_edge(0, 2), Mesh2::kNone);
  // The outer edges' constraints and references moved with them (nav2::flip's payload hook).
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t e = mesh.find_half_edge(k, (k + 1) % 4);
    ASSERT_NE(e, Mesh2::kNone);
    EXPECT_TRUE(mesh.is_constrained(e));
    EXPECT_EQ(mesh.edge_ref(e), static_cast<int>(7 + k));
  }
}

// The visibility walk of the shared core (nav2::locate) on Mesh2: a vertex, an edge, inside,
// outside the hull, and stopped by constrained edges.
TEST(Mesh2, LocateOnVertexEdgeInsideOutsideAndBlocked) {
  MeshData2 data;
  data.vertices = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}};
  data.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  data.edges = {{0, 4}, {2, 4}};  // with the hull: (2, 3, 4) and (0, 1, 4) on opposite sides
  const Mesh2 mesh = mesh2_from_data(data);
  const std::uint32_t start = Mesh2::triangle_of(mesh.find_half_edge(2, 3));  // (2, 3, 4)
  auto vertices_of = [&](std::uint32_t t) {
    return std::set<std::uint32_t>{mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2)};
  };
  Mesh2::Location at = mesh.locate({1, 1}, start);
  EXPECT_EQ(at.where, Mesh2::Where::Vertex);
  EXPECT_EQ(at.handle, 4u);
  at = mesh.locate({0.5, 0.5}, start);
  ASSERT_EQ(at.where, Mesh2::Where::Edge);
  EXPECT_EQ((std::set{mesh.origin(at.handle), mesh.destination(at.handle)}), (std::set<std::uint32_t>{0, 4}));
  EXPECT_EQ(Mesh2::triangle_of(at.handle), at.triangle);
  at = mesh.locate({1, 0.25}, start);
  ASSERT_EQ(at.where, Mesh2::Where::Triangle);
  EXPECT_EQ(vertices_of(at.triangle), (std::set<std::uint32_t>{0, 1, 4}));
  at = mesh.locate({3, 1}, start);
  ASSERT_EQ(at.where, Mesh2::Where::Outside);
  EXPECT_TRUE(mesh.is_ghost(at.triangle));
  at = mesh.locate({1, 0.25}, start, /*stop_at_constraints=*/true);
  EXPECT_TRUE(at.blocked);
  EXPECT_EQ(at.where, Mesh2::Where::Triangle);
  EXPECT_NE(vertices_of(at.triangle), (std::set<std::uint32_t>{0, 1, 4}));
}

// The kernel with an isotropic metric keeps the mesh Delaunay: every unconstrained interior edge
// passes the exact incircle test.
TEST(DelaunayKernel2, IsotropicInsertionKeepsTheMeshDelaunay) {
  MeshData2 data;
  data.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  data.triangles = {{0, 1, 2}, {0, 2, 3}};
  Mesh2 mesh = mesh2_from_data(data);
  DelaunayKernel2 kernel(mesh);
  std::uint64_t s = 12345;
  std::uint32_t inserted = 0;
  for (int i = 0; i < 400; ++i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const Vec2 p{static_cast<double>(s >> 11) / 9007199254740992.0, static_cast<double>((s * 31) >> 11) / 9007199254740992.0};
    std::uint32_t start = 0;
    while (!mesh.in_domain(start)) ++start;
    const Mesh2::Location loc = mesh.locate(p, start);
    if (loc.where != Mesh2::Where::Triangle && loc.where != Mesh2::Where::Edge) continue;
    if (!kernel.find_cavity(p, Metric2::isotropic(0.1), loc.triangle)) continue;
    kernel.commit(p, Metric2::isotropic(0.1));
    ++inserted;
  }
  mesh.check();
  EXPECT_GT(inserted, 390u);
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (mesh.is_constrained(h) || !mesh.in_domain(Mesh2::triangle_of(mesh.twin(h)))) continue;
      const Vec2 q = mesh.point(mesh.vertex_at(mesh.twin(h)));
      EXPECT_NE(incircle(mesh.point(mesh.vertex(t, 0)), mesh.point(mesh.vertex(t, 1)), mesh.point(mesh.vertex(t, 2)), q),
                Sign::Positive);
    }
  }
}

TEST(DelaunayKernel2, AnisotropicInsertionStaysValid) {
  MeshData2 data;
  data.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  data.triangles = {{0, 1, 2}, {0, 2, 3}};
  Mesh2 mesh = mesh2_from_data(data);
  DelaunayKernel2 kernel(mesh);
  std::uint64_t s = 777;
  for (int i = 0; i < 600; ++i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const Vec2 p{static_cast<double>(s >> 11) / 9007199254740992.0, static_cast<double>((s * 31) >> 11) / 9007199254740992.0};
    const double angle = 3.0 * p.x;
    const Metric2 m = Metric2::from_sizes({std::cos(angle), std::sin(angle)}, 0.5, 0.0005);
    std::uint32_t start = 0;
    while (!mesh.in_domain(start)) ++start;
    const Mesh2::Location loc = mesh.locate(p, start);
    if (loc.where != Mesh2::Where::Triangle && loc.where != Mesh2::Where::Edge) continue;
    if (!kernel.find_cavity(p, m, loc.triangle)) continue;
    kernel.commit(p, m);
  }
  mesh.check();
}

TEST(Mesh2d, SquareWithHoleUniformSize) {
  const Domain d = square_minus_disc(25);
  const Mesh2dResult r = mesh2d(d.input(), {});
  expect_valid(d, r);
  EXPECT_GT(r.output.triangles.size(), 1000u);
  EXPECT_GT(r.stats.field_points, 300u);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_LT(q.quality_worst, 3.0);
  EXPECT_GT(q.unit_edge_share, 0.9);
}

TEST(Mesh2d, ClassicalSizesGradeBetweenFineAndCoarseBoundaries) {
  // A coarse outer square (4 segments a side) around a finely cut circle: sizes grade between.
  Domain d;
  std::vector<Vec2> square;
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < 4; ++i) {
      const double t = i / 4.0;
      square.push_back(s == 0 ? Vec2{t, 0} : s == 1 ? Vec2{1, t} : s == 2 ? Vec2{1 - t, 1} : Vec2{0, 1 - t});
    }
  }
  add_loop(d, square, 1);
  add_loop(d, gen::circle_polygon({0.5, 0.5}, 0.1, 64), 2);
  d.holes.push_back({0.5, 0.5});
  const Mesh2dResult r = mesh2d(d.input(), {});
  expect_valid(d, r);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_LT(q.quality_worst, 4.0);
}

TEST(Mesh2d, RegionsAndMarkersAreKept) {
  Domain d;
  add_loop(d, {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 5);
  // A wall at x = 1 splitting two regions.
  d.points.push_back({1, 0});
  d.points.push_back({1, 1});
  d.segments.push_back({4, 5});
  d.markers.push_back(9);
  d.regions = {{{0.5, 0.5}, 10}, {{1.5, 0.5}, 20}};
  Mesh2dOptions options;
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(0.1), {-1, -1}, {3, 2});
  options.control = &control;
  const Mesh2dResult r = mesh2d(d.input(), options);
  expect_valid(d, r);
  std::size_t left = 0, right = 0;
  for (const int ref : r.output.triangle_refs) (ref == 10 ? left : right) += 1;
  EXPECT_GT(left, 100u);
  EXPECT_GT(right, 100u);
  std::size_t wall_edges = 0;
  for (const int ref : r.output.edge_refs) wall_edges += ref == 9;
  EXPECT_GE(wall_edges, 1u);
}

TEST(Mesh2d, IsDeterministic) {
  const Domain d = square_minus_disc(16);
  const Mesh2dResult a = mesh2d(d.input(), {});
  const Mesh2dResult b = mesh2d(d.input(), {});
  EXPECT_EQ(a.output, b.output);
}

// UGAWG's "linear" boundary layer in 2D: h_x = 0.1, h_y = h0 + 2 (0.1 - h0) |y - 0.5|.
Metric2 linear_layer(const Vec2& p, double h0) {
  const double hy = h0 + 2 * (0.1 - h0) * std::fabs(p.y - 0.5);
  return Metric2::from_sizes({1, 0}, 0.1, hy);
}

TEST(Mesh2d, AnisotropicLinearLayer) {
  Domain d;
  std::vector<Vec2> square;
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < 10; ++i) {
      const double t = i / 10.0;
      square.push_back(s == 0 ? Vec2{t, 0} : s == 1 ? Vec2{1, t} : s == 2 ? Vec2{1 - t, 1} : Vec2{0, 1 - t});
    }
  }
  add_loop(d, square, 1);
  // Background: a 40 x 40 grid with the analytic metric at its vertices.
  MeshData2 bg;
  const int n = 40;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) bg.vertices.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, e = a + n + 1;
      bg.triangles.push_back({a, b, c});
      bg.triangles.push_back({a, c, e});
    }
  }
  std::vector<Metric2> metrics;
  for (const Vec2& p : bg.vertices) metrics.push_back(linear_layer(p, 0.01));
  ControlSpace2 control(bg, metrics);
  Mesh2dOptions options;
  options.control = &control;
  const Mesh2dResult r = mesh2d(d.input(), options);
  expect_valid(d, r);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_GT(q.unit_edge_share, 0.8);
}

TEST(Mesh2d, RefusesAnOpenBoundary) {
  Domain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_THROW(mesh2d(d.input(), {}), InputError);
}

TEST(Mesh2d, RefusesAnUnknownMethod) {
  const Domain d = square_minus_disc(4);
  Mesh2dOptions options;
  options.method = "magic";
  EXPECT_THROW(mesh2d(d.input(), options), InputError);
}

TEST(Mesh2d, RefusesANonPositiveMetric) {
  MeshData2 bg{{{-1, -1}, {3, -1}, {3, 2}, {-1, 2}}, {}, {}, {}, {{0, 1, 2}, {0, 2, 3}}, {0, 0}};
  std::vector<Metric2> metrics(4, Metric2::isotropic(0.1));
  metrics[2].m = {1.0, 2.0, 1.0};  // indefinite
  try {
    ControlSpace2 control(bg, metrics);
    FAIL() << "an indefinite metric was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos) << e.what();
  }
}

// Random star-shaped polygons with a random polygonal hole, random uniform sizes, small angles.
RC_GTEST_PROP(Mesh2dProperty, RandomPolygonsWithHolesMeshValidly, ()) {
  const int n = *rc::gen::inRange(3, 24);
  std::vector<double> radii = *rc::gen::container<std::vector<double>>(n, rc::gen::map(rc::gen::inRange(400, 1000), [](int r) { return r / 1000.0; }));
  Domain d;
  std::vector<Vec2> outer;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    outer.push_back({radii[i] * std::cos(a), radii[i] * std::sin(a)});
  }
  add_loop(d, outer, 1);
  const bool hole = *rc::gen::arbitrary<bool>();
  if (hole) {
    add_loop(d, gen::circle_polygon({0, 0}, 0.2, *rc::gen::inRange(3, 12)), 2);
    d.holes.push_back({0, 0});
  }
  const double h = *rc::gen::inRange(3, 20) / 100.0;
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(h), {-2, -2}, {2, 2});
  Mesh2dOptions options;
  options.control = &control;
  const Mesh2dResult r = mesh2d(d.input(), options);
  r.mesh.check();
  const MeshCheckReport2 report = check_mesh2d(d.input(), constrained2d(d.input()), r.output);
  RC_ASSERT(report.ok);
  // Bounded: no more vertices than the domain's area over the smallest equilateral cell, with room.
  RC_ASSERT(r.output.vertices.size() < 20 * (4.0 / (h * h)) + 200);
}

// A strip 1000 times longer than wide, meshed with sizes from its boundary (classical).
TEST(Mesh2d, ThinStrip) {
  Domain d;
  std::vector<Vec2> loop;
  for (int i = 0; i <= 100; ++i) loop.push_back({i / 100.0, 0});
  loop.push_back({1, 0.001});
  for (int i = 99; i >= 0; --i) loop.push_back({i / 100.0, 0.001});
  add_loop(d, loop, 1);
  const Mesh2dResult r = mesh2d(d.input(), {});
  expect_valid(d, r);
}

// The interrupt check (kernel/interrupt.hpp) is asked between the phases, at each field point
// pass and in each optimization round; answering yes at the k-th question stops the run there by
// Interrupted, naming the place; a check that says no changes nothing in the output.
TEST(Mesh2d, InterruptCheckStopsTheRunWhereItIsAsked) {
  const Domain d = square_minus_disc(25);
  std::uint32_t asked = 0;
  Mesh2dOptions options;
  options.interrupt = [&asked] {
    ++asked;
    return false;
  };
  const Mesh2dResult whole = mesh2d(d.input(), options);
  EXPECT_EQ(whole.output.vertices, mesh2d(d.input(), {}).output.vertices);
  ASSERT_GE(asked, 5u);  // two phases, >= 1 field point pass, >= 1 round of >= 2 questions
  const std::vector<std::pair<std::uint32_t, std::string>> stops{
      {1, "after the empty mesh"}, {2, "after the control space"}, {3, "field points"}, {asked, "optimize2d"}};
  const auto run = [&](InterruptCheck check) {
    options.interrupt = std::move(check);
    (void)mesh2d(d.input(), options);
  };
  for (const auto& stop : stops) test::expect_interrupted_at(run, stop.first, stop.second);
}

}  // namespace
}  // namespace dtlab
