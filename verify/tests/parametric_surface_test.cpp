// Parametric surfaces (book §6): exact derivatives of every patch against finite differences,
// the metrics of the fundamental forms, and the meshes: every vertex on the analytic surface, unit
// edges in the metric, closed spheres and tori, named errors for bad patches.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "algorithms/parametric/mesh_patch.hpp"
#include "algorithms/surface/patch_description.hpp"
#include "algorithms/surface/surface_metric.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab {
namespace {

constexpr double kPi = std::numbers::pi;

Patch3 sample_bspline() {
  // A bicubic 4 x 5 net with an interior knot along v: a bumpy sheet.
  std::vector<Vec3> c;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 5; ++j) c.push_back({double(i), double(j), std::sin(1.3 * i + 0.7 * j)});
  return Patch3::bspline(c, 4, 5, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, 3, 3);
}

std::vector<std::pair<std::string, Patch3>> patches() {
  return {{"plane", Patch3::plane({1, 2, 3}, {1, 0, 0}, {0.6, 0.8, 0})},
          {"sphere_face_2", Patch3::sphere_face({0.5, 0, 0}, 2.0, 2)},
          {"sphere_face_5", Patch3::sphere_face({0, 0, 0}, 1.0, 5)},
          {"cylinder", Patch3::cone({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.5, 1.5, 2.0)},
          {"cone", Patch3::cone({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.5, 0.5, 2.0)},
          {"torus", Patch3::torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 0.5)},
          {"sine_graph", Patch3::sine_graph(3.0, 2.0, 2.0)},
          {"bspline", sample_bspline()}};
}

double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

// Central differences of the point (first derivatives) and of the exact first derivatives (second).
TEST(Patch3, DerivativesMatchFiniteDifferences) {
  const double h = 1e-5;
  for (const auto& [name, patch] : patches()) {
    for (const Vec2 uv : {Vec2{0.21, 0.33}, Vec2{0.5, 0.71}, Vec2{0.9, 0.12}}) {
      const PatchDerivatives d = patch.evaluate(uv);
      const PatchDerivatives pu = patch.evaluate({uv.x + h, uv.y}), mu = patch.evaluate({uv.x - h, uv.y});
      const PatchDerivatives pv = patch.evaluate({uv.x, uv.y + h}), mv = patch.evaluate({uv.x, uv.y - h});
      const double scale = 1.0 + norm(d.du) + norm(d.dv) + norm(d.duu) + norm(d.dvv);
      const double tol = 1e-6 * scale;
      EXPECT_LT(distance(d.du, (0.5 / h) * (pu.point - mu.point)), tol) << name;
      EXPECT_LT(distance(d.dv, (0.5 / h) * (pv.point - mv.point)), tol) << name;
      EXPECT_LT(distance(d.duu, (0.5 / h) * (pu.du - mu.du)), tol) << name;
      EXPECT_LT(distance(d.dvv, (0.5 / h) * (pv.dv - mv.dv)), tol) << name;
      EXPECT_LT(distance(d.duv, (0.5 / h) * (pv.du - mv.du)), tol) << name;
      EXPECT_LT(distance(d.duv, (0.5 / h) * (pu.dv - mu.dv)), tol) << name;
    }
  }
}

// A property: at random parameters of the torus the exact derivatives match finite differences.
RC_GTEST_PROP(Patch3, TorusDerivativesAnywhere, ()) {
  const double u = *rc::gen::inRange(0, 6283) / 1000.0, v = *rc::gen::inRange(0, 6283) / 1000.0;
  const Patch3 t = Patch3::torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 3.0, 1.0);
  const double h = 1e-5;
  const PatchDerivatives d = t.evaluate({u, v});
  RC_ASSERT(distance(d.duv, (0.5 / h) * (t.evaluate({u + h, v}).dv - t.evaluate({u - h, v}).dv)) < 1e-5);
  RC_ASSERT(distance(d.dvv, (0.5 / h) * (t.evaluate({u, v + h}).dv - t.evaluate({u, v - h}).dv)) < 1e-5);
}

