// The classical control space in 3D (book §7.5, "classical case"): with no size given, the size
// at a surface vertex is the mean length of the surface edges at it, and the size field inside is
// its P1 interpolation on the empty mesh. A vertex on no constrained edge (an isolated input point,
// an interior Steiner point of the recovery) takes the mean length of all its edges.
#include <algorithm>
#include <cmath>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/error.hpp"
#include "mesh/edge_key.hpp"

namespace dtlab {

namespace {

}  // namespace

ControlSpace3 classical_control_space(const Mesh3& empty) {
  // Every edge once, with whether it is constrained.
  std::vector<std::uint64_t> edges;
  edges.reserve(6 * empty.tetrahedron_capacity());
  for (std::uint32_t t = 0; t < empty.tetrahedron_capacity(); ++t) {
    if (!empty.is_alive(t) || empty.is_ghost(t)) continue;
    for (std::uint32_t i = 0; i < 4; ++i)
      for (std::uint32_t j = i + 1; j < 4; ++j) edges.push_back(edge_key(empty.vertex(t, i), empty.vertex(t, j)));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const std::uint32_t n = empty.vertex_capacity();
  std::vector<double> constrained_sum(n, 0.0), all_sum(n, 0.0);
  std::vector<std::uint32_t> constrained_count(n, 0), all_count(n, 0);
  for (const std::uint64_t k : edges) {
    const std::uint32_t a = static_cast<std::uint32_t>(k >> 32), b = static_cast<std::uint32_t>(k);
    const double l = norm(empty.point(b) - empty.point(a));
    all_sum[a] += l, all_sum[b] += l;
    ++all_count[a], ++all_count[b];
    if (empty.is_constrained_edge(a, b)) {
      constrained_sum[a] += l, constrained_sum[b] += l;
      ++constrained_count[a], ++constrained_count[b];
    }
  }
  std::vector<Metric3> metrics(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (empty.is_dead_vertex(v) || all_count[v] == 0) continue;  // unused: the identity, never read
    const double h = constrained_count[v] ? constrained_sum[v] / constrained_count[v] : all_sum[v] / all_count[v];
    DTLAB_ASSERT(h > 0.0 && std::isfinite(h));
    metrics[v] = Metric3::isotropic(h);
  }
  return ControlSpace3(empty, std::move(metrics));
}

}  // namespace dtlab
