#include "mpi/distributed_delaunay.hpp"

#include <algorithm>

#include "algorithms/distributed/kd_tiles.hpp"
#include "algorithms/distributed/tile_delaunay.hpp"
#include "kernel/error.hpp"

namespace dtlab::mpi {
namespace {

template <class T>
std::uint64_t bytes_of(const std::vector<std::vector<T>>& lists) {
  std::uint64_t n = 0;
  for (const auto& l : lists) n += l.size() * sizeof(T);
  return n;
}

template <int kDim, class Vec>
DistributedElements<kDim + 1> run(const Comm& comm, std::span<const Vec> points) {
  const auto ranks = static_cast<std::uint32_t>(comm.size());
  const auto me = static_cast<std::uint32_t>(comm.rank());
  const std::vector<std::uint32_t> tile_of = kd_tiles(points, ranks);
  TilePoints<Vec> own = tile_points(points, tile_of, me);
  TileDelaunay<kDim> tile(me, tile_boxes(points, tile_of, ranks), std::move(own.ids), std::move(own.points));
  DistributedElements<kDim + 1> result;
  std::uint64_t bytes = 0;
  const std::uint64_t max_rounds = points.size() + 2;
  const auto seeded = tile.seed();
  bytes += bytes_of(seeded);
  tile.receive(comm.exchange(seeded));
  for (bool more = true; more;) {
    if (++result.rounds > max_rounds)
      throw InternalError("dtlab-mpi delaunay: no convergence after " + std::to_string(max_rounds) + " rounds");
    const auto asked = tile.triangulate_and_ask();
    bytes += bytes_of(asked);
    const auto answers = tile.answer(comm.exchange(asked));
    bytes += bytes_of(answers);
    more = comm.any(tile.receive(comm.exchange(answers)));
  }
  const auto mine = tile.owned_elements();
  result.elements = comm.gather(mine, 0);
  std::sort(result.elements.begin(), result.elements.end());
  result.ghosts = comm.sum(tile.counts().ghosts);
  result.questions = comm.sum(tile.counts().questions_sent);
  result.bytes_exchanged = comm.sum(bytes);
  result.seconds_max_triangulating = comm.max(tile.counts().seconds_triangulating);
  // Rank 0's tile says why there are no elements when none has any (every tile knows every point
  // by then: the exchange asks everything of the others when a tile has no element).
  if (me == 0 && result.elements.empty()) result.degenerate_message = tile.degenerate_message();
  return result;
}

}  // namespace

DistributedElements<3> distributed_delaunay(const Comm& comm, std::span<const Vec2> points) {
  return run<2>(comm, points);
}
DistributedElements<4> distributed_delaunay(const Comm& comm, std::span<const Vec3> points) {
  return run<3>(comm, points);
}

}  // namespace dtlab::mpi