TEST(SurfaceMetric, CurvaturesOfSphereCylinderTorus) {
  const PatchDerivatives s = Patch3::sphere_face({0, 0, 0}, 2.0, 0).evaluate({0.3, -0.4});
  const PrincipalCurvatures cs = principal_curvatures(s);
  EXPECT_NEAR(std::abs(cs.k1), 0.5, 1e-12);
  EXPECT_NEAR(std::abs(cs.k2), 0.5, 1e-12);
  const PrincipalCurvatures cc = principal_curvatures(Patch3::cone({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 4.0, 4.0, 1.0).evaluate({1.0, 0.5}));
  EXPECT_NEAR(std::abs(cc.k1), 0.25, 1e-12);
  EXPECT_NEAR(cc.k2, 0.0, 1e-12);
  // Torus R = 3, r = 1 at v = 0 (outer equator): curvatures 1 / r and cos v / (R + r cos v) = 1 / 4.
  const PrincipalCurvatures ct = principal_curvatures(Patch3::torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 3.0, 1.0).evaluate({0.7, 0.0}));
  EXPECT_NEAR(std::abs(ct.k1), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(ct.k2), 0.25, 1e-12);
}

TEST(SurfaceMetric, InducedMetricMeasuresThreeDLengthOverH) {
  const Patch3 p = Patch3::sine_graph(3.0, 2.0, 2.0);
  const PatchDerivatives d = p.evaluate({0.4, -0.2});
  const Metric2 m = induced_metric(d, 0.1);
  const Vec2 w{0.3, -0.7};
  EXPECT_NEAR(m.length(w), norm(w.x * d.du + w.y * d.dv) / 0.1, 1e-12);
  // The anisotropic geometric metric: along a principal direction, the size alpha rho clipped.
  SurfaceMetricSpec spec{.size = 0.0, .user_metric = {}, .geometric = GeometricMetric::Anisotropic, .relative_gap = 0.01, .h_min = 1e-3, .h_max = 10.0};
  const Metric2 g = geometric_metric(d, spec);
  const PrincipalCurvatures c = principal_curvatures(d);
  const double alpha = 2.0 * std::sqrt(0.01 * 1.99);
  // Parameters of t1: solve [du dv] w = t1 in the least-squares sense (t1 is tangent).
  const double e = dot(d.du, d.du), f = dot(d.du, d.dv), gg = dot(d.dv, d.dv);
  const double a = dot(c.t1, d.du), b = dot(c.t1, d.dv), det = e * gg - f * f;
  const Vec2 w1{(gg * a - f * b) / det, (e * b - f * a) / det};
  EXPECT_NEAR(g.length(w1), std::abs(c.k1) / alpha, 1e-9 * std::abs(c.k1) / alpha);
}

// §6.3.3's physico-geometric case: the user's 3D map and the geometric one intersected; every
// tangent vector is at least as long in the result as in each (the largest ellipse inside both).
RC_GTEST_PROP(SurfaceMetric, IntersectionIsInsideBoth, ()) {
  const double x = *rc::gen::inRange(-290, 290) / 100.0, y = *rc::gen::inRange(-290, 290) / 100.0;
  const double angle = *rc::gen::inRange(0, 628) / 100.0;
  const PatchDerivatives d = Patch3::sine_graph(3.0, 2.0, 2.0).evaluate({x, y});
  const auto user = [](const Vec3& p) { return Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.2, 0.2, 0.01 + 0.1 * std::abs(p.z)); };
  SurfaceMetricSpec spec{.size = 0.0, .user_metric = user, .geometric = GeometricMetric::Anisotropic, .relative_gap = 0.02,
                         .hausdorff = 0.0, .h_min = 0.01, .h_max = 1.0};
  const Metric2 both = parameter_metric(d, spec);
  const Metric2 geometric = geometric_metric(d, spec), pulled = pull_back(d, user(d.point));
  const Vec2 w{std::cos(angle), std::sin(angle)};
  RC_ASSERT(both.length(w) >= (1.0 - 1e-9) * geometric.length(w));
  RC_ASSERT(both.length(w) >= (1.0 - 1e-9) * pulled.length(w));
  // and no longer than the two together could ask for (sum of the quadratic forms).
  RC_ASSERT(both.length(w) <= (1.0 + 1e-9) * std::hypot(geometric.length(w), pulled.length(w)));
}

