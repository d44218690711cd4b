// The control spaces (algorithms/mesh2d/control_space.hpp, algorithms/mesh3d/control_space.hpp)
// in backgrounds that are not convex: a point whose straight walk from the hint crosses a hole
// must still take the metric of the element holding it (the visibility walk stops at the hole's
// boundary; the bucket grid of mesh/element_grid.hpp settles it). The size varies linearly, so
// the interpolation of sizes is exact and the expected metric is known.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "algorithms/mesh3d/control_space.hpp"
#include "kernel/error.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/mesh3_from_data.hpp"
#include "verify/generators/domains2d.hpp"
#include "verify/generators/kuhn_cubes.hpp"

namespace dtlab {
namespace {

double size2(const Metric2& m) { return 1.0 / std::sqrt(m.m[0]); }
double size3(const Metric3& m) { return 1.0 / std::sqrt(m.m[0]); }

TEST(ControlSpace2, LocatesAcrossAHole) {
  // The unit square minus the disc (0.5, 0.5, 0.2); size h = 0.01 + 0.1 y.
  const ControlSpace2 uniform = ControlSpace2::uniform(Metric2::isotropic(0.05), {-1, -1}, {2, 2});
  Mesh2dOptions options;
  options.control = &uniform;
  const gen::Domain2 domain = gen::square_minus_disc(20);
  const MeshData2 background = mesh2d(domain.input(), options).output;
  std::vector<Metric2> metrics;
  for (const Vec2& p : background.vertices) metrics.push_back(Metric2::isotropic(0.01 + 0.1 * p.y));
  const ControlSpace2 control(background, metrics);
  // Below, above, below, ... the hole, the hint carried from one query to the next.
  const std::vector<Vec2> queries{{0.5, 0.2}, {0.5, 0.8}, {0.45, 0.22}, {0.55, 0.75}, {0.5, 0.26}, {0.52, 0.95}};
  std::uint32_t hint = ControlSpace2::kNoHint;
  for (const Vec2& p : queries) {
    EXPECT_NEAR(size2(control.metric_at(p, hint)), 0.01 + 0.1 * p.y, 1e-12) << p.x << ", " << p.y;
  }
  // A point outside takes the metric of a nearby boundary point, within the size's range.
  const double outside = size2(control.metric_at({0.5, 1.2}, hint));
  EXPECT_GE(outside, 0.01);
  EXPECT_LE(outside, 0.11 + 1e-12);
}

// A ring of 8 unit cells around the empty cell [1, 2] x [1, 2] x [0, 1].
MeshData3 ring_of_cells() {
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != 1 || j != 1) cells.push_back({i, j, 0});
  return gen::kuhn_cubes(cells);
}

TEST(ControlSpace3, LocatesAcrossAHole) {
  // Size h = 0.1 + 0.1 y.
  const MeshData3 background = ring_of_cells();
  std::vector<Metric3> metrics;
  for (const Vec3& p : background.vertices) metrics.push_back(Metric3::isotropic(0.1 + 0.1 * p.y));
  const ControlSpace3 control(background, metrics);
  const std::vector<Vec3> queries{{1.5, 0.5, 0.5}, {1.5, 2.5, 0.5}, {1.4, 0.7, 0.3}, {1.6, 2.2, 0.6}, {1.5, 0.9, 0.5}};
  std::uint32_t hint = ControlSpace3::kNoHint;
  for (const Vec3& p : queries) {
    EXPECT_NEAR(size3(control.metric_at(p, hint)), 0.1 + 0.1 * p.y, 1e-12) << p.x << ", " << p.y << ", " << p.z;
  }
}

// The two constructors: a file's tetrahedra, and a Mesh3 (as the classical case gives it, with
// ghosts, a dead slot and its constraints) of the same background give the same metric exactly,
// in the ring and in its hole (where the bucket fallback finds nothing).
TEST(ControlSpace3, MeshAndDataBackgroundsAgree) {
  const MeshData3 data = ring_of_cells();
  std::vector<Metric3> metrics;
  for (const Vec3& p : data.vertices) metrics.push_back(Metric3::isotropic(0.1 + 0.1 * p.y + 0.05 * p.x * p.z));
  Mesh3 mesh = mesh3_from_data(data);
  const auto v = mesh.tetrahedron(0);
  mesh.remove_tetrahedron(mesh.add_tetrahedron(v[0], v[1], v[2], v[3], 0));  // a free slot, not to be seen
  const ControlSpace3 a(data, metrics), b(mesh, metrics);
  std::uint32_t ha = ControlSpace3::kNoHint, hb = ControlSpace3::kNoHint;
  for (int k = 0; k < 400; ++k) {
    const Vec3 p{0.0075 * (k % 400), 0.0071 * ((k * 37) % 420), 0.0023 * ((k * 11) % 430)};
    std::uint32_t fresh = ControlSpace3::kNoHint;
    const Metric3 ma = a.metric_at(p, ha), mb = b.metric_at(p, hb);
    ASSERT_EQ(ma, mb) << p.x << ", " << p.y << ", " << p.z;
    ASSERT_EQ(ha, hb);
    // Inside the ring the answer does not depend on the hint (up to rounding on a shared facet).
    const bool in_ring = p.x <= 1 || p.x >= 2 || p.y <= 1 || p.y >= 2;
    ASSERT_TRUE(!in_ring || std::abs(size3(b.metric_at(p, fresh)) - size3(mb)) < 1e-12) << p.x << ", " << p.y;
  }
  const Metric3 hole = a.metric_at({1.5, 1.5, 0.5}, ha);  // outside: the nearest point of a tetrahedron
  EXPECT_GE(size3(hole), 0.1);
  EXPECT_LE(size3(hole), 0.55);
  // Two tetrahedra sharing only an edge: their boundary is no closed 2-manifold.
  MeshData3 bowtie;
  bowtie.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}};
  bowtie.tetrahedra = {{0, 1, 2, 3}, {0, 4, 5, 3}};
  for (auto& t : bowtie.tetrahedra)
    if (orient3d(bowtie.vertices[t[0]], bowtie.vertices[t[1]], bowtie.vertices[t[2]], bowtie.vertices[t[3]]) != Sign::Positive)
      std::swap(t[1], t[2]);
  EXPECT_THROW(ControlSpace3(bowtie, std::vector<Metric3>(6)), InputError);
}

TEST(ElementGrid, ListsEveryElementMeetingABucket) {
  // Two triangles of the unit square: every point of the square has the triangle holding it
  // among its candidates; points outside the box get the nearest bucket's.
  const std::vector<Vec2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::array<std::uint32_t, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  const ElementGrid<Vec2> grid{std::span<const Vec2>(points), std::span<const std::array<std::uint32_t, 3>>(triangles)};
  for (double x = 0.05; x < 1.0; x += 0.1) {
    for (double y = 0.05; y < 1.0; y += 0.1) {
      const std::uint32_t holder = y < x ? 0u : 1u;
      bool found = false;
      for (const std::uint32_t t : grid.candidates({x, y})) found = found || t == holder;
      EXPECT_TRUE(found) << x << ", " << y;
    }
  }
  EXPECT_FALSE(grid.candidates({-5.0, 0.5}).empty());
  EXPECT_FALSE(grid.candidates({0.5, 7.0}).empty());
  const std::vector<bool> skip{true, true};
  EXPECT_TRUE(ElementGrid<Vec2>(std::span<const Vec2>(points), std::span<const std::array<std::uint32_t, 3>>(triangles), &skip).empty());
}

}  // namespace
}  // namespace dtlab
