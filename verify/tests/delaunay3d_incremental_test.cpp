// Tests of the 3D tetrahedralization structure, 3D spatial sort, element sets and the
// "incremental" 3D Delaunay variant, with inline exact checks: topology, positive orientation by
// exact orient3d, every interior facet locally Delaunay under insphere_perturbed, ghosts facing
// outwards, a locally convex boundary (so that the tetrahedra tile the convex hull), every
// distinct point used; against brute force on small sets, and invariance under input order.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rounding.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/element_sets3.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {
namespace {

using T3 = Tetrahedralization3;
using Tet = std::array<std::uint32_t, 4>;
constexpr std::uint32_t kInf = T3::kInfinite;

Delaunay3dResult run(const std::vector<Vec3>& points) { return delaunay3d(points, {.algorithm = "incremental"}); }

// One name per positive tetrahedron: the even permutation that puts the smallest id first and
// the next smallest second.
Tet canonical(Tet t) {
  const auto smallest = static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
  // Even permutations moving position k to 0: double transpositions.
  switch (smallest) {
    case 1: t = {t[1], t[0], t[3], t[2]}; break;
    case 2: t = {t[2], t[3], t[0], t[1]}; break;
    case 3: t = {t[3], t[2], t[1], t[0]}; break;
    default: break;
  }
  // Rotate the last three (a 3-cycle is even) so the smallest of them comes first.
  while (t[1] > t[2] || t[1] > t[3]) t = {t[0], t[2], t[3], t[1]};
  return t;
}

std::set<Tet> tetrahedron_set(const T3& tet) {
  std::set<Tet> out;
  for (const Tet& t : tet.finite_tetrahedra()) out.insert(canonical(t));
  return out;
}

// Tetrahedra as sorted coordinate lists (positive orientation checked elsewhere): comparable
// across inputs that hold the same points in different orders.
std::set<std::array<double, 12>> geometric_set(const T3& tet) {
  std::set<std::array<double, 12>> out;
  const auto P = tet.points();
  for (const Tet& t : tet.finite_tetrahedra()) {
    std::array<Vec3, 4> v = {P[t[0]], P[t[1]], P[t[2]], P[t[3]]};
    std::sort(v.begin(), v.end(), [](const Vec3& a, const Vec3& b) { return a < b; });
    std::array<double, 12> key{};
    for (int k = 0; k < 4; ++k) key[3 * k] = v[k].x, key[3 * k + 1] = v[k].y, key[3 * k + 2] = v[k].z;
    out.insert(key);
  }
  return out;
}

// The exact checks every result must pass; returns "" or what failed. `all_points_one_side` adds
// the O(n * hull) check that every point lies on the inner side of every hull facet.
std::string delaunay_problems(const Delaunay3dResult& r, bool all_points_one_side = false) {
  const T3& tet = r.tetrahedralization;
  try {
    tet.check_topology();
  } catch (const InternalError& e) {
    return e.what();
  }
  const auto P = tet.points();
  const auto count = static_cast<std::uint32_t>(tet.tetrahedron_count());
  std::vector<bool> used(P.size(), false);
  std::size_t not_positive = 0, not_delaunay = 0, ghost_inward = 0, concave = 0, outside = 0, usage = 0;
  for (std::uint32_t t = 0; t < count; ++t) {
    if (tet.is_ghost(t)) {
      const Vec3 &a = P[tet.vertex(t, 1)], &b = P[tet.vertex(t, 2)], &c = P[tet.vertex(t, 3)];
      // The finite tetrahedron across the hull facet lies on the inner side.
      const std::uint32_t h = tet.twin(4 * t);
      ghost_inward += orient3d(P[tet.vertex(h >> 2, h & 3u)], a, b, c) != Sign::Negative;
      // Boundary convex at each hull edge: the apex of the next hull facet is not beyond this one.
      for (std::uint32_t i = 1; i < 4; ++i) {
        const std::uint32_t g = tet.twin(4 * t + i);
        concave += orient3d(P[tet.vertex(g >> 2, g & 3u)], a, b, c) == Sign::Positive;
      }
      if (all_points_one_side)
        for (const Vec3& q : P) outside += orient3d(q, a, b, c) == Sign::Positive;
      continue;
    }
    const Vec3 &a = P[tet.vertex(t, 0)], &b = P[tet.vertex(t, 1)], &c = P[tet.vertex(t, 2)], &d = P[tet.vertex(t, 3)];
    for (std::uint32_t i = 0; i < 4; ++i) used[tet.vertex(t, i)] = true;
    not_positive += orient3d(a, b, c, d) != Sign::Positive;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = tet.twin(4 * t + i);
      if (tet.is_ghost(h >> 2)) continue;
      not_delaunay += insphere_perturbed(a, b, c, d, P[tet.vertex(h >> 2, h & 3u)]) != Sign::Negative;
    }
  }
  const std::set<std::uint32_t> dropped(r.duplicates.begin(), r.duplicates.end());
  for (std::uint32_t v = 0; v < P.size(); ++v) usage += used[v] == (dropped.count(v) != 0);
  std::string out;
  auto report = [&out](std::size_t n, const char* what) {
    if (n != 0) out += std::to_string(n) + " " + what + "; ";
  };
  report(not_positive, "tetrahedra not positive");
  report(not_delaunay, "interior facets not locally Delaunay");
  report(ghost_inward, "ghosts facing inwards");
  report(concave, "concave hull edges");
  report(outside, "points beyond a hull facet");
  report(usage, "points used although dropped, or unused although distinct");
  return out;
}