// Mesh checks shared by the surfaces.
struct EdgeUse {
  int forward = 0, backward = 0;
};
std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edge_uses(const MeshData3& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> uses;
  for (const auto& t : m.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      if (a < b) ++uses[{a, b}].forward;
      else ++uses[{b, a}].backward;
    }
  }
  return uses;
}

void expect_closed(const MeshData3& m, const std::string& name) {
  std::size_t bad = 0;
  for (const auto& [edge, use] : edge_uses(m)) bad += !(use.forward == 1 && use.backward == 1);
  EXPECT_EQ(bad, 0u) << name << ": edges not shared by exactly two triangles of opposite orientation";
}

double unit_edge_share(const SurfaceMeshResult& r) {
  std::uint64_t unit = 0, edges = 0;
  for (const ChartMesh& c : r.charts) {
    const QualityReport q = measure_quality(c.parameters.vertices, c.parameters.triangles, c.metrics);
    unit += q.unit_edges;
    edges += q.edges;
  }
  return static_cast<double>(unit) / static_cast<double>(edges);
}

SurfaceMeshOptions sized(double h) {
  SurfaceMeshOptions o;
  o.metric.size = h;
  return o;
}

TEST(MeshPatch, SphereIsClosedAndOnTheSurface) {
  const Vec3 centre{1, -2, 0.5};
  const double radius = 2.0;
  const SurfaceMeshResult r = mesh_patch_surface(PatchSurface3::sphere(centre, radius), sized(0.3));
  ASSERT_GT(r.surface.triangles.size(), 100u);
  expect_closed(r.surface, "sphere");
  for (const Vec3& p : r.surface.vertices) EXPECT_NEAR(norm(p - centre), radius, 4e-15 * radius);
  EXPECT_GE(unit_edge_share(r), 0.9);
  // Euler characteristic 2 and outward orientation (positive volume).
  const std::size_t edges = edge_uses(r.surface).size();
  EXPECT_EQ(static_cast<long>(r.surface.vertices.size()) - static_cast<long>(edges) + static_cast<long>(r.surface.triangles.size()), 2);
  double volume = 0;
  for (const auto& t : r.surface.triangles)
    volume += dot(r.surface.vertices[t[0]] - centre, cross(r.surface.vertices[t[1]] - centre, r.surface.vertices[t[2]] - centre)) / 6.0;
  EXPECT_NEAR(volume, 4.0 / 3.0 * kPi * radius * radius * radius, 0.05 * volume);
}

TEST(MeshPatch, TorusIsClosedAndOnTheSurface) {
  const double major = 2.0, minor = 0.6;
  const SurfaceMeshResult r = mesh_patch_surface(PatchSurface3::torus({0, 0, 0}, {0, 0, 1}, major, minor), sized(0.2));
  expect_closed(r.surface, "torus");
  for (const Vec3& p : r.surface.vertices) {
    const double ring = std::hypot(p.x, p.y) - major;
    EXPECT_NEAR(std::hypot(ring, p.z), minor, 1e-14 * major);
  }
  EXPECT_GE(unit_edge_share(r), 0.9);
  const std::size_t edges = edge_uses(r.surface).size();
  EXPECT_EQ(static_cast<long>(r.surface.vertices.size()) - static_cast<long>(edges) + static_cast<long>(r.surface.triangles.size()), 0);
}

