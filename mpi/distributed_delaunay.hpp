// Distributed Delaunay over MPI: each rank one tile of algorithms/distributed/tile_delaunay.hpp,
// the messages moved by mpi::Comm, the elements gathered at rank 0. The same elements as the
// sequential call for every rank count (tested against it: verify/tests/cli_mpi.cmake).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mpi/comm.hpp"
#include "kernel/vec.hpp"

namespace dtlab::mpi {

template <std::size_t K>
struct DistributedElements {
  std::vector<std::array<std::uint32_t, K>> elements;  // at rank 0: all, canonical, sorted
  std::string degenerate_message;                      // at rank 0
  // Over all ranks.
  std::uint64_t rounds = 0;
  std::uint64_t ghosts = 0;          // points a rank received from others
  std::uint64_t questions = 0;       // element questions sent
  std::uint64_t bytes_exchanged = 0;
  double seconds_max_triangulating = 0.0;  // the slowest rank's
};

// Every rank passes the same points (read or generated alike) and keeps its tile of them.
DistributedElements<3> distributed_delaunay(const Comm& comm, std::span<const Vec2> points);
DistributedElements<4> distributed_delaunay(const Comm& comm, std::span<const Vec3> points);

}  // namespace dtlab::mpi
