// A uniform grid of buckets over a mesh's bounding box, each bucket listing the elements whose
// bounding box meets it: the fallback of point location in a background mesh that is not convex.
// A visibility walk stops at the boundary when the straight path to the point leaves the domain
// through a hole or a concavity (the wall of the UGAWG cube-cylinder, the arc of a quarter
// annulus), so a point inside the domain would take the metric of a far element; the elements of
// the point's bucket are the candidates that settle it (George and Borouchaki §9.5: the control
// space must answer anywhere in the domain). Deterministic: elements are listed in their order.
//
//   ElementGrid<Vec2> grid(points, triangles);     // elements: arrays of vertex numbers
//   for (std::uint32_t t : grid.candidates(p)) ... // exact containment tests by the caller
//                                                   // (closed_triangle_holds in 2D)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "kernel/predicates.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

// The exact test the grid's callers make on its candidates: p in the closed triangle abc
// (counter-clockwise), by three orient2d.
inline bool closed_triangle_holds(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  return orient2d(a, b, p) != Sign::Negative && orient2d(b, c, p) != Sign::Negative && orient2d(c, a, p) != Sign::Negative;
}
// The same in 3D: p in the closed positive tetrahedron abcd (p put for each vertex in turn).
inline bool closed_tetrahedron_holds(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p) {
  return orient3d(p, b, c, d) != Sign::Negative && orient3d(a, p, c, d) != Sign::Negative &&
         orient3d(a, b, p, d) != Sign::Negative && orient3d(a, b, c, p) != Sign::Negative;
}

template <class Point>
class ElementGrid {
 public:
  static constexpr int kDim = std::is_same_v<Point, Vec2> ? 2 : 3;

