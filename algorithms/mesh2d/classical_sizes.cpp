// The classical control space (book §5, §7.4 "the classical case"): with no size given, the size
// at a boundary vertex is the mean length of the boundary edges at it, and the size field inside
// is its P1 interpolation on the empty mesh. A vertex on no constrained edge (an isolated input
// point) takes the mean length of all its edges.
#include <algorithm>
#include <cmath>

#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/error.hpp"

namespace dtlab {

ControlSpace2 classical_control_space(const Mesh2& empty) {
  std::vector<double> constrained_sum(empty.vertex_capacity(), 0.0), all_sum(empty.vertex_capacity(), 0.0);
  std::vector<std::uint32_t> constrained_count(empty.vertex_capacity(), 0), all_count(empty.vertex_capacity(), 0);
  for (std::uint32_t t = 0; t < empty.triangle_capacity(); ++t) {
    if (!empty.is_alive(t) || empty.is_ghost(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      const std::uint32_t a = empty.origin(h), b = empty.destination(h);
      const double l = norm(empty.point(b) - empty.point(a));
      // An edge is seen from each of its finite triangles: both sides weigh the same in the mean.
      all_sum[a] += l;
      ++all_count[a];
      all_sum[b] += l;
      ++all_count[b];
      if (empty.is_constrained(h)) {
        constrained_sum[a] += l;
        ++constrained_count[a];
        constrained_sum[b] += l;
        ++constrained_count[b];
      }
    }
  }
  std::vector<Metric2> metrics(empty.vertex_capacity());
  for (std::uint32_t v = 0; v < empty.vertex_capacity(); ++v) {
    if (empty.is_dead_vertex(v)) continue;
    const double h = constrained_count[v] ? constrained_sum[v] / constrained_count[v]
                                          : (all_count[v] ? all_sum[v] / all_count[v] : 0.0);
    DTLAB_ASSERT(h > 0.0 && std::isfinite(h));
    metrics[v] = Metric2::isotropic(h);
  }
  return ControlSpace2(empty, std::move(metrics));
}

ControlSpace2 input_control_space(const Mesh2& empty, std::span<const Metric2> given, MetricInterpolation mode) {
  std::vector<Metric2> metrics(empty.vertex_capacity());
  std::copy(given.begin(), given.end(), metrics.begin());
  std::vector<std::uint32_t> ring;
  std::vector<Metric2> around;
  std::vector<double> weights;
  for (std::uint32_t v = static_cast<std::uint32_t>(given.size()); v < empty.vertex_capacity(); ++v) {
    if (empty.is_dead_vertex(v)) continue;
    // A crossing point: the mean of the input vertices it is joined to by constrained edges (all
    // its input neighbours if none).
    around.clear();
    empty.ball(v, ring);
    for (int pass = 0; pass < 2 && around.empty(); ++pass) {
      for (const std::uint32_t h : ring) {
        const std::uint32_t w = empty.origin(h);  // the link edge runs w -> next; prev(h) is v -> w
        if (w == Mesh2::kInfinite || w >= given.size()) continue;
        if (pass == 0 && !empty.is_constrained(Mesh2::prev(h))) continue;
        around.push_back(given[w]);
      }
    }
    DTLAB_ASSERT(!around.empty());
    weights.assign(around.size(), 1.0 / static_cast<double>(around.size()));
    metrics[v] = interpolate(std::span<const Metric2>(around), std::span<const double>(weights), mode);
  }
  return ControlSpace2(empty, std::move(metrics), mode);
}

}  // namespace dtlab
