// Vertex relocation of book §8.4.1: the optimal point P* of the ball of P ("optimal shape
// relocation", (8.17), after Brière de l'Isle and George 1995) is the mean of the ideal points
// I_j of the ring edges, each I_j the apex of the triangle that is equilateral in the edge's
// metric, weighted by the current Q_Kj (the book's choice a_j = Q_Kj: the worse triangles pull
// harder). The sub-relaxation (8.13) P' = (1 - w) P + w P* tries w = 1, 1/2, ... and keeps the
// first P' whose ball is valid (exact orient2d) and better (worst Q_K, in the metric at P').
#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

using optimize2d_detail::is_free;
using optimize2d_detail::quality;

namespace {

// A weight beyond this (a flat triangle has Q_K = +inf) would swamp the mean into NaN.
constexpr double kMaxWeight = 1e6;

// The apex, on the left of a -> b, of the triangle on ab that is equilateral in m: in the space
// where m is the identity (x -> m^1/2 x) the apex is the midpoint plus sqrt(3)/2 times ab turned
// by +90 degrees; mapped back by m^-1/2.
Vec2 ideal_apex(const Vec2& a, const Vec2& b, const Metric2& m) {
  const Vec2 mid = 0.5 * (a + b);
  // An isotropic m scales and unscales: the Euclidean apex (no eigen-decomposition).
  if (m.m[1] == 0.0 && m.m[0] == m.m[2]) {
    const Vec2 d = b - a;
    return mid + 0.8660254037844386 * Vec2{-d.y, d.x};
  }
  const Metric2 root = power(m, 0.5);
  const Metric2 inverse_root = power(m, -0.5);
  const Vec2 d = transform(root, b - a);
  const Vec2 up{-d.y, d.x};
  return mid + transform(inverse_root, 0.8660254037844386 * up);
}

// try_relocate for a free vertex v with ball `ring` whose triangles (v, origin, destination) have
// the qualities `q` (the same values, bit for bit, as quality(mesh, v, a, b) now).
bool relocate_with(Mesh2& mesh, std::uint32_t v, std::span<const std::uint32_t> ring, std::span<const double> q,
                   const MetricField2& field, const RelocateOptions& options) {
  const Vec2 p = mesh.point(v);
  double before = 0.0;
  Vec2 sum{0.0, 0.0};
  double weights = 0.0;
  std::size_t worst = 0;  // the ball's worst triangle: measured first at each candidate
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::uint32_t a = mesh.origin(ring[i]), b = mesh.destination(ring[i]);
    if (q[i] > before) worst = i;
    before = std::max(before, q[i]);
    const double w = std::min(q[i], kMaxWeight);
    const Metric2 m = interpolate(mesh.metric(a), mesh.metric(b), 0.5);
    sum = sum + w * ideal_apex(mesh.point(a), mesh.point(b), m);
    weights += w;
  }
  if (!(weights > 0.0)) return false;
  const Vec2 target = (1.0 / weights) * sum;
  if (!std::isfinite(target.x) || !std::isfinite(target.y)) return false;
  // A candidate is kept when its ball's worst Q_K is below `bound`: the first triangle at or above
  // it decides the refusal (the maximum of the others could only be larger), so the triangle that
  // refused the previous candidate is measured first. The decision is the full maximum's.
  const double bound = before * (1.0 - options.margin);
  std::size_t first = worst;
  double w = 1.0;
  for (std::uint32_t k = 0; k < options.tries; ++k, w *= 0.5) {
    const Vec2 moved = (1.0 - w) * p + w * target;
    if (moved == p) break;
    bool valid = true;
    for (const std::uint32_t h : ring) {
      if (orient2d(moved, mesh.point(mesh.origin(h)), mesh.point(mesh.destination(h))) != Sign::Positive) {
        valid = false;
        break;
      }
    }
    if (!valid) continue;
    const Metric2 metric = field ? field(moved) : mesh.metric(v);
    bool better = true;
    for (std::size_t j = 0; j < ring.size() && better; ++j) {
      const std::size_t i = (first + j) % ring.size();
      const std::uint32_t a = mesh.origin(ring[i]), b = mesh.destination(ring[i]);
      // NaN never refuses (the maximum ignores it): the comparison is false.
      if (shape_quality(moved, mesh.point(a), mesh.point(b), metric, mesh.metric(a), mesh.metric(b)) >= bound) {
        better = false;
        first = i;
      }
    }
    if (better) {
      mesh.set_point(v, moved);
      mesh.set_metric(v, metric);
      return true;
    }
  }
  return false;
}

