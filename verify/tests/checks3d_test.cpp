// Tests of the 3D exact checkers (verify/checks3d): they accept what "incremental" produces on
// general and degenerate input, and each corruption of a correct result is reported by the check
// responsible for it (and by verify_delaunay3d): a reflected point set (negative tetrahedra), a
// 2-3 flip (a valid tetrahedralization that is not Delaunay), the other diagonal of a flat hull
// face (ghost rule), a dropped tetrahedron (concave hull), broken twins, a vertex swapped for
// another, a missing record, unreferenced points and wrong duplicate lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "verify/checks3d.hpp"

namespace dtlab {
namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;

std::vector<Vec3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> out(n);
  const auto u = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (Vec3& p : out) p = {u(), u(), u()};
  return out;
}

std::vector<Vec3> grid(int side) {
  std::vector<Vec3> out;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) out.push_back({double(x), double(y), double(z)});
  return out;
}

std::vector<Vec3> sphere_points(int r) {
  std::vector<Vec3> out;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) out.push_back({double(x), double(y), double(z)});
  return out;
}

// A closed structure from finite tetrahedra (each positive): facets paired by their vertices,
// unpaired facets closed by ghosts, ghosts paired along hull edges. Pairs nothing twice, so a
// non-manifold list leaves kNone twins for check_topology to find.
T3 build(std::vector<Vec3> points, const std::vector<TetrahedronIds>& tetrahedra) {
  T3 tet(std::move(points));
  for (const TetrahedronIds& t : tetrahedra) tet.add_tetrahedron(t[0], t[1], t[2], t[3]);
  const auto finite = static_cast<std::uint32_t>(tet.tetrahedron_count());
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> open;
  std::vector<std::uint32_t> hull;
  for (std::uint32_t h = 0; h < 4 * finite; ++h) {
    auto key = tet.facet_vertices(h);
    std::sort(key.begin(), key.end());
    const auto it = open.find(key);
    if (it == open.end()) {
      open.emplace(key, h);
    } else {
      tet.link(h, it->second);
      open.erase(it);
    }
  }
  for (const auto& [key, h] : open) {
    const auto f = tet.facet_vertices(h);
    const std::uint32_t g = tet.add_tetrahedron(kInf, f[0], f[1], f[2]);
    tet.link(h, T3::facet(g, 0));
    hull.push_back(g);
  }
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> edges;
  for (const std::uint32_t g : hull) {
    for (std::uint32_t i = 1; i < 4; ++i) {
      auto key = tet.facet_vertices(T3::facet(g, i));
      std::sort(key.begin(), key.end());
      const auto it = edges.find(key);
      if (it == edges.end()) {
        edges.emplace(key, T3::facet(g, i));
      } else {
        tet.link(T3::facet(g, i), it->second);
        edges.erase(it);
      }
    }
  }
  return tet;
}

T3 run(const std::vector<Vec3>& points) { return delaunay3d(points).tetrahedralization; }

bool mentions(const CheckReport3& r, const std::string& what) {
  return std::any_of(r.problems.begin(), r.problems.end(),
                     [&](const std::string& p) { return p.find(what) != std::string::npos; });
}

// verify_delaunay3d must reject the structure and name `what` in some problem.
void expect_rejected(const std::vector<Vec3>& points, const T3& tet, const std::string& what,
                     const std::vector<std::uint32_t>& duplicates = {}) {
  const CheckReport3 r = verify_delaunay3d(points, tet, duplicates);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, what)) << "expected a problem naming '" << what << "', got:\n" << to_text(r);
}

TEST(Checks3d, AcceptsCorrectResults) {
  const std::vector<std::vector<Vec3>> inputs = {
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, uniform(2000, 1), grid(5), sphere_points(9),
      [] {  // two coplanar layers and a point between
        std::vector<Vec3> P;
        for (int x = 0; x < 5; ++x)
          for (int y = 0; y < 5; ++y) P.push_back({double(x), double(y), 0}), P.push_back({double(x), double(y), 4});
        P.push_back({1.5, 2.5, 2});
        return P;
      }()};
  for (const auto& P : inputs) {
    const Delaunay3dResult r = delaunay3d(P);
    const CheckReport3 report = verify_delaunay3d(P, r.tetrahedralization, r.duplicates);
    EXPECT_TRUE(report.ok) << to_text(report);
    EXPECT_EQ(report.tetrahedra, r.tetrahedralization.finite_tetrahedron_count());
    EXPECT_EQ(report.referenced_points, P.size());
    EXPECT_GT(report.interior_facets + report.hull_facets, 0u);
    for (const auto& single : {check_topology3(r.tetrahedralization), check_orientation3(r.tetrahedralization),
                               check_empty_sphere3(r.tetrahedralization), check_hull3(r.tetrahedralization),
                               check_coverage3(r.tetrahedralization), check_unreferenced3(r.tetrahedralization, {})}) {
      EXPECT_TRUE(single.ok) << to_text(single);
    }
    // The builder reproduces the structure from its finite tetrahedra (used by the corruptions).
    const T3 rebuilt = build(P, r.tetrahedralization.finite_tetrahedra());
    EXPECT_TRUE(verify_delaunay3d(P, rebuilt).ok) << to_text(verify_delaunay3d(P, rebuilt));
  }
}

