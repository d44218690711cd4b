// Tests of the "parallel" 3D Delaunay variant: for 1, 2, 3, 4 and 8 threads, the same set of
// tetrahedra as "incremental", ghosts (the hull) included, and a valid compact structure, on hand
// cases, degenerate sets (integer grids, lattice points of a sphere, coplanar layers, collinear
// runs), clustered, scaled and translated sets, points on a sphere (every point on the hull, so
// the threads' cavities hold ghosts) and uniform sets up to 10^6; a deterministic storage order
// for a given thread count; the workers' predicate counts reach the caller.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/cavity_kernel.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/prepare.hpp"
#include "kernel/worker_team.hpp"
#include "kernel/error.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {
namespace {

using T3 = Tetrahedralization3;
using Tet = std::array<std::uint32_t, 4>;

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

constexpr unsigned kThreadCounts[] = {1, 2, 3, 4, 8};

// One name per positive tetrahedron (ghosts too: kInfinite is an id like any other): the even
// permutation that puts the smallest id first and the next smallest second.
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

// Every stored tetrahedron, ghosts included, canonical and sorted.
std::vector<Tet> all_tetrahedra(const T3& tet) {
  std::vector<Tet> out;
  out.reserve(tet.tetrahedron_count());
  for (const T3::Record& r : tet.records()) out.push_back(canonical(r.vertex));
  std::sort(out.begin(), out.end());
  return out;
}

Delaunay3dResult run(const std::vector<Vec3>& points, const std::string& algorithm, unsigned threads = 1) {
  return delaunay3d(points, {.algorithm = algorithm, .threads = threads});
}

// "" or what differs from incremental for some thread count.
std::string differences(const std::vector<Vec3>& points, std::span<const unsigned> thread_counts = kThreadCounts) {
  const Delaunay3dResult reference = run(points, "incremental");
  const std::vector<Tet> expected = all_tetrahedra(reference.tetrahedralization);
  std::string out;
  for (const unsigned threads : thread_counts) {
    const Delaunay3dResult r = run(points, "parallel", threads);
    const std::string tag = "threads " + std::to_string(threads) + ": ";
    if (r.degenerate_message != reference.degenerate_message) out += tag + "degenerate message differs; ";
    if (r.duplicates != reference.duplicates) out += tag + "duplicates differ; ";
    try {
      r.tetrahedralization.check_topology();
    } catch (const InternalError& e) {
      out += tag + e.what() + "; ";
    }
    if (all_tetrahedra(r.tetrahedralization) != expected) out += tag + "tetrahedra differ from incremental; ";
    if (r.tetrahedralization.points().size() != points.size() ||
        !std::equal(points.begin(), points.end(), r.tetrahedralization.points().begin()))
      out += tag + "points not restored to input order; ";
  }
  return out;
}

std::vector<Vec3> uniform(std::size_t n, std::uint64_t seed, double scale = 1.0, Vec3 shift = {}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = Vec3{u(rng) * scale, u(rng) * scale, u(rng) * scale} + shift;
  return out;
}

std::vector<Vec3> grid(int side) {
  std::vector<Vec3> out;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) out.push_back({double(x), double(y), double(z)});
  std::shuffle(out.begin(), out.end(), std::mt19937(static_cast<unsigned>(side)));
  return out;
}

// Integer points on the sphere x^2 + y^2 + z^2 = r^2: all cospherical, all on the hull.
std::vector<Vec3> sphere_lattice(int r) {
  std::vector<Vec3> out;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) out.push_back({double(x), double(y), double(z)});
  return out;
}

TEST(Delaunay3dParallel, HandCases) {
  const std::vector<std::vector<Vec3>> cases = {
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}},
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},  // octahedron
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) EXPECT_EQ(differences(cases[k]), "") << "case " << k;
}

TEST(Delaunay3dParallel, PointsOnASphereAllOnTheHull) {
  for (const int r : {3, 9, 21, 45}) EXPECT_EQ(differences(sphere_lattice(r)), "") << "radius " << r;
  // Random points of the unit sphere: every insertion opens a cavity through ghosts.
  std::vector<Vec3> P = uniform(kSanitized ? 3000 : 20000, 3);
  for (Vec3& p : P) p = (1.0 / std::sqrt(dot(p, p))) * p;
  EXPECT_EQ(differences(P), "");
  // The sphere's centre opens one cavity holding every tetrahedron.
  auto Q = sphere_lattice(21);
  Q.push_back({0, 0, 0});
  EXPECT_EQ(differences(Q), "");
}

TEST(Delaunay3dParallel, IntegerGrids) {
  for (const int side : {4, 10, 20}) EXPECT_EQ(differences(grid(side)), "") << "side " << side;
}

TEST(Delaunay3dParallel, CoplanarLayersAndCollinearRuns) {
  std::vector<Vec3> layers;
  for (int x = 0; x < 30; ++x)
    for (int y = 0; y < 30; ++y) layers.push_back({double(x), double(y), (x + y) % 2 == 0 ? 0.0 : 7.0});
  EXPECT_EQ(differences(layers), "");
  std::vector<Vec3> runs;
  for (int line = 0; line < 20; ++line)
    for (int k = 0; k < 50; ++k) runs.push_back({double(k), double(3 * line), double(k + 2 * line)});
  for (int k = 0; k < 10; ++k) runs.push_back({double(5 * k), 1.0 + k, -3.0 * k});
  EXPECT_EQ(differences(runs), "");
}

