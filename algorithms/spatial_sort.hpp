// Spatial sorting for incremental insertion: Hilbert curve order and BRIO.
//
// Hilbert order (Hilbert 1891; as an insertion order for Delaunay: Amenta, Choi, Rote,
// "Incremental constructions con BRIO", SoCG 2003): points are quantised on a 2^16 x 2^16 grid
// over their bounding box and sorted by the index of their cell along the Hilbert curve (radix
// sort); a cell holding many points is sorted again on its own bounding box, so clustered input
// keeps its locality. BRIO (Biased Randomized Insertion Order, same paper): each point joins
// round r with probability 2^-(r+1) (the last round holds about half the points, each earlier
// round half the next); rounds are inserted from the smallest up, each in Hilbert order.
//
// 3D: the same sort on a 2^10 x 2^10 x 2^10 grid with the 3D Hilbert curve (Skilling's
// transposition, AIP Conf. Proc. 707, 2004); the recursion on shared cells and BRIO are the
// same code for both dimensions (spatial_sort.cpp).
//
// Everything is deterministic (a seed drives BRIO), O(n log n) at worst, O(n) for bounded
// clustering, and allocates per call, never per point.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/vec.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/uninitialized_vector.hpp"

namespace dtlab {

// Index of cell (x, y) of the 2^16 x 2^16 grid along the Hilbert curve that starts at cell (0, 0)
// and ends at cell (2^16 - 1, 0).
std::uint32_t hilbert_index2(std::uint32_t x, std::uint32_t y) noexcept;

// Sorts `ids` (indices into `points`) into Hilbert order. Points with equal coordinates end up
// next to each other, in increasing id order: a duplicate scan after this sort is one linear
// pass comparing neighbours.
void hilbert_sort(std::span<const Vec2> points, std::span<std::uint32_t> ids);

// hilbert_sort that also drops duplicates from `ids` on the way (no extra pass over the points):
// of each group of equal points only the smallest id stays. Returns the dropped ids, ascending,
// each with the id it duplicates: (dropped, kept). Ids must be below 2^31. With `team`, a large
// sort shares its passes out among the team's threads; the result is the same.
std::vector<std::pair<std::uint32_t, std::uint32_t>> hilbert_sort_unique(std::span<const Vec2> points,
                                                                        std::vector<std::uint32_t>& ids,
                                                                        WorkerTeam* team = nullptr);

// Index of cell (x, y, z) of the 2^bits grid per axis (bits <= 10) along the 3D Hilbert curve
// that starts at cell (0, 0, 0).
std::uint32_t hilbert_index3(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits = 10) noexcept;
// The same index computed bit by bit by Skilling's transposition, which defines the curve (the
// one above reads tables derived from it): for tests.
std::uint32_t hilbert_index3_skilling(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits = 10) noexcept;

// The same for 3D points.
void hilbert_sort(std::span<const Vec3> points, std::span<std::uint32_t> ids);
std::vector<std::pair<std::uint32_t, std::uint32_t>> hilbert_sort_unique(std::span<const Vec3> points,
                                                                        std::vector<std::uint32_t>& ids,
                                                                        WorkerTeam* team = nullptr);

// Every input index once: the distinct points (the smallest index of each coordinate tuple) in
// Hilbert order, and the dropped duplicates (ascending) with the kept index each repeats. The
// shared first step of the Delaunay variants' preparation, 2D and 3D.
struct DistinctPoints {
  std::vector<std::uint32_t> distinct;
  std::vector<std::uint32_t> duplicates;
  std::vector<std::uint32_t> duplicate_of;
};
DistinctPoints distinct_in_hilbert_order(std::span<const Vec2> points, WorkerTeam* team = nullptr);
DistinctPoints distinct_in_hilbert_order(std::span<const Vec3> points, WorkerTeam* team = nullptr);

// BRIO order of ids that are already in Hilbert order (hilbert_sort): a stable partition into
// rounds keeps each round in Hilbert order. Rounds smaller than `first_round` are merged into
// the first one.
std::vector<std::uint32_t> brio_order_of_sorted(std::span<const std::uint32_t> hilbert_sorted_ids,
                                                std::uint64_t seed, std::size_t first_round = 64);

// The same order (ids) dealt on the threads of `team` (same result), and if asked the position
// in hilbert_sorted_ids of each (ranks: within a round they increase).
struct BrioOrder {
  UninitializedVector<std::uint32_t> ids;
  UninitializedVector<std::uint32_t> ranks;  // empty unless asked for
};
BrioOrder brio_order_of_sorted(std::span<const std::uint32_t> hilbert_sorted_ids, std::uint64_t seed,
                               WorkerTeam* team, bool with_ranks, std::size_t first_round = 64);

// hilbert_sort, then brio_order_of_sorted.
std::vector<std::uint32_t> brio_order(std::span<const Vec2> points, std::span<const std::uint32_t> ids,
                                      std::uint64_t seed, std::size_t first_round = 64);
std::vector<std::uint32_t> brio_order(std::span<const Vec3> points, std::span<const std::uint32_t> ids,
                                      std::uint64_t seed, std::size_t first_round = 64);

}  // namespace dtlab
