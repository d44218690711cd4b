// Tiles of a point set for distributed Delaunay (book §13.3, a-priori partitioning): a k-d tree
// on point quantiles that gives any number of tiles, not only powers of two. Each split cuts
// the longest side of its points' bounding box at the quantile that gives the two halves point
// counts in proportion to their tile counts, never between points with equal coordinates (equal
// points stay in one tile, so a tile's Delaunay call sees every duplicate of its points and
// keeps the one with the lowest id, as the sequential call does).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

// A tile's points' bounding box (empty: no points, lo > hi).
template <class Vec>
struct TileBox {
  Vec lo, hi;
  bool empty = true;
};

// The tile (0 .. tiles-1) of each point; the same for every caller given the same points
// (ties broken by coordinates, then by index). InputError for tiles == 0.
std::vector<std::uint32_t> kd_tiles(std::span<const Vec2> points, std::uint32_t tiles);
std::vector<std::uint32_t> kd_tiles(std::span<const Vec3> points, std::uint32_t tiles);

// The bounding box of each tile's points.
std::vector<TileBox<Vec2>> tile_boxes(std::span<const Vec2> points, std::span<const std::uint32_t> tile_of,
                                      std::uint32_t tiles);
std::vector<TileBox<Vec3>> tile_boxes(std::span<const Vec3> points, std::span<const std::uint32_t> tile_of,
                                      std::uint32_t tiles);

// The points of one tile: their ids (ascending) and coordinates.
template <class Vec>
struct TilePoints {
  std::vector<std::uint32_t> ids;
  std::vector<Vec> points;
};
TilePoints<Vec2> tile_points(std::span<const Vec2> points, std::span<const std::uint32_t> tile_of, std::uint32_t tile);
TilePoints<Vec3> tile_points(std::span<const Vec3> points, std::span<const std::uint32_t> tile_of, std::uint32_t tile);

}  // namespace dtlab