// Sum of 6 x volume, exact for small integer coordinates (every product below 2^53).
double six_volume(const T3& tet) {
  const auto P = tet.points();
  double sum = 0;
  for (const Tet& t : tet.finite_tetrahedra()) {
    const Vec3 u = P[t[1]] - P[t[0]], v = P[t[2]] - P[t[0]], w = P[t[3]] - P[t[0]];
    sum += dot(u, cross(v, w));
  }
  return sum;
}

// Every 4-subset whose perturbed sphere is empty: the perturbed Delaunay tetrahedra by definition.
std::set<Tet> brute_force(const std::vector<Vec3>& P) {
  std::set<Tet> out;
  const auto n = static_cast<std::uint32_t>(P.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c)
        for (std::uint32_t d = c + 1; d < n; ++d) {
          Tet t{a, b, c, d};
          const Sign o = orient3d(P[a], P[b], P[c], P[d]);
          if (o == Sign::Zero) continue;
          if (o == Sign::Negative) std::swap(t[2], t[3]);
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            empty = insphere_perturbed(P[t[0]], P[t[1]], P[t[2]], P[t[3]], P[e]) == Sign::Negative;
          }
          if (empty) out.insert(canonical(t));
        }
  return out;
}

std::vector<Vec3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = {u(rng), u(rng), u(rng)};
  return out;
}

std::vector<Vec3> grid(int side) {
  std::vector<Vec3> out;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) out.push_back({double(x), double(y), double(z)});
  return out;
}

// Integer points on the sphere x^2 + y^2 + z^2 = r^2: all cospherical.
std::vector<Vec3> sphere_points(int r) {
  std::vector<Vec3> out;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) out.push_back({double(x), double(y), double(z)});
  return out;
}

// --- Structure -----------------------------------------------------------------------------

TEST(Tetrahedralization3, FacetTableListsFacetsCounterClockwiseFromTheOppositeVertex) {
  const std::array<Vec3, 4> v = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  ASSERT_EQ(orient3d(v[0], v[1], v[2], v[3]), Sign::Positive);
  for (std::uint32_t i = 0; i < 4; ++i) {
    const auto& f = T3::kFacetVertex[i];
    EXPECT_EQ(orient3d(v[f[0]], v[f[1]], v[f[2]], v[i]), Sign::Positive) << "facet " << i;
    for (const std::uint32_t k : f) EXPECT_NE(k, i);
  }
}

TEST(Tetrahedralization3, AddTetrahedronPutsInfiniteFirstKeepingOrientation) {
  T3 tet(std::vector<Vec3>(3));
  for (int k = 0; k < 4; ++k) {
    std::array<std::uint32_t, 4> ids = {0, 1, 2, 3};
    ids[k] = kInf;
    std::array<std::uint32_t, 4> ranks = ids;
    ranks[k] = 3;
    for (std::uint32_t j = 0, r = 0; j < 4; ++j)
      if (j != static_cast<std::uint32_t>(k)) ranks[j] = r++;
    const std::uint32_t t = tet.add_tetrahedron(ids[0], ids[1], ids[2], ids[3]);
    EXPECT_EQ(tet.vertex(t, 0), kInf);
    // The stored order is an even permutation of the given one.
    std::array<std::uint32_t, 4> pos{};
    for (std::uint32_t j = 0; j < 4; ++j)
      for (std::uint32_t i = 0; i < 4; ++i)
        if (tet.vertex(t, j) == ids[i]) pos[j] = i;
    int inversions = 0;
    for (int x = 0; x < 4; ++x)
      for (int y = x + 1; y < 4; ++y) inversions += pos[x] > pos[y];
    EXPECT_EQ(inversions % 2, 0) << "infinite vertex at " << k;
  }
}

TEST(Tetrahedralization3, CheckTopologyNamesTheBrokenFacet) {
  const auto r = run({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}});
  T3 tet = r.tetrahedralization;
  ASSERT_NO_THROW(tet.check_topology());
  EXPECT_EQ(tet.tetrahedron_count(), tet.finite_tetrahedron_count() + 6);  // hull: a bipyramid, 6 facets
  T3 broken = tet;
  broken.mutable_records()[1].neighbour[1] = broken.mutable_records()[1].neighbour[2];
  try {
    broken.check_topology();
    FAIL() << "no error";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("facet"), std::string::npos);
  }
  broken = tet;
  broken.mutable_records()[0].vertex[1] = kInf;
  EXPECT_THROW(broken.check_topology(), InternalError);
  broken = tet;
  std::swap(broken.mutable_records()[0].vertex[0], broken.mutable_records()[0].vertex[1]);  // twins no longer reversed
  EXPECT_THROW(broken.check_topology(), InternalError);
}

// --- Spatial sort --------------------------------------------------------------------------

