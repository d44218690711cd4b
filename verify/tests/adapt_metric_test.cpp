// Metrics from solutions (algorithms/adapt/hessian.hpp, metric_from_solution.hpp): the least
// squares recovery is exact on quadratics (boundary vertices included), the double L2 projection
// converges on a smooth field, a linear field has no Hessian; the L∞ metric of x² + 100 y² is the
// closed form; the Lp metric has exactly the complexity asked, whatever the field's scale, after
// the clipping to [h_min, h_max] too (and a complexity those cannot reach is refused); the
// intersection of two fields' metrics lies inside both; a tanh layer gives metrics stretched
// along it; h_min / h_max hold; bad input is named: a field linear to round-off (2D and 3D), a
// size bound out of range, a target error whose metric leaves the doubles.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/adapt/metric_from_solution.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"
#include "verify/generators/domains2d.hpp"

namespace dtlab {
namespace {

// The unit square at size h (mesh2d), its sides cut into n pieces.
MeshData2 square_mesh(int n, double h) {
  gen::Domain2 d;
  std::vector<Vec2> loop;
  for (int s = 0; s < 4; ++s)
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      loop.push_back(s == 0 ? Vec2{t, 0} : s == 1 ? Vec2{1, t} : s == 2 ? Vec2{1 - t, 1} : Vec2{0, 1 - t});
    }
  gen::add_loop(d, loop, 1);
  const ControlSpace2 control = ControlSpace2::uniform(Metric2::isotropic(h), {-1, -1}, {2, 2});
  Mesh2dOptions options;
  options.control = &control;
  return mesh2d(d.input(), options).output;
}

// The unit cube cut into n^3 cells of 6 tetrahedra each (Kuhn's triangulation, all positive).
struct TetMesh {
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
};
TetMesh cube_mesh(int n) {
  TetMesh m;
  auto id = [n](int i, int j, int k) { return static_cast<std::uint32_t>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.push_back({double(i) / n, double(j) / n, double(k) / n});
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          std::array<std::uint32_t, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &cc = m.points[t[2]], &d = m.points[t[3]];
          if (dot(cross(b - a, cc - a), d - a) < 0) std::swap(t[2], t[3]);
          m.tetrahedra.push_back(t);
        }
  return m;
}

template <class P>
std::vector<double> sample(const std::vector<P>& points, const std::function<double(const P&)>& f) {
  std::vector<double> v;
  for (const P& p : points) v.push_back(f(p));
  return v;
}

TEST(HessianRecovery, LeastSquaresIsExactOnQuadratics2d) {
  const MeshData2 mesh = square_mesh(8, 0.1);
  const auto u = sample<Vec2>(mesh.vertices, [](const Vec2& p) {
    return 1 + 2 * p.x - p.y + 3 * p.x * p.x + 4 * p.x * p.y - 5 * p.y * p.y;
  });
  const auto h = recover_hessian(mesh.vertices, mesh.triangles, u, HessianRecovery::LeastSquares);
  for (const auto& t : h) {  // every vertex, the boundary's included
    EXPECT_NEAR(t[0], 6.0, 1e-8);
    EXPECT_NEAR(t[1], 4.0, 1e-8);
    EXPECT_NEAR(t[2], -10.0, 1e-8);
  }
}

TEST(HessianRecovery, LeastSquaresIsExactOnQuadratics3d) {
  const TetMesh mesh = cube_mesh(4);
  const auto u = sample<Vec3>(mesh.points, [](const Vec3& p) {
    return p.x * p.x - 2 * p.y * p.y + 0.5 * p.z * p.z + 3 * p.x * p.y - p.x * p.z + 2 * p.y * p.z + p.x - 7;
  });
  const auto h = recover_hessian(mesh.points, mesh.tetrahedra, u, HessianRecovery::LeastSquares);
  const double expected[6] = {2, 3, -4, -1, 2, 1};  // h11 h12 h22 h13 h23 h33
  for (const auto& t : h)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(t[k], expected[k], 1e-8) << k;
}

TEST(HessianRecovery, BothMethodsGiveZeroOnLinearFields) {
  const MeshData2 mesh = square_mesh(6, 0.12);
  const auto u = sample<Vec2>(mesh.vertices, [](const Vec2& p) { return 3 * p.x - 2 * p.y + 1; });
  for (const HessianRecovery m : {HessianRecovery::LeastSquares, HessianRecovery::L2Projection})
    for (const auto& t : recover_hessian(mesh.vertices, mesh.triangles, u, m))
      for (const double x : t) EXPECT_NEAR(x, 0.0, 1e-9);
}

// The error of the recovered h11 of sin(2x) e^y at vertices at least 0.2 from the boundary (the
// L2 projection is one-sided there): the largest, and the mean.
struct RecoveryError {
  double max = 0.0, mean = 0.0;
};
RecoveryError interior_error(const MeshData2& mesh, HessianRecovery method) {
  const auto u = sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::sin(2 * p.x) * std::exp(p.y); });
  const auto h = recover_hessian(mesh.vertices, mesh.triangles, u, method);
  RecoveryError e;
  int count = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec2 p = mesh.vertices[v];
    if (std::min({p.x, p.y, 1 - p.x, 1 - p.y}) < 0.2) continue;
    const double x = std::fabs(h[v][0] + 4 * std::sin(2 * p.x) * std::exp(p.y));
    e.max = std::max(e.max, x);
    e.mean += x;
    ++count;
  }
  e.mean /= count;
  return e;
}

