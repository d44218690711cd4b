// Edge split of book §8.3.6: a point P on edge ab replaces its two triangles by four (two
// triangles and two ghosts or exterior triangles at the boundary, when boundary splits are
// allowed). P is the metric midpoint: with the length density varying geometrically from a to b
// (the interpolation behind kernel/metric.hpp edge_length), both halves have the same length.
// Its metric comes from the control space. The pass treats the longest edges first and swaps
// around each new point (§8.6.2), so the mesh stays close to Delaunay-like shapes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

using optimize2d_detail::edge_length;
using optimize2d_detail::is_locked;
using optimize2d_detail::NewTriangle;

namespace {

// s in (0, 1) with a + s (b - a) the metric midpoint: the length from a to a + s(b - a) is
// l_a (r^s - 1) / ln r (r = l_b / l_a), half of the whole (l_b - l_a) / ln r at r^s = (1 + r) / 2.
double midpoint_parameter(const Vec2& a, const Metric2& ma, const Vec2& b, const Metric2& mb) noexcept {
  const double la = ma.length(b - a), lb = mb.length(b - a);
  if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la) || !std::isfinite(lb)) return 0.5;
  const double r = lb / la;
  if (std::fabs(r - 1.0) < 1e-9) return 0.5;
  return std::log((1.0 + r) / 2.0) / std::log(r);
}

}  // namespace

Vec2 metric_midpoint(const Vec2& a, const Metric2& ma, const Vec2& b, const Metric2& mb) noexcept {
  const double s = midpoint_parameter(a, ma, b, mb);
  return a + s * (b - a);
}

std::uint32_t try_split(Mesh2& mesh, std::uint32_t h, const MetricField2& field, const SplitOptions& options,
                        bool* fell_back) {
  if (fell_back != nullptr) *fell_back = false;
  if (!mesh.in_domain(Mesh2::triangle_of(h))) {
    h = mesh.twin(h);
    if (!mesh.in_domain(Mesh2::triangle_of(h))) return Mesh2::kNone;
  }
  const bool locked = is_locked(mesh, h);
  if (locked && !options.boundary) return Mesh2::kNone;
  const std::uint32_t g = mesh.twin(h);
  const std::uint32_t t1 = Mesh2::triangle_of(h), t2 = Mesh2::triangle_of(g);
  // t1 = (p, a, b), t2 = (q, b, a); q is kInfinite when t2 is a ghost (its vertex 0).
  const std::uint32_t p = mesh.vertex_at(h), a = mesh.origin(h), b = mesh.destination(h), q = mesh.vertex_at(g);
  const double s = midpoint_parameter(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b));
  Vec2 at = mesh.point(a) + s * (mesh.point(b) - mesh.point(a));
  // The four new triangles, checked before anything changes (P is rounded: it may be a hair off ab).
  auto valid = [&](const Vec2& x) {
    if (x == mesh.point(a) || x == mesh.point(b)) return false;
    auto positive = [&](std::uint32_t u, std::uint32_t w) {
      return orient2d(mesh.point(u), mesh.point(w), x) == Sign::Positive;
    };
    // (p, a, P) and (p, P, b) positive: P strictly left of p -> a and right of p -> b.
    if (!positive(p, a) || !positive(b, p)) return false;
    return q == Mesh2::kInfinite || (positive(q, b) && positive(a, q));
  };
  bool chord = true;
  if (locked && options.boundary_point && mesh.is_constrained(h)) {
    const Vec2 on_support = options.boundary_point(mesh, h, s);
    if (valid(on_support)) {
      at = on_support;
      chord = false;
    }
    if (fell_back != nullptr) *fell_back = chord;
  }
  if (chord && !valid(at)) return Mesh2::kNone;
  if (!coordinate_in_range(at.x) || !coordinate_in_range(at.y)) return Mesh2::kNone;
  const Metric2 metric = field ? field(at) : interpolate(mesh.metric(a), mesh.metric(b), s);
  // No spoke shorter than the unit bound: near an edge that may not be split (the input's
  // boundary) the triangles would otherwise be split again and again, ever flatter.
  for (const std::uint32_t opposite : {p, q}) {
    if (opposite == Mesh2::kInfinite) continue;
    const double spoke = dtlab::edge_length(at, metric, mesh.point(opposite), mesh.metric(opposite));
    if (!(spoke >= options.short_length)) return Mesh2::kNone;
  }
  // Beside an edge that may not be split (a long boundary edge) each split would leave flatter
  // triangles than the last, without end: a split that makes the pair worse than max(old worst,
  // quality_limit) is taken only if every new triangle keeps an altitude of min_height in the
  // metric at P. Splits that make the pair worse but stay thick are what refinement needs:
  // the swaps that follow improve them.
  double before = 0.0, after = 0.0, lowest = std::numeric_limits<double>::infinity();
  for (const std::uint32_t t : {t1, t2}) {
    if (mesh.in_domain(t)) before = std::max(before, optimize2d_detail::triangle_quality(mesh, t));
  }
  const std::uint32_t corners[4][2] = {{p, a}, {b, p}, {q, b}, {a, q}};  // (o, e, P) counter-clockwise
  const double root_det = std::sqrt(std::max(0.0, metric.determinant()));
  for (int k = 0; k < 4; ++k) {
    if (!mesh.in_domain(k < 2 ? t1 : t2)) continue;
    const Vec2 &o = mesh.point(corners[k][0]), &e = mesh.point(corners[k][1]);
    after = std::max(after, shape_quality(o, e, at, mesh.metric(corners[k][0]), mesh.metric(corners[k][1]), metric));
    const double longest = std::max({metric.length(e - o), metric.length(at - e), metric.length(o - at)});
    lowest = std::min(lowest, root_det * std::fabs(cross(e - o, at - o)) / longest);  // 2 area / base
  }
  const bool guarded = !(edge_length(mesh, a, b) > options.unguarded_length);
  if (guarded && !(after <= std::max(before, options.quality_limit)) && !(lowest >= options.min_height)) return Mesh2::kNone;
  const bool constrained = mesh.is_constrained(h);
  const int edge_ref = mesh.edge_ref(h);
  const std::uint32_t v = mesh.add_vertex(at, metric, constrained ? Mesh2::kOnBoundary : 0);
  const int r1 = mesh.ref(t1), r2 = mesh.ref(t2);
  const NewTriangle created[4] = {{p, a, v, r1}, {p, v, b, r1}, {q, b, v, r2}, {q, v, a, r2}};
  const std::uint32_t old_triangles[2] = {t1, t2};
  std::vector<MeshEdge2> halves;
  if (constrained) halves = {{a, v, edge_ref}, {v, b, edge_ref}};
  std::vector<std::uint32_t> slots;
  optimize2d_detail::replace_triangles(mesh, old_triangles, created, halves, slots);
  return v;
}