// Any sphere or torus (random centre, axis, radii, size): closed, of the right Euler
// characteristic, every vertex on the surface.
RC_GTEST_PROP(MeshPatch, RandomSpheresAndToriAreClosed, ()) {
  const Vec3 centre{*rc::gen::inRange(-100, 100) / 10.0, *rc::gen::inRange(-100, 100) / 10.0, *rc::gen::inRange(-100, 100) / 10.0};
  const double radius = *rc::gen::inRange(5, 50) / 10.0;
  const double size = radius * *rc::gen::inRange(15, 200) / 100.0;
  const bool torus = *rc::gen::arbitrary<bool>();
  const Vec3 axis{*rc::gen::inRange(-10, 10) / 10.0, *rc::gen::inRange(-10, 10) / 10.0, 0.5 + *rc::gen::inRange(0, 10) / 10.0};
  const double minor = radius * *rc::gen::inRange(10, 80) / 100.0;
  const PatchSurface3 s = torus ? PatchSurface3::torus(centre, axis, radius, minor) : PatchSurface3::sphere(centre, radius);
  const SurfaceMeshResult r = mesh_patch_surface(s, sized(size));
  std::size_t bad = 0;
  const auto uses = edge_uses(r.surface);
  for (const auto& [edge, use] : uses) bad += !(use.forward == 1 && use.backward == 1);
  RC_ASSERT(bad == 0u);
  const long euler = static_cast<long>(r.surface.vertices.size()) - static_cast<long>(uses.size()) +
                     static_cast<long>(r.surface.triangles.size());
  RC_ASSERT(euler == (torus ? 0 : 2));
  if (!torus) {
    for (const Vec3& p : r.surface.vertices) RC_ASSERT(std::abs(norm(p - centre) - radius) <= 1e-14 * (radius + norm(centre)));
  }
}

TEST(MeshPatch, CylinderConeAndGraphOnTheirSurfaces) {
  const SurfaceMeshResult cyl = mesh_patch_surface(PatchSurface3::cylinder({0, 0, 0}, {0, 0, 1}, 1.0, 2.0), sized(0.2));
  for (const Vec3& p : cyl.surface.vertices) EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 4e-15);
  EXPECT_GE(unit_edge_share(cyl), 0.9);
  // The open boundary: two circles of Edges, every other edge in two triangles.
  std::size_t once = 0;
  for (const auto& [e, use] : edge_uses(cyl.surface)) {
    EXPECT_LE(use.forward + use.backward, 2);
    once += use.forward + use.backward == 1;
  }
  EXPECT_EQ(once, cyl.surface.edges.size());
  const SurfaceMeshResult cone = mesh_patch_surface(PatchSurface3::cone({0, 0, 0}, {0, 0, 1}, 1.0, 0.4, 1.5), sized(0.15));
  for (const Vec3& p : cone.surface.vertices) EXPECT_NEAR(std::hypot(p.x, p.y), 1.0 + (0.4 - 1.0) * p.z / 1.5, 1e-14);
  EXPECT_GE(unit_edge_share(cone), 0.9);
  const SurfaceMeshResult graph = mesh_patch_surface(PatchSurface3::sine_graph(3, 2, 2, 3), sized(0.3));
  for (const Vec3& p : graph.surface.vertices) {
    EXPECT_NEAR(p.z, 3.0 * std::sin(2.0 * p.x) * std::cos(2.0 * p.y), 1e-14 * 3.0);
    EXPECT_LE(std::hypot(p.x, p.y), 3.0 * (1 + 1e-15));
  }
  // The graph's slope reaches 6: in its parameter plane the induced metric stretches 37:1 and turns
  // fast, where the 2D generator's band is about 0.8 (mesh2d_test's varying layer expects 0.8).
  EXPECT_GE(unit_edge_share(graph), 0.78);
}

