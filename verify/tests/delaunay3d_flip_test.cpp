// Tests of the 3D Delaunay variant "flip" (algorithms/delaunay3d/flip.cpp): on every input,
// degenerate ones above all (cospherical, coplanar, collinear, grids, points on hull facets and
// edges, scaled and translated), it must return exactly the tetrahedra and the hull of
// "incremental", in a compact, closed structure.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/flip_insertion.hpp"
#include "algorithms/delaunay3d/flip_orientation.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {
namespace {

using T3 = Tetrahedralization3;
using Tet = std::array<std::uint32_t, 4>;
using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kInf = T3::kInfinite;

// One name per positive tetrahedron: the even permutation with the smallest id first and the
// smallest of the other three second.
Tet canonical(Tet t) {
  const auto smallest = static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
  switch (smallest) {
    case 1: t = {t[1], t[0], t[3], t[2]}; break;
    case 2: t = {t[2], t[3], t[0], t[1]}; break;
    case 3: t = {t[3], t[2], t[1], t[0]}; break;
    default: break;
  }
  while (t[1] > t[2] || t[1] > t[3]) t = {t[0], t[2], t[3], t[1]};
  return t;
}

std::vector<Tet> tetrahedron_set(const T3& tet) {
  std::vector<Tet> out;
  for (const Tet& t : tet.finite_tetrahedra()) out.push_back(canonical(t));
  std::sort(out.begin(), out.end());
  return out;
}

// The hull facets under the ghosts, each rotated (keeping its orientation) to start at its
// smallest id.
std::vector<Tri> hull_set(const T3& tet) {
  std::vector<Tri> out;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (!tet.is_ghost(t)) continue;
    Tri f = {tet.vertex(t, 1), tet.vertex(t, 2), tet.vertex(t, 3)};
    while (f[0] > f[1] || f[0] > f[2]) f = {f[1], f[2], f[0]};
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// "" if "flip" returns what "incremental" returns on P, else what differs.
// `seed` changes flip's insertion order, not the answer.
std::string differences(const std::vector<Vec3>& P, std::uint64_t seed = Delaunay3dOptions{}.seed) {
  const Delaunay3dResult a = delaunay3d(P, {.algorithm = "incremental"});
  const Delaunay3dResult b = delaunay3d(P, {.algorithm = "flip", .seed = seed});
  if (a.degenerate_message != b.degenerate_message) return "degenerate messages differ";
  try {
    b.tetrahedralization.check_topology();
  } catch (const InternalError& e) {
    return std::string("topology: ") + e.what();
  }
  if (a.tetrahedralization.tetrahedron_count() != b.tetrahedralization.tetrahedron_count())
    return "record counts differ: " + std::to_string(a.tetrahedralization.tetrahedron_count()) + " vs " +
           std::to_string(b.tetrahedralization.tetrahedron_count());
  const auto ta = tetrahedron_set(a.tetrahedralization), tb = tetrahedron_set(b.tetrahedralization);
  if (ta != tb) {
    std::size_t missing = 0;
    for (const Tet& t : ta) missing += !std::binary_search(tb.begin(), tb.end(), t);
    return std::to_string(missing) + " of " + std::to_string(ta.size()) + " tetrahedra missing, flip has " +
           std::to_string(tb.size());
  }
  if (hull_set(a.tetrahedralization) != hull_set(b.tetrahedralization)) return "hulls differ";
  if (b.tetrahedralization.points().size() != P.size() ||
      !std::equal(P.begin(), P.end(), b.tetrahedralization.points().begin()))
    return "points not restored";
  if (a.duplicates != b.duplicates) return "duplicates differ";
  return "";
}

std::vector<Vec3> grid(int side, double step = 1.0) {
  std::vector<Vec3> P;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) P.push_back({x * step, y * step, z * step});
  return P;
}

// Integer points on the sphere x^2 + y^2 + z^2 = r^2: all cospherical.
std::vector<Vec3> sphere_points(int r) {
  std::vector<Vec3> P;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) P.push_back({double(x), double(y), double(z)});
  return P;
}

std::vector<Vec3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> P(n);
  for (Vec3& p : P) p = {u(rng), u(rng), u(rng)};
  return P;
}

TEST(Delaunay3dFlip, RegisteredUnderItsName) {
  ASSERT_NE(delaunay3d_variants().find("flip"), nullptr);
}

