// Vertex relocation of book §8.4.1: the optimal point P* of the ball of P ("optimal shape
// relocation", (8.17), after Brière de l'Isle and George 1995) is the mean of the ideal points
// I_j of the ring edges, each I_j the apex of the triangle that is equilateral in the edge's
// metric, weighted by the current Q_Kj (the book's choice a_j = Q_Kj: the worse triangles pull
// harder). The sub-relaxation (8.13) P' = (1 - w) P + w P* tries w = 1, 1/2, ... and keeps the
// first P' whose ball is valid (exact orient2d) and better (worst Q_K, in the metric at P').
#include <algorithm>
#include <cmath>
#include <utility>

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

}  // namespace

bool try_relocate(Mesh2& mesh, std::uint32_t v, const MetricField2& field, const RelocateOptions& options) {
  std::vector<std::uint32_t> ring;
  if (!is_free(mesh, v, ring)) return false;
  const Vec2 p = mesh.point(v);
  double before = 0.0;
  Vec2 sum{0.0, 0.0};
  double weights = 0.0;
  for (const std::uint32_t h : ring) {
    const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
    const double q = quality(mesh, v, a, b);
    before = std::max(before, q);
    const double w = std::min(q, kMaxWeight);
    const Metric2 m = interpolate(mesh.metric(a), mesh.metric(b), 0.5);
    sum = sum + w * ideal_apex(mesh.point(a), mesh.point(b), m);
    weights += w;
  }
  if (!(weights > 0.0)) return false;
  const Vec2 target = (1.0 / weights) * sum;
  if (!std::isfinite(target.x) || !std::isfinite(target.y)) return false;
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
    double after = 0.0;
    for (const std::uint32_t h : ring) {
      const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
      after = std::max(after, shape_quality(moved, mesh.point(a), mesh.point(b), metric, mesh.metric(a), mesh.metric(b)));
    }
    if (after < before * (1.0 - options.margin)) {
      mesh.set_point(v, moved);
      mesh.set_metric(v, metric);
      return true;
    }
  }
  return false;
}

std::uint64_t relocate_sweep(Mesh2& mesh, const MetricField2& field, const RelocateOptions& options) {
  // Worst ball first (ties by vertex id): the book's classification of §8.6.3.
  std::vector<std::pair<double, std::uint32_t>> order;
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!is_free(mesh, v, ring)) continue;
    double worst = 0.0;
    for (const std::uint32_t h : ring) worst = std::max(worst, quality(mesh, v, mesh.origin(h), mesh.destination(h)));
    order.emplace_back(worst, v);
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::uint64_t moved = 0;
  for (const auto& entry : order) moved += try_relocate(mesh, entry.second, field, options) ? 1 : 0;
  return moved;
}

}  // namespace dtlab
