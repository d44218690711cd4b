#include "algorithms/distributed/distributed_in_process.hpp"

#include <algorithm>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"

namespace dtlab {
namespace {

template <class T>
std::vector<std::vector<T>> column(std::vector<std::vector<std::vector<T>>>& sent, std::size_t to) {
  std::vector<std::vector<T>> in(sent.size());
  for (std::size_t from = 0; from < sent.size(); ++from) in[from] = std::move(sent[from][to]);
  return in;
}

template <int kDim, class Vec>
DistributedDelaunayResult<kDim> run(std::span<const Vec> points, std::uint32_t tiles) {
  const std::vector<std::uint32_t> tile_of = kd_tiles(points, tiles);
  const auto boxes = tile_boxes(points, tile_of, tiles);
  std::vector<TileDelaunay<kDim>> tile;
  tile.reserve(tiles);
  for (std::uint32_t t = 0; t < tiles; ++t) {
    TilePoints<Vec> own = tile_points(points, tile_of, t);
    tile.emplace_back(t, boxes, std::move(own.ids), std::move(own.points));
  }
  DistributedDelaunayResult<kDim> result;
  result.points = points.size();
  const std::uint64_t max_rounds = points.size() + 2;
  {
    std::vector<std::vector<std::vector<typename TileDelaunay<kDim>::Ghost>>> seeded(tiles);
    for (std::uint32_t t = 0; t < tiles; ++t) seeded[t] = tile[t].seed();
    for (std::uint32_t t = 0; t < tiles; ++t) tile[t].receive(column(seeded, t));
  }
  for (bool more = true; more;) {
    if (++result.rounds > max_rounds)
      throw InternalError("distributed Delaunay: no convergence after " + std::to_string(max_rounds) + " rounds");
    std::vector<std::vector<std::vector<typename TileDelaunay<kDim>::Question>>> asked(tiles);
    for (std::uint32_t t = 0; t < tiles; ++t) asked[t] = tile[t].triangulate_and_ask();
    std::vector<std::vector<std::vector<typename TileDelaunay<kDim>::Ghost>>> answered(tiles);
    for (std::uint32_t t = 0; t < tiles; ++t) answered[t] = tile[t].answer(column(asked, t));
    more = false;
    for (std::uint32_t t = 0; t < tiles; ++t) more = tile[t].receive(column(answered, t)) || more;
  }
  for (const auto& t : tile) {
    const auto mine = t.owned_elements();
    result.elements.insert(result.elements.end(), mine.begin(), mine.end());
    result.ghosts += t.counts().ghosts;
    if (result.degenerate_message.empty() && t.own_point_count() > 0) result.degenerate_message = t.degenerate_message();
  }
  std::sort(result.elements.begin(), result.elements.end());
  if (!result.elements.empty()) result.degenerate_message.clear();
  return result;
}

template <class Elements>
Elements canonical(Elements e) {
  for (auto& x : e) x = canonical_element(x);
  std::sort(e.begin(), e.end());
  return e;
}

}  // namespace

DistributedDelaunayResult<2> distributed_delaunay_in_process(std::span<const Vec2> points, std::uint32_t tiles) {
  return run<2>(points, tiles);
}
DistributedDelaunayResult<3> distributed_delaunay_in_process(std::span<const Vec3> points, std::uint32_t tiles) {
  return run<3>(points, tiles);
}

std::vector<std::array<std::uint32_t, 3>> canonical_delaunay_elements(std::span<const Vec2> points) {
  return canonical(delaunay2d(points).triangulation.finite_triangles());
}
std::vector<std::array<std::uint32_t, 4>> canonical_delaunay_elements(std::span<const Vec3> points) {
  return canonical(delaunay3d(points).tetrahedralization.finite_tetrahedra());
}

}  // namespace dtlab