TEST(Checks3d, CountsMatchTheStructure) {
  const auto P = uniform(500, 2);
  const T3 tet = run(P);
  const CheckReport3 r = verify_delaunay3d(P, tet);
  ASSERT_TRUE(r.ok) << to_text(r);
  EXPECT_EQ(r.points, 500u);
  EXPECT_EQ(r.hull_facets, tet.tetrahedron_count() - tet.finite_tetrahedron_count());
  // Euler on the 3-sphere: T = E - V with V counting the infinite vertex (edges to it: hull vertices).
  EXPECT_EQ(tet.tetrahedron_count(), r.edges + r.hull_vertices - (P.size() + 1));
  // Each finite tetrahedron has 4 facets: 2 x interior + hull facets.
  EXPECT_EQ(4 * r.tetrahedra, 2 * r.interior_facets + r.hull_facets);
  EXPECT_NE(to_json(r).find("\"ok\":true"), std::string::npos);
}

TEST(Checks3d, ReflectedPointsMakeEveryTetrahedronNegative) {
  auto P = uniform(300, 3);
  const T3 tet = run(P);
  for (Vec3& p : P) p.x = -p.x;
  const T3 mirrored = build(P, tet.finite_tetrahedra());
  const CheckReport3 r = check_orientation3(mirrored);
  EXPECT_EQ(r.problem_count, tet.finite_tetrahedron_count());
  EXPECT_TRUE(mentions(r, "is negative"));
  expect_rejected(P, mirrored, "orientation");
}

TEST(Checks3d, OneTetrahedronFlippedInPlaceBreaksTheTwins) {
  const auto P = uniform(300, 4);
  T3 tet = run(P);
  std::uint32_t t = 0;
  while (tet.is_ghost(t)) ++t;
  std::swap(tet.mutable_records()[t].vertex[1], tet.mutable_records()[t].vertex[2]);
  EXPECT_FALSE(check_topology3(tet).ok);
  expect_rejected(P, tet, "topology");
}

// Replaces two finite tetrahedra sharing a facet whose union is convex by three (a 2-3 flip):
// still a tetrahedralization of the hull, no longer Delaunay.
std::vector<TetrahedronIds> flip23(const std::vector<Vec3>& P, const T3& tet) {
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (tet.is_ghost(t)) continue;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t g = tet.twin(T3::facet(t, i));
      if (tet.is_ghost(T3::tetrahedron_of(g))) continue;
      const auto f = tet.facet_vertices(T3::facet(t, i));
      const std::uint32_t d = tet.vertex(t, i), e = tet.apex(g);
      const Sign s0 = orient3d(P[d], P[e], P[f[0]], P[f[1]]);
      if (s0 == Sign::Zero || orient3d(P[d], P[e], P[f[1]], P[f[2]]) != s0 ||
          orient3d(P[d], P[e], P[f[2]], P[f[0]]) != s0)
        continue;
      std::vector<TetrahedronIds> out;
      for (std::uint32_t u = 0; u < tet.tetrahedron_count(); ++u)
        if (!tet.is_ghost(u) && u != t && u != T3::tetrahedron_of(g)) out.push_back(tet.records()[u].vertex);
      for (int k = 0; k < 3; ++k) {
        TetrahedronIds n = {f[k], f[(k + 1) % 3], d, e};
        if (orient3d(P[n[0]], P[n[1]], P[n[2]], P[n[3]]) == Sign::Negative) std::swap(n[0], n[1]);
        out.push_back(n);
      }
      return out;
    }
  }
  return {};
}

TEST(Checks3d, FlippedFacetIsNotDelaunay) {
  for (const auto& P : {uniform(200, 5), sphere_points(7), sphere_points(9)}) {
    const T3 tet = run(P);
    const auto flipped = flip23(P, tet);
    ASSERT_FALSE(flipped.empty());
    const T3 broken = build(P, flipped);
    EXPECT_TRUE(check_topology3(broken).ok) << to_text(check_topology3(broken));
    EXPECT_TRUE(check_orientation3(broken).ok);
    EXPECT_TRUE(check_coverage3(broken).ok);
    const CheckReport3 r = check_empty_sphere3(broken);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(mentions(r, "not locally Delaunay")) << to_text(r);
    expect_rejected(P, broken, "empty sphere");
  }
}