TEST(SpatialSort3, HilbertIndexIsABijectionThroughAdjacentCells) {
  constexpr int kBits = 3;
  constexpr std::uint32_t kSide = 1u << kBits;
  std::vector<std::array<std::uint32_t, 3>> by_index(kSide * kSide * kSide, {kSide, kSide, kSide});
  for (std::uint32_t x = 0; x < kSide; ++x)
    for (std::uint32_t y = 0; y < kSide; ++y)
      for (std::uint32_t z = 0; z < kSide; ++z) {
        const std::uint32_t i = hilbert_index3(x, y, z, kBits);
        ASSERT_LT(i, by_index.size());
        EXPECT_EQ(by_index[i][0], kSide) << "index " << i << " twice";
        by_index[i] = {x, y, z};
      }
  EXPECT_EQ(by_index[0], (std::array<std::uint32_t, 3>{0, 0, 0}));
  for (std::size_t i = 1; i < by_index.size(); ++i) {
    int distance = 0;
    for (int k = 0; k < 3; ++k)
      distance += std::abs(static_cast<int>(by_index[i][k]) - static_cast<int>(by_index[i - 1][k]));
    EXPECT_EQ(distance, 1) << "cells " << i - 1 << " and " << i << " not adjacent";
  }
}

// The table-driven index (hilbert_index3) against the bit-by-bit definition (Skilling's
// transposition): every cell of the grids up to 2^5 a side, and random cells of the 2^10 grid.
TEST(SpatialSort3, HilbertTablesAgreeWithSkillingsTransposition) {
  for (int bits = 1; bits <= 5; ++bits) {
    const std::uint32_t side = 1u << bits;
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y)
        for (std::uint32_t z = 0; z < side; ++z)
          ASSERT_EQ(hilbert_index3(x, y, z, bits), hilbert_index3_skilling(x, y, z, bits))
              << "cell (" << x << ", " << y << ", " << z << ") of the 2^" << bits << " grid";
  }
  std::mt19937_64 rng(23);
  for (int k = 0; k < 200000; ++k) {
    const auto x = static_cast<std::uint32_t>(rng() & 1023u), y = static_cast<std::uint32_t>(rng() & 1023u),
               z = static_cast<std::uint32_t>(rng() & 1023u);
    ASSERT_EQ(hilbert_index3(x, y, z), hilbert_index3_skilling(x, y, z)) << "cell (" << x << ", " << y << ", " << z << ")";
  }
}

// On a team of threads the sort (its passes over the whole set, and the shared cells sorted
// again on several threads) gives the same order and the same duplicates as on one, on sets large
// enough to take the threaded path: uniform, and clustered with repeated points (many cells
// shared, sorted again).
TEST(SpatialSort3, SortOnATeamEqualsTheSortOnOneThread) {
  WorkerTeam team(2);
  std::vector<Vec3> uniform_points = uniform(200000, 11);
  std::vector<Vec3> clustered;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> spread(0.0, 1e-7);
  for (int c = 0; c < 40; ++c) {
    const Vec3 centre{static_cast<double>(c % 7), static_cast<double>(c % 5), static_cast<double>(c % 3)};
    for (int k = 0; k < 4000; ++k) clustered.push_back({centre.x + spread(rng), centre.y + spread(rng), centre.z + spread(rng)});
  }
  for (int k = 0; k < 5000; ++k) clustered.push_back(clustered[static_cast<std::size_t>(k * 31)]);
  for (const std::vector<Vec3>* points : {&uniform_points, &clustered}) {
    std::vector<std::uint32_t> alone(points->size()), shared;
    std::iota(alone.begin(), alone.end(), 0u);
    shared = alone;
    const auto dropped_alone = hilbert_sort_unique(*points, alone);
    const auto dropped_shared = hilbert_sort_unique(*points, shared, &team);
    EXPECT_EQ(alone, shared);
    EXPECT_EQ(dropped_alone, dropped_shared);
    // distinct_in_hilbert_order sorts the positions themselves (no gather of ids): same order.
    for (WorkerTeam* on : {static_cast<WorkerTeam*>(nullptr), &team}) {
      const DistinctPoints split = distinct_in_hilbert_order(std::span<const Vec3>(*points), on);
      EXPECT_EQ(split.distinct, alone);
      ASSERT_EQ(split.duplicates.size(), dropped_alone.size());
      for (std::size_t k = 0; k < dropped_alone.size(); ++k) {
        EXPECT_EQ(split.duplicates[k], dropped_alone[k].first);
        EXPECT_EQ(split.duplicate_of[k], dropped_alone[k].second);
      }
    }
  }
  std::vector<Vec2> plane(100000);
  std::mt19937_64 rng2(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (Vec2& p : plane) p = {u(rng2), u(rng2)};
  plane[99999] = plane[12];
  std::vector<std::uint32_t> plane_ids(plane.size());
  std::iota(plane_ids.begin(), plane_ids.end(), 0u);
  const auto plane_dropped = hilbert_sort_unique(plane, plane_ids);
  const DistinctPoints plane_split = distinct_in_hilbert_order(std::span<const Vec2>(plane), &team);
  EXPECT_EQ(plane_split.distinct, plane_ids);
  ASSERT_EQ(plane_dropped.size(), 1u);
  EXPECT_EQ(plane_split.duplicates, std::vector<std::uint32_t>{99999});
  EXPECT_EQ(distinct_in_hilbert_order(std::span<const Vec3>(clustered), &team).duplicates.size(), 5000u);
}

// The BRIO order dealt on a team is the one-thread order, and the ranks it gives with it are
// each id's position in the Hilbert order, increasing within each round.
TEST(SpatialSort3, BrioOnATeamEqualsTheBrioOnOneThread) {
  WorkerTeam team(3);
  const std::vector<Vec3> points = uniform(100000, 21);
  std::vector<std::uint32_t> sorted(points.size());
  std::iota(sorted.begin(), sorted.end(), 0u);
  hilbert_sort(points, sorted);
  for (const std::size_t n : {std::size_t{0}, std::size_t{50}, std::size_t{64}, std::size_t{65}, std::size_t{4097},
                              sorted.size()}) {
    const std::span<const std::uint32_t> ids(sorted.data(), n);
    const std::vector<std::uint32_t> alone = brio_order_of_sorted(ids, 9);
    const BrioOrder shared = brio_order_of_sorted(ids, 9, &team, true);
    ASSERT_EQ(alone.size(), n);
    EXPECT_TRUE(std::equal(alone.begin(), alone.end(), shared.ids.begin(), shared.ids.end())) << n;
    ASSERT_EQ(shared.ranks.size(), n);
    std::size_t descents = 0;
    for (std::size_t r = 0; r < n; ++r) {
      EXPECT_EQ(shared.ids[r], ids[shared.ranks[r]]);
      descents += r > 0 && shared.ranks[r] < shared.ranks[r - 1];
    }
    EXPECT_LE(descents, 20u) << n;  // one a round at most: log2(n / 64) + 1 rounds
    EXPECT_TRUE(brio_order_of_sorted(ids, 9, nullptr, false).ranks.empty());
  }
}

TEST(SpatialSort3, SortUniqueDropsDuplicatesKeepingTheSmallestId) {
  std::vector<Vec3> P = uniform(5000, 3);
  for (int k = 0; k < 300; ++k) P.push_back(P[static_cast<std::size_t>(k * 7)]);
  P.push_back(P[7]);
  std::vector<std::uint32_t> ids(P.size());
  std::iota(ids.begin(), ids.end(), 0u);
  const auto dropped = hilbert_sort_unique(P, ids);
  EXPECT_EQ(ids.size(), 5000u);
  EXPECT_EQ(dropped.size(), 301u);
  for (const auto& [d, kept] : dropped) {
    EXPECT_EQ(P[d], P[kept]);
    EXPECT_LT(kept, d);
    EXPECT_LT(kept, 5000u);
  }
  std::vector<std::uint32_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t k = 0; k < 5000; ++k) EXPECT_EQ(sorted[k], k);
  // Locality: consecutive points of a Hilbert order are close (mean step far below a random pair's).
  double step = 0;
  for (std::size_t k = 1; k < ids.size(); ++k) step += norm(P[ids[k]] - P[ids[k - 1]]);
  EXPECT_LT(step / static_cast<double>(ids.size() - 1), 0.2);
}

