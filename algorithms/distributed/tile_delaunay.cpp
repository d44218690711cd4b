#include "algorithms/distributed/tile_delaunay.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"

namespace dtlab {
namespace {

// What one triangulation of the known points gives: elements (local ids, positive) and the
// hull facets with the inner vertex of the element behind each.
template <int kDim>
struct Local {
  std::vector<std::array<std::uint32_t, kDim + 1>> elements;
  std::vector<std::array<std::uint32_t, kDim + 1>> hull;  // facet (kDim ids), then the inner vertex
  std::string degenerate;
};

Local<2> triangulate(std::span<const Vec2> points) {
  Local<2> out;
  const Delaunay2dResult r = delaunay2d(points);
  out.degenerate = r.degenerate_message;
  const Triangulation2& t = r.triangulation;
  for (std::uint32_t k = 0; k < t.triangle_count(); ++k) {
    if (t.is_ghost(k)) continue;
    out.elements.push_back({t.vertex(k, 0), t.vertex(k, 1), t.vertex(k, 2)});
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (!t.is_ghost(t.adjacent(k, i))) continue;
      out.hull.push_back({t.vertex(k, (i + 1) % 3), t.vertex(k, (i + 2) % 3), t.vertex(k, i)});
    }
  }
  return out;
}

Local<3> triangulate(std::span<const Vec3> points) {
  Local<3> out;
  const Delaunay3dResult r = delaunay3d(points);
  out.degenerate = r.degenerate_message;
  const Tetrahedralization3& t = r.tetrahedralization;
  for (std::uint32_t k = 0; k < t.tetrahedron_count(); ++k) {
    if (t.is_ghost(k)) continue;
    out.elements.push_back({t.vertex(k, 0), t.vertex(k, 1), t.vertex(k, 2), t.vertex(k, 3)});
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (!t.is_ghost(t.adjacent(k, i))) continue;
      const auto f = t.facet_vertices(Tetrahedralization3::facet(k, i));
      out.hull.push_back({f[0], f[1], f[2], t.vertex(k, i)});
    }
  }
  return out;
}

// Exact: p in conflict with the element (strictly inside its perturbed circumball).
bool in_conflict(const std::array<Vec2, 3>& e, const Vec2& p) {
  return incircle_perturbed(e[0], e[1], e[2], p) == Sign::Positive;
}
bool in_conflict(const std::array<Vec3, 4>& e, const Vec3& p) {
  return insphere_perturbed(e[0], e[1], e[2], e[3], p) == Sign::Positive;
}
// Exact: p on the hull facet's line / plane or on the other side than the inner vertex.
bool beyond(const std::array<Vec2, 3>& f, const Vec2& p) {
  const Sign s = orient2d(f[0], f[1], p);
  return s == Sign::Zero || s != orient2d(f[0], f[1], f[2]);
}
bool beyond(const std::array<Vec3, 4>& f, const Vec3& p) {
  const Sign s = orient3d(f[0], f[1], f[2], p);
  return s == Sign::Zero || s != orient3d(f[0], f[1], f[2], f[3]);
}

// A ball sure to hold the element's circumball, in doubles: the circumcentre by Cramer's rule and
// the largest distance to a vertex, widened by a margin; not finite for a near-flat element (the
// caller then asks and searches everywhere).
struct Ball2 {
  Vec2 centre;
  double radius;
};
Ball2 safe_ball(const std::array<Vec2, 3>& e) {
  const Vec2 b = e[1] - e[0], c = e[2] - e[0];
  const double d = 2.0 * (b.x * c.y - b.y * c.x);
  const double bb = b.x * b.x + b.y * b.y, cc = c.x * c.x + c.y * c.y;
  const Vec2 o = e[0] + Vec2{(c.y * bb - b.y * cc) / d, (b.x * cc - c.x * bb) / d};
  double r = 0.0;
  for (const Vec2& v : e) r = std::max(r, norm(v - o));
  const double scale = std::max(bb, cc);
  if (!(std::abs(d) * std::sqrt(scale) > 1e-10 * scale * std::sqrt(scale)) || !std::isfinite(r))
    return {o, std::numeric_limits<double>::infinity()};
  return {o, r * (1.0 + 1e-6) + 1e-300};
}
struct Ball3 {
  Vec3 centre;
  double radius;
};
Ball3 safe_ball(const std::array<Vec3, 4>& e) {
  const Vec3 b = e[1] - e[0], c = e[2] - e[0], d = e[3] - e[0];
  const Vec3 cd = cross(c, d), db = cross(d, b), bc = cross(b, c);
  const double det = 2.0 * dot(b, cd);
  const double bb = dot(b, b), cc = dot(c, c), dd = dot(d, d);
  const Vec3 o = e[0] + (1.0 / det) * (bb * cd + cc * db + dd * bc);
  double r = 0.0;
  for (const Vec3& v : e) r = std::max(r, norm(v - o));
  const double scale = std::max({bb, cc, dd});
  if (!(std::abs(det) > 1e-10 * scale * std::sqrt(scale)) || !std::isfinite(r))
    return {o, std::numeric_limits<double>::infinity()};
  return {o, r * (1.0 + 1e-6) + 1e-300};
}

