// Distributed Delaunay with every tile in this process (tile_delaunay.hpp), the messages moved by
// hand: the reference the MPI driver (mpi/) is tested against, and a way to test the exchange
// scheme for any tile count without mpirun. Also the sequential elements in the same canonical
// form, for comparison.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/distributed/tile_delaunay.hpp"

namespace dtlab {

template <int kDim>
struct DistributedDelaunayResult {
  // Every element once, lowest id first (orientation kept), sorted.
  std::vector<typename TileDelaunay<kDim>::Element> elements;
  std::string degenerate_message;  // empty unless there are no elements
  std::uint64_t rounds = 0;
  std::uint64_t ghosts = 0;  // points received by tiles other than their own, over all tiles
  std::uint64_t points = 0;
};

// InputError for tiles == 0; InternalError naming the round count if the exchange does not settle
// within points + 2 rounds (each round that goes on brings a new ghost to some tile).
DistributedDelaunayResult<2> distributed_delaunay_in_process(std::span<const Vec2> points, std::uint32_t tiles);
DistributedDelaunayResult<3> distributed_delaunay_in_process(std::span<const Vec3> points, std::uint32_t tiles);

// The sequential call's elements (delaunay2d / delaunay3d, default variant) in the same form.
std::vector<std::array<std::uint32_t, 3>> canonical_delaunay_elements(std::span<const Vec2> points);
std::vector<std::array<std::uint32_t, 4>> canonical_delaunay_elements(std::span<const Vec3> points);

}  // namespace dtlab