TEST(Checks3d, WrongDiagonalOfAFlatHullFaceBreaksTheGhostRule) {
  // A square pyramid: the base is a flat hull face with two triangulations; the perturbation
  // picks one, the other is reported by the ghost rule (and by the in-sphere test of the
  // interior facet, since the five points are cospherical).
  const std::vector<Vec3> P = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 1}};
  const T3 good = run(P);
  ASSERT_TRUE(verify_delaunay3d(P, good).ok);
  const auto tetrahedra = canonical_tetrahedron_set(good);
  ASSERT_EQ(tetrahedra.size(), 2u);
  const bool uses_02 = std::any_of(tetrahedra.begin(), tetrahedra.end(), [](const TetrahedronIds& t) {
    return std::count(t.begin(), t.end(), 0u) + std::count(t.begin(), t.end(), 2u) == 2;
  }) && std::all_of(tetrahedra.begin(), tetrahedra.end(), [](const TetrahedronIds& t) {
    return std::count(t.begin(), t.end(), 0u) + std::count(t.begin(), t.end(), 2u) == 2;
  });
  std::vector<TetrahedronIds> other;
  const std::array<std::uint32_t, 2> diagonal = uses_02 ? std::array<std::uint32_t, 2>{1, 3} : std::array<std::uint32_t, 2>{0, 2};
  for (const std::uint32_t c : uses_02 ? std::array<std::uint32_t, 2>{0, 2} : std::array<std::uint32_t, 2>{1, 3}) {
    TetrahedronIds t = {diagonal[0], diagonal[1], c, 4};
    if (orient3d(P[t[0]], P[t[1]], P[t[2]], P[t[3]]) == Sign::Negative) std::swap(t[0], t[1]);
    other.push_back(t);
  }
  const T3 wrong = build(P, other);
  EXPECT_TRUE(check_topology3(wrong).ok);
  EXPECT_TRUE(check_orientation3(wrong).ok);
  EXPECT_TRUE(check_coverage3(wrong).ok);
  const CheckReport3 r = check_hull3(wrong);
  EXPECT_TRUE(mentions(r, "ghost rule")) << to_text(r);
  expect_rejected(P, wrong, "ghost rule");
}

TEST(Checks3d, DroppedTetrahedronIsReported) {
  for (const auto& P : {uniform(200, 6), grid(4), sphere_points(5)}) {
    const T3 tet = run(P);
    // An interior tetrahedron (no facet on the hull): dropping it leaves a hole whose facets
    // become hull facets facing inwards.
    auto tetrahedra = tet.finite_tetrahedra();
    std::uint32_t inner = T3::kNone;
    for (std::uint32_t t = 0; t < tet.tetrahedron_count() && inner == T3::kNone; ++t) {
      bool interior = !tet.is_ghost(t);
      for (std::uint32_t i = 0; i < 4 && interior; ++i) interior = !tet.is_ghost(tet.adjacent(t, i));
      if (interior) inner = t;
    }
    ASSERT_NE(inner, T3::kNone);
    const auto it = std::find(tetrahedra.begin(), tetrahedra.end(), tet.records()[inner].vertex);
    tetrahedra.erase(it);
    expect_rejected(P, build(P, tetrahedra), "hull");
    // A hull tetrahedron: the rebuilt hull is concave there, or a vertex is left out.
    tetrahedra = tet.finite_tetrahedra();
    tetrahedra.erase(tetrahedra.begin());
    EXPECT_FALSE(verify_delaunay3d(P, build(P, tetrahedra)).ok);
    // The record removed from the structure itself: twins point at nothing.
    T3 cut = tet;
    cut.mutable_records().pop_back();
    expect_rejected(P, cut, "topology");
  }
}

TEST(Checks3d, BrokenTwinsAreReported) {
  const auto P = uniform(300, 7);
  const T3 tet = run(P);
  T3 broken = tet;
  broken.mutable_records()[3].neighbour[1] = broken.mutable_records()[3].neighbour[2];
  expect_rejected(P, broken, "topology");
  // Two pairs of twins exchanged consistently (twin(twin(h)) == h still holds): caught by the
  // facet vertices.
  broken = tet;
  auto& rec = broken.mutable_records();
  const std::uint32_t g0 = rec[0].neighbour[0], g1 = rec[5].neighbour[2];
  broken.link(T3::facet(0, 0), g1);
  broken.link(T3::facet(5, 2), g0);
  expect_rejected(P, broken, "topology");
}