TEST(Delaunay3dParallel, ClusteredScaledTranslated) {
  std::vector<Vec3> clustered = uniform(20000, 6);
  for (std::size_t k = 0; k < 15000; ++k) clustered[k] = 1e-4 * clustered[k];
  EXPECT_EQ(differences(clustered), "");
  EXPECT_EQ(differences(uniform(10000, 7, 1e-9)), "");
  EXPECT_EQ(differences(uniform(10000, 8, 1e9)), "");
  EXPECT_EQ(differences(uniform(10000, 9, 1.0, {1e9, 1e9, 1e9})), "");
}

TEST(Delaunay3dParallel, DuplicatesAndDegenerateInput) {
  std::vector<Vec3> P = uniform(3000, 10);
  for (std::size_t k = 0; k < 300; ++k) P.push_back(P[7 * k]);
  EXPECT_EQ(differences(P), "");
  std::vector<Vec3> plane;
  for (int x = 0; x < 20; ++x)
    for (int y = 0; y < 20; ++y) plane.push_back({double(x), double(y), 0.0});
  EXPECT_EQ(differences(plane), "");  // coplanar: the same message, no tetrahedra
  EXPECT_THROW(delaunay3d(P, {.algorithm = "parallel", .threads = 0}), InputError);
}

TEST(Delaunay3dParallel, Uniform) {
  EXPECT_EQ(differences(uniform(10'000, 11)), "");
  EXPECT_EQ(differences(uniform(kSanitized ? 30'000 : 100'000, 12)), "");
  if (!kSanitized) {
    const unsigned two[] = {2};
    EXPECT_EQ(differences(uniform(1'000'000, 13), two), "");
  }
}

TEST(Delaunay3dParallel, StorageOrderDeterministicForAThreadCount) {
  const auto P = uniform(30'000, 14);
  for (const unsigned threads : {2u, 3u}) {
    const auto a = run(P, "parallel", threads), b = run(P, "parallel", threads);
    ASSERT_EQ(a.tetrahedralization.tetrahedron_count(), b.tetrahedralization.tetrahedron_count());
    EXPECT_TRUE(std::equal(a.tetrahedralization.records().begin(), a.tetrahedralization.records().end(),
                           b.tetrahedralization.records().begin(), [](const T3::Record& x, const T3::Record& y) {
                             return x.vertex == y.vertex && x.neighbour == y.neighbour;
                           }))
        << "threads " << threads;
  }
}

// The runs of increasing Hilbert rank the parallel variant inserts by: every place in the
// insertion order where the Hilbert rank goes down, found here from the Hilbert order itself,
// on input whose first simplex is not its first points (collinear and coplanar starts).
TEST(Delaunay3dParallel, RunEndsAreTheDescentsOfTheHilbertRank) {
  WorkerTeam team(2);
  std::vector<std::vector<Vec3>> inputs;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  inputs.emplace_back();
  for (int k = 0; k < 30000; ++k) inputs.back().push_back({u(rng), u(rng), u(rng)});
  inputs.emplace_back();  // most points on one line, a few on a plane, a few off it
  for (int k = 0; k < 20000; ++k) inputs.back().push_back({u(rng), 0.0, 0.0});
  for (int k = 0; k < 20; ++k) inputs.back().push_back({u(rng), u(rng), 0.0});
  for (int k = 0; k < 20; ++k) inputs.back().push_back({u(rng), u(rng), u(rng)});
  for (const std::vector<Vec3>& points : inputs) {
    const PreparedPoints3 input = prepare_points3(points, 7, &team);
    const InsertionOrder order(input, &team, true);
    std::vector<std::uint32_t> rank_by_id(points.size(), T3::kNone);
    for (std::size_t k = 0; k < input.distinct.size(); ++k) rank_by_id[input.distinct[k]] = static_cast<std::uint32_t>(k);
    std::vector<std::uint32_t> expected;
    const auto ids = order.input_ids();
    for (std::size_t r = 5; r < order.distinct_count(); ++r)
      if (rank_by_id[ids[r]] < rank_by_id[ids[r - 1]]) expected.push_back(static_cast<std::uint32_t>(r));
    expected.push_back(static_cast<std::uint32_t>(order.distinct_count()));
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), order.run_ends().begin(), order.run_ends().end()));
    EXPECT_TRUE(InsertionOrder(input).run_ends().empty());
    const InsertionOrder alone(input, nullptr, true);
    EXPECT_TRUE(std::equal(ids.begin(), ids.end(), alone.input_ids().begin(), alone.input_ids().end()));
  }
}

TEST(Delaunay3dParallel, WorkerPredicateCountsReachTheCaller) {
  // Each point costs in-sphere tests wherever it goes in: without the workers' counts, four
  // threads would report about a quarter of the sequential count.
  const auto P = uniform(50'000, 15);
  const auto sequential = run(P, "incremental").predicate_stats[Predicate::Insphere].calls();
  const auto parallel = run(P, "parallel", 4).predicate_stats[Predicate::Insphere].calls();
  EXPECT_GE(parallel, sequential * 9 / 10);
  EXPECT_LE(parallel, sequential * 2);
}

RC_GTEST_PROP(Delaunay3dParallel, SmallIntegerSetsMatchIncremental, ()) {
  // Small coordinates make cospherical and coplanar subsets common.
  const auto n = *rc::gen::inRange<std::size_t>(4, 41);
  const auto side = *rc::gen::inRange(2, 6);
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < n; ++k)
    P.push_back({double(*rc::gen::inRange(0, side)), double(*rc::gen::inRange(0, side)),
                 double(*rc::gen::inRange(0, side))});
  const unsigned threads = *rc::gen::element(2u, 3u, 4u, 8u);
  const unsigned counts[] = {threads};
  RC_ASSERT(differences(P, counts) == "");
}

}  // namespace
}  // namespace dtlab
