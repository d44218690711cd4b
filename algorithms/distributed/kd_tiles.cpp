#include "algorithms/distributed/kd_tiles.hpp"

#include <algorithm>
#include <array>

#include "algorithms/distributed/coordinates.hpp"
#include "kernel/error.hpp"

namespace dtlab {
namespace {

using distributed::coordinate;
template <class Vec>
constexpr int kDim = distributed::kDimOf<Vec>;

template <class Vec>
bool same_point(const Vec& a, const Vec& b) {
  return a == b;
}

// Splits ids (the points of `tiles` tiles, the first of them `first`) in place; bounded by the
// tile count (each level halves it).
template <class Vec>
void split(std::span<const Vec> points, std::span<std::uint32_t> ids, std::uint32_t first, std::uint32_t tiles,
           std::vector<std::uint32_t>& tile_of) {
  if (tiles == 1 || ids.size() <= 1) {
    for (const std::uint32_t i : ids) tile_of[i] = first;
    return;
  }
  std::array<double, 3> lo{}, hi{};
  for (int a = 0; a < kDim<Vec>; ++a) lo[a] = hi[a] = coordinate(points[ids[0]], a);
  for (const std::uint32_t i : ids) {
    for (int a = 0; a < kDim<Vec>; ++a) {
      lo[a] = std::min(lo[a], coordinate(points[i], a));
      hi[a] = std::max(hi[a], coordinate(points[i], a));
    }
  }
  int axis = 0;
  for (int a = 1; a < kDim<Vec>; ++a)
    if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
  const auto before = [&](std::uint32_t i, std::uint32_t j) {
    const double ci = coordinate(points[i], axis), cj = coordinate(points[j], axis);
    if (ci != cj) return ci < cj;
    if (points[i] != points[j]) return points[i] < points[j];
    return i < j;
  };
  std::sort(ids.begin(), ids.end(), before);
  const std::uint32_t left_tiles = tiles / 2;
  std::size_t k = ids.size() * left_tiles / tiles;
  // Never between equal points: move the cut forward past a run of equal ones.
  while (k > 0 && k < ids.size() && same_point(points[ids[k]], points[ids[k - 1]])) ++k;
  split(points, ids.first(k), first, left_tiles, tile_of);
  split(points, ids.subspan(k), first + left_tiles, tiles - left_tiles, tile_of);
}

template <class Vec>
std::vector<std::uint32_t> tiles_of(std::span<const Vec> points, std::uint32_t tiles) {
  if (tiles == 0) throw InputError("kd_tiles: zero tiles");
  std::vector<std::uint32_t> ids(points.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  std::vector<std::uint32_t> tile_of(points.size(), 0);
  split<Vec>(points, ids, 0, tiles, tile_of);
  return tile_of;
}

template <class Vec>
std::vector<TileBox<Vec>> boxes_of(std::span<const Vec> points, std::span<const std::uint32_t> tile_of,
                                   std::uint32_t tiles) {
  std::vector<TileBox<Vec>> boxes(tiles);
  for (std::size_t i = 0; i < points.size(); ++i) {
    TileBox<Vec>& b = boxes[tile_of[i]];
    const Vec& p = points[i];
    if (b.empty) {
      b.lo = b.hi = p;
      b.empty = false;
      continue;
    }
    b.lo.x = std::min(b.lo.x, p.x), b.hi.x = std::max(b.hi.x, p.x);
    b.lo.y = std::min(b.lo.y, p.y), b.hi.y = std::max(b.hi.y, p.y);
    if constexpr (kDim<Vec> == 3) b.lo.z = std::min(b.lo.z, p.z), b.hi.z = std::max(b.hi.z, p.z);
  }
  return boxes;
}

template <class Vec>
TilePoints<Vec> points_of_tile(std::span<const Vec> points, std::span<const std::uint32_t> tile_of, std::uint32_t tile) {
  TilePoints<Vec> out;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (tile_of[i] != tile) continue;
    out.ids.push_back(i);
    out.points.push_back(points[i]);
  }
  return out;
}

}  // namespace

std::vector<std::uint32_t> kd_tiles(std::span<const Vec2> points, std::uint32_t tiles) { return tiles_of(points, tiles); }
std::vector<std::uint32_t> kd_tiles(std::span<const Vec3> points, std::uint32_t tiles) { return tiles_of(points, tiles); }
std::vector<TileBox<Vec2>> tile_boxes(std::span<const Vec2> points, std::span<const std::uint32_t> tile_of,
                                      std::uint32_t tiles) {
  return boxes_of(points, tile_of, tiles);
}
std::vector<TileBox<Vec3>> tile_boxes(std::span<const Vec3> points, std::span<const std::uint32_t> tile_of,
                                      std::uint32_t tiles) {
  return boxes_of(points, tile_of, tiles);
}

TilePoints<Vec2> tile_points(std::span<const Vec2> points, std::span<const std::uint32_t> tile_of, std::uint32_t tile) {
  return points_of_tile(points, tile_of, tile);
}
TilePoints<Vec3> tile_points(std::span<const Vec3> points, std::span<const std::uint32_t> tile_of, std::uint32_t tile) {
  return points_of_tile(points, tile_of, tile);
}

}  // namespace dtlab
