// Constrained tetrahedralization (issue 8): the Schönhardt family, the exhaustive exact search
// for a tetrahedralization without Steiner points, and the methods of constrained3d.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "algorithms/constrained3d/exhaustive_tetrahedralization.hpp"
#include "algorithms/constrained3d/plc_checks.hpp"
#include "algorithms/constrained3d/schonhardt.hpp"
#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {
namespace {

using Ids3 = std::array<std::uint32_t, 3>;

Rational exact_volume6(std::span<const Vec3> p, std::span<const Ids3> triangles) {
  // 6 x the enclosed volume by the divergence theorem: sum of det(a, b, c).
  Rational v;
  for (const auto& t : triangles) {
    const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    const Rational ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z), cx(c.x), cy(c.y), cz(c.z);
    v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return v;
}

void expect_valid_surface(const ClosedSurface3& s) {
  EXPECT_NO_THROW(check_plc(s.points, s.triangles));
  EXPECT_EQ(exact_volume6(s.points, s.triangles).sign(), Sign::Positive);  // outward orientation
}

TEST(Schonhardt, GeneratorsGiveValidOutwardSurfaces) {
  for (const double twist : {1.0, 5.0, 30.0, 55.0, 59.0}) expect_valid_surface(schonhardt_polyhedron(twist));
  for (const int n : {3, 4, 5, 8})
    for (const int layers : {1, 2, 3})
      expect_valid_surface(twisted_prism({.sides = n, .twist_degrees = 100.0 / n, .layers = layers}));
  expect_valid_surface(twisted_prism({.sides = 3, .twist_degrees = 20, .offset = {1e6, -1e6, 1e6}}));
  for (const int n : {1, 2, 3, 5}) expect_valid_surface(chazelle_polyhedron(n));
  const auto s = schonhardt_polyhedron(30);
  EXPECT_EQ(s.points.size(), 6u);
  EXPECT_EQ(s.triangles.size(), 8u);
}

TEST(Schonhardt, GeneratorsRefuseBadParameters) {
  EXPECT_THROW(twisted_prism({.sides = 2}), InputError);
  EXPECT_THROW(twisted_prism({.layers = 0}), InputError);
  EXPECT_THROW(twisted_prism({.radius = 0}), InputError);
  EXPECT_THROW(chazelle_polyhedron(0), InputError);
  EXPECT_THROW(chazelle_polyhedron(2, 0.3), InputError);
}

TEST(Schonhardt, NoTetrahedralizationWithoutSteinerPoints) {
  for (const double twist : {0.5, 5.0, 20.0, 30.0, 45.0, 55.0, 59.5}) {
    const auto s = schonhardt_polyhedron(twist);
    const auto r = find_tetrahedralization_without_steiner(s.points, s.triangles);
    EXPECT_FALSE(r.exists) << "twist " << twist;
  }
}

Rational tetrahedra_volume6(std::span<const Vec3> p, std::span<const std::array<std::uint32_t, 4>> tetrahedra) {
  Rational sum;
  for (const auto& t : tetrahedra) {
    const std::array<Ids3, 4> faces{{{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}}};  // outward
    sum += exact_volume6(p, faces);
  }
  return sum;
}

// The prism with one side's diagonal flipped: no longer cyclic.
ClosedSurface3 acyclic_prism(double twist) {
  ClosedSurface3 s = twisted_prism({.sides = 3, .twist_degrees = twist});
  // Side 2 (b2 b0 t0 t2) is stored last, as (b2, b0, t0), (b2, t0, t5): take the other diagonal.
  s.triangles.resize(s.triangles.size() - 2);
  s.triangles.push_back({2, 0, 5});
  s.triangles.push_back({0, 3, 5});
  return s;
}

TEST(Schonhardt, SearchFindsTetrahedralizationsWhereTheyExist) {
  // The convex hull of the twisted prism (the convex diagonals) and prisms whose diagonals are
  // not cyclic are tetrahedralizable: the search must find one, and its tetrahedra must fill
  // the volume exactly.
  for (const auto& s : {acyclic_prism(0), acyclic_prism(-20),
                        twisted_prism({.sides = 3, .twist_degrees = 30, .diagonal = PrismDiagonal::ConvexDiagonal}),
                        twisted_prism({.sides = 4, .twist_degrees = 20, .diagonal = PrismDiagonal::ConvexDiagonal}),
                        twisted_prism({.sides = 3, .twist_degrees = 20, .layers = 2, .diagonal = PrismDiagonal::ConvexDiagonal})}) {
    ASSERT_NO_THROW(check_plc(s.points, s.triangles));
    const auto r = find_tetrahedralization_without_steiner(s.points, s.triangles);
    ASSERT_TRUE(r.exists);
    for (const auto& t : r.tetrahedra)
      EXPECT_EQ(orient3d(s.points[t[0]], s.points[t[1]], s.points[t[2]], s.points[t[3]]), Sign::Positive);
    EXPECT_EQ(tetrahedra_volume6(s.points, r.tetrahedra), exact_volume6(s.points, s.triangles));
  }
}

TEST(Schonhardt, UntwistedCyclicPrismHasNoTetrahedralization) {
  const auto s = twisted_prism({.sides = 3, .twist_degrees = 0});
  EXPECT_FALSE(find_tetrahedralization_without_steiner(s.points, s.triangles).exists);
}

TEST(Schonhardt, TwistedSquarePrismAndStacksHaveNoTetrahedralization) {
  for (const double twist : {5.0, 20.0, 40.0}) {
    const auto s = twisted_prism({.sides = 4, .twist_degrees = twist});
    EXPECT_FALSE(find_tetrahedralization_without_steiner(s.points, s.triangles).exists) << twist;
  }
  for (const double twist : {10.0, 30.0}) {
    const auto s = twisted_prism({.sides = 3, .twist_degrees = twist, .layers = 2});
    EXPECT_FALSE(find_tetrahedralization_without_steiner(s.points, s.triangles).exists) << twist;
  }
}

TEST(Schonhardt, SearchRefusesWhenItWouldBeIncomplete) {
  // The untwisted square prism: a diagonal plane through four vertices cuts it.
  const auto s = twisted_prism({.sides = 4, .twist_degrees = 0});
  EXPECT_THROW(find_tetrahedralization_without_steiner(s.points, s.triangles), InputError);
}

}  // namespace
}  // namespace dtlab