// Measured on these meshes (h = 0.1, 0.05, 0.025, 0.0125): least squares, max 0.33, 0.13, 0.071,
// 0.035 (first order); the double L2 projection, mean 0.12, 0.068, 0.057, 0.029 but max 0.33,
// 0.29, 0.53, 0.41: on unstructured meshes it is not consistent pointwise (the lumped projection
// is exact only on symmetric patches), which is why least squares is the default.
TEST(HessianRecovery, LeastSquaresConvergesPointwiseL2ProjectionOnAverage) {
  const MeshData2 coarse = square_mesh(10, 0.1), fine = square_mesh(40, 0.025);
  const RecoveryError lsq1 = interior_error(coarse, HessianRecovery::LeastSquares);
  const RecoveryError lsq2 = interior_error(fine, HessianRecovery::LeastSquares);
  EXPECT_LT(lsq2.max, 0.4 * lsq1.max) << lsq1.max << " -> " << lsq2.max;
  const RecoveryError l2_1 = interior_error(coarse, HessianRecovery::L2Projection);
  const RecoveryError l2_2 = interior_error(fine, HessianRecovery::L2Projection);
  EXPECT_LT(l2_2.mean, 0.7 * l2_1.mean) << l2_1.mean << " -> " << l2_2.mean;
}

TEST(SolutionMetric, LinfOfAQuadraticIsItsClosedForm) {
  const MeshData2 mesh = square_mesh(6, 0.15);
  const auto u = sample<Vec2>(mesh.vertices, [](const Vec2& p) { return p.x * p.x + 100 * p.y * p.y; });
  SolutionMetricOptions o;
  o.error = 0.01;
  const std::vector<std::vector<double>> fields{u};
  const auto m = metric_from_solutions(mesh.vertices, mesh.triangles, fields, o);
  const double c = 2.0 / 9.0 / 0.01;
  for (const Metric2& x : m) {
    EXPECT_NEAR(x.m[0], 2 * c, 1e-6 * c);
    EXPECT_NEAR(x.m[1], 0.0, 1e-6 * c);
    EXPECT_NEAR(x.m[2], 200 * c, 1e-6 * c);
  }
}