TEST(Delaunay3dFlip, SingleTetrahedronEitherOrientation) {
  EXPECT_EQ(differences({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), "");
  EXPECT_EQ(differences({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}), "");
}

TEST(Delaunay3dFlip, FivePointsInsideOutsideOnAFacetOnAnEdge) {
  const std::vector<Vec3> base = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
  for (const Vec3 q : {Vec3{1, 1, 1}, Vec3{5, 5, 5}, Vec3{-1, -1, -1}, Vec3{1, 1, 0}, Vec3{2, 0, 0},
                       Vec3{2, 2, 0}, Vec3{8, 0, 0}, Vec3{-3, 0, 0}, Vec3{2, 2, 2}, Vec3{3, 3, 0}}) {
    auto P = base;
    P.push_back(q);
    EXPECT_EQ(differences(P), "") << q.x << " " << q.y << " " << q.z;
    P.insert(P.begin(), q);  // first in input order too
    P.pop_back();
    EXPECT_EQ(differences(P), "") << q.x << " " << q.y << " " << q.z;
  }
}

TEST(Delaunay3dFlip, OctahedronAndCube) {
  const std::vector<Vec3> octahedron = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  EXPECT_EQ(differences(octahedron), "");
  auto with_centre = octahedron;
  with_centre.push_back({0, 0, 0});
  EXPECT_EQ(differences(with_centre), "");
  EXPECT_EQ(differences(grid(2)), "");
  auto cube = grid(2, 2.0);
  cube.push_back({1, 1, 1});
  for (const Vec3 c : {Vec3{1, 1, 0}, Vec3{1, 0, 1}, Vec3{0, 1, 1}, Vec3{1, 1, 2}, Vec3{1, 2, 1}, Vec3{2, 1, 1}})
    cube.push_back(c);
  EXPECT_EQ(differences(cube), "");
}

TEST(Delaunay3dFlip, IntegerPointsOnASphere) {
  for (const int radius : {3, 5, 9}) {
    auto P = sphere_points(radius);
    EXPECT_EQ(differences(P), "") << "radius " << radius;
    P.push_back({0, 0, 0});  // in every sphere: one cavity of everything
    EXPECT_EQ(differences(P), "") << "radius " << radius << " with centre";
  }
}

TEST(Delaunay3dFlip, IntegerGrids) {
  for (const int side : {3, 4, 10, 20}) EXPECT_EQ(differences(grid(side)), "") << side;
}

TEST(Delaunay3dFlip, InsertionOrderDoesNotChangeTheAnswer) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    EXPECT_EQ(differences(grid(6), seed), "") << seed;
    EXPECT_EQ(differences(sphere_points(7), seed), "") << seed;
  }
}

TEST(Delaunay3dFlip, TwoCoplanarLayers) {
  std::vector<Vec3> P;
  for (int x = 0; x < 15; ++x)
    for (int y = 0; y < 15; ++y) {
      P.push_back({double(x), double(y), 0.0});
      P.push_back({x + 0.5, y + 0.25, 3.0});
    }
  EXPECT_EQ(differences(P), "");
}

TEST(Delaunay3dFlip, CollinearRunsAndAFewOffLinePoints) {
  std::vector<Vec3> P;
  for (int k = 0; k < 60; ++k) {
    P.push_back({double(k), 0, 0});
    P.push_back({0, double(k), 2 * double(k)});
    P.push_back({double(k), double(k), double(k)});
  }
  for (const Vec3 q : {Vec3{3, 7, 1}, Vec3{-5, 2, 9}, Vec3{30, -4, 11}, Vec3{10, 10, -10}}) P.push_back(q);
  EXPECT_EQ(differences(P), "");
}

TEST(Delaunay3dFlip, PointsOnHullFacetsAndEdgesInsertedLate) {
  // A big tetrahedron first (its corners are the extreme points), then points on its facets and
  // edges and on the lines through its edges beyond the corners.
  std::vector<Vec3> P = {{0, 0, 0}, {12, 0, 0}, {0, 12, 0}, {0, 0, 12}};
  for (int k = 1; k < 12; ++k) {
    P.push_back({double(k), 0, 0});
    P.push_back({0, double(k), 12.0 - k});
    for (int l = 1; k + l < 12; ++l) P.push_back({double(k), double(l), 0});
  }
  for (int k = 13; k < 20; ++k) P.push_back({double(k), 0, 0});
  EXPECT_EQ(differences(P), "");
}

TEST(Delaunay3dFlip, ClusteredScaledTranslated) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1e-3);
  std::vector<Vec3> clusters;
  for (int c = 0; c < 20; ++c) {
    const Vec3 centre = {double(c % 4), double(c / 4 % 3), double(c % 7)};
    for (int k = 0; k < 150; ++k) clusters.push_back({centre.x + g(rng), centre.y + g(rng), centre.z + g(rng)});
  }
  EXPECT_EQ(differences(clusters), "");
  const auto base = uniform(3000, 11);
  for (const double scale : {1e-9, 1e9}) {
    std::vector<Vec3> P = base;
    for (Vec3& p : P) p = {p.x * scale, p.y * scale, p.z * scale};
    EXPECT_EQ(differences(P), "") << scale;
  }
  // Translated by 1e9: the coordinates round to a grid of spacing 2^-23, full of ties.
  std::vector<Vec3> T = base;
  for (Vec3& p : T) p = {p.x + 1e9, p.y + 1e9, p.z + 1e9};
  EXPECT_EQ(differences(T), "");
  auto G = grid(6);
  for (Vec3& p : G) p = {p.x + 1e9, p.y - 1e9, p.z + 1e9};
  EXPECT_EQ(differences(G), "");
}