TEST(Checks3d, VertexSwappedForAnotherIsReported) {
  const auto P = uniform(300, 8);
  const T3 tet = run(P);
  std::uint32_t t = 0;
  while (tet.is_ghost(t)) ++t;
  // Another vertex: the tetrahedron no longer matches its neighbours.
  T3 broken = tet;
  auto& v = broken.mutable_records()[t].vertex;
  v[0] = (v[0] + 1) % static_cast<std::uint32_t>(P.size());
  while (std::count(v.begin(), v.end(), v[0]) > 1) v[0] = (v[0] + 1) % static_cast<std::uint32_t>(P.size());
  expect_rejected(P, broken, "topology");
  // The same vertex renamed in every tetrahedron (topology intact): geometry and references catch it.
  broken = tet;
  const std::uint32_t from = 0, to = static_cast<std::uint32_t>(P.size());
  std::vector<Vec3> Q = P;
  Q.push_back(P[150]);  // the renamed vertex now sits on point 150
  T3 renamed(Q);
  renamed.mutable_records() = tet.records();
  for (auto& r : renamed.mutable_records())
    for (auto& id : r.vertex)
      if (id == from) id = to;
  EXPECT_FALSE(verify_delaunay3d(Q, renamed).ok);
}

TEST(Checks3d, ReferencesAndDuplicates) {
  auto P = uniform(200, 9);
  const T3 tet = run(P);
  // A point left out of the tetrahedralization.
  auto Q = P;
  Q.push_back({0.5, 0.5, 0.5});
  T3 missing(Q);
  missing.mutable_records() = tet.records();
  expect_rejected(Q, missing, "vertex of no tetrahedron");
  // Duplicates: declared and correct, declared but not a copy, a copy not declared.
  P.push_back(P[17]);
  const Delaunay3dResult r = delaunay3d(P);
  ASSERT_EQ(r.duplicates, (std::vector<std::uint32_t>{200}));
  EXPECT_TRUE(verify_delaunay3d(P, r.tetrahedralization, r.duplicates).ok);
  expect_rejected(P, r.tetrahedralization, "coincide", {});
  expect_rejected(P, r.tetrahedralization, "is a vertex of", {17, 200});
  expect_rejected(P, r.tetrahedralization, "out of range", {200, 999});
  expect_rejected(P, r.tetrahedralization, "listed twice", {200, 200});
  // Points that differ from the input.
  auto moved = P;
  moved[3].x += 1.0;
  expect_rejected(moved, r.tetrahedralization, "not the");
}

TEST(Checks3d, NoTetrahedraOnlyForCoplanarPoints) {
  std::vector<Vec3> plane;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y) plane.push_back({double(x), double(y), double(x - y)});
  const Delaunay3dResult flat = delaunay3d(plane);
  ASSERT_FALSE(flat.degenerate_message.empty());
  EXPECT_TRUE(verify_delaunay3d(plane, flat.tetrahedralization).ok);
  const std::vector<Vec3> few = {{0, 0, 0}, {1, 2, 3}, {1, 2, 3}};
  const Delaunay3dResult small = delaunay3d(few);
  EXPECT_TRUE(verify_delaunay3d(few, small.tetrahedralization, small.duplicates).ok);
  // An empty result for points that span space is wrong.
  const auto P = uniform(20, 10);
  expect_rejected(P, T3(P), "not coplanar");
}

TEST(Checks3d, CoordinatesOutOfRangeAreReportedNotUsed) {
  auto P = uniform(50, 11);
  const T3 tet = run(P);
  P[7].z = 1e300;
  expect_rejected(P, tet, "point 7");
}

TEST(Checks3d, CanonicalSetIsOrientationPreservingAndOrderFree) {
  const std::vector<TetrahedronIds> a = {{5, 2, 9, 7}, {3, 1, 4, 8}};
  const auto c = canonical_tetrahedron_set(a);
  ASSERT_EQ(c.size(), 2u);
  for (const TetrahedronIds& t : c) {
    EXPECT_LT(t[0], t[1]);
    EXPECT_LT(t[1], t[2]);
    EXPECT_LT(t[1], t[3]);
  }
  // Every even permutation gives the same name, every odd one another.
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  TetrahedronIds t = {0, 1, 2, 3};
  const auto reference = canonical_tetrahedron_set(std::vector<TetrahedronIds>{t});
  std::sort(t.begin(), t.end());
  do {
    const bool even = orient3d(P[t[0]], P[t[1]], P[t[2]], P[t[3]]) == Sign::Positive;
    EXPECT_EQ(canonical_tetrahedron_set(std::vector<TetrahedronIds>{t}) == reference, even);
  } while (std::next_permutation(t.begin(), t.end()));
}

}  // namespace
}  // namespace dtlab