// --- Delaunay: hand cases and degenerate sets ------------------------------------------------

TEST(Delaunay3dIncremental, SingleTetrahedronEitherOrientation) {
  for (const auto& P : {std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                        std::vector<Vec3>{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}}) {
    const auto r = run(P);
    ASSERT_TRUE(r.degenerate_message.empty());
    EXPECT_EQ(r.tetrahedralization.finite_tetrahedron_count(), 1u);
    EXPECT_EQ(r.tetrahedralization.tetrahedron_count(), 5u);
    EXPECT_EQ(delaunay_problems(r, true), "");
  }
}

TEST(Delaunay3dIncremental, MatchesBruteForceOnSmallRandomSets) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto P = uniform(5 + seed % 9, seed);
    const auto r = run(P);
    EXPECT_EQ(delaunay_problems(r, true), "");
    EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P)) << "seed " << seed;
  }
}

TEST(Delaunay3dIncremental, CubeVerticesCospherical) {
  std::vector<Vec3> P;
  for (int k = 0; k < 8; ++k) P.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  const auto r = run(P);
  EXPECT_EQ(delaunay_problems(r, true), "");
  EXPECT_EQ(six_volume(r.tetrahedralization), 6.0);
  EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P));
  // Every input order gives the same tetrahedra (the perturbation ranks by coordinates).
  auto Q = P;
  std::mt19937 rng(5);
  for (int k = 0; k < 10; ++k) {
    std::shuffle(Q.begin(), Q.end(), rng);
    EXPECT_EQ(geometric_set(run(Q).tetrahedralization), geometric_set(r.tetrahedralization));
  }
}

TEST(Delaunay3dIncremental, CubeWithCentreAndFaceCentres) {
  std::vector<Vec3> P;
  for (int k = 0; k < 8; ++k) P.push_back({2.0 * (k & 1), 2.0 * ((k >> 1) & 1), 2.0 * ((k >> 2) & 1)});
  P.push_back({1, 1, 1});
  for (const Vec3& f : {Vec3{0, 1, 1}, Vec3{2, 1, 1}, Vec3{1, 0, 1}, Vec3{1, 2, 1}, Vec3{1, 1, 0}, Vec3{1, 1, 2}})
    P.push_back(f);
  const auto r = run(P);
  EXPECT_EQ(delaunay_problems(r, true), "");
  EXPECT_EQ(six_volume(r.tetrahedralization), 48.0);
  EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P));
}

TEST(Delaunay3dIncremental, Grid5x5x5) {
  const auto P = grid(5);
  const auto r = run(P);
  EXPECT_EQ(delaunay_problems(r, true), "");
  EXPECT_EQ(six_volume(r.tetrahedralization), 6.0 * 64);
  auto Q = P;
  std::mt19937 rng(11);
  for (int k = 0; k < 3; ++k) {
    std::shuffle(Q.begin(), Q.end(), rng);
    const auto s = run(Q);
    EXPECT_EQ(delaunay_problems(s), "");
    EXPECT_EQ(geometric_set(s.tetrahedralization), geometric_set(r.tetrahedralization));
  }
}

