// Edge split of book §8.3.6 in 3D: a new vertex m at the metric midpoint of a free edge ab, each
// tetrahedron (a, b, c, d) of the shell cut in two, (m, b, c, d) and (a, m, c, d); then swaps
// around m (split_pass3). Toward a unit mesh: every edge longer than sqrt2 in the metric.
#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {

using namespace optimize3d_detail;

Vec3 metric_midpoint3(const Vec3& a, const Metric3& ma, const Vec3& b, const Metric3& mb) noexcept {
  const double la = ma.length(b - a), lb = mb.length(b - a);
  double s = 0.5;
  if (la > 0.0 && lb > 0.0 && std::abs(lb - la) > 1e-12 * la) {
    const double r = lb / la;
    s = std::log((1.0 + r) / 2.0) / std::log(r);
  }
  if (!(s > 0.0 && s < 1.0)) s = 0.5;
  return a + s * (b - a);
}

namespace {

// Mesh3::find_edge(a, b) for live finite a, b: the first tetrahedron of a's ball, in
// Mesh3::ball's breadth-first order, that holds b (so the shell starts where it did), with a
// stamp per tetrahedron for "seen" and the search stopped there.
class EdgeFinder {
 public:
  std::uint32_t find(const Mesh3& mesh, std::uint32_t a, std::uint32_t b) {
    if (seen_.size() < mesh.tetrahedron_capacity()) seen_.resize(mesh.tetrahedron_capacity(), 0);
    ++stamp_;
    // The first tetrahedron of a's ball (in Mesh3::ball's order) that holds b.
    return nav3::search_ball(mesh, a, mesh.vertex_tetrahedron(a), list_, nav3::marking(seen_, stamp_), [&](std::uint32_t t) {
      return mesh.vertex(t, 0) == b || mesh.vertex(t, 1) == b || mesh.vertex(t, 2) == b || mesh.vertex(t, 3) == b;
    });
  }

 private:
  std::vector<std::uint32_t> seen_, list_;
  std::uint32_t stamp_ = 0;
};

// try_split3 with `hint` a live tetrahedron with edge ab, or kNone (then searched).
std::uint32_t split_edge(Mesh3& mesh, std::uint32_t a, std::uint32_t b, const MetricField3& field,
                         const Split3Options& options, std::uint32_t hint) {
  std::vector<std::uint32_t> shell, ring;
  if (!is_free_edge(mesh, a, b, shell, ring, hint)) return Mesh3::kNone;
  const Vec3 m = metric_midpoint3(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b));
  if (m == mesh.point(a) || m == mesh.point(b)) return Mesh3::kNone;
  const Metric3 mm = field ? field(m) : interpolate(mesh.metric(a), mesh.metric(b), 0.5);
  const double before = worst_quality(mesh, shell);
  double after = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t c = ring[k], d = ring[(k + 1) % n];
    if (dtlab::edge_length(m, mm, mesh.point(c), mesh.metric(c)) < options.short_length) return Mesh3::kNone;
    // (a, b, c, d) positive: (m, b, c, d) and (a, m, c, d).
    if (orient3d(m, mesh.point(b), mesh.point(c), mesh.point(d)) != Sign::Positive ||
        orient3d(mesh.point(a), m, mesh.point(c), mesh.point(d)) != Sign::Positive)
      return Mesh3::kNone;
    after = std::max({after,
                      positive_quality_in(m, mesh.point(b), mesh.point(c), mesh.point(d), mm, mesh.metric(b), mesh.metric(c),
                                 mesh.metric(d)),
                      positive_quality_in(mesh.point(a), m, mesh.point(c), mesh.point(d), mesh.metric(a), mm, mesh.metric(c),
                                 mesh.metric(d))});
  }
  if (after > std::max(before, options.quality_limit)) return Mesh3::kNone;
  const int ref = mesh.ref(shell.front());
  const std::uint32_t v = mesh.add_vertex(m, mm, 0);
  std::vector<NewTetrahedron> fresh;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t c = ring[k], d = ring[(k + 1) % n];
    fresh.push_back({{v, b, c, d}, ref});
    fresh.push_back({{a, v, c, d}, ref});
  }
  std::vector<std::uint32_t> slots;
  replace_tetrahedra(mesh, shell, fresh, slots);
  return v;
}

}  // namespace

std::uint32_t try_split3(Mesh3& mesh, std::uint32_t a, std::uint32_t b, const MetricField3& field,
                         const Split3Options& options) {
  return split_edge(mesh, a, b, field, options, Mesh3::kNone);
}

SplitPass3Result split_pass3(Mesh3& mesh, const MetricField3& field, const Split3Options& options) {
  return optimize3d_detail::split_pass(mesh, field, options, {});
}

SplitPass3Result optimize3d_detail::split_pass(Mesh3& mesh, const MetricField3& field, const Split3Options& options,
                                               Region region) {
  SplitPass3Result result;
  using Item = std::tuple<double, std::uint32_t, std::uint32_t>;
  // Longest first; ties by the smaller ids (tuple order on the negated key keeps it deterministic).
  std::priority_queue<Item, std::vector<Item>, std::less<>> queue;
  auto consider = [&](std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    if (!in_region(region, a) || !in_region(region, b)) return;
    const double l = edge_length(mesh, a, b);
    if (l > options.long_length) queue.emplace(l, a, b);
  };
  std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const auto v = mesh.tetrahedron(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) consider(v[i], v[j]);
  }
  std::vector<std::uint32_t> ball;
  // No vertex moves or dies in this pass (splits add them): one cache for every swap pass.
  QualityCache cache;
  EdgeFinder finder;
  while (!queue.empty()) {
    const auto [l, a, b] = queue.top();
    queue.pop();
    if (mesh.live_vertex_count() >= options.max_vertices) {
      result.limit_reached = true;
      break;
    }
    if (mesh.is_dead_vertex(a) || mesh.is_dead_vertex(b) || edge_length(mesh, a, b) != l) continue;
    const std::uint32_t hint = finder.find(mesh, a, b);
    if (hint == Mesh3::kNone) continue;  // no edge any more: is_free_edge would refuse it
    const std::uint32_t v = split_edge(mesh, a, b, field, options, hint);
    if (v == Mesh3::kNone) continue;
    ++result.splits;
    mesh.ball(v, ball);
    const SwapPassResult s = swap_pass(mesh, options.margin, ball, 0.0, cache);
    result.swaps += s.face_swaps + s.shell_transformations;
    consider(a, v);
    consider(v, b);
  }
  return result;
}

}  // namespace dtlab
