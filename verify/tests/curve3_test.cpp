// Curves and their meshes under a size or metric map (algorithms/surface/curve3): the map length
// of Table 11.1's segment against its closed forms (linear, geometric), every sub-segment of the
// same map length L / n with n the rounding of L, under sizes, metrics (Table 11.2), along arcs,
// polylines and B-splines; B-spline points and derivatives against de Casteljau and differences;
// bad curves and maps refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/surface/curve3.hpp"
#include "kernel/error.hpp"

namespace dtlab {
namespace {

// A size map.
CurveMap sized(std::vector<double> abscissas, std::vector<double> sizes,
               SizeInterpolation mode = SizeInterpolation::Linear) {
  CurveMap map;
  map.abscissas = std::move(abscissas);
  map.sizes = std::move(sizes);
  map.interpolation = mode;
  return map;
}

// Table 11.1: abscissas and sizes along a segment of length 10.
CurveMap table_11_1(SizeInterpolation mode) {
  CurveMap map;
  map.abscissas = {0, 3, 4, 8, 10};
  map.sizes = {1.5, 0.5, 2.0, 0.1, 0.7};
  map.interpolation = mode;
  return map;
}

void expect_unit_pieces(const CurveMesh& mesh) {
  const auto n = mesh.lengths.size();
  ASSERT_GE(n, 1u);
  EXPECT_EQ(static_cast<double>(n), std::max(1.0, std::round(mesh.map_length)));
  for (const double l : mesh.lengths) EXPECT_NEAR(l, mesh.map_length / n, 1e-9 * mesh.map_length);
  for (std::size_t k = 1; k < mesh.parameters.size(); ++k) EXPECT_LT(mesh.parameters[k - 1], mesh.parameters[k]);
}

TEST(CurveMesh, TableElevenOneMatchesTheClosedForms) {
  const Curve3 segment = Curve3::segment({0, 0, 0}, {10, 0, 0});
  const std::vector<double> s{0, 3, 4, 8, 10}, h{1.5, 0.5, 2.0, 0.1, 0.7};
  double linear = 0.0, geometric = 0.0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const double d = s[i + 1] - s[i], a = h[i], b = h[i + 1];
    linear += d / (b - a) * std::log(b / a);
    geometric += d * (1.0 / a - 1.0 / b) / std::log(b / a);
  }
  const CurveMesh l = mesh_curve(segment, table_11_1(SizeInterpolation::Linear));
  const CurveMesh g = mesh_curve(segment, table_11_1(SizeInterpolation::Geometric));
  const CurveMesh sine = mesh_curve(segment, table_11_1(SizeInterpolation::Sinusoidal));
  EXPECT_NEAR(l.map_length, linear, 1e-12 * linear);
  EXPECT_NEAR(g.map_length, geometric, 1e-12 * geometric);
  expect_unit_pieces(l);
  expect_unit_pieces(g);
  expect_unit_pieces(sine);
  // Points on the segment, ends included.
  EXPECT_EQ(l.points.front(), (Vec3{0, 0, 0}));
  EXPECT_EQ(l.points.back(), (Vec3{10, 0, 0}));
}

TEST(CurveMesh, TableElevenTwoUnderMetrics) {
  // (abscissa, angle of the first direction, h1, h2) along the x axis from 0 to 6.
  const double rows[4][4] = {{0, 30, 0.70, 0.25}, {2, 90, 1.10, 0.15}, {3, 0, 0.30, 0.30}, {6, -60, 1.50, 0.40}};
  CurveMap map;
  for (const auto& r : rows) {
    const double a = r[1] * std::numbers::pi / 180.0;
    const Vec3 e1{std::cos(a), std::sin(a), 0}, e2{-std::sin(a), std::cos(a), 0};
    map.abscissas.push_back(r[0]);
    map.metrics.push_back(Metric3::from_sizes(e1, e2, r[2], r[3], 1.0));
  }
  const CurveMesh mesh = mesh_curve(Curve3::segment({0, 0, 0}, {6, 0, 0}), map);
  expect_unit_pieces(mesh);
  EXPECT_GT(mesh.lengths.size(), 6u);  // finer than 1 everywhere along x
}

TEST(CurveMesh, ArcWithAConstantSize) {
  const Curve3 circle = Curve3::circle_arc({1, 2, 0}, {2, 2, 0}, {0, 0, 1}, 2.0 * std::numbers::pi);
  const CurveMesh mesh = mesh_curve(circle, sized({0}, {2.0 * std::numbers::pi / 20.0}));
  EXPECT_EQ(mesh.lengths.size(), 20u);
  expect_unit_pieces(mesh);
  for (const Vec3& p : mesh.points) EXPECT_NEAR(norm(p - Vec3{1, 2, 0}), 1.0, 1e-15);
  for (std::size_t k = 1; k < mesh.points.size(); ++k)
    EXPECT_NEAR(norm(mesh.points[k] - mesh.points[k - 1]), 2.0 * std::sin(std::numbers::pi / 20.0), 1e-12);
}

TEST(CurveMesh, PolylineIsMeshedAcrossItsCorners) {
  const Curve3 l = Curve3::polyline({{0, 0, 0}, {1, 0, 0}, {1, 2, 0}});
  EXPECT_DOUBLE_EQ(l.length(), 3.0);
  EXPECT_EQ(l.point(1.0 / 3.0), (Vec3{1, 0, 0}));
  const CurveMesh mesh = mesh_curve(l, sized({0, 3}, {0.1, 0.3}, SizeInterpolation::Geometric));
  expect_unit_pieces(mesh);
}

TEST(CurveMesh, BSplinePointsDerivativesAndLength) {
  // A clamped cubic with one interior knot, against de Casteljau on each of its two Bézier pieces
  // is not needed: a clamped cubic with no interior knot is the Bézier curve of its controls.
  const std::vector<Vec3> c{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}};
  const Curve3 bezier = Curve3::bspline(c, {0, 0, 0, 0, 1, 1, 1, 1}, 3);
  for (const double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const double u = 1.0 - t;
    const Vec3 expected = (u * u * u) * c[0] + (3 * u * u * t) * c[1] + (3 * u * t * t) * c[2] + (t * t * t) * c[3];
    EXPECT_NEAR(norm(bezier.point(t) - expected), 0.0, 1e-14);
  }
  // A spline with interior knots: derivative against central differences, length against a fine
  // polyline.
  const Curve3 spline = Curve3::bspline({{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 1, 1}, {4, 0, 0}, {5, 1, 0}},
                                        {0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1}, 3);
  for (const double t : {0.1, 0.3, 0.5, 0.85}) {
    const double e = 1e-6;
    const Vec3 fd = (1.0 / (2 * e)) * (spline.point(t + e) - spline.point(t - e));
    EXPECT_NEAR(norm(spline.derivative(t) - fd), 0.0, 1e-6 * norm(fd)) << t;
  }
  double chords = 0.0;
  const int pieces = 200000;
  for (int k = 0; k < pieces; ++k) chords += norm(spline.point((k + 1.0) / pieces) - spline.point(double(k) / pieces));
  EXPECT_NEAR(spline.length(), chords, 1e-8 * chords);
  EXPECT_EQ(spline.breaks().size(), 2u);
  expect_unit_pieces(mesh_curve(spline, sized({0, spline.length()}, {0.05, 0.2})));
  // Degree 1 is the polyline of its controls.
  const Curve3 line = Curve3::bspline({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {0, 0, 0.5, 1, 1}, 1);
  EXPECT_NEAR(norm(line.point(0.75) - Vec3{1, 0.5, 0}), 0.0, 1e-15);
}

void expect_refused(auto&& make, const std::string& words) {
  try {
    make();
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(CurveMesh, RefusesBadCurvesAndMapsByName) {
  expect_refused([] { Curve3::polyline({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}); }, "points 2 and 3 are the same");
  expect_refused([] { Curve3::bspline({{0, 0, 0}, {1, 0, 0}}, {0, 0, 1}, 1); }, "3 knots for 2 control points");
  expect_refused([] { Curve3::bspline({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}}, {0, 0.1, 0.5, 1, 1}, 1); }, "not clamped");
  expect_refused([] { Curve3::circle_arc({0, 0, 0}, {1, 0, 1}, {0, 0, 1}, 1.0); }, "not in the plane");
  const double nan = std::nan("");
  expect_refused([&] { Curve3::segment({0, 0, 0}, {nan, 0, 0}); }, "segment: point 2 is not finite");
  expect_refused([&] { Curve3::polyline({{0, 0, 0}, {1, 0, 0}, {1, HUGE_VAL, 0}}); }, "polyline: point 3 is not finite");
  expect_refused([&] { Curve3::bspline({{0, 0, 0}, {nan, 0, 0}}, {0, 0, 1, 1}, 1); }, "B-spline control: point 2");
  expect_refused([&] { Curve3::circle_arc({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, nan); }, "the angle must be finite");
  const Curve3 segment = Curve3::segment({0, 0, 0}, {1, 0, 0});
  expect_refused([&] { mesh_curve(segment, sized({0, 0}, {1, 1})); }, "abscissa 2");
  expect_refused([&] { mesh_curve(segment, sized({0}, {-1})); }, "size 1");
  expect_refused([&] { mesh_curve(segment, sized({0}, {})); }, "give sizes or metrics");
  expect_refused([&] { mesh_curve(Curve3::segment({1, 1, 1}, {1, 1, 1}), sized({0}, {1})); },
                 "zero length");
}

}  // namespace
}  // namespace dtlab