// The qualities of v's ball triangles (v, origin, destination), appended to `q`.
void ball_qualities(const Mesh2& mesh, std::uint32_t v, std::span<const std::uint32_t> ring, std::vector<double>& q) {
  for (const std::uint32_t h : ring) q.push_back(quality(mesh, v, mesh.origin(h), mesh.destination(h)));
}

}  // namespace

bool try_relocate(Mesh2& mesh, std::uint32_t v, const MetricField2& field, const RelocateOptions& options) {
  std::vector<std::uint32_t> ring;
  if (!is_free(mesh, v, ring)) return false;
  std::vector<double> q;
  ball_qualities(mesh, v, ring, q);
  return relocate_with(mesh, v, ring, q, field, options);
}

RelocationSweeps::RelocationSweeps(Mesh2& mesh, const MetricField2& field, const RelocateOptions& options)
    : mesh_(mesh), field_(field), options_(options) {}

void RelocationSweeps::measure() {
  const std::uint32_t n = mesh_.vertex_capacity();
  stale_.assign(n, 0);
  start_.assign(n + 1, 0);
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < n; ++v) {
    start_[v] = static_cast<std::uint32_t>(q_.size());
    if (!is_free(mesh_, v, ring)) continue;
    free_.push_back(v);
    rings_.insert(rings_.end(), ring.begin(), ring.end());
    ball_qualities(mesh_, v, ring, q_);
  }
  start_[n] = static_cast<std::uint32_t>(q_.size());
}

RelocationSweeps::Ball RelocationSweeps::ball(std::uint32_t v) {
  const std::size_t first = start_[v], size = start_[v + 1] - start_[v];
  const Ball b{{rings_.data() + first, size}, {q_.data() + first, size}};
  if (stale_[v]) {
    for (std::size_t i = 0; i < size; ++i)
      b.q[i] = quality(mesh_, v, mesh_.origin(b.ring[i]), mesh_.destination(b.ring[i]));
    stale_[v] = 0;
  }
  return b;
}

std::uint64_t RelocationSweeps::sweep() {
  if (start_.empty()) measure();
  // Worst ball first (ties by vertex id): the book's classification of §8.6.3.
  std::vector<std::pair<double, std::uint32_t>> order;
  order.reserve(free_.size());
  for (const std::uint32_t v : free_) {
    double worst = 0.0;
    for (const double q : ball(v).q) worst = std::max(worst, q);
    order.emplace_back(worst, v);
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::uint64_t moved = 0;
  for (const auto& entry : order) {
    const std::uint32_t v = entry.second;
    const Ball b = ball(v);
    // Every vertex is tried again, even one refused with its ball unmoved since: a field with a
    // walk hint (mesh_pipeline::metric_field) may answer in other bits after other questions.
    if (!relocate_with(mesh_, v, b.ring, b.q, field_, options_)) continue;
    ++moved;
    stale_[v] = 1;
    for (const std::uint32_t h : b.ring) stale_[mesh_.origin(h)] = 1;
  }
  return moved;
}

std::uint64_t relocate_sweep(Mesh2& mesh, const MetricField2& field, const RelocateOptions& options) {
  return RelocationSweeps(mesh, field, options).sweep();
}

}  // namespace dtlab
