// The 3D edge method's filter grid (edge_points.cpp, book §7.5: candidates are filtered "by
// simply using a grid"). The vertices bucketed in cubic cells of side `cell`, each cell a singly
// linked list through `next_` (vertex ids). Only insertion: the edge method never removes a
// vertex. The cells over the box [lo, hi] (the empty mesh's vertices: every field point lies on
// one of its edges) are a dense array when there are at most `dense_cells` of them
// (Mesh3dOptions::filter_dense_cells); others, and all of them past that bound, in a hash table.
// The candidate filter looks at 27 cells a point: an array read each instead of a hash lookup.
// field_point_regions.hpp shares the dense cells out between regions (dense_cell, cell_of,
// all_cells) and reserves next_ before the regions insert at once, each in its own cells.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

class VertexGrid {
 public:
  VertexGrid(const Vec3& lo, const Vec3& hi, double cell, std::uint64_t dense_cells) : origin_(lo), cell_(cell) {
    const std::int64_t nx = coordinate(hi.x - lo.x) + 1, ny = coordinate(hi.y - lo.y) + 1,
                       nz = coordinate(hi.z - lo.z) + 1;
    // At most 2^31, so that nx * ny and nx * ny * nz below cannot overflow.
    const auto limit = static_cast<std::int64_t>(std::min<std::uint64_t>(dense_cells, std::uint64_t{1} << 31));
    if (nx > 0 && ny > 0 && nz > 0 && nx <= limit && ny <= limit && nz <= limit && nx * ny <= limit &&
        nx * ny * nz <= limit) {
      n_ = {nx, ny, nz};
      dense_.assign(static_cast<std::size_t>(nx * ny * nz), kEnd);
    }
  }

  // Adds vertex v at p.
  void insert(std::uint32_t v, const Vec3& p) {
    if (next_.size() <= v) next_.resize(std::max<std::size_t>(v + 1, next_.size() * 3 / 2), kEnd);
    const std::int64_t x = coordinate(p.x - origin_.x), y = coordinate(p.y - origin_.y),
                       z = coordinate(p.z - origin_.z);
    std::uint32_t* head = nullptr;
    if (const std::int64_t i = dense_index(x, y, z); i >= 0)
      head = &dense_[static_cast<std::size_t>(i)];
    else
      head = &head_.try_emplace(key(x, y, z), kEnd).first->second;
    next_[v] = *head;
    *head = v;
  }

  // Whether a vertex lies closer than `distance` to p in the metric m, whose largest size is
  // h_max (so that the Euclidean search radius is distance * h_max).
  bool any_closer(const Vec3& p, const Metric3& m, double h_max, double distance, std::span<const Vec3> points) const {
    bool found = false;
    for_cells(p, distance * h_max, [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      for (std::uint32_t v = first(x, y, z); v != kEnd; v = next_[v]) {
        if (m.length(points[v] - p) < distance) return found = true;
      }
      return false;
    });
    return found;
  }

  // For inserters that share the cells out between threads (field_point_regions.hpp).
  bool dense() const noexcept { return !dense_.empty(); }
  std::size_t dense_cell_count() const noexcept { return dense_.size(); }
  // The integer coordinates of dense cell i.
  std::array<std::int64_t, 3> dense_cell(std::size_t i) const noexcept {
    const auto k = static_cast<std::int64_t>(i);
    return {k % n_[0], (k / n_[0]) % n_[1], k / (n_[0] * n_[1])};
  }
  std::array<std::int64_t, 3> dense_dims() const noexcept { return n_; }
  // The dense index of p's cell, -1 outside the dense array.
  std::int64_t cell_of(const Vec3& p) const {
    return dense_index(coordinate(p.x - origin_.x), coordinate(p.y - origin_.y), coordinate(p.z - origin_.z));
  }
  // Whether every cell that any_closer(p, _, h_max, distance) looks at is a dense one that
  // satisfies pred(index).
  template <class F>
  bool all_cells(const Vec3& p, double h_max, double distance, F&& pred) const {
    bool all = true;
    for_cells(p, distance * h_max, [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      const std::int64_t i = dense_index(x, y, z);
      return !(all = i >= 0 && pred(static_cast<std::size_t>(i)));
    });
    return all;
  }
  // Room for vertex ids below n, so that insert() does not reallocate.
  void reserve_vertices(std::size_t n) {
    if (next_.size() < n) next_.resize(n, kEnd);
  }

 private:
  static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;
  std::int64_t coordinate(double d) const { return static_cast<std::int64_t>(std::floor(d / cell_)); }
  std::int64_t dense_index(std::int64_t x, std::int64_t y, std::int64_t z) const {
    if (dense_.empty() || x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) return -1;
    return (z * n_[1] + y) * n_[0] + x;
  }
  // Calls f(x, y, z) on the cells meeting the box of half-side r around p until it returns true.
  template <class F>
  void for_cells(const Vec3& p, double r, F&& f) const {
    const std::int64_t x0 = coordinate(p.x - r - origin_.x), x1 = coordinate(p.x + r - origin_.x);
    const std::int64_t y0 = coordinate(p.y - r - origin_.y), y1 = coordinate(p.y + r - origin_.y);
    const std::int64_t z0 = coordinate(p.z - r - origin_.z), z1 = coordinate(p.z + r - origin_.z);
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y)
        for (std::int64_t z = z0; z <= z1; ++z)
          if (f(x, y, z)) return;
  }
  std::uint32_t first(std::int64_t x, std::int64_t y, std::int64_t z) const {
    if (const std::int64_t i = dense_index(x, y, z); i >= 0) return dense_[static_cast<std::size_t>(i)];
    if (head_.empty()) return kEnd;
    const auto it = head_.find(key(x, y, z));
    return it == head_.end() ? kEnd : it->second;
  }
  // Cells far apart may share a key: their lists merge, which only adds vertices to look at.
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x) * 73856093u) ^ (static_cast<std::uint64_t>(y) * 19349663u * 1000003u) ^
           (static_cast<std::uint64_t>(z) * 83492791u * 998244353u);
  }

  Vec3 origin_;
  double cell_;
  std::array<std::int64_t, 3> n_{};
  std::vector<std::uint32_t> dense_;
  std::unordered_map<std::uint64_t, std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
};

}  // namespace dtlab