SplitPassResult split_pass(Mesh2& mesh, const MetricField2& field, const SplitOptions& options) {
  SplitPassResult result;
  // Longest first; ties by the vertex pair (deterministic).
  using Entry = std::tuple<double, std::uint32_t, std::uint32_t>;
  auto later = [](const Entry& x, const Entry& y) {
    if (std::get<0>(x) != std::get<0>(y)) return std::get<0>(x) < std::get<0>(y);
    return std::tie(std::get<1>(x), std::get<2>(x)) > std::tie(std::get<1>(y), std::get<2>(y));
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
  auto consider = [&](std::uint32_t h) {
    const std::uint32_t t = Mesh2::triangle_of(h), u = Mesh2::triangle_of(mesh.twin(h));
    if (!mesh.in_domain(t) && !mesh.in_domain(u)) return;
    if (!options.boundary && is_locked(mesh, h)) return;
    const std::uint32_t x = mesh.origin(h), y = mesh.destination(h);
    if (x == Mesh2::kInfinite || y == Mesh2::kInfinite) return;
    const double length = edge_length(mesh, x, y);
    if (length > options.long_length) queue.emplace(length, std::min(x, y), std::max(x, y));
  };
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      // Each edge once: from its smaller half-edge, or from the domain side at the boundary.
      if (mesh.twin(h) > h || !mesh.in_domain(Mesh2::triangle_of(mesh.twin(h)))) consider(h);
    }
  }
  std::vector<std::uint32_t> ring;
  std::vector<std::uint32_t> seeds;
  while (!queue.empty()) {
    const std::uint32_t x = std::get<1>(queue.top()), y = std::get<2>(queue.top());
    queue.pop();
    if (mesh.is_dead_vertex(x) || mesh.is_dead_vertex(y)) continue;
    const std::uint32_t h = mesh.find_half_edge(x, y);
    if (h == Mesh2::kNone) continue;
    if (mesh.live_vertex_count() >= options.max_vertices) {
      result.limit_reached = true;
      break;
    }
    bool fell_back = false;
    const std::uint32_t v = try_split(mesh, h, field, options, &fell_back);
    if (v == Mesh2::kNone) continue;
    ++result.splits;
    if (fell_back) ++result.support_fallbacks;
    // Swaps on the edges of the new triangles (the ring of v and its spokes).
    mesh.ball(v, ring);
    seeds.clear();
    for (const std::uint32_t e : ring) {
      seeds.push_back(e);
      seeds.push_back(Mesh2::prev(e));
    }
    result.swaps += swap_pass(mesh, options.swap_margin, seeds).swaps;
    mesh.ball(v, ring);
    for (const std::uint32_t e : ring) {
      if (mesh.origin(e) != Mesh2::kInfinite) consider(Mesh2::prev(e));  // v -> origin(e)
    }
  }
  return result;
}

}  // namespace dtlab