  ElementGrid() = default;
  // `elements` holds the vertex numbers of each element (kDim + 1 of them, into `points`);
  // `skip` (optional, one per element) marks elements left out (dead slots, ghosts). About
  // `cells_per_element` buckets per listed element.
  template <class Element>
  ElementGrid(std::span<const Point> points, std::span<const Element> elements, const std::vector<bool>* skip = nullptr,
              double cells_per_element = 1.0) {
    std::uint64_t listed = 0;
    bool first = true;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (skip != nullptr && (*skip)[e]) continue;
      ++listed;
      for (const auto v : elements[e]) {
        const Point& p = points[v];
        for (int d = 0; d < kDim; ++d) {
          lo_[d] = first ? coord(p, d) : std::min(lo_[d], coord(p, d));
          hi_[d] = first ? coord(p, d) : std::max(hi_[d], coord(p, d));
        }
        first = false;
      }
    }
    if (listed == 0) return;
    // Cells as cubic as the box allows, about cells_per_element * listed of them, at most 2^24. A
    // side a million times thinner than the longest (a flat surface in 3D) is one cell thick.
    std::array<double, 3> extent{};
    double longest = 0.0;
    for (int d = 0; d < kDim; ++d) {
      extent[d] = std::max(hi_[d] - lo_[d], 1e-300);
      longest = std::max(longest, extent[d]);
    }
    double volume = 1.0;
    int thick = 0;
    for (int d = 0; d < kDim; ++d) {
      if (extent[d] < 1e-6 * longest) continue;
      volume *= extent[d];
      ++thick;
    }
    const double target = std::clamp(cells_per_element * static_cast<double>(listed), 1.0, 16777216.0);
    const double side = std::pow(volume / target, 1.0 / thick);
    std::uint64_t total = 1;
    for (int d = 0; d < kDim; ++d) {
      n_[d] = static_cast<std::uint32_t>(std::clamp(std::ceil(extent[d] / side), 1.0, 4096.0));
      scale_[d] = n_[d] / extent[d];
      total *= n_[d];
    }
    // Two passes: count per bucket, then fill (compressed rows).
    offsets_.assign(total + 1, 0);
    auto each_cell = [&](const auto& element, auto&& visit) {
      std::array<std::uint32_t, 3> a{}, b{};
      for (int d = 0; d < kDim; ++d) {
        double mn = coord(points[element[0]], d), mx = mn;
        for (const auto v : element) {
          mn = std::min(mn, coord(points[v], d));
          mx = std::max(mx, coord(points[v], d));
        }
        a[d] = cell(mn, d);
        b[d] = cell(mx, d);
      }
      for (std::uint32_t z = a[2]; z <= b[2]; ++z)
        for (std::uint32_t y = a[1]; y <= b[1]; ++y)
          for (std::uint32_t x = a[0]; x <= b[0]; ++x) visit(index(x, y, z));
    };
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (skip != nullptr && (*skip)[e]) continue;
      each_cell(elements[e], [&](std::uint64_t c) { ++offsets_[c + 1]; });
    }
    for (std::uint64_t c = 0; c < total; ++c) offsets_[c + 1] += offsets_[c];
    items_.resize(offsets_[total]);
    std::vector<std::uint64_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (skip != nullptr && (*skip)[e]) continue;
      each_cell(elements[e], [&](std::uint64_t c) { items_[fill[c]++] = static_cast<std::uint32_t>(e); });
    }
  }

  bool empty() const noexcept { return items_.empty(); }

  // The listed element nearest to p: the one with the least distance(e), the caller's distance
  // from p to element e (to its closest point; never more than to any point of it), lowest number
  // on ties; kNoElement when none is listed. Buckets are searched in shells around p's bucket
  // until no bucket left can hold a nearer element (an element lies in every bucket its bounding
  // box meets, so its closest point to p does); at most every bucket once.
  static constexpr std::uint32_t kNoElement = 0xFFFFFFFFu;
  template <class Distance>
  std::uint32_t nearest(const Point& p, Distance&& distance) const {
    if (items_.empty()) return kNoElement;
    std::array<std::int64_t, 3> c{}, n{};
    for (int d = 0; d < 3; ++d) {
      c[d] = d < kDim ? cell(coord(p, d), d) : 0;
      n[d] = n_[d];
    }
    std::uint32_t best = kNoElement;
    double best_distance = std::numeric_limits<double>::infinity();
    auto visit = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      const std::uint64_t i = index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), static_cast<std::uint32_t>(z));
      for (std::uint64_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
        const std::uint32_t e = items_[k];
        const double dist = distance(e);
        if (dist < best_distance || (dist == best_distance && e < best)) best = e, best_distance = dist;
      }
    };
    const std::int64_t shells = std::max({n[0], n[1], n[2]});
    for (std::int64_t r = 0; r < shells; ++r) {
      std::array<std::int64_t, 3> a{}, b{};
      for (int d = 0; d < 3; ++d) a[d] = std::max<std::int64_t>(c[d] - r, 0), b[d] = std::min(c[d] + r, n[d] - 1);
      for (std::int64_t z = a[2]; z <= b[2]; ++z)
        for (std::int64_t y = a[1]; y <= b[1]; ++y) {
          const bool face = std::abs(z - c[2]) == r || std::abs(y - c[1]) == r;
          for (std::int64_t x = a[0]; x <= b[0]; x += face || b[0] == a[0] ? 1 : b[0] - a[0]) {
            if (face || std::abs(x - c[0]) == r) visit(x, y, z);
          }
        }
      // Any bucket beyond shell r lies past a face of the block [c - r, c + r] that is not the grid's.
      double beyond = std::numeric_limits<double>::infinity();
      for (int d = 0; d < kDim; ++d) {
        if (c[d] - r > 0) beyond = std::min(beyond, coord(p, d) - (lo_[d] + (c[d] - r) / scale_[d]));
        if (c[d] + r < n[d] - 1) beyond = std::min(beyond, lo_[d] + (c[d] + r + 1) / scale_[d] - coord(p, d));
      }
      if (beyond == std::numeric_limits<double>::infinity() || beyond > best_distance) break;
    }
    return best;
  }
  // The elements whose bounding box meets p's bucket (p outside the box: the nearest bucket).
  std::span<const std::uint32_t> candidates(const Point& p) const noexcept {
    if (items_.empty()) return {};
    std::array<std::uint32_t, 3> c{};
    for (int d = 0; d < kDim; ++d) c[d] = cell(coord(p, d), d);
    const std::uint64_t i = index(c[0], c[1], c[2]);
    return {items_.data() + offsets_[i], static_cast<std::size_t>(offsets_[i + 1] - offsets_[i])};
  }

 private:
  static double coord(const Point& p, int d) noexcept {
    if constexpr (kDim == 2) return d == 0 ? p.x : p.y;
    else return d == 0 ? p.x : d == 1 ? p.y : p.z;
  }
  std::uint32_t cell(double x, int d) const noexcept {
    const double c = std::floor((x - lo_[d]) * scale_[d]);
    if (!(c > 0.0)) return 0;  // below, or NaN
    return c >= n_[d] ? n_[d] - 1 : static_cast<std::uint32_t>(c);
  }
  std::uint64_t index(std::uint32_t x, std::uint32_t y, std::uint32_t z) const noexcept {
    return (static_cast<std::uint64_t>(z) * n_[1] + y) * n_[0] + x;
  }

  std::array<double, 3> lo_{}, hi_{}, scale_{};
  std::array<std::uint32_t, 3> n_{1, 1, 1};
  std::vector<std::uint64_t> offsets_;
  std::vector<std::uint32_t> items_;
};

}  // namespace dtlab