TEST(Delaunay3dIncremental, GridSmallMatchesBruteForce) {
  const auto P = grid(3);
  const auto r = run(P);
  EXPECT_EQ(delaunay_problems(r, true), "");
  EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P));
}

TEST(Delaunay3dIncremental, IntegerPointsOnASphere) {
  for (const int radius : {3, 5, 9, 15}) {
    const auto P = sphere_points(radius);
    ASSERT_GE(P.size(), 6u);
    const auto r = run(P);
    ASSERT_TRUE(r.degenerate_message.empty());
    EXPECT_EQ(delaunay_problems(r, true), "");
    if (P.size() <= 40) {
      EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P)) << "radius " << radius;
    }
    auto Q = P;
    std::mt19937 rng(static_cast<unsigned>(radius));
    std::shuffle(Q.begin(), Q.end(), rng);
    EXPECT_EQ(geometric_set(run(Q).tetrahedralization), geometric_set(r.tetrahedralization)) << "radius " << radius;
  }
}

TEST(Delaunay3dIncremental, SphereCentreOpensOneLargeCavity) {
  // Every tetrahedron of cospherical points has the centre inside its sphere: inserting the centre
  // replaces all finite tetrahedra at once (a ball with hundreds of boundary vertices).
  for (const int radius : {21, 45}) {
    auto P = sphere_points(radius);
    P.push_back({0, 0, 0});
    const auto r = run(P);
    EXPECT_EQ(delaunay_problems(r, true), "") << "radius " << radius;
    // The centre is joined to every hull facet: the finite tetrahedra are exactly the cones.
    const auto centre = static_cast<std::uint32_t>(P.size() - 1);
    std::size_t cones = 0;
    for (const Tet& t : r.tetrahedralization.finite_tetrahedra())
      cones += std::find(t.begin(), t.end(), centre) != t.end();
    EXPECT_EQ(cones, r.tetrahedralization.finite_tetrahedron_count());
  }
}

TEST(Delaunay3dIncremental, PointsOnHullFacetsAndEdges) {
  // A big tetrahedron with points on its facets, edges and coplanar with hull facets outside them:
  // exercises the coplanar ghost rule.
  std::vector<Vec3> P = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}};
  for (int x = 0; x <= 8; x += 2)
    for (int y = 0; x + y <= 8; y += 2) P.push_back({double(x), double(y), 0});  // on facet z = 0
  for (int x = 0; x <= 8; x += 4) P.push_back({double(x), 0, double(8 - x)});    // on an edge
  P.push_back({1, 1, 1});
  P.push_back({-4, 2, 0});  // in the plane z = 0, outside the hull so far
  P.push_back({2, 2, -3});
  const auto r = run(P);
  std::set<Vec3> seen;
  std::size_t repeated = 0;
  for (const Vec3& p : P) repeated += !seen.insert(p).second;
  EXPECT_EQ(r.duplicates.size(), repeated);
  EXPECT_EQ(delaunay_problems(r, true), "");
  std::vector<Vec3> distinct;
  std::set<std::uint32_t> dropped(r.duplicates.begin(), r.duplicates.end());
  for (std::uint32_t k = 0; k < P.size(); ++k)
    if (dropped.count(k) == 0) distinct.push_back(P[k]);
  auto expected = run(distinct);
  EXPECT_EQ(geometric_set(expected.tetrahedralization), geometric_set(r.tetrahedralization));
  std::set<Tet> brute;
  for (const Tet& t : brute_force(distinct)) brute.insert(t);
  EXPECT_EQ(tetrahedron_set(expected.tetrahedralization), brute);
}

TEST(Delaunay3dIncremental, CoplanarPointsInsideAHullFacetPlane) {
  // Many points in the plane z = 0 and few above: the hull's bottom is a 2D Delaunay problem.
  std::vector<Vec3> P;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y) P.push_back({double(x), double(y), 0});
  P.push_back({2.5, 2.5, 3});
  P.push_back({1, 4, 2});
  const auto r = run(P);
  EXPECT_EQ(delaunay_problems(r, true), "");
  EXPECT_EQ(tetrahedron_set(r.tetrahedralization), brute_force(P));
}

TEST(Delaunay3dIncremental, DuplicatesReportedAndUnreferenced) {
  std::vector<Vec3> P = uniform(200, 9);
  P.push_back(P[3]);
  P.push_back(P[50]);
  P.push_back(P[3]);
  const auto r = run(P);
  EXPECT_EQ(r.duplicates, (std::vector<std::uint32_t>{200, 201, 202}));
  EXPECT_EQ(r.duplicate_of, (std::vector<std::uint32_t>{3, 50, 3}));
  EXPECT_EQ(delaunay_problems(r, true), "");
}

