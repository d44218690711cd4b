// Boundary vertex relocation on the geometric support (algorithms/optimize3d/relocate_boundary.hpp):
// on a capped cylinder, the wall's vertices move and stay on r = 0.5, the caps' stay exactly in
// their planes, the rims' (ridges) and the interior's do not move, the boundary facets and their
// references are the same, every tetrahedron stays positive and the worst Q_K does not rise; the
// same for any constant metric (a RapidCheck property).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/relocate_boundary.hpp"
#include "algorithms/surface/boundary_support3.hpp"
#include "kernel/predicates.hpp"
#include "verify/generators/surfaces3.hpp"

namespace dtlab {
namespace {

Mesh3 cylinder_mesh(std::uint32_t around = 24, std::uint32_t rows = 6) {
  const gen::Surface3 surface = gen::capped_cylinder(0.5, around, rows);
  Mesh3dInput input;
  input.points = surface.points;
  input.triangles = surface.triangles;
  return mesh3d(input).mesh;
}

// A metric that asks the wall for other shapes than the classical mesh's: sizes 0.05 along z,
// 0.2 across (the metric of the cylinder's boundary layer turned along its axis).
MetricField3 axial_field() {
  return [](const Vec3&) { return Metric3::from_sizes({1, 0, 0}, {0, 1, 0}, 0.2, 0.2, 0.05); };
}

// The constrained facets of the domain as sorted vertex ids with their reference.
std::multiset<std::pair<std::array<std::uint32_t, 3>, int>> facets_by_id(const Mesh3& mesh) {
  std::multiset<std::pair<std::array<std::uint32_t, 3>, int>> s;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(t, i);
      if (!mesh.is_constrained(h)) continue;
      auto f = mesh.facet_vertices(h);
      std::sort(f.begin(), f.end());
      s.insert({f, mesh.facet_ref(h)});
    }
  }
  return s;
}

double worst_quality(const Mesh3& mesh) {
  double w = 0.0;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t)
    if (mesh.in_domain(t)) w = std::max(w, optimize3d_detail::tetrahedron_quality(mesh, t));
  return w;
}

void set_metrics(Mesh3& mesh, const MetricField3& field) {
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v)) mesh.set_metric(v, field(mesh.point(v)));
}

TEST(RelocateBoundary3, WallMovesOnTheCylinderCapsStayPlanarRimsStay) {
  Mesh3 mesh = cylinder_mesh();
  const MetricField3 field = axial_field();
  set_metrics(mesh, field);
  const BoundarySupport3 support = boundary_support3(mesh);
  const std::vector<Vec3> before(mesh.points().begin(), mesh.points().end());
  const auto facets_before = facets_by_id(mesh);
  const double worst_before = worst_quality(mesh);
  std::uint64_t moved = 0;
  for (int sweep = 0; sweep < 3; ++sweep) moved += boundary_relocate_sweep3(mesh, field, support.support);
  mesh.check();
  EXPECT_GT(moved, 0u);
  EXPECT_EQ(facets_by_id(mesh), facets_before);
  EXPECT_LE(worst_quality(mesh), worst_before);
  std::uint64_t wall_moved = 0, cap_moved = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    const Vec3 &p = mesh.point(v), &q = before[v];
    const bool boundary = (mesh.flags(v) & Mesh3::kOnBoundary) != 0;
    if (!boundary) {
      EXPECT_EQ(p, q) << "interior vertex " << v << " moved";
      continue;
    }
    const bool cap = q.z == 0.0 || q.z == 1.0;
    const bool rim = cap && std::abs(std::hypot(q.x, q.y) - 0.5) < 1e-12;
    if (rim) {
      EXPECT_EQ(p, q) << "rim vertex " << v << " moved";
    } else if (cap) {
      EXPECT_EQ(p.z, q.z) << "cap vertex " << v << " left its plane";
      cap_moved += p == q ? 0 : 1;
    } else {
      EXPECT_LT(std::abs(std::hypot(p.x, p.y) - 0.5), 2.5e-4) << "wall vertex " << v << " off the cylinder";
      EXPECT_GT(p.z, 0.0);
      EXPECT_LT(p.z, 1.0);
      wall_moved += p == q ? 0 : 1;
    }
  }
  EXPECT_GT(wall_moved, 0u);
  std::cout << "boundary relocation: " << moved << " moves, " << wall_moved << " wall vertices and " << cap_moved
            << " cap vertices moved; worst Q_K " << worst_before << " -> " << worst_quality(mesh) << "\n";
}