TEST(SolutionMetric, LpMetricHasTheComplexityAsked) {
  const MeshData2 mesh = square_mesh(20, 0.05);
  const auto u = sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::tanh(20 * (p.y - 0.5 - 0.2 * std::sin(6 * p.x))); });
  const std::vector<std::vector<double>> fields{u};
  for (const double p : {1.0, 2.0, 4.0, std::numeric_limits<double>::infinity()}) {
    SolutionMetricOptions o;
    o.p = p;
    o.complexity = 1234.0;
    SolutionMetricStats s;
    metric_from_solutions(mesh.vertices, mesh.triangles, fields, o, &s);
    EXPECT_NEAR(s.complexity_before_clipping, 1234.0, 1e-9 * 1234.0) << "p = " << p;
  }
  const TetMesh cube = cube_mesh(5);
  const std::vector<std::vector<double>> fields3{sample<Vec3>(cube.points, [](const Vec3& q) { return std::tanh(10 * (q.x + q.y - q.z)); })};
  SolutionMetricOptions o;
  o.p = 2.0;
  o.complexity = 5000.0;
  SolutionMetricStats s;
  metric_from_solutions(cube.points, cube.tetrahedra, fields3, o, &s);
  EXPECT_NEAR(s.complexity_before_clipping, 5000.0, 1e-9 * 5000.0);
}

TEST(SolutionMetric, IntersectionLiesInsideEveryFieldsMetric) {
  const MeshData2 mesh = square_mesh(10, 0.1);
  const std::vector<std::vector<double>> fields{
      sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::tanh(10 * (p.x - 0.4)); }),
      sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::exp(3 * p.y) * p.x; })};
  SolutionMetricOptions o;
  o.error = 0.01;
  const auto both = metric_from_solutions(mesh.vertices, mesh.triangles, fields, o);
  for (std::size_t f = 0; f < 2; ++f) {
    const std::vector<std::vector<double>> one{fields[f]};
    const auto single = metric_from_solutions(mesh.vertices, mesh.triangles, one, o);
    for (std::size_t v = 0; v < both.size(); ++v)
      for (int k = 0; k < 16; ++k) {
        const Vec2 d{std::cos(k * 0.3927), std::sin(k * 0.3927)};
        EXPECT_GE(both[v].length(d), single[v].length(d) * (1 - 1e-9));  // the unit ball is inside
      }
  }
}

TEST(SolutionMetric, TanhLayerStretchesAlongTheLayerWithinTheSizeBounds) {
  const MeshData2 mesh = square_mesh(40, 0.025);
  const std::vector<std::vector<double>> fields{sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::tanh(10 * (p.y - 0.5)); })};
  SolutionMetricOptions o;
  o.complexity = 2000.0;
  o.h_min = 1e-3;
  o.h_max = 0.2;
  SolutionMetricStats s;
  const auto m = metric_from_solutions(mesh.vertices, mesh.triangles, fields, o, &s);
  EXPECT_GE(s.h_min, 1e-3 * (1 - 1e-12));
  EXPECT_LE(s.h_max, 0.2 * (1 + 1e-12));
  std::uint32_t checked = 0;
  for (std::size_t v = 0; v < m.size(); ++v) {
    const Vec2 p = mesh.vertices[v];
    if (std::fabs(p.y - 0.5) > 0.12 || std::fabs(p.y - 0.5) < 0.03 || p.x < 0.1 || p.x > 0.9) continue;
    const MetricEigen2 e = eigen(m[v]);
    EXPECT_GT(std::fabs(e.vectors[1].y), 0.98) << p.x << " " << p.y;  // the small size across the layer
    EXPECT_GT(e.values[1] / e.values[0], 10.0);
    ++checked;
  }
  EXPECT_GT(checked, 20u);
}