TEST(Delaunay3dFlip, DegenerateAndDuplicateInput) {
  EXPECT_EQ(differences({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}), "");
  EXPECT_EQ(differences({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}}), "");
  auto P = grid(4);
  P.push_back({1, 1, 1});
  P.push_back({0, 0, 0});
  EXPECT_EQ(differences(P), "");
}

TEST(Delaunay3dFlip, RandomUniform10k) { EXPECT_EQ(differences(uniform(10'000, 1)), ""); }

TEST(Delaunay3dFlip, RandomUniform100k) { EXPECT_EQ(differences(uniform(100'000, 2)), ""); }

// The corners of a cube first, then the other points of a 4^3 grid in lexicographic order:
// points land on hull edges and facets and on inner edges and facets, and coplanar
// neighbourhoods need 4->4 flips; every kind of move must run, and the result must agree.
TEST(Delaunay3dFlip, EveryMoveRunsOnAGridInsertedCornersFirst) {
  std::vector<Vec3> P = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {3, 3, 0}, {3, 0, 3}, {0, 3, 3}, {3, 3, 3}};
  for (const Vec3& q : grid(4))
    if (std::find(P.begin(), P.end(), q) == P.end()) P.push_back(q);
  T3 tet(P);
  FlipInserter inserter(tet.points().data(), tet.mutable_records(), {0, 1, 2, 3});
  inserter.start();
  for (std::uint32_t r = 4; r < P.size(); ++r) inserter.insert(r);
  inserter.finish();
  ASSERT_NO_THROW(tet.check_topology());
  const Delaunay3dResult reference = delaunay3d(P, {.algorithm = "incremental"});
  EXPECT_EQ(tetrahedron_set(tet), tetrahedron_set(reference.tetrahedralization));
  EXPECT_EQ(hull_set(tet), hull_set(reference.tetrahedralization));
  const FlipCounts& c = inserter.counts();
  EXPECT_GT(c.splits[0], 0u);
  EXPECT_GT(c.splits[1], 0u);
  EXPECT_GT(c.splits[2], 0u);
  EXPECT_GT(c.flips23, 0u);
  EXPECT_GT(c.flips32, 0u);
  EXPECT_GT(c.flips44, 0u);
}

// The orientation rule with the infinite vertex: a ghost over a hull facet is positive, and the
// sign flips with an odd permutation.
TEST(Delaunay3dFlip, InfiniteVertexActsAsAnInteriorPointNegated) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {3, 3, 3}, {0, 0, 7}};
  const FlipOrientation o(P.data(), {0, 1, 2, 3});
  // Facet 0 of the first tetrahedron lists (1, 3, 2): its ghost is (inf, 1, 3, 2), positive.
  EXPECT_EQ(o.orient(kInf, 1, 3, 2), Sign::Positive);
  EXPECT_EQ(o.orient(1, kInf, 3, 2), Sign::Negative);
  EXPECT_EQ(o.orient(1, 3, kInf, 2), Sign::Positive);
  EXPECT_EQ(o.orient(1, 3, 2, kInf), Sign::Negative);
  EXPECT_EQ(o.orient(kInf, 1, 2, 3), Sign::Negative);
  // Facet (0, 1, 2) lies in z = 0: only the fourth corner decides, and it is above.
  EXPECT_EQ(o.orient(kInf, 0, 1, 2), -orient3d(P[3], P[0], P[1], P[2]));
  // Collinear 0, 3, 5: zero whatever the interior point.
  EXPECT_EQ(o.orient(kInf, 0, 3, 5), Sign::Zero);
  EXPECT_EQ(o.orient(0, 1, 2, 3), orient3d(P[0], P[1], P[2], P[3]));
}

// Small sets on a tiny lattice: ties everywhere.
RC_GTEST_PROP(Delaunay3dFlip, SmallLatticeSetsAgreeWithIncremental, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(4, 41);
  const auto side = *rc::gen::inRange(2, 5);
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = *rc::gen::container<std::array<int, 3>>(rc::gen::inRange(0, side));
    P.push_back({double(c[0]), double(c[1]), double(c[2])});
  }
  RC_ASSERT(differences(P, *rc::gen::arbitrary<std::uint64_t>()) == "");
}

// Larger sets on a small lattice: long chains of flips through coplanar and cospherical ties.
RC_GTEST_PROP(Delaunay3dFlip, LatticeSetsAgreeWithIncremental, ()) {
  const auto side = *rc::gen::inRange(3, 8);
  const auto n = *rc::gen::inRange<std::size_t>(20, 300);
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = *rc::gen::container<std::array<int, 3>>(rc::gen::inRange(0, side));
    P.push_back({double(c[0]), double(c[1]), double(c[2])});
  }
  RC_ASSERT(differences(P, *rc::gen::arbitrary<std::uint64_t>()) == "");
}

}  // namespace
}  // namespace dtlab