TEST(MeshPatch, GeometricMetricsOnTheBookSurface) {
  SurfaceMeshOptions iso;
  iso.metric = {.size = 0.0, .user_metric = {}, .geometric = GeometricMetric::Isotropic, .relative_gap = 0.05, .h_min = 0.02, .h_max = 0.5};
  SurfaceMeshOptions aniso = iso;
  aniso.metric.geometric = GeometricMetric::Anisotropic;
  const PatchSurface3 s = PatchSurface3::sine_graph(3, 2, 2, 3);
  const SurfaceMeshResult ri = mesh_patch_surface(s, iso), ra = mesh_patch_surface(s, aniso);
  EXPECT_GE(unit_edge_share(ri), 0.78);  // the induced part stretches 37:1 (above)
  EXPECT_GE(unit_edge_share(ra), 0.85);
  // The book's trend (Table 6.2): the anisotropic map needs far fewer points (here half: h_max
  // 0.5 caps the long direction).
  EXPECT_LT(3 * ra.surface.vertices.size(), 2 * ri.surface.vertices.size());
}

// --hausdorff E: the triangles stay within E of the surface (sampled at their centres and edge
// midpoints), and not far inside it (the sizes are not needlessly small).
TEST(MeshPatch, HausdorffBoundHolds) {
  for (const double e : {0.01, 0.001}) {
    SurfaceMeshOptions o;
    o.metric = {.size = 0.0, .user_metric = {}, .geometric = GeometricMetric::Isotropic, .relative_gap = 0.01, .hausdorff = e,
                .h_min = 0.0, .h_max = 1.0};
    const SurfaceMeshResult r = mesh_patch_surface(PatchSurface3::sphere({0, 0, 0}, 1.0), o);
    double worst = 0.0;
    for (const auto& t : r.surface.triangles) {
      const Vec3 &a = r.surface.vertices[t[0]], &b = r.surface.vertices[t[1]], &c = r.surface.vertices[t[2]];
      for (const Vec3& p : {(1.0 / 3.0) * (a + b + c), 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)}) worst = std::max(worst, 1.0 - norm(p));
    }
    EXPECT_LE(worst, e) << e;
    EXPECT_GE(worst, 0.4 * e) << e;
  }
}

TEST(MeshPatch, BsplinePatchOnItsSurface) {
  const Patch3 p = sample_bspline();
  const SurfaceMeshResult r = mesh_patch_surface(PatchSurface3::bspline(p, {0, 0}, {1, 1}), sized(0.25));
  for (std::size_t c = 0; c < r.charts.size(); ++c)
    for (std::size_t i = 0; i < r.charts[c].parameters.vertices.size(); ++i)
      EXPECT_EQ(r.surface.vertices[r.charts[c].vertex[i]], p.point(r.charts[c].parameters.vertices[i]));
  EXPECT_GE(unit_edge_share(r), 0.9);
}

TEST(MeshPatch, BadPatchesNamed) {
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(message([] { PatchSurface3::sphere({0, 0, 0}, 0.0); }).find("degenerate patch: sphere radius"), std::string::npos);
  EXPECT_NE(message([] { PatchSurface3::cone({0, 0, 0}, {0, 0, 1}, 1.0, 0.0, 1.0); }).find("apex"), std::string::npos);
  EXPECT_NE(message([] { PatchSurface3::torus({0, 0, 0}, {0, 0, 1}, 1.0, 1.0); }).find("meets itself"), std::string::npos);
  EXPECT_NE(message([] { PatchSurface3::plane({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0}, {1, 1}); }).find("singular parametrization"),
            std::string::npos);
  EXPECT_NE(message([] { patch_from_description(parse_json(R"({"type": "klein_bottle"})", "t")); }).find("unknown patch type 'klein_bottle'"),
            std::string::npos);
  EXPECT_NE(message([] { patch_from_description(parse_json(R"({"type": "sphere", "radius": 1, "colour": 2})", "t")); })
                .find("unknown key 'colour'"),
            std::string::npos);
  std::vector<Vec3> flat(16, Vec3{1, 1, 1});
  EXPECT_NE(message([&] {
              PatchSurface3::bspline(Patch3::bspline(flat, 4, 4, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 3, 3), {0, 0}, {1, 1});
            }).find("singular parametrization"),
            std::string::npos);
}

}  // namespace
}  // namespace dtlab