// The message of the InputError that f throws (fails the test if none).
std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(SolutionMetric, LinearFieldIsRefusedAsRoundOffIn2dAnd3d) {
  const MeshData2 mesh = square_mesh(10, 0.1);
  const TetMesh cube = cube_mesh(4);
  for (const HessianRecovery r : {HessianRecovery::LeastSquares, HessianRecovery::L2Projection}) {
    SolutionMetricOptions complexity;
    complexity.complexity = 2000;
    complexity.recovery = r;
    SolutionMetricOptions error;
    error.error = 0.01;
    error.recovery = r;
    for (const double scale : {1.0, 1e-300, 1e300}) {
      const std::vector<std::vector<double>> f2{sample<Vec2>(mesh.vertices, [&](const Vec2& p) { return scale * (2 * p.x + 3 * p.y + 0.1); })};
      const std::vector<std::vector<double>> f3{sample<Vec3>(cube.points, [&](const Vec3& p) { return scale * (2 * p.x + 3 * p.y - p.z); })};
      for (const SolutionMetricOptions& o : {complexity, error}) {
        EXPECT_NE(refusal([&] { metric_from_solutions(mesh.vertices, mesh.triangles, f2, o); }).find("linear to round-off"),
                  std::string::npos);
        EXPECT_NE(refusal([&] { metric_from_solutions(cube.points, cube.tetrahedra, f3, o); }).find("linear to round-off"),
                  std::string::npos);
      }
    }
  }
}

TEST(SolutionMetric, FieldLinearInOneRegionAndCurvedElsewhereHasTheComplexityAsked) {
  const MeshData2 mesh = square_mesh(20, 0.05);
  const std::vector<std::vector<double>> fields{sample<Vec2>(mesh.vertices, [](const Vec2& p) {
    return 2 * p.x + 3 * p.y + std::pow(std::max(p.x - 0.5, 0.0), 3);
  })};
  SolutionMetricOptions o;
  o.complexity = 2000;
  o.h_max = 0.3;
  SolutionMetricStats s;
  const auto m = metric_from_solutions(mesh.vertices, mesh.triangles, fields, o, &s);
  EXPECT_NEAR(s.complexity_before_clipping, 2000.0, 1e-9 * 2000.0);
  for (std::size_t v = 0; v < m.size(); ++v) {  // the linear half gets h_max, the curved one less
    if (mesh.vertices[v].x < 0.4) {
      EXPECT_NEAR(sizes(m[v])[1], 0.3, 1e-9) << v;
    }
  }
  EXPECT_LT(s.h_min, 0.05);
}

TEST(SolutionMetric, MetricForAComplexityDoesNotDependOnAScalingOfTheField) {
  const MeshData2 mesh = square_mesh(10, 0.1);
  const auto f = [](const Vec2& p) { return p.x * p.x + 3 * p.y * p.y + std::sin(3 * p.x * p.y); };
  SolutionMetricOptions o;
  o.complexity = 2000;
  const std::vector<std::vector<double>> unit{sample<Vec2>(mesh.vertices, f)};
  const auto reference = metric_from_solutions(mesh.vertices, mesh.triangles, unit, o);
  for (const double scale : {1e300, 1e-300, -7.0}) {
    const std::vector<std::vector<double>> scaled{sample<Vec2>(mesh.vertices, [&](const Vec2& p) { return scale * f(p); })};
    SolutionMetricStats s;
    const auto m = metric_from_solutions(mesh.vertices, mesh.triangles, scaled, o, &s);
    EXPECT_NEAR(s.complexity_before_clipping, 2000.0, 1e-9 * 2000.0) << scale;
    for (std::size_t v = 0; v < m.size(); ++v)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(m[v].m[k], reference[v].m[k], 1e-6 * std::fabs(reference[v].m[0] + reference[v].m[2])) << scale;
  }
  // With a target error the scale matters; one that takes the sizes out of the doubles is refused.
  SolutionMetricOptions e;
  e.error = 1e-3;
  const std::vector<std::vector<double>> huge{sample<Vec2>(mesh.vertices, [&](const Vec2& p) { return 1e300 * f(p); })};
  EXPECT_NE(refusal([&] { metric_from_solutions(mesh.vertices, mesh.triangles, huge, e); }).find("out of the representable range"),
            std::string::npos);
}

