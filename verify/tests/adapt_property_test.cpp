// Properties of the adaptation (algorithms/adapt), on random meshes and fields (RapidCheck):
//  - transfer is exact on linear fields, in 2D between two random jittered grids and in 3D
//    between two Kuhn meshes of the unit cube at random resolutions;
//  - the L∞ metric of a quadratic field is c_2 / ε times its Hessian (the least-squares recovery
//    is exact on quadratics), and normalized to a complexity N its continuous complexity is N;
//  - local adaptation to a random anisotropic layer leaves a valid mesh of the same square, with
//    no inverted triangle, its corners kept, and more unit edges than before.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "algorithms/adapt/adapt2d.hpp"
#include "algorithms/adapt/metric_from_solution.hpp"
#include "algorithms/adapt/transfer.hpp"
#include "mesh/mesh2_from_data.hpp"
#include "verify/generators/grid_meshes.hpp"
#include "verify/generators/kuhn_cubes.hpp"

namespace dtlab {
namespace {

RC_GTEST_PROP(AdaptProperties, Transfer2dIsExactOnLinearFields, ()) {
  const MeshData2 a = gen::jittered_grid(*rc::gen::inRange(2, 13), *rc::gen::inRange(0, 31) / 100.0);
  const MeshData2 b = gen::jittered_grid(*rc::gen::inRange(2, 13), *rc::gen::inRange(0, 31) / 100.0);
  const double c0 = *rc::gen::inRange(-100, 101) / 10.0, c1 = *rc::gen::inRange(-100, 101) / 10.0;
  const double c2 = *rc::gen::inRange(-100, 101) / 10.0;
  auto u = [&](const Vec2& p) { return c0 + c1 * p.x + c2 * p.y; };
  std::vector<double> field;
  for (const Vec2& p : a.vertices) field.push_back(u(p));
  TransferStats st;
  const std::vector<double> w = transfer_field2(a, field, 1, b, {}, &st);
  RC_ASSERT(st.snapped == 0u);
  for (std::size_t v = 0; v < b.vertices.size(); ++v) RC_ASSERT(std::fabs(w[v] - u(b.vertices[v])) <= 1e-10 * (1 + std::fabs(u(b.vertices[v]))));
}

MeshData3 unit_cube(int n) {
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) cells.push_back({i, j, k});
  MeshData3 d = gen::kuhn_cubes(cells);
  for (Vec3& p : d.vertices) p = (1.0 / n) * p;
  return d;
}

RC_GTEST_PROP(AdaptProperties, Transfer3dIsExactOnLinearFields, ()) {
  const MeshData3 a = unit_cube(*rc::gen::inRange(1, 4)), b = unit_cube(*rc::gen::inRange(1, 6));
  const std::array<double, 4> c{*rc::gen::inRange(-100, 101) / 10.0, *rc::gen::inRange(-100, 101) / 10.0,
                                *rc::gen::inRange(-100, 101) / 10.0, *rc::gen::inRange(-100, 101) / 10.0};
  auto u = [&](const Vec3& p) { return c[0] + c[1] * p.x + c[2] * p.y + c[3] * p.z; };
  std::vector<double> field;
  for (const Vec3& p : a.vertices) field.push_back(u(p));
  TransferStats st;
  const std::vector<double> w = transfer_field3(a, field, 1, b, {}, &st);
  RC_ASSERT(st.located == b.vertices.size());
  for (std::size_t v = 0; v < b.vertices.size(); ++v) RC_ASSERT(std::fabs(w[v] - u(b.vertices[v])) <= 1e-10 * (1 + std::fabs(u(b.vertices[v]))));
}

RC_GTEST_PROP(AdaptProperties, LInfinityMetricOfAQuadraticIsItsScaledHessian, ()) {
  // H = R diag(l1, l2) R^T, u = x^T H x / 2 (centred in the square).
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101);
  const double t = *rc::gen::inRange(0, 180) * std::numbers::pi / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  const std::array<double, 3> h{c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2};
  const MeshData2 mesh = gen::jittered_grid(*rc::gen::inRange(4, 11), *rc::gen::inRange(0, 31) / 100.0);
  std::vector<std::vector<double>> fields(1);
  for (const Vec2& p : mesh.vertices) {
    const double x = p.x - 0.5, y = p.y - 0.5;
    fields[0].push_back(0.5 * (h[0] * x * x + 2 * h[1] * x * y + h[2] * y * y));
  }
  SolutionMetricOptions options;
  options.error = 0.01;
  const std::vector<Metric2> m = metric_from_solutions(mesh.vertices, mesh.triangles, fields, options);
  const double scale = (2.0 / 9.0) / 0.01;  // c_2 / ε
  for (const Metric2& x : m)
    for (int k = 0; k < 3; ++k) RC_ASSERT(std::fabs(x.m[k] - scale * h[k]) <= 1e-6 * scale * (l1 + l2));
  // Normalized to a complexity N: its continuous complexity is N, the closed form's and that of
  // the metric delivered, clipped to the default [1e-8, 1] of the diagonal (issue 42, item 6).
  SolutionMetricOptions with_n;
  with_n.complexity = *rc::gen::inRange(50, 5001);
  SolutionMetricStats stats;
  metric_from_solutions(mesh.vertices, mesh.triangles, fields, with_n, &stats);
  RC_ASSERT(std::fabs(stats.complexity_before_clipping - *with_n.complexity) <= 1e-9 * *with_n.complexity);
  RC_ASSERT(std::fabs(stats.complexity - *with_n.complexity) <= 1e-6 * *with_n.complexity);
}

RC_GTEST_PROP(AdaptProperties, LocalAdaptationStaysValidAndGetsCloserToUnit, ()) {
  const MeshData2 input = gen::jittered_grid(*rc::gen::inRange(4, 11), *rc::gen::inRange(0, 31) / 100.0);
  // A layer along a random direction through the centre: h_normal from h0 up to 0.2, h_along 0.2.
  const double t = *rc::gen::inRange(0, 180) * std::numbers::pi / 180.0;
  const double h0 = *rc::gen::inRange(10, 51) / 1000.0;
  const Vec2 along{std::cos(t), std::sin(t)};
  std::vector<Metric2> metrics;
  for (const Vec2& p : input.vertices) {
    const double d = std::fabs(cross(along, p - Vec2{0.5, 0.5}));
    metrics.push_back(Metric2::from_sizes(along, 0.2, std::min(0.2, h0 + 0.5 * d)));
  }
  const ControlSpace2 control(input, metrics);
  Mesh2 mesh = mesh2_from_data(input);
  const Adapt2dStats s = adapt2d(mesh, control);
  mesh.check();  // throws InternalError if the structure is broken
  RC_ASSERT(s.after.inverted == 0u);
  RC_ASSERT(s.after.flat == 0u);
  RC_ASSERT(std::fabs(s.after.measure - 1.0) <= 1e-12);
  RC_ASSERT(s.corners == 4u);
  RC_ASSERT(s.after.unit_edge_share > s.before.unit_edge_share);
  RC_ASSERT(s.after.mean_ratio_worst > 0.0);
}

}  // namespace
}  // namespace dtlab
