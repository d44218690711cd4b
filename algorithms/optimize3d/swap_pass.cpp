// The swap pass of 3D optimization (book §8.6.2: "face and edge swaps, worst element first"):
// a queue of tetrahedra ordered by Q_K, worst first; for each, the face swaps on its four facets
// and the shell transformations of its six edges, the first that improves applied and its new
// tetrahedra queued. Stale entries (a slot freed or reused since) are skipped.
#include <algorithm>
#include <array>
#include <queue>
#include <tuple>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

struct Entry {
  double quality;
  std::uint32_t t;
  std::array<std::uint32_t, 4> v;
  // Worst first; ties by slot, so the order is deterministic.
  bool operator<(const Entry& o) const noexcept { return quality < o.quality || (quality == o.quality && t > o.t); }
};

// Local indices of the six edges.
constexpr std::array<std::array<std::uint32_t, 2>, 6> kEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

}  // namespace

SwapPassResult optimize3d_detail::swap_pass(Mesh3& mesh, double margin, std::span<const std::uint32_t> seeds,
                                            double threshold, QualityCache& cache, AttemptMemo* memo) {
  SwapPassResult result;
  std::priority_queue<Entry> queue;
  auto push = [&](std::uint32_t t) {
    if (!mesh.in_domain(t)) return;
    const double q = cache.get(mesh, t);
    if (q > threshold) queue.push({q, t, mesh.tetrahedron(t)});
  };
  if (seeds.empty()) {
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) push(t);
  } else {
    for (const std::uint32_t t : seeds) push(t);
  }
  const std::uint64_t limit = 20ull * mesh.live_tetrahedron_count() + 1000;
  std::vector<std::uint32_t> created;
  while (!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    if (!mesh.in_domain(e.t) || mesh.tetrahedron(e.t) != e.v) continue;
    if (result.face_swaps + result.shell_transformations >= limit) {
      result.limit_reached = true;
      break;
    }
    bool changed = false;
    for (std::uint32_t i = 0; i < 4 && !changed; ++i) {
      if (face_swap(mesh, Mesh3::facet(e.t, i), margin, &created, &cache)) {
        ++result.face_swaps;
        changed = true;
      }
    }
    for (std::uint32_t k = 0; k < 6 && !changed; ++k) {
      if (shell_transformation(mesh, e.v[kEdges[k][0]], e.v[kEdges[k][1]], margin, &created, e.t, &cache,
                               memo ? &memo->shell : nullptr)) {
        ++result.shell_transformations;
        changed = true;
      }
    }
    if (changed)
      for (const std::uint32_t t : created) push(t);
  }
  return result;
}

SwapPass3Result swap_pass3(Mesh3& mesh, double margin, std::span<const std::uint32_t> seeds, double threshold) {
  QualityCache cache;
  const SwapPassResult r = swap_pass(mesh, margin, seeds, threshold, cache);
  return {r.face_swaps, r.shell_transformations, r.limit_reached};
}

}  // namespace dtlab