TEST(Delaunay3dIncremental, DegenerateInputGivesAMessageAndNoTetrahedra) {
  const auto few = run({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}});
  EXPECT_NE(few.degenerate_message.find("fewer than 4 distinct points"), std::string::npos);
  EXPECT_EQ(few.tetrahedralization.tetrahedron_count(), 0u);
  EXPECT_EQ(few.duplicates, (std::vector<std::uint32_t>{3}));
  EXPECT_NE(run({}).degenerate_message.find("fewer than 4"), std::string::npos);

  std::vector<Vec3> line;
  for (int k = 0; k < 10; ++k) line.push_back({double(k), 2.0 * k, -3.0 * k});
  EXPECT_NE(run(line).degenerate_message.find("collinear"), std::string::npos);

  std::vector<Vec3> plane;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y) plane.push_back({double(x), double(y), double(x + 2 * y)});
  const auto flat = run(plane);
  EXPECT_NE(flat.degenerate_message.find("coplanar"), std::string::npos);
  EXPECT_EQ(flat.tetrahedralization.tetrahedron_count(), 0u);
  EXPECT_EQ(flat.tetrahedralization.point_count(), plane.size());
}

TEST(Delaunay3dIncremental, BadInputNamesThePoint) {
  std::vector<Vec3> P = uniform(20, 1);
  P[13].y = std::numeric_limits<double>::quiet_NaN();
  try {
    run(P);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("13"), std::string::npos) << e.what();
  }
  P[13].y = 1e300;
  EXPECT_THROW(run(P), InputError);
  EXPECT_THROW(delaunay3d(uniform(10, 1), {.algorithm = "no-such"}), InputError);
  EXPECT_THROW(delaunay3d(uniform(10, 1), {.threads = 0}), InputError);
}

TEST(Delaunay3dIncremental, RegistryListsIncremental) {
  ASSERT_NE(delaunay3d_variants().find("incremental"), nullptr);
  EXPECT_EQ(delaunay3d_variants().find("nonsense"), nullptr);
  EXPECT_FALSE(delaunay3d_variants().empty());
}

TEST(Delaunay3dIncremental, Random10k) {
  const auto r = run(uniform(10'000, 77));
  EXPECT_EQ(delaunay_problems(r, true), "");
  // Euler on the 3-sphere: T = E - V, with V counting the infinite vertex.
  const T3& tet = r.tetrahedralization;
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t)
    for (std::uint32_t i = 0; i < 4; ++i)
      for (std::uint32_t j = i + 1; j < 4; ++j) {
        const std::uint32_t a = tet.vertex(t, i), b = tet.vertex(t, j);
        edges.insert({std::min(a, b), std::max(a, b)});
      }
  EXPECT_EQ(tet.tetrahedron_count(), edges.size() - (tet.point_count() + 1));
}

TEST(Delaunay3dIncremental, Random100kClusteredAndScaled) {
  auto P = uniform(100'000, 5);
  EXPECT_EQ(delaunay_problems(run(P)), "");
  // A dense cluster far from sparse points, at scales 1e-9 and 1e9 shifted by 1e9.
  std::vector<Vec3> Q = uniform(30'000, 6);
  for (std::size_t k = 0; k < 20'000; ++k) Q[k] = 1e-6 * Q[k];
  for (Vec3& q : Q) q = 1e-9 * q;
  EXPECT_EQ(delaunay_problems(run(Q)), "");
  for (Vec3& q : Q) q = Vec3{1e9, 1e9, 1e9} + 1e18 * q;
  EXPECT_EQ(delaunay_problems(run(Q)), "");
}

RC_GTEST_PROP(Delaunay3dIncremental, SmallIntegerSetsMatchBruteForce, ()) {
  // Small coordinates make cospherical and coplanar subsets common.
  const auto n = *rc::gen::inRange<std::size_t>(4, 14);
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({double(*rc::gen::inRange(0, 3)), double(*rc::gen::inRange(0, 3)), double(*rc::gen::inRange(0, 3))});
  const auto r = run(P);
  if (!r.degenerate_message.empty()) {
    RC_ASSERT(r.tetrahedralization.tetrahedron_count() == 0u);
    return;
  }
  RC_ASSERT(delaunay_problems(r, true) == "");
  std::vector<Vec3> distinct;
  std::set<std::uint32_t> dropped(r.duplicates.begin(), r.duplicates.end());
  for (std::uint32_t k = 0; k < P.size(); ++k)
    if (dropped.count(k) == 0) distinct.push_back(P[k]);
  RC_ASSERT(geometric_set(run(distinct).tetrahedralization) == geometric_set(r.tetrahedralization));
  RC_ASSERT(tetrahedron_set(run(distinct).tetrahedralization) == brute_force(distinct));
}

// --- Element sets --------------------------------------------------------------------------

TEST(ElementSets3, FindInMeshAgreesWithAScanOfEveryTetrahedron) {
  // Every vertex pair and a random half of the vertex triples of a small set (points on a grid:
  // many cospherical), in shuffled vertex order; the answer is what a scan of the finite
  // tetrahedra says.
  for (const auto& points : {uniform(40, 3), grid(3)}) {
    const T3& tet = run(points).tetrahedralization;
    const auto n = static_cast<std::uint32_t>(tet.point_count());
    std::mt19937_64 rng(7);
    std::vector<std::array<std::uint32_t, 2>> edges;
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b) {
        edges.push_back(rng() % 2 ? std::array{a, b} : std::array{b, a});
        for (std::uint32_t c = b + 1; c < n; ++c)
          if (rng() % 2) faces.push_back({c, a, b});
      }
    std::vector<std::uint8_t> edge_found, face_found;
    find_in_mesh(tet, edges, faces, edge_found, face_found);
    const auto holds = [&](std::uint32_t t, std::uint32_t v) {
      for (std::uint32_t i = 0; i < 4; ++i)
        if (tet.vertex(t, i) == v) return true;
      return false;
    };
    const auto scan = [&](auto&& has) {
      for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t)
        if (!tet.is_ghost(t) && has(t)) return true;
      return false;
    };
    std::size_t edges_in = 0, faces_in = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const bool in = scan([&](std::uint32_t t) { return holds(t, edges[k][0]) && holds(t, edges[k][1]); });
      ASSERT_EQ(edge_found[k] != 0, in) << "edge " << edges[k][0] << " " << edges[k][1];
      edges_in += in;
    }
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const bool in = scan([&](std::uint32_t t) {
        return holds(t, faces[k][0]) && holds(t, faces[k][1]) && holds(t, faces[k][2]);
      });
      ASSERT_EQ(face_found[k] != 0, in) << "face " << faces[k][0] << " " << faces[k][1] << " " << faces[k][2];
      faces_in += in;
    }
    EXPECT_GT(edges_in, 0u);  // both answers occur
    EXPECT_LT(edges_in, edges.size());
    EXPECT_GT(faces_in, 0u);
    EXPECT_LT(faces_in, faces.size());
  }
}

