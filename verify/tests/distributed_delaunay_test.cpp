// Distributed Delaunay (algorithms/distributed): for every tile count the elements are those of
// the sequential call, on every point generator of the 2D and 3D suites, degenerate ones
// included (grids, exact circles and spheres, duplicates, collinear and coplanar sets).
#include <gtest/gtest.h>

#include <string>

#include "algorithms/distributed/distributed_in_process.hpp"
#include "algorithms/distributed/kd_tiles.hpp"
#include "kernel/error.hpp"
#include "verify/generators/points2d.hpp"
#include "verify/generators/points3d.hpp"

namespace dtlab {
namespace {

constexpr std::uint32_t kTileCounts[] = {1, 2, 3, 4, 7};

TEST(KdTiles, EveryTileGetsItsShareAndEqualPointsStayTogether) {
  const std::vector<Vec3> points = generate_points3d("duplicates", 1000, 7);
  for (const std::uint32_t tiles : kTileCounts) {
    const auto tile_of = kd_tiles(std::span<const Vec3>(points), tiles);
    std::vector<std::uint32_t> count(tiles, 0);
    for (const std::uint32_t t : tile_of) ++count[t];
    for (const std::uint32_t c : count) EXPECT_GT(c, 1000 / tiles / 2) << tiles << " tiles";
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (points[i] == points[j]) {
          EXPECT_EQ(tile_of[i], tile_of[j]) << "points " << j << " and " << i;
        }
      }
    }
  }
  EXPECT_THROW(kd_tiles(std::span<const Vec3>(points), 0), InputError);
}

TEST(DistributedDelaunay2d, SameTrianglesAsSequentialForEveryTileCount) {
  for (const char* name : {"uniform", "normal", "grid", "circle", "exact_circle", "clustered", "collinear",
                           "duplicates", "scaled_small", "scaled_large", "multiscale", "translated"}) {
    const std::vector<Vec2> points = generate_points2d(name, 600, 11);
    const auto expected = canonical_delaunay_elements(std::span<const Vec2>(points));
    for (const std::uint32_t tiles : kTileCounts) {
      const auto r = distributed_delaunay_in_process(std::span<const Vec2>(points), tiles);
      EXPECT_EQ(r.elements, expected) << name << ", " << tiles << " tiles";
      EXPECT_LT(r.rounds, 40u) << name << ", " << tiles << " tiles";
    }
  }
}

TEST(DistributedDelaunay3d, SameTetrahedraAsSequentialForEveryTileCount) {
  for (const char* name : {"uniform", "normal", "grid", "sphere", "exact_sphere", "clustered", "duplicates",
                           "coplanar", "collinear"}) {
    const std::vector<Vec3> points = generate_points3d(name, 500, 13);
    const auto expected = canonical_delaunay_elements(std::span<const Vec3>(points));
    for (const std::uint32_t tiles : kTileCounts) {
      const auto r = distributed_delaunay_in_process(std::span<const Vec3>(points), tiles);
      EXPECT_EQ(r.elements, expected) << name << ", " << tiles << " tiles";
    }
  }
}

TEST(DistributedDelaunay3d, DegenerateInputGivesNoElementsAndSaysWhy) {
  std::vector<Vec3> points;
  for (int i = 0; i < 40; ++i) points.push_back({double(i % 7), double(i / 7), 0.0});  // coplanar
  const auto r = distributed_delaunay_in_process(std::span<const Vec3>(points), 3);
  EXPECT_TRUE(r.elements.empty());
  EXPECT_FALSE(r.degenerate_message.empty());
}

TEST(CanonicalElement, LowestFirstOrientationKept) {
  EXPECT_EQ(canonical_element(std::array<std::uint32_t, 3>{5, 2, 9}), (std::array<std::uint32_t, 3>{2, 9, 5}));
  // Every even permutation of (0, 1, 2, 3) maps to (0, 1, 2, 3); every odd one to (0, 1, 3, 2).
  std::array<std::uint32_t, 4> p{0, 1, 2, 3};
  int parity = 0;
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    parity = inversions % 2;
    EXPECT_EQ(canonical_element(p), parity == 0 ? (std::array<std::uint32_t, 4>{0, 1, 2, 3})
                                                : (std::array<std::uint32_t, 4>{0, 1, 3, 2}));
  } while (std::next_permutation(p.begin(), p.end()));
}

}  // namespace
}  // namespace dtlab
