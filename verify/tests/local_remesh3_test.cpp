// Local remeshing (algorithms/mesh3d/local_remesh.hpp) on empty meshes, whose tetrahedra join
// boundary vertices only (none of them may move: the operators of optimize3d cannot cure their
// slivers): the smallest dihedral angle grows, the mesh stays valid (Mesh3::check, exact), the
// domain's volume, every constrained facet with its reference, every constrained edge and every
// fixed vertex are kept, two regions keep their internal face, the result is deterministic, and
// the work bound stops the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/mesh3d/local_remesh.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "verify/tests/box_surface.hpp"

namespace dtlab {
namespace {

using test::add_box;
using Surface = test::SurfaceData;

Mesh3 empty_mesh_of(const Surface& s) {
  Constrained3dOptions recovery;
  recovery.method = "recover";
  return empty_mesh(constrained3d(s.input(), recovery));
}

// What the domain is made of: its smallest dihedral angle (degrees), its volume, its constrained
// facets (sorted vertex ids with their reference), its constrained edges, its fixed vertices.
struct Summary {
  double min_dihedral_deg = 180.0;
  double volume = 0.0;
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, int>> constrained_facets;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> constrained_edges;
  std::vector<std::uint32_t> fixed_vertices;
};

Summary summarize(const Mesh3& m) {
  Summary s;
  double highest_cos = -1.0;
  for (std::uint32_t t = 0; t < m.tetrahedron_capacity(); ++t) {
    if (!m.in_domain(t)) continue;
    const auto v = m.tetrahedron(t);
    const Vec3 &a = m.point(v[0]), &b = m.point(v[1]), &c = m.point(v[2]), &d = m.point(v[3]);
    highest_cos = std::max(highest_cos, dihedral_cosine_range(a, b, c, d)[1]);
    s.volume += dot(b - a, cross(c - a, d - a)) / 6.0;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(t, i);
      if (!m.is_constrained(h)) continue;
      auto f = m.facet_vertices(h);
      std::sort(f.begin(), f.end());
      s.constrained_facets.emplace_back(f[0], f[1], f[2], m.facet_ref(h));
    }
    for (std::uint32_t i = 0; i < 4; ++i)
      for (std::uint32_t j = i + 1; j < 4; ++j)
        if (m.is_constrained_edge(v[i], v[j])) s.constrained_edges.emplace_back(std::min(v[i], v[j]), std::max(v[i], v[j]));
  }
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v)
    if (!m.is_dead_vertex(v) && (m.flags(v) & Mesh3::kFixed)) s.fixed_vertices.push_back(v);
  s.min_dihedral_deg = std::acos(highest_cos) * 57.295779513082320877;
  for (auto* list : {&s.constrained_facets}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  std::sort(s.constrained_edges.begin(), s.constrained_edges.end());
  s.constrained_edges.erase(std::unique(s.constrained_edges.begin(), s.constrained_edges.end()), s.constrained_edges.end());
  return s;
}

void expect_kept(const Summary& before, const Summary& after) {
  EXPECT_NEAR(after.volume, before.volume, 1e-12 * before.volume);
  EXPECT_EQ(after.constrained_facets, before.constrained_facets);
  EXPECT_EQ(after.constrained_edges, before.constrained_edges);
  EXPECT_EQ(after.fixed_vertices, before.fixed_vertices);
}

TEST(LocalRemesh3, LiftsTheSmallestAngleOfAnEmptyMesh) {
  Surface s;
  add_box(s, {0, 0, 0}, {1.0, 1.0, 1.0}, {12, 3, 3}, 1);  // thin triangles along the edges parallel to x
  Mesh3 m = empty_mesh_of(s);
  const Summary before = summarize(m);
  const LocalRemesh3Stats stats = remesh_small_angles(m, {});
  m.check();
  const Summary after = summarize(m);
  expect_kept(before, after);
  EXPECT_GT(stats.remeshed, 0u);
  EXPECT_GT(stats.vertices_added, 0u);
  EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg + 1.0)
      << "before " << before.min_dihedral_deg << ", after " << after.min_dihedral_deg;
}

TEST(LocalRemesh3, TwoRegionsKeepTheirInternalFace) {
  Surface s;
  add_box(s, {0, 0, 0}, {1.0, 1.0, 1.0}, {6, 2, 2}, 1);
  add_box(s, {1, 0, 0}, {1.0, 1.0, 1.0}, {6, 2, 2}, 11, /*skip_face=*/0);  // shares the face x = 1
  Mesh3 m = empty_mesh_of(s);
  std::map<int, double> volume_before, volume_after;
  const auto volumes = [](const Mesh3& mesh, std::map<int, double>& by_ref) {
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const auto v = mesh.tetrahedron(t);
      const Vec3 &a = mesh.point(v[0]), &b = mesh.point(v[1]), &c = mesh.point(v[2]), &d = mesh.point(v[3]);
      by_ref[mesh.ref(t)] += dot(b - a, cross(c - a, d - a)) / 6.0;
    }
  };
  volumes(m, volume_before);
  const Summary before = summarize(m);
  const LocalRemesh3Stats stats = remesh_small_angles(m, {});
  m.check();
  volumes(m, volume_after);
  expect_kept(before, summarize(m));
  EXPECT_GT(stats.remeshed, 0u);
  ASSERT_EQ(volume_after.size(), 2u);
  for (const auto& [ref, v] : volume_before) EXPECT_NEAR(volume_after[ref], v, 1e-12) << "region " << ref;
}

TEST(LocalRemesh3, Deterministic) {
  Surface s;
  add_box(s, {0, 0, 0}, {1.0, 1.0, 1.0}, {9, 2, 3}, 1);
  Mesh3 first = empty_mesh_of(s), second = empty_mesh_of(s);
  remesh_small_angles(first, {});
  remesh_small_angles(second, {});
  EXPECT_EQ(first.domain(), second.domain());
}

TEST(LocalRemesh3, NothingBelowTheBoundNothingChanges) {
  Surface s;
  add_box(s, {0, 0, 0}, {1.0, 1.0, 1.0}, {12, 3, 3}, 1);
  Mesh3 m = empty_mesh_of(s);
  const MeshData3 before = m.domain();
  LocalRemesh3Options o;
  o.below_deg = 0.0;
  const LocalRemesh3Stats stats = remesh_small_angles(m, {}, o);
  EXPECT_EQ(stats.tried, 0u);
  EXPECT_EQ(m.domain(), before);
}

// The work bound stops the step after the first region once it holds more tetrahedra than
// allowed, and says so; the mesh stays valid.
TEST(LocalRemesh3, StopsAtItsWorkBound) {
  Surface s;
  add_box(s, {0, 0, 0}, {1.0, 1.0, 1.0}, {12, 3, 3}, 1);
  Mesh3 m = empty_mesh_of(s);
  LocalRemesh3Options o;
  o.work_factor = 0.0;
  o.work_floor = 1.0;
  const LocalRemesh3Stats stats = remesh_small_angles(m, {}, o);
  m.check();
  EXPECT_EQ(stats.tried, 1u);
  EXPECT_TRUE(stats.work_bound_reached);
  // A floor of 300 tetrahedra: a few regions, then the bound (each region holds dozens).
  Mesh3 n = empty_mesh_of(s);
  o.work_floor = 300.0;
  const LocalRemesh3Stats few = remesh_small_angles(n, {}, o);
  n.check();
  EXPECT_GT(few.tried, 1u);
  EXPECT_GE(few.work, 300u);
  EXPECT_TRUE(few.work_bound_reached);
}

}  // namespace
}  // namespace dtlab