TEST(ElementSets3, BallAndShellOfEveryVertexAndEdge) {
  const auto r = run(uniform(100, 12));
  const T3& tet = r.tetrahedralization;
  const auto start = vertex_tetrahedra(tet);
  for (std::uint32_t v = 0; v < tet.point_count(); ++v) {
    ASSERT_NE(start[v], T3::kNone);
    const auto b = ball(tet, start[v], v);
    std::size_t expected = 0;
    for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t)
      for (std::uint32_t i = 0; i < 4; ++i) expected += tet.vertex(t, i) == v;
    EXPECT_EQ(b.size(), expected) << "vertex " << v;
    for (const std::uint32_t t : b) {
      // Shell of each edge from v inside the ball: every tetrahedron holds both ends, each once,
      // consecutive ones share a facet, and the shell's size matches a count.
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t w = tet.vertex(t, i);
        if (w == v || w < v) continue;
        const auto s = shell(tet, t, v, w);
        std::size_t holding = 0;
        for (std::uint32_t u = 0; u < tet.tetrahedron_count(); ++u) {
          bool hv = false, hw = false;
          for (std::uint32_t j = 0; j < 4; ++j) hv |= tet.vertex(u, j) == v, hw |= tet.vertex(u, j) == w;
          holding += hv && hw;
        }
        EXPECT_EQ(s.size(), holding);
        for (std::size_t k = 0; k < s.size(); ++k) {
          const std::uint32_t a = s[k], c = s[(k + 1) % s.size()];
          bool adjacent = false;
          for (std::uint32_t j = 0; j < 4; ++j) adjacent |= tet.adjacent(a, j) == c;
          EXPECT_TRUE(adjacent);
        }
      }
    }
  }
}

TEST(ElementSets3, ShellTurnsRightHandedAboutTheEdge) {
  // Edge along +z through the origin, surrounded by points: successive tetrahedra turn
  // counter-clockwise seen from the top end.
  std::vector<Vec3> P = {{0, 0, -1}, {0, 0, 1}};
  for (int k = 0; k < 6; ++k) {
    const double a = k * 2.0 * 3.141592653589793 / 6;
    P.push_back({std::cos(a) * 3, std::sin(a) * 3, 0.1 * k});
  }
  const auto r = run(P);
  const T3& tet = r.tetrahedralization;
  std::uint32_t first = T3::kNone;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count() && first == T3::kNone; ++t) {
    bool h0 = false, h1 = false;
    for (std::uint32_t i = 0; i < 4; ++i) h0 |= tet.vertex(t, i) == 0, h1 |= tet.vertex(t, i) == 1;
    if (h0 && h1 && !tet.is_ghost(t)) first = t;
  }
  ASSERT_NE(first, T3::kNone);
  const auto s = shell(tet, first, 0, 1);
  ASSERT_GE(s.size(), 3u);
  // Right-handedness: orient3d(0, 1, c, d) > 0 for the c before d, and d is shared with the next.
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::uint32_t t = s[k], u = s[(k + 1) % s.size()];
    std::uint32_t shared = T3::kNone, own = T3::kNone;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t x = tet.vertex(t, i);
      if (x == 0 || x == 1) continue;
      bool in_u = false;
      for (std::uint32_t j = 0; j < 4; ++j) in_u |= tet.vertex(u, j) == x;
      (in_u ? shared : own) = x;
    }
    ASSERT_NE(shared, T3::kNone);
    ASSERT_NE(own, T3::kNone);
    if (shared == kInf || own == kInf) continue;
    const auto Q = tet.points();
    EXPECT_EQ(orient3d(Q[0], Q[1], Q[own], Q[shared]), Sign::Positive) << "step " << k;
  }
}

