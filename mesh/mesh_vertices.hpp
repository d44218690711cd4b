// The vertex half of the mutable meshes (mesh/mesh2.hpp, mesh/mesh3.hpp), written once for both
// dimensions: per vertex slot a point, a metric, a flag set and one incident element, with a
// free list so that a removed vertex keeps its slot, marked dead, and the next new vertex reuses
// it (last freed, first reused). Mesh2 and Mesh3 derive from it and add their elements; Mesh3
// adds its change epochs and its count of anisotropic metrics around the slot calls below.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

template <class Point, class Metric>
class MeshVertices {
 public:
  // Vertex flags (a bit set).
  static constexpr std::uint8_t kFixed = 1;       // an input vertex or a recovery Steiner point: never moved or removed
  static constexpr std::uint8_t kOnBoundary = 2;  // lies on a constrained edge (2D), facet or edge (3D)
  static constexpr std::uint8_t kDead = 4;        // a free slot

  // Slots, dead ones included.
  std::uint32_t vertex_capacity() const noexcept { return static_cast<std::uint32_t>(points_.size()); }
  std::uint32_t live_vertex_count() const noexcept {
    return vertex_capacity() - static_cast<std::uint32_t>(free_vertices_.size());
  }
  const Point& point(std::uint32_t v) const noexcept { return points_[v]; }
  std::span<const Point> points() const noexcept { return points_; }
  const Metric& metric(std::uint32_t v) const noexcept { return metrics_[v]; }
  std::span<const Metric> metrics() const noexcept { return metrics_; }
  std::uint8_t flags(std::uint32_t v) const noexcept { return vertex_flags_[v]; }
  bool is_dead_vertex(std::uint32_t v) const noexcept { return (vertex_flags_[v] & kDead) != 0; }
  void set_flags(std::uint32_t v, std::uint8_t f) noexcept { vertex_flags_[v] = f; }
  // A slot in range, not dead, with an element.
  bool is_live_vertex(std::uint32_t v) const noexcept {
    return v < vertex_capacity() && !is_dead_vertex(v) && vertex_element_[v] != kNoElement;
  }
  // Marks v dead and frees its slot; no live element may still use it.
  void remove_vertex(std::uint32_t v) {
    DTLAB_ASSERT(v < vertex_capacity() && !is_dead_vertex(v));
    vertex_flags_[v] = kDead;
    vertex_element_[v] = kNoElement;
    free_vertices_.push_back(v);
  }

 protected:
  static constexpr std::uint32_t kNoElement = 0xFFFFFFFFu;  // Triangulation2/Tetrahedralization3::kNone

  // Every point of a triangulation becomes a slot with `metric` and the flag kFixed; `incident`
  // gives one element per vertex, kNoElement for a vertex no element uses (a duplicate of the
  // input): such a slot is dead and free, the lowest one reused first.
  void adopt_vertices(std::span<const Point> points, const Metric& metric, std::vector<std::uint32_t> incident) {
    points_.assign(points.begin(), points.end());
    metrics_.assign(points.size(), metric);
    vertex_flags_.assign(points.size(), kFixed);
    vertex_element_ = std::move(incident);
    for (std::uint32_t v = 0; v < points_.size(); ++v) {
      if (vertex_element_[v] == kNoElement) {
        vertex_flags_[v] = kDead;
        free_vertices_.push_back(v);
      }
    }
    std::reverse(free_vertices_.begin(), free_vertices_.end());
  }
  // A slot for a new vertex, with no element: the last freed one, else a new one at the end
  // (point and metric value-initialised, flags kDead) while fewer than `max_points` exist. The
  // caller sets the point, the metric and the flags.
  std::uint32_t take_slot(std::uint32_t max_points) {
    std::uint32_t v;
    if (!free_vertices_.empty()) {
      v = free_vertices_.back();
      free_vertices_.pop_back();
    } else {
      DTLAB_ASSERT(points_.size() < max_points);
      v = static_cast<std::uint32_t>(points_.size());
      points_.push_back({});
      metrics_.push_back({});
      vertex_flags_.push_back(kDead);
      vertex_element_.push_back(kNoElement);
    }
    vertex_element_[v] = kNoElement;
    return v;
  }

  std::vector<Point> points_;
  std::vector<Metric> metrics_;
  std::vector<std::uint8_t> vertex_flags_;
  std::vector<std::uint32_t> vertex_element_;  // one live incident element, kNoElement for a dead slot
  std::vector<std::uint32_t> free_vertices_;
};

}  // namespace dtlab
