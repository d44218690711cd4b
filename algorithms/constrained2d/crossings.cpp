// snap_crossings (crossings.hpp): the segments' pipes in the triangulation, candidate pairs from
// the triangles they share, exact crossing tests (orient2d), exact intersections rounded
// correctly (MPFR), then each segment's stops: the vertices exactly on it and the hot points
// whose rounding box it meets, ordered along it exactly.
#include "algorithms/constrained2d/crossings.hpp"

#include <algorithm>
#include <tuple>

#include "kernel/predicates.hpp"
#include "mesh/element_sets2.hpp"

namespace dtlab {

namespace {

using Segment = std::array<std::uint32_t, 2>;

// Each segment's pipe in the triangulation: the triangles it crosses (for an edge, or a run
// along an edge between vertices on it, the two triangles of that edge) and the vertices exactly
// on it, in order. Compressed rows per segment.
struct Pipes {
  std::vector<std::uint32_t> first{0}, triangles;
  std::vector<std::uint32_t> through_first{0}, through;
};

Pipes walk_pipes(const ConstrainedMesh2& mesh, std::span<const Segment> segments) {
  const Triangulation2& tri = mesh.tri();
  Pipes out;
  const auto add_edge = [&](std::uint32_t u, std::uint32_t v) {
    const std::uint32_t h = mesh.find_half_edge(u, v);
    if (h == ConstrainedMesh2::kNone) return false;
    out.triangles.push_back(Triangulation2::triangle_of(h));
    out.triangles.push_back(Triangulation2::triangle_of(tri.twin(h)));
    return true;
  };
  for (const auto& [a, b] : segments) {
    if (!add_edge(a, b)) {
      Pipe2 p = pipe(tri, mesh.triangle_of_vertex(a), a, b);
      out.triangles.insert(out.triangles.end(), p.triangles.begin(), p.triangles.end());
      std::uint32_t from = a;
      for (const std::uint32_t v : p.through) add_edge(from, v), from = v;
      if (!p.through.empty()) add_edge(from, b);
      out.through.insert(out.through.end(), p.through.begin(), p.through.end());
    }
    out.first.push_back(static_cast<std::uint32_t>(out.triangles.size()));
    out.through_first.push_back(static_cast<std::uint32_t>(out.through.size()));
  }
  return out;
}

// Pairs (i < j) of segments whose pipes share a triangle, each once.
std::vector<std::uint64_t> candidate_pairs(const Pipes& pipes, std::size_t triangle_count) {
  // Counting sort of (triangle, segment) by triangle.
  std::vector<std::uint32_t> start(triangle_count + 1, 0);
  for (const std::uint32_t t : pipes.triangles) ++start[t + 1];
  for (std::size_t t = 0; t < triangle_count; ++t) start[t + 1] += start[t];
  std::vector<std::uint32_t> in_triangle(pipes.triangles.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t k = 0; k + 1 < pipes.first.size(); ++k)
      for (std::uint32_t i = pipes.first[k]; i < pipes.first[k + 1]; ++i) in_triangle[fill[pipes.triangles[i]]++] = k;
  }
  std::vector<std::uint64_t> pairs;
  for (std::size_t t = 0; t < triangle_count; ++t)
    for (std::uint32_t x = start[t]; x < start[t + 1]; ++x)
      for (std::uint32_t y = x + 1; y < start[t + 1]; ++y) {
        const std::uint32_t i = in_triangle[x], j = in_triangle[y];
        if (i != j) pairs.push_back(std::uint64_t{std::min(i, j)} << 32 | std::max(i, j));
      }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

bool properly_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Sign c_side = orient2d(a, b, c), d_side = orient2d(a, b, d);
  if (c_side == Sign::Zero || d_side == Sign::Zero || c_side == d_side) return false;
  const Sign a_side = orient2d(c, d, a), b_side = orient2d(c, d, b);
  return a_side != Sign::Zero && b_side != Sign::Zero && a_side != b_side;
}

}  // namespace

std::vector<std::uint32_t> order_along_segment(const Vec2& a, const Vec2& b,
                                               std::vector<std::pair<Vec2, std::uint32_t>> stops) {
  if (stops.empty()) return {};
  const Rational ex = Rational(b.x) - Rational(a.x), ey = Rational(b.y) - Rational(a.y);
  const Rational length2 = ex * ex + ey * ey;
  std::vector<std::pair<Rational, std::uint32_t>> keyed;
  keyed.reserve(stops.size());
  for (const auto& [p, id] : stops) {
    Rational t = (Rational(p.x) - Rational(a.x)) * ex + (Rational(p.y) - Rational(a.y)) * ey;
    if (t.sign() == Sign::Positive && t < length2) keyed.emplace_back(std::move(t), id);
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  });
  std::vector<std::uint32_t> ids;
  for (const auto& [t, id] : keyed)
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  return ids;
}

