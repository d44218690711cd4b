// The advancing-front field point placement of the 2D mesher (algorithms/mesh2d/front_points.cpp,
// --method front): its output passes the exact checks (verify/checks_mesh2d.hpp) and Mesh2::check on
// a square minus a disc with a uniform size, with classical sizes, with a uniform anisotropic
// metric, and on random star-shaped polygons with holes; its quality figures are those of a unit
// mesh; it is deterministic.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "mesh/mesh_quality.hpp"
#include "verify/checks_mesh2d.hpp"
#include "verify/generators/domains2d.hpp"

namespace dtlab {
namespace {

using Segment = std::array<std::uint32_t, 2>;

using gen::add_loop;
using gen::square_minus_disc;
using Domain = gen::Domain2;

// A uniform metric on two triangles around the domain [lo, hi]^2.
ControlSpace2 uniform_control(double lo, double hi, const Metric2& m) { return ControlSpace2::uniform(m, {lo, lo}, {hi, hi}); }

// The front method's own output: optimization off, so that the figures measure the placement.
Mesh2dOptions front_options(const ControlSpace2* control) {
  Mesh2dOptions options;
  options.method = "front";
  options.control = control;
  options.optimize = false;
  return options;
}

void expect_valid(const Domain& d, const Mesh2dResult& r) {
  r.mesh.check();
  const MeshCheckReport2 report = check_mesh2d(d.input(), constrained2d(d.input()), r.output);
  EXPECT_TRUE(report.ok) << to_text(report);
}

TEST(Mesh2dFront, SquareWithHoleUniformSize) {
  // Boundary spacing 0.05 (n = 20) matches the size: the boundary edges are unit.
  const Domain d = square_minus_disc(20);
  const ControlSpace2 control = uniform_control(-1, 2, Metric2::isotropic(0.05));
  const Mesh2dResult r = mesh2d(d.input(), front_options(&control));
  expect_valid(d, r);
  // Area 1 - 0.04 pi over the unit equilateral triangle's sqrt(3)/4 h^2: about 590 triangles.
  EXPECT_GT(r.output.triangles.size(), 400u);
  EXPECT_LT(r.output.triangles.size(), 900u);
  EXPECT_GT(r.stats.field_points, 100u);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_LT(q.quality_worst, 3.0);
  EXPECT_GT(q.unit_edge_share, 0.9);
  EXPECT_EQ(q.inverted + q.flat, 0u);
}

TEST(Mesh2dFront, ClassicalSizes) {
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
  const Mesh2dResult r = mesh2d(d.input(), front_options(nullptr));
  expect_valid(d, r);
  EXPECT_GT(r.stats.field_points, 50u);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_LT(q.quality_worst, 4.0);
  EXPECT_GT(q.unit_edge_share, 0.7);
}

TEST(Mesh2dFront, UniformAnisotropicMetric) {
  // Sizes 0.1 along x, 0.01 along y; the boundary is cut to match (10 pieces along x, 100 along y).
  Domain d;
  std::vector<Vec2> loop;
  for (int i = 0; i < 10; ++i) loop.push_back({i / 10.0, 0});
  for (int i = 0; i < 100; ++i) loop.push_back({1, i / 100.0});
  for (int i = 10; i > 0; --i) loop.push_back({i / 10.0, 1});
  for (int i = 100; i > 0; --i) loop.push_back({0, i / 100.0});
  add_loop(d, loop, 1);
  const ControlSpace2 control = uniform_control(-1, 2, Metric2::from_sizes({1, 0}, 0.1, 0.01));
  const Mesh2dResult r = mesh2d(d.input(), front_options(&control));
  expect_valid(d, r);
  // 1 / (sqrt(3)/4 * 0.1 * 0.01): about 2300 unit triangles.
  EXPECT_GT(r.output.triangles.size(), 1500u);
  const QualityReport q = measure_quality(r.output.vertices, r.output.triangles, r.output_metrics);
  EXPECT_GT(q.unit_edge_share, 0.85);
  EXPECT_LT(q.quality_worst, 4.0);
  // Stretched in the Euclidean sense (ratio 10): unit triangles of the metric are far from equilateral.
  const QualityReport euclidean = measure_quality(r.output.vertices, r.output.triangles);
  EXPECT_GT(euclidean.quality_mean, 4.0);
}

TEST(Mesh2dFront, IsDeterministic) {
  const Domain d = square_minus_disc(16);
  const ControlSpace2 control = uniform_control(-1, 2, Metric2::isotropic(0.04));
  const Mesh2dResult a = mesh2d(d.input(), front_options(&control));
  const Mesh2dResult b = mesh2d(d.input(), front_options(&control));
  EXPECT_EQ(a.output, b.output);
  EXPECT_EQ(a.stats.field_points, b.stats.field_points);
  EXPECT_EQ(a.stats.filtered, b.stats.filtered);
}

TEST(Mesh2dFront, DiffersFromTheEdgeMethod) {
  // The dispatch reaches the front method: its point counts are its own.
  const Domain d = square_minus_disc(20);
  const ControlSpace2 control = uniform_control(-1, 2, Metric2::isotropic(0.05));
  Mesh2dOptions edge = front_options(&control);
  edge.method = "edge";
  const Mesh2dResult e = mesh2d(d.input(), edge);
  const Mesh2dResult f = mesh2d(d.input(), front_options(&control));
  EXPECT_NE(e.output, f.output);
}

TEST(Mesh2dFront, VertexBoundIsNamed) {
  const Domain d = square_minus_disc(20);
  const ControlSpace2 control = uniform_control(-1, 2, Metric2::isotropic(0.05));
  Mesh2dOptions options = front_options(&control);
  options.max_vertices = 200;
  try {
    mesh2d(d.input(), options);
    FAIL() << "the vertex bound was not enforced";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex bound"), std::string::npos) << e.what();
  }
}

// Random star-shaped polygons with a random polygonal hole, random uniform sizes, small angles.
RC_GTEST_PROP(Mesh2dFrontProperty, RandomPolygonsWithHolesMeshValidly, ()) {
  const int n = *rc::gen::inRange(3, 24);
  const std::vector<double> radii =
      *rc::gen::container<std::vector<double>>(n, rc::gen::map(rc::gen::inRange(400, 1000), [](int r) { return r / 1000.0; }));
  Domain d;
  std::vector<Vec2> outer;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    outer.push_back({radii[i] * std::cos(a), radii[i] * std::sin(a)});
  }
  add_loop(d, outer, 1);
  if (*rc::gen::arbitrary<bool>()) {
    add_loop(d, gen::circle_polygon({0, 0}, 0.2, *rc::gen::inRange(3, 12)), 2);
    d.holes.push_back({0, 0});
  }
  const double h = *rc::gen::inRange(5, 20) / 100.0;
  const ControlSpace2 control = uniform_control(-2, 2, Metric2::isotropic(h));
  const Mesh2dResult r = mesh2d(d.input(), front_options(&control));
  r.mesh.check();
  const MeshCheckReport2 report = check_mesh2d(d.input(), constrained2d(d.input()), r.output);
  RC_ASSERT(report.ok);
  RC_ASSERT(r.output.vertices.size() < 20 * (4.0 / (h * h)) + 200);
}

}  // namespace
}  // namespace dtlab
