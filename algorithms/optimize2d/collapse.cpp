// Edge collapse, the "edge suppression by reduction" of book §8.3.5 (Figure 8.6: the merged
// point put on one end): the free end v of edge vw is removed and its ball reconnected to w; the
// two triangles of vw disappear. Simulated first (§8.6.1): the link condition (v and w share only
// the two opposite vertices; Hoppe et al. 1993, Dey et al. 1999), every new triangle positive
// (exact orient2d), no new edge longer than the unit bound, the ball's worst Q_K bounded.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using optimize2d_detail::edge_length;
using optimize2d_detail::is_free;
using optimize2d_detail::is_locked;
using optimize2d_detail::NewTriangle;
using optimize2d_detail::quality;

namespace {

constexpr double kRejected = std::numeric_limits<double>::infinity();

// The worst Q_K after collapsing v onto w (v free, `ring` its ball), or kRejected; `out` gets
// the new triangles.
double simulate(const Mesh2& mesh, std::uint32_t v, std::uint32_t w, const std::vector<std::uint32_t>& ring,
                const CollapseOptions& options, CollapseCriterion criterion, std::vector<NewTriangle>& out) {
  out.clear();
  std::uint32_t x = Mesh2::kNone, y = Mesh2::kNone;  // the vertices opposite vw
  double before = 0.0;
  for (const std::uint32_t h : ring) {
    const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
    before = std::max(before, quality(mesh, v, a, b));
    if (a == w) x = b;
    if (b == w) y = a;
  }
  if (x == Mesh2::kNone || y == Mesh2::kNone || x == y) return kRejected;
  // Link condition: a vertex beside both v and w other than x and y would give a doubled edge.
  std::vector<std::uint32_t> around_v;
  for (const std::uint32_t h : ring) around_v.push_back(mesh.origin(h));
  std::sort(around_v.begin(), around_v.end());
  std::vector<std::uint32_t> ring_w;
  mesh.ball(w, ring_w);
  for (const std::uint32_t h : ring_w) {
    const std::uint32_t c = mesh.origin(h);
    if (c == v || c == x || c == y || c == Mesh2::kInfinite) continue;
    if (std::binary_search(around_v.begin(), around_v.end(), c)) return kRejected;
  }
  double after = 0.0;
  const int ref = mesh.ref(Mesh2::triangle_of(ring.front()));
  for (const std::uint32_t h : ring) {
    const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
    if (a == w || b == w) continue;
    if (orient2d(mesh.point(w), mesh.point(a), mesh.point(b)) != Sign::Positive) return kRejected;
    if (a != x && edge_length(mesh, w, a) > std::max(options.long_length, edge_length(mesh, v, a))) return kRejected;
    after = std::max(after, quality(mesh, w, a, b));
    out.push_back({w, a, b, ref});
  }
  const bool accepted = criterion == CollapseCriterion::Improve
                            ? after < before * (1.0 - options.margin)
                            : after <= std::max(before, options.quality_limit);
  return accepted ? after : kRejected;
}

}  // namespace

bool try_collapse(Mesh2& mesh, std::uint32_t h, const CollapseOptions& options, CollapseCriterion criterion) {
  if (is_locked(mesh, h)) return false;
  const std::uint32_t ends[2] = {mesh.origin(h), mesh.destination(h)};
  std::vector<std::uint32_t> ring[2];
  std::vector<NewTriangle> created[2];
  double result[2] = {kRejected, kRejected};
  for (int k = 0; k < 2; ++k) {
    if (is_free(mesh, ends[k], ring[k])) {
      result[k] = simulate(mesh, ends[k], ends[1 - k], ring[k], options, criterion, created[k]);
    }
  }
  const int best = result[1] < result[0] ? 1 : 0;
  if (result[best] == kRejected) return false;
  std::vector<std::uint32_t> old_triangles;
  for (const std::uint32_t e : ring[best]) old_triangles.push_back(Mesh2::triangle_of(e));
  std::vector<std::uint32_t> slots;
  optimize2d_detail::replace_triangles(mesh, old_triangles, created[best], {}, slots);
  mesh.remove_vertex(ends[best]);
  return true;
}

std::uint64_t collapse_pass(Mesh2& mesh, const CollapseOptions& options) {
  // Shortest first; ties by the vertex pair (deterministic).
  using Entry = std::tuple<double, std::uint32_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<std::uint32_t> ring;
  auto consider = [&](std::uint32_t h) {
    if (is_locked(mesh, h)) return;
    const std::uint32_t u = mesh.origin(h), w = mesh.destination(h);
    const double length = edge_length(mesh, u, w);
    if (length < options.short_length) queue.emplace(length, std::min(u, w), std::max(u, w));
  };
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (mesh.twin(h) > h) consider(h);
    }
  }
  std::uint64_t collapses = 0;
  const std::uint64_t bound = 10ull * mesh.live_triangle_count() + 1000;
  for (std::uint64_t pops = 0; !queue.empty() && pops < bound; ++pops) {
    const std::uint32_t u = std::get<1>(queue.top()), w = std::get<2>(queue.top());
    queue.pop();
    if (mesh.is_dead_vertex(u) || mesh.is_dead_vertex(w)) continue;
    const std::uint32_t h = mesh.find_half_edge(u, w);
    if (h == Mesh2::kNone || !try_collapse(mesh, h, options)) continue;
    ++collapses;
    const std::uint32_t kept = mesh.is_dead_vertex(u) ? w : u;
    mesh.ball(kept, ring);
    for (const std::uint32_t e : ring) {
      if (mesh.origin(e) != Mesh2::kInfinite) consider(Mesh2::prev(e));  // kept -> origin(e)
    }
  }
  return collapses;
}

}  // namespace dtlab