// Squared distance from a point to a box (0 inside).
double box_distance2(const TileBox<Vec2>& box, const Vec2& p) {
  const double dx = std::max({box.lo.x - p.x, 0.0, p.x - box.hi.x});
  const double dy = std::max({box.lo.y - p.y, 0.0, p.y - box.hi.y});
  return dx * dx + dy * dy;
}
double box_distance2(const TileBox<Vec3>& box, const Vec3& p) {
  const double dx = std::max({box.lo.x - p.x, 0.0, p.x - box.hi.x});
  const double dy = std::max({box.lo.y - p.y, 0.0, p.y - box.hi.y});
  const double dz = std::max({box.lo.z - p.z, 0.0, p.z - box.hi.z});
  return dx * dx + dy * dy + dz * dz;
}
template <class Ball, class Box>
bool ball_meets(const Ball& ball, const Box& box) {
  if (box.empty) return false;
  if (!std::isfinite(ball.radius)) return true;
  return box_distance2(box, ball.centre) <= ball.radius * ball.radius;
}

// Whether some corner of the box is on or beyond the hull facet's line / plane (in doubles, with
// a margin: a tile asked for nothing answers nothing).
bool box_beyond(const TileBox<Vec2>& box, const std::array<Vec2, 3>& f) {
  if (box.empty) return false;
  const Vec2 t = f[1] - f[0];
  Vec2 n{t.y, -t.x};
  if (dot(n, f[2] - f[0]) > 0) n = -1.0 * n;  // away from the inner vertex
  const double margin = 1e-9 * (norm(n) * (norm(t) + norm(box.hi - box.lo)) + 1e-300);
  for (const double x : {box.lo.x, box.hi.x})
    for (const double y : {box.lo.y, box.hi.y})
      if (dot(n, Vec2{x, y} - f[0]) >= -margin) return true;
  return false;
}
bool box_beyond(const TileBox<Vec3>& box, const std::array<Vec3, 4>& f) {
  if (box.empty) return false;
  Vec3 n = cross(f[1] - f[0], f[2] - f[0]);
  if (dot(n, f[3] - f[0]) > 0) n = -1.0 * n;
  const double margin = 1e-9 * (norm(n) * (norm(f[1] - f[0]) + norm(box.hi - box.lo)) + 1e-300);
  for (const double x : {box.lo.x, box.hi.x})
    for (const double y : {box.lo.y, box.hi.y})
      for (const double z : {box.lo.z, box.hi.z})
        if (dot(n, Vec3{x, y, z} - f[0]) >= -margin) return true;
  return false;
}

template <class Vec>
bool inside_ball(const Vec& p, const Vec& centre, double radius) {
  return !std::isfinite(radius) || norm(p - centre) <= radius;
}

}  // namespace

template <std::size_t K>
std::array<std::uint32_t, K> canonical_element(std::array<std::uint32_t, K> e) {
  const auto m = static_cast<std::size_t>(std::min_element(e.begin(), e.end()) - e.begin());
  if constexpr (K == 3) {
    std::rotate(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(m), e.end());
  } else {
    static_assert(K == 4);
    // Bring the lowest to the front by one swap, and keep the parity by a second among the rest.
    if (m != 0) {
      std::swap(e[0], e[m]);
      const std::size_t a = m == 1 ? 2 : 1, b = m == 3 ? 2 : 3;
      std::swap(e[a], e[b]);
    }
    // Rotate the other three (an even permutation) so that the lowest of them comes second.
    const auto k = static_cast<std::size_t>(std::min_element(e.begin() + 1, e.end()) - e.begin());
    std::rotate(e.begin() + 1, e.begin() + static_cast<std::ptrdiff_t>(k), e.end());
  }
  return e;
}
template std::array<std::uint32_t, 3> canonical_element(std::array<std::uint32_t, 3>);
template std::array<std::uint32_t, 4> canonical_element(std::array<std::uint32_t, 4>);

template <int kDim>
TileDelaunay<kDim>::TileDelaunay(std::uint32_t tile, std::vector<TileBox<Vec>> boxes, std::vector<std::uint32_t> own_ids,
                                 std::vector<Vec> own_points)
    : tile_(tile), boxes_(std::move(boxes)), own_ids_(std::move(own_ids)), own_points_(std::move(own_points)) {
  if (tile_ >= boxes_.size()) throw InputError("TileDelaunay: tile " + std::to_string(tile_) + " of " +
                                               std::to_string(boxes_.size()));
  if (own_ids_.size() != own_points_.size()) throw InputError("TileDelaunay: ids and points differ in number");
  if (!std::is_sorted(own_ids_.begin(), own_ids_.end())) throw InputError("TileDelaunay: own ids not ascending");
  sent_.assign(boxes_.size(), std::vector<std::uint8_t>(own_ids_.size(), 0));
}