TEST(RelocateBoundary3, RefusesInteriorRidgeAndDeadVertices) {
  Mesh3 mesh = cylinder_mesh();
  const MetricField3 field = axial_field();
  set_metrics(mesh, field);
  const BoundarySupport3 support = boundary_support3(mesh);
  std::uint64_t tried = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    const Vec3 p = mesh.point(v);
    const bool boundary = (mesh.flags(v) & Mesh3::kOnBoundary) != 0;
    const bool rim = (p.z == 0.0 || p.z == 1.0) && std::abs(std::hypot(p.x, p.y) - 0.5) < 1e-12;
    if (boundary && !rim) continue;
    EXPECT_FALSE(try_relocate_boundary3(mesh, v, field, support.support)) << "vertex " << v;
    EXPECT_EQ(mesh.point(v), p);
    ++tried;
  }
  EXPECT_GT(tried, 48u);  // the two rims at least
  EXPECT_FALSE(try_relocate_boundary3(mesh, mesh.vertex_capacity(), field, support.support));
}

TEST(RelocateBoundary3, Deterministic) {
  Mesh3 a = cylinder_mesh(), b = cylinder_mesh();
  const MetricField3 field = axial_field();
  set_metrics(a, field);
  set_metrics(b, field);
  const BoundarySupport3 sa = boundary_support3(a), sb = boundary_support3(b);
  EXPECT_EQ(boundary_relocate_sweep3(a, field, sa.support), boundary_relocate_sweep3(b, field, sb.support));
  ASSERT_EQ(a.vertex_capacity(), b.vertex_capacity());
  for (std::uint32_t v = 0; v < a.vertex_capacity(); ++v) EXPECT_EQ(a.point(v), b.point(v));
}

// Any constant metric (random sizes 0.03-0.3 along random axes), any resolution of the cylinder
// from 24 around:
// a valid mesh (Mesh3::check: every tetrahedron positive, exactly), the same boundary facets and
// references, moved wall vertices within 2.5e-4 of r = 0.5 (or no
// farther than before, for the mesher's Steiner points on the facets), cap vertices exactly in their planes, rims
// and interior vertices unmoved, the worst Q_K not higher.
RC_GTEST_PROP(RelocateBoundary3Properties, AnyMetricKeepsTheMeshValidAndTheBoundaryOnItsSurface, ()) {
  // From 24 vertices a circle: on coarser ones the support itself is off the cylinder by more
  // than 2.5e-4 beside the rims (12: 1.3e-2; its normals at ridge vertices are one-sided,
  // surface_support3.hpp), which no relocation on it can undo.
  const std::uint32_t around = static_cast<std::uint32_t>(*rc::gen::inRange(24, 33));
  const std::uint32_t rows = static_cast<std::uint32_t>(*rc::gen::inRange(2, 5));
  const double h1 = *rc::gen::inRange(3, 31) / 100.0, h2 = *rc::gen::inRange(3, 31) / 100.0,
               h3 = *rc::gen::inRange(3, 31) / 100.0;
  const double a = *rc::gen::inRange(0, 628) / 100.0, b = *rc::gen::inRange(0, 314) / 100.0;
  const Vec3 e1{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)};
  const Vec3 helper = std::abs(e1.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  const Vec3 e2 = (1.0 / norm(cross(e1, helper))) * cross(e1, helper);
  const Metric3 m = Metric3::from_sizes(e1, e2, h1, h2, h3);
  const MetricField3 field = [m](const Vec3&) { return m; };
  Mesh3 mesh = cylinder_mesh(around, rows);
  set_metrics(mesh, field);
  const BoundarySupport3 support = boundary_support3(mesh);
  const std::vector<Vec3> before(mesh.points().begin(), mesh.points().end());
  const auto facets_before = facets_by_id(mesh);
  const double worst_before = worst_quality(mesh);
  boundary_relocate_sweep3(mesh, field, support.support);
  boundary_relocate_sweep3(mesh, field, support.support);
  mesh.check();
  RC_ASSERT(facets_by_id(mesh) == facets_before);
  RC_ASSERT(worst_quality(mesh) <= worst_before);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    const Vec3 &p = mesh.point(v), &q = before[v];
    if ((mesh.flags(v) & Mesh3::kOnBoundary) == 0) {
      RC_ASSERT(p == q);
    } else if (q.z == 0.0 || q.z == 1.0) {
      RC_ASSERT(p.z == q.z);
      if (std::abs(std::hypot(q.x, q.y) - 0.5) < 1e-12) RC_ASSERT(p == q);
    } else {
      // The mesher's Steiner points on the facets are off (3.6e-3 measured), and so is the support
      // through them: those may stay as far off, not farther.
      const double off_before = std::abs(std::hypot(q.x, q.y) - 0.5);
      if (p != q) RC_ASSERT(std::abs(std::hypot(p.x, p.y) - 0.5) < std::max(2.5e-4, off_before + 1e-6));
    }
  }
}

}  // namespace
}  // namespace dtlab