// The pipe against its definition, tetrahedron by tetrahedron over the whole mesh: the open
// segment meets the closed tetrahedron iff some point of it lies in the tetrahedron, tested with
// exact rationals at the points where the segment crosses the tetrahedron's planes.
std::set<std::uint32_t> brute_force_pipe(const T3& tet, std::uint32_t a, std::uint32_t b) {
  const auto P = tet.points();
  std::set<std::uint32_t> out;
  for (std::uint32_t t = 0; t < tet.tetrahedron_count(); ++t) {
    if (tet.is_ghost(t)) continue;
    // Barycentric signs of a + s (b - a) are affine in s: the segment's points in t form an
    // interval, found from where each of the four signed volumes changes sign.
    std::array<Rational, 4> va, vb;  // signed volumes of the facets with a and with b
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto& f = T3::kFacetVertex[i];
      const ExactPoint3 x = to_exact(P[tet.vertex(t, f[0])]), y = to_exact(P[tet.vertex(t, f[1])]),
                        z = to_exact(P[tet.vertex(t, f[2])]);
      const auto volume = [&](const ExactPoint3& q) {
        const Rational ux = y.x - x.x, uy = y.y - x.y, uz = y.z - x.z, wx = z.x - x.x, wy = z.y - x.y, wz = z.z - x.z;
        const Rational qx = q.x - x.x, qy = q.y - x.y, qz = q.z - x.z;
        return ux * (wy * qz - wz * qy) - uy * (wx * qz - wz * qx) + uz * (wx * qy - wy * qx);
      };
      va[i] = volume(to_exact(P[a]));
      vb[i] = volume(to_exact(P[b]));
    }
    // The points a + s (b - a) of t: s in [lo, hi], where each volume (1 - s) va + s vb is
    // non-negative; the open segment meets t iff that interval meets (0, 1).
    Rational lo(0), hi(1);
    bool empty = false;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const Rational d = vb[i] - va[i];
      if (d.sign() == Sign::Zero) {
        empty = empty || va[i].sign() == Sign::Negative;
        continue;
      }
      const Rational zero = (Rational(0) - va[i]) / d;
      if (d.sign() == Sign::Positive) lo = std::max(lo, zero);
      else hi = std::min(hi, zero);
    }
    if (!empty && lo <= hi && (lo < hi || (Rational(0) < lo && lo < Rational(1)))) out.insert(t);
  }
  return out;
}

TEST(ElementSets3, PipeOfRandomSegmentsMatchesItsDefinition) {
  const auto r = run(uniform(60, 5));
  const T3& tet = r.tetrahedralization;
  const auto start = vertex_tetrahedra(tet);
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::uint32_t> vertex(0, static_cast<std::uint32_t>(tet.point_count() - 1));
  for (int k = 0; k < 120; ++k) {
    const std::uint32_t a = vertex(rng), b = vertex(rng);
    if (a == b) continue;
    const auto p = pipe(tet, start[a], a, b);
    const std::set<std::uint32_t> got(p.begin(), p.end());
    EXPECT_EQ(got.size(), p.size()) << "a tetrahedron listed twice";
    EXPECT_EQ(got, brute_force_pipe(tet, a, b)) << "segment " << a << " - " << b;
  }
}

TEST(ElementSets3, PipeThroughAVertexAndAnEdgeTakesTheirBallAndShell) {
  // A 3 x 3 x 3 grid: the main diagonal passes through the centre vertex, and the segment from
  // (0, 0, 1) to (2, 2, 1) through the middle; every tetrahedron of the centre's ball is in both
  // pipes, since each holds the centre.
  std::vector<Vec3> P;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) P.push_back({double(x), double(y), double(z)});
  const auto r = run(P);
  const T3& tet = r.tetrahedralization;
  const auto start = vertex_tetrahedra(tet);
  const auto id = [](int x, int y, int z) { return static_cast<std::uint32_t>(x + 3 * y + 9 * z); };
  const std::uint32_t centre = id(1, 1, 1);
  std::set<std::uint32_t> centre_ball;
  for (const std::uint32_t t : ball(tet, start[centre], centre))
    if (!tet.is_ghost(t)) centre_ball.insert(t);
  for (const auto& [a, b] : {std::pair{id(0, 0, 0), id(2, 2, 2)}, std::pair{id(0, 0, 1), id(2, 2, 1)}}) {
    const auto p = pipe(tet, start[a], a, b);
    const std::set<std::uint32_t> got(p.begin(), p.end());
    for (const std::uint32_t t : centre_ball) EXPECT_TRUE(got.count(t)) << "tetrahedron " << t;
    EXPECT_EQ(got, brute_force_pipe(tet, a, b));
  }
  // An edge's pipe is its finite shell.
  const std::uint32_t t0 = start[0];
  std::uint32_t w = T3::kNone;
  for (std::uint32_t i = 0; i < 4; ++i)
    if (tet.vertex(t0, i) != 0 && tet.vertex(t0, i) != kInf) w = tet.vertex(t0, i);
  std::set<std::uint32_t> finite_shell;
  for (const std::uint32_t t : shell(tet, t0, 0, w))
    if (!tet.is_ghost(t)) finite_shell.insert(t);
  const auto p = pipe(tet, t0, 0, w);
  EXPECT_EQ(std::set<std::uint32_t>(p.begin(), p.end()), finite_shell);
}

TEST(ElementSets3, BrokenStartGivesInternalError) {
  const auto r = run(uniform(50, 2));
  const T3& tet = r.tetrahedralization;
  std::uint32_t t = 0;
  std::uint32_t missing = 0;
  while (missing < tet.point_count()) {
    bool has = false;
    for (std::uint32_t i = 0; i < 4; ++i) has |= tet.vertex(t, i) == missing;
    if (!has) break;
    ++missing;
  }
  EXPECT_THROW(ball(tet, t, missing), InternalError);
  EXPECT_THROW(shell(tet, t, missing, tet.vertex(t, 1)), InternalError);
}

}  // namespace
}  // namespace dtlab