template <int kDim>
auto TileDelaunay<kDim>::triangulate_and_ask() -> std::vector<std::vector<Question>> {
  const auto start = std::chrono::steady_clock::now();
  ++counts_.rounds;
  // The known points in ascending id (a duplicate keeps its lowest id, as in the sequential call).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // (id, index: own < n, else ghost)
  order.reserve(own_ids_.size() + ghosts_.size());
  for (std::uint32_t i = 0; i < own_ids_.size(); ++i) order.push_back({own_ids_[i], i});
  for (std::uint32_t g = 0; g < ghosts_.size(); ++g)
    order.push_back({ghosts_[g].id, static_cast<std::uint32_t>(own_ids_.size()) + g});
  std::sort(order.begin(), order.end());
  std::vector<Vec> points(order.size());
  local_ids_.resize(order.size());
  local_tiles_.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t i = order[k].second;
    const bool own = i < own_ids_.size();
    points[k] = own ? own_points_[i] : ghosts_[i - own_ids_.size()].point;
    local_ids_[k] = order[k].first;
    local_tiles_[k] = own ? tile_ : ghosts_[i - own_ids_.size()].tile;
  }
  Local<kDim> local = triangulate(std::span<const Vec>(points));
  degenerate_ = local.degenerate;
  local_elements_ = std::move(local.elements);
  counts_.seconds_triangulating += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::vector<Question>> ask(boxes_.size());
  const auto has_own = [&](const auto& ids, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      if (local_tiles_[ids[i]] == tile_) return true;
    return false;
  };
  if (local_elements_.empty() && !own_ids_.empty()) {
    // Too few or degenerate: everything the others have may matter.
    for (std::uint32_t s = 0; s < boxes_.size(); ++s)
      if (s != tile_ && !boxes_[s].empty) ask[s].push_back(Question{Question::Everything, {}});
  }
  for (const auto& e : local_elements_) {
    if (!has_own(e, kDim + 1)) continue;
    Question q{Question::Ball, {}};
    for (int i = 0; i <= kDim; ++i) q.points[i] = points[e[i]];
    const auto ball = safe_ball(q.points);
    for (std::uint32_t s = 0; s < boxes_.size(); ++s)
      if (s != tile_ && ball_meets(ball, boxes_[s])) ask[s].push_back(q);
  }
  for (const auto& h : local.hull) {
    if (!has_own(h, kDim)) continue;
    Question q{Question::Beyond, {}};
    for (int i = 0; i <= kDim; ++i) q.points[i] = points[h[i]];
    for (std::uint32_t s = 0; s < boxes_.size(); ++s)
      if (s != tile_ && box_beyond(boxes_[s], q.points)) ask[s].push_back(q);
  }
  for (const auto& a : ask) counts_.questions_sent += a.size();
  return ask;
}

template <int kDim>
auto TileDelaunay<kDim>::answer(const std::vector<std::vector<Question>>& questions) -> std::vector<std::vector<Ghost>> {
  if (questions.size() != boxes_.size()) throw InputError("TileDelaunay::answer: one list per tile expected");
  std::vector<std::vector<Ghost>> out(boxes_.size());
  for (std::uint32_t s = 0; s < questions.size(); ++s) {
    std::vector<std::uint8_t>& sent = sent_[s];
    for (const Question& q : questions[s]) {
      const auto ball = q.kind == Question::Ball ? safe_ball(q.points) : decltype(safe_ball(q.points)){};
      for (std::uint32_t i = 0; i < own_points_.size(); ++i) {
        if (sent[i]) continue;
        const Vec& p = own_points_[i];
        bool send = false;
        switch (q.kind) {
          case Question::Ball: send = inside_ball(p, ball.centre, ball.radius) && in_conflict(q.points, p); break;
          case Question::Beyond: send = beyond(q.points, p); break;
          case Question::Everything: send = true; break;
          default: throw InputError("TileDelaunay::answer: unknown question kind " + std::to_string(q.kind));
        }
        if (!send) continue;
        sent[i] = 1;
        out[s].push_back(Ghost{own_ids_[i], tile_, p});
        ++counts_.ghosts_sent;
      }
    }
  }
  return out;
}

template <int kDim>
bool TileDelaunay<kDim>::receive(const std::vector<std::vector<Ghost>>& ghosts) {
  bool any = false;
  for (const auto& from : ghosts) {
    for (const Ghost& g : from) {
      ghosts_.push_back(g);
      any = true;
    }
    counts_.ghosts += from.size();
  }
  return any;
}

template <int kDim>
auto TileDelaunay<kDim>::owned_elements() const -> std::vector<Element> {
  std::vector<Element> out;
  for (const auto& e : local_elements_) {
    // Local ids ascend with global ids: the lowest local id is the lowest global one.
    const std::uint32_t lowest = *std::min_element(e.begin(), e.end());
    if (local_tiles_[lowest] != tile_) continue;
    Element g;
    for (int i = 0; i <= kDim; ++i) g[i] = local_ids_[e[i]];
    out.push_back(canonical_element(g));
  }
  std::sort(out.begin(), out.end());
  return out;
}

template class TileDelaunay<2>;
template class TileDelaunay<3>;

}  // namespace dtlab