SnappedCrossings snap_crossings(const ConstrainedMesh2& mesh, std::span<const Segment> segments) {
  SnappedCrossings out;
  const auto m = static_cast<std::uint32_t>(segments.size());
  const std::span<const Vec2> points = mesh.tri().points();
  const Pipes pipes = walk_pipes(mesh, segments);
  const std::vector<std::uint64_t> pairs = candidate_pairs(pipes, mesh.tri().triangle_count());

  struct Crossing {
    Vec2 point;
    ExactPoint2 exact;
    bool exact_double;
    std::uint32_t s, t;
  };
  std::vector<Crossing> crossings;
  for (const std::uint64_t pair : pairs) {
    const auto s = static_cast<std::uint32_t>(pair >> 32), t = static_cast<std::uint32_t>(pair);
    const Vec2 &a = points[segments[s][0]], &b = points[segments[s][1]];
    const Vec2 &c = points[segments[t][0]], &d = points[segments[t][1]];
    if (!properly_cross(a, b, c, d)) continue;
    ExactPoint2 exact = *line_intersection_exact(a, b, c, d);  // lines not parallel: they cross
    const RoundedPoint2 rounded = round_point_checked(exact);
    out.rounded = out.rounded || !rounded.exact;
    crossings.push_back({rounded.point, std::move(exact), rounded.exact, s, t});
  }
  // Distinct points, by coordinates; each keeps its first pair.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.point.x, x.point.y, x.s, x.t) < std::tie(y.point.x, y.point.y, y.s, y.t);
  });
  std::vector<std::vector<std::uint32_t>> own(m);  // each segment's hot points
  for (const Crossing& c : crossings) {
    if (out.hot.empty() || !(out.hot.back().point == c.point))
      out.hot.push_back({c.point, c.exact, c.exact_double, c.s, c.t});
    const auto h = static_cast<std::uint32_t>(out.hot.size() - 1);
    own[c.s].push_back(h);
    own[c.t].push_back(h);
  }

  // Neighbours: the candidate pairs, both ways (compressed rows).
  std::vector<std::uint32_t> first(m + 1, 0), near(2 * pairs.size());
  for (const std::uint64_t pair : pairs) ++first[(pair >> 32) + 1], ++first[static_cast<std::uint32_t>(pair) + 1];
  for (std::uint32_t k = 0; k < m; ++k) first[k + 1] += first[k];
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const std::uint64_t pair : pairs) {
      const auto s = static_cast<std::uint32_t>(pair >> 32), t = static_cast<std::uint32_t>(pair);
      near[fill[s]++] = t;
      near[fill[t]++] = s;
    }
  }

  out.first.assign(1, 0);
  std::vector<std::pair<Vec2, std::uint32_t>> candidates;
  for (std::uint32_t k = 0; k < m; ++k) {
    const auto [ia, ib] = segments[k];
    const Vec2 &a = points[ia], &b = points[ib];
    candidates.clear();
    for (std::uint32_t i = pipes.through_first[k]; i < pipes.through_first[k + 1]; ++i)
      candidates.emplace_back(points[pipes.through[i]], pipes.through[i]);
    for (const std::uint32_t h : own[k]) candidates.emplace_back(out.hot[h].point, SnappedCrossings::kHot | h);
    // Once a crossing is rounded, chains bend: route this one through every hot point nearby,
    // the rounded crossings of the segments it shares a triangle with and the vertices of its
    // pipe's triangles (any vertex within an ulp of it is one).
    if (out.rounded) {
      for (std::uint32_t x = first[k]; x < first[k + 1]; ++x)
        for (const std::uint32_t h : own[near[x]])
          if (rounding_box_meets_segment(out.hot[h].point, a, b))
            candidates.emplace_back(out.hot[h].point, SnappedCrossings::kHot | h);
      for (std::uint32_t i = pipes.first[k]; i < pipes.first[k + 1]; ++i)
        for (std::uint32_t c = 0; c < 3; ++c) {
          const std::uint32_t v = mesh.tri().vertex(pipes.triangles[i], c);
          if (v != Triangulation2::kInfinite && v != ia && v != ib && rounding_box_meets_segment(points[v], a, b))
            candidates.emplace_back(points[v], v);
        }
    }
    // Two stops at one point (a hot point on an input vertex): the vertex.
    std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return std::tie(x.first.x, x.first.y, x.second) < std::tie(y.first.x, y.first.y, y.second);
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (kept == 0 || !(candidates[kept - 1].first == candidates[i].first)) candidates[kept++] = candidates[i];
    candidates.resize(kept);
    const std::vector<std::uint32_t> ordered = order_along_segment(a, b, candidates);
    out.stops.insert(out.stops.end(), ordered.begin(), ordered.end());
    out.first.push_back(static_cast<std::uint32_t>(out.stops.size()));
  }
  return out;
}

}  // namespace dtlab