// Issue 42, item 6: x² is curved along x only, so the closed form spends the complexity on the
// floored y eigenvalue (sizes 1e6 times h_max) and the clipping to h_max then inflated it (2000
// asked gave about 3e4 delivered). The constant is now solved for the clipped metric.
TEST(SolutionMetric, ClippedMetricHasTheComplexityAsked) {
  const MeshData2 mesh = square_mesh(20, 0.05);
  const auto f = [](const Vec2& p) { return p.x * p.x; };
  const std::vector<std::vector<double>> unit{sample<Vec2>(mesh.vertices, f)};
  for (const double p : {2.0, std::numeric_limits<double>::infinity()}) {
    SolutionMetricOptions o;
    o.p = p;
    o.complexity = 2000;
    SolutionMetricStats s;
    const auto reference = metric_from_solutions(mesh.vertices, mesh.triangles, unit, o, &s);
    EXPECT_NEAR(s.complexity, 2000.0, 1e-6 * 2000.0) << "p = " << p;
    EXPECT_EQ(s.complexity, s.complexity_before_gradation);
    // On the unit square (the recovery is exact on x²): along y the default h_max, the diagonal
    // sqrt 2 (lambda 0.5); along x lambda with sqrt(0.5 lambda) = 2000, size 3.54e-4 (the closed
    // form's was 2e9, size 2.2e-5, i.e. s = 0.004).
    EXPECT_NEAR(s.normalisation_scale, 0.004, 1e-6) << "p = " << p;
    EXPECT_NEAR(s.h_max, std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(s.h_min, 1 / std::sqrt(8e6), 1e-6 / std::sqrt(8e6));
    // Scale invariance holds through the solve: 1e300 x² gives the metric of x².
    const std::vector<std::vector<double>> huge{sample<Vec2>(mesh.vertices, [&](const Vec2& q) { return 1e300 * f(q); })};
    const auto m = metric_from_solutions(mesh.vertices, mesh.triangles, huge, o);
    for (std::size_t v = 0; v < m.size(); ++v)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(m[v].m[k], reference[v].m[k], 1e-6 * std::fabs(reference[v].m[0] + reference[v].m[2])) << p;
  }
  // With bounds that bind at both ends, and in 3D.
  SolutionMetricOptions bounded;
  bounded.complexity = 3000;
  bounded.h_min = 0.01;
  bounded.h_max = 0.2;
  SolutionMetricStats s;
  const std::vector<std::vector<double>> layer{
      sample<Vec2>(mesh.vertices, [](const Vec2& p) { return std::tanh(40 * (p.y - 0.5)); })};
  metric_from_solutions(mesh.vertices, mesh.triangles, layer, bounded, &s);
  EXPECT_NEAR(s.complexity, 3000.0, 1e-6 * 3000.0);
  EXPECT_NEAR(s.h_min, 0.01, 1e-9);
  const TetMesh cube = cube_mesh(5);
  const std::vector<std::vector<double>> f3{sample<Vec3>(cube.points, [](const Vec3& q) { return q.x * q.x; })};
  SolutionMetricOptions o3;
  o3.p = 2.0;
  o3.complexity = 5000.0;
  metric_from_solutions(cube.points, cube.tetrahedra, f3, o3, &s);
  EXPECT_NEAR(s.complexity, 5000.0, 1e-6 * 5000.0);
  // The gradation comes after and only grows the metric.
  SolutionMetricOptions graded;
  graded.complexity = 2000;
  graded.gradation = 1.5;
  metric_from_solutions(mesh.vertices, mesh.triangles, layer, graded, &s);
  EXPECT_NEAR(s.complexity_before_gradation, 2000.0, 1e-6 * 2000.0);
  EXPECT_GE(s.complexity, s.complexity_before_gradation * (1 - 1e-12));
}

TEST(SolutionMetric, ComplexityTheSizeBoundsCannotReachIsRefused) {
  const MeshData2 mesh = square_mesh(10, 0.1);
  const std::vector<std::vector<double>> fields{sample<Vec2>(mesh.vertices, [](const Vec2& p) { return p.x * p.x; })};
  SolutionMetricOptions o;
  o.complexity = 1e12;
  o.h_min = 0.1;  // the unit square holds about 100 of these
  const std::string above = refusal([&] { metric_from_solutions(mesh.vertices, mesh.triangles, fields, o); });
  EXPECT_NE(above.find("complexity 1e+12 is above the complexity of the all-h_min metric"), std::string::npos) << above;
  EXPECT_NE(above.find("reach complexities 0.5 (every size h_max) to 100 (every size h_min)"), std::string::npos) << above;
  o.complexity = 0.1;  // h_max, the diagonal sqrt 2, already gives 0.5
  o.h_min.reset();
  const std::string below = refusal([&] { metric_from_solutions(mesh.vertices, mesh.triangles, fields, o); });
  EXPECT_NE(below.find("complexity 0.1 is below the complexity of the all-h_max metric"), std::string::npos) << below;
  o.complexity = 100;  // the all-h_min end itself is reachable
  o.h_min = 0.1;
  SolutionMetricStats s;
  metric_from_solutions(mesh.vertices, mesh.triangles, fields, o, &s);
  EXPECT_NEAR(s.complexity, 100.0, 1e-6 * 100.0);
}

TEST(SolutionMetric, SizeBoundsOutOfRangeAreRefusedWithTheirValue) {
  const MeshData2 mesh = square_mesh(4, 0.3);
  const std::vector<std::vector<double>> fields{sample<Vec2>(mesh.vertices, [](const Vec2& p) { return p.x * p.x; })};
  auto message = [&](std::optional<double> h_min, std::optional<double> h_max) {
    SolutionMetricOptions o;
    o.complexity = 100;
    o.h_min = h_min;
    o.h_max = h_max;
    return refusal([&] { metric_from_solutions(mesh.vertices, mesh.triangles, fields, o); });
  };
  const std::string huge = message(std::nullopt, 1e200);
  EXPECT_NE(huge.find("h_max = 1e+200"), std::string::npos) << huge;
  EXPECT_NE(huge.find("representable range"), std::string::npos) << huge;
  const std::string tiny = message(1e-200, std::nullopt);
  EXPECT_NE(tiny.find("h_min = 1e-200"), std::string::npos) << tiny;
  EXPECT_NE(tiny.find("representable range"), std::string::npos) << tiny;
  const std::string floor = message(1e-12, std::nullopt);  // the diagonal is sqrt 2: floor 1.4e-9
  EXPECT_NE(floor.find("h_min = 1e-12"), std::string::npos) << floor;
  EXPECT_NE(floor.find("diagonal"), std::string::npos) << floor;
}

TEST(SolutionMetric, BadInputIsNamed) {
  const MeshData2 mesh = square_mesh(4, 0.3);
  std::vector<double> u(mesh.vertices.size(), 1.0);
  SolutionMetricOptions o;
  o.complexity = 100;
  auto run = [&](std::vector<double> f, const SolutionMetricOptions& opt) {
    const std::vector<std::vector<double>> fields{std::move(f)};
    return metric_from_solutions(mesh.vertices, mesh.triangles, fields, opt);
  };
  std::vector<double> short_u(u.begin(), u.end() - 1);
  EXPECT_THROW(run(short_u, o), InputError);
  std::vector<double> nan_u = u;
  nan_u[2] = std::nan("");
  try {
    run(nan_u, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(run(u, o), InputError);  // constant: nothing to distribute
  SolutionMetricOptions both = o;
  both.error = 0.1;
  EXPECT_THROW(run(u, both), InputError);
  SolutionMetricOptions lp_error;
  lp_error.error = 0.1;
  lp_error.p = 2;
  EXPECT_THROW(run(u, lp_error), InputError);
  SolutionMetricOptions bounds = o;
  bounds.h_min = 0.5;
  bounds.h_max = 0.1;
  EXPECT_THROW(run(u, bounds), InputError);
}

}  // namespace
}  // namespace dtlab
