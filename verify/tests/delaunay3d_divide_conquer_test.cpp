// Tests of the "divide-conquer" 3D Delaunay variant (DeWall): on every input, degenerate
// included, the same finite tetrahedra and the same hull facets as "incremental" (the perturbed
// Delaunay tetrahedralization), a structure that passes check_topology and, on the smaller
// inputs, the full exact verification of verify/checks3d.hpp.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "verify/checks3d.hpp"

namespace dtlab {
namespace {

using T3 = Tetrahedralization3;

Delaunay3dResult run(const std::vector<Vec3>& points, const std::string& algorithm) {
  return delaunay3d(points, {.algorithm = algorithm});
}

// Hull facets (the facet under each ghost, as the finite tetrahedron lists it), each rotated to
// start at its smallest id, sorted.
std::vector<std::array<std::uint32_t, 3>> hull_facets(const T3& tet) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (!tet.is_ghost(t)) continue;
    auto f = tet.facet_vertices(tet.twin(4 * t));
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Same tetrahedra, same hull, same record count as incremental; `verify` adds the full exact
// checks of checks3d.hpp.
void expect_matches_incremental(const std::vector<Vec3>& points, const std::string& what, bool verify = true) {
  SCOPED_TRACE(what);
  const Delaunay3dResult mine = run(points, "divide-conquer");
  const Delaunay3dResult reference = run(points, "incremental");
  ASSERT_TRUE(reference.degenerate_message.empty()) << reference.degenerate_message;
  const T3& tet = mine.tetrahedralization;
  ASSERT_NO_THROW(tet.check_topology());
  EXPECT_EQ(tet.tetrahedron_count(), reference.tetrahedralization.tetrahedron_count());
  EXPECT_EQ(canonical_tetrahedron_set(tet), canonical_tetrahedron_set(reference.tetrahedralization));
  EXPECT_EQ(hull_facets(tet), hull_facets(reference.tetrahedralization));
  if (verify) {
    const CheckReport3 report = verify_delaunay3d(points, tet, mine.duplicates);
    EXPECT_TRUE(report.ok) << to_text(report);
  }
}

std::vector<Vec3> uniform(std::size_t n, std::uint64_t seed, double scale = 1.0, double shift = 0.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = {shift + scale * u(rng), shift + scale * u(rng), shift + scale * u(rng)};
  return out;
}

std::vector<Vec3> grid(int side) {
  std::vector<Vec3> out;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) out.push_back({double(x), double(y), double(z)});
  return out;
}

// --- Hand cases --------------------------------------------------------------------------

TEST(Delaunay3dDivideConquer, SingleTetrahedronEitherOrientation) {
  expect_matches_incremental({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, "positive");
  expect_matches_incremental({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, "negative");
  const Delaunay3dResult r = run({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, "divide-conquer");
  EXPECT_EQ(r.tetrahedralization.tetrahedron_count(), 5u);  // one tetrahedron, four ghosts
}

TEST(Delaunay3dDivideConquer, FivePoints) {
  expect_matches_incremental({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}, "two tetrahedra or three");
  expect_matches_incremental({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1}}, "one inside");
}

TEST(Delaunay3dDivideConquer, OctahedronCospherical) {
  expect_matches_incremental({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, "octahedron");
}

TEST(Delaunay3dDivideConquer, CubeCorners) {
  expect_matches_incremental(grid(2), "cube");
  std::vector<Vec3> with_centres = grid(2);
  with_centres.push_back({0.5, 0.5, 0.5});
  for (const Vec3& c : {Vec3{0.5, 0.5, 0}, Vec3{0.5, 0.5, 1}, Vec3{0.5, 0, 0.5}, Vec3{0, 0.5, 0.5}})
    with_centres.push_back(c);
  expect_matches_incremental(with_centres, "cube with centre and face centres");
}

TEST(Delaunay3dDivideConquer, IntegerPointsOnASphere) {
  std::vector<Vec3> points;
  for (int x = -9; x <= 9; ++x)
    for (int y = -9; y <= 9; ++y)
      for (int z = -9; z <= 9; ++z)
        if (x * x + y * y + z * z == 81) points.push_back({double(x), double(y), double(z)});
  ASSERT_GT(points.size(), 100u);
  expect_matches_incremental(points, "x^2 + y^2 + z^2 = 81");
  points.push_back({0, 0, 0});  // the centre: every tetrahedron touches it
  expect_matches_incremental(points, "sphere and centre");
}

TEST(Delaunay3dDivideConquer, Duplicates) {
  std::vector<Vec3> points = grid(3);
  points.push_back(points[5]);
  points.insert(points.begin(), points[13]);
  const Delaunay3dResult r = run(points, "divide-conquer");
  EXPECT_EQ(r.duplicates.size(), 2u);
  expect_matches_incremental(points, "grid with duplicates");
}

// --- Degenerate sets -----------------------------------------------------------------------

TEST(Delaunay3dDivideConquer, IntegerGrids) {
  expect_matches_incremental(grid(4), "4^3");
  expect_matches_incremental(grid(10), "10^3");
  expect_matches_incremental(grid(20), "20^3", false);
}

TEST(Delaunay3dDivideConquer, TwoCoplanarLayers) {
  std::vector<Vec3> points;
  for (int x = 0; x < 15; ++x)
    for (int y = 0; y < 15; ++y) points.push_back({double(x), double(y), 0.0});
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y) points.push_back({0.5 + x, 0.25 + y, 3.0});
  expect_matches_incremental(points, "two grid layers");
}

TEST(Delaunay3dDivideConquer, CollinearRunsAndFewOffLine) {
  std::vector<Vec3> points;
  for (int k = 0; k < 200; ++k) points.push_back({double(k), 0.0, 0.0});
  for (int k = 0; k < 100; ++k) points.push_back({0.0, double(k), double(k)});
  points.push_back({50, 50, -3});
  points.push_back({-7, 20, 40});
  points.push_back({120, -30, 5});
  expect_matches_incremental(points, "collinear runs");
}

TEST(Delaunay3dDivideConquer, Clustered) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  std::vector<Vec3> points;
  for (int c = 0; c < 12; ++c) {
    const Vec3 centre{u(rng), u(rng), u(rng)};
    const double spread = std::ldexp(1.0, -3 * c);
    for (int k = 0; k < 150 + 20 * c; ++k)
      points.push_back({centre.x + spread * g(rng), centre.y + spread * g(rng), centre.z + spread * g(rng)});
  }
  expect_matches_incremental(points, "clusters");
}

TEST(Delaunay3dDivideConquer, NearlyFlatSlab) {
  // Nearly coplanar points: circumspheres are ill-conditioned, the search must still be exact.
  std::vector<Vec3> points = uniform(500, 11);
  for (Vec3& p : points) p.z *= 1e-13;
  expect_matches_incremental(points, "slab");
}

TEST(Delaunay3dDivideConquer, ScaledAndTranslated) {
  expect_matches_incremental(uniform(3000, 3, 1e-9), "scaled 1e-9");
  expect_matches_incremental(uniform(3000, 4, 1e9), "scaled 1e9");
  expect_matches_incremental(uniform(3000, 5, 1.0, 1e9), "translated by 1e9");
  std::vector<Vec3> shifted_grid = grid(6);
  for (Vec3& p : shifted_grid) p = {p.x + 1e9, p.y - 1e9, p.z + 1e9};
  expect_matches_incremental(shifted_grid, "grid translated by 1e9");
}

// --- Random sets ---------------------------------------------------------------------------

TEST(Delaunay3dDivideConquer, Uniform10k) { expect_matches_incremental(uniform(10'000, 21), "10^4"); }

TEST(Delaunay3dDivideConquer, Uniform100k) { expect_matches_incremental(uniform(100'000, 22), "10^5", false); }

RC_GTEST_PROP(Delaunay3dDivideConquer, TinyGridSetsMatchIncremental, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(4, 41);
  const auto side = *rc::gen::inRange(2, 6);
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(0, side));
    points.push_back({double(c[0]), double(c[1]), double(c[2])});
  }
  const Delaunay3dResult reference = run(points, "incremental");
  const Delaunay3dResult mine = run(points, "divide-conquer");
  RC_ASSERT(mine.degenerate_message == reference.degenerate_message);
  if (!reference.degenerate_message.empty()) return;  // neither variant ran
  mine.tetrahedralization.check_topology();
  RC_ASSERT(canonical_tetrahedron_set(mine.tetrahedralization) ==
            canonical_tetrahedron_set(reference.tetrahedralization));
  RC_ASSERT(hull_facets(mine.tetrahedralization) == hull_facets(reference.tetrahedralization));
  RC_ASSERT(mine.tetrahedralization.tetrahedron_count() == reference.tetrahedralization.tetrahedron_count());
}

}  // namespace
}  // namespace dtlab
