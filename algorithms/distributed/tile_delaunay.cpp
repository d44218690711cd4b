#include "algorithms/distributed/tile_delaunay.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/distributed/coordinates.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"
#include "mesh/canonical_element.hpp"

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

// The elements and hull facets of a triangulation (Triangulation2 or Tetrahedralization3: the
// same navigation, kDim + 1 vertices an element, element k's side i opposite its vertex i).
template <int kDim, class Structure>
Local<kDim> elements_and_hull(const Structure& t, std::size_t count, std::string degenerate) {
  Local<kDim> out;
  out.degenerate = std::move(degenerate);
  for (std::uint32_t k = 0; k < count; ++k) {
    if (t.is_ghost(k)) continue;
    std::array<std::uint32_t, kDim + 1> e;
    for (std::uint32_t i = 0; i <= kDim; ++i) e[i] = t.vertex(k, i);
    out.elements.push_back(e);
    for (std::uint32_t i = 0; i <= kDim; ++i) {
      if (!t.is_ghost(t.adjacent(k, i))) continue;
      if constexpr (kDim == 2) {
        out.hull.push_back({e[(i + 1) % 3], e[(i + 2) % 3], e[i]});
      } else {
        const auto f = t.facet_vertices(Tetrahedralization3::facet(k, i));
        out.hull.push_back({f[0], f[1], f[2], e[i]});
      }
    }
  }
  return out;
}

Local<2> triangulate(std::span<const Vec2> points) {
  const Delaunay2dResult r = delaunay2d(points);
  return elements_and_hull<2>(r.triangulation, r.triangulation.triangle_count(), r.degenerate_message);
}
Local<3> triangulate(std::span<const Vec3> points) {
  const Delaunay3dResult r = delaunay3d(points);
  return elements_and_hull<3>(r.tetrahedralization, r.tetrahedralization.tetrahedron_count(), r.degenerate_message);
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
  double r2 = 0.0;
  for (const Vec2& v : e) r2 = std::max(r2, dot(v - o, v - o));
  const double r = std::sqrt(r2);
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
  double r2 = 0.0;
  for (const Vec3& v : e) r2 = std::max(r2, dot(v - o, v - o));
  const double r = std::sqrt(r2);
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

constexpr std::uint32_t kNoPoint = 0xFFFFFFFFu;
constexpr std::size_t kPerBall = 2;

using distributed::coordinate;
using distributed::kDimOf;
using distributed::set_coordinate;

// A uniform grid over a tile's own points, about two points a cell, for the ball questions.
template <class Vec>
class PointGrid {
 public:
  static constexpr int kD = kDimOf<Vec>;
  explicit PointGrid(std::span<const Vec> points) {
    if (points.empty()) return;
    for (int a = 0; a < kD; ++a) lo_[a] = hi_[a] = coordinate(points[0], a);
    for (const Vec& p : points) {
      for (int a = 0; a < kD; ++a) {
        lo_[a] = std::min(lo_[a], coordinate(p, a));
        hi_[a] = std::max(hi_[a], coordinate(p, a));
      }
    }
    const double per_side = std::max(1.0, std::floor(std::pow(double(points.size()) / 2.0, 1.0 / kD)));
    std::size_t cells = 1;
    for (int a = 0; a < kD; ++a) {
      n_[a] = hi_[a] > lo_[a] ? static_cast<std::uint32_t>(std::min(per_side, 1024.0)) : 1u;
      scale_[a] = hi_[a] > lo_[a] ? n_[a] / (hi_[a] - lo_[a]) : 0.0;
      cells *= n_[a];
    }
    start_.assign(cells + 1, 0);
    std::vector<std::uint32_t> cell_of(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) ++start_[(cell_of[i] = cell(points[i])) + 1];
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    ids_.resize(points.size());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < points.size(); ++i) ids_[next[cell_of[i]]++] = i;
  }
  // Visits the cells that meet the box [lo, hi] ring by ring (Chebyshev distance in cells) around
  // the cell of `centre`: point(i) for every point of a cell that cell_ok(cell_lo, cell_hi)
  // accepts; after ring r, stops when done(r) says so. Bounded by the cells in the box.
  template <class CellOk, class PointFn, class Done>
  void visit_rings(const Vec& centre, const Vec& lo, const Vec& hi, CellOk cell_ok, PointFn point, Done done) const {
    if (ids_.empty()) return;
    std::array<std::int64_t, 3> first{}, last{}, c{};
    for (int a = 0; a < kD; ++a) {
      if (coordinate(hi, a) < lo_[a] || coordinate(lo, a) > hi_[a]) return;
      first[a] = index(coordinate(lo, a), a);
      last[a] = index(coordinate(hi, a), a);
      c[a] = std::clamp<std::int64_t>(index(coordinate(centre, a), a), first[a], last[a]);
    }
    std::int64_t rings = 0;
    for (int a = 0; a < kD; ++a) rings = std::max({rings, c[a] - first[a], last[a] - c[a]});
    for (std::int64_t r = 0; r <= rings; ++r) {
      const auto from = [&](int a) { return std::max(first[a], c[a] - r); };
      const auto to = [&](int a) { return std::min(last[a], c[a] + r); };
      const std::int64_t z0 = kD == 3 ? from(2) : 0, z1 = kD == 3 ? to(2) : 0;
      for (std::int64_t z = z0; z <= z1; ++z) {
        const bool z_on_ring = kD == 3 && std::abs(z - c[2]) == r;
        for (std::int64_t y = from(1); y <= to(1); ++y) {
          const bool whole_row = z_on_ring || std::abs(y - c[1]) == r;
          if (whole_row || r == 0) {
            for (std::int64_t x = from(0); x <= to(0); ++x) visit_cell({x, y, z}, cell_ok, point);
          } else {  // only the row's two ends are on the ring
            if (c[0] - r >= first[0]) visit_cell({c[0] - r, y, z}, cell_ok, point);
            if (c[0] + r <= last[0]) visit_cell({c[0] + r, y, z}, cell_ok, point);
          }
        }
      }
      if (done(r)) return;
    }
  }

 private:
  template <class CellOk, class PointFn>
  void visit_cell(const std::array<std::int64_t, 3>& k, CellOk& cell_ok, PointFn& point) const {
    Vec cell_lo{}, cell_hi{};
    for (int a = 0; a < kD; ++a) {
      const double l = scale_[a] > 0 ? lo_[a] + static_cast<double>(k[a]) / scale_[a] : lo_[a];
      const double h = scale_[a] > 0 ? lo_[a] + static_cast<double>(k[a] + 1) / scale_[a] : hi_[a];
      set_coordinate(cell_lo, a, l);
      set_coordinate(cell_hi, a, h);
    }
    if (!cell_ok(cell_lo, cell_hi)) return;
    const std::size_t cell = (static_cast<std::size_t>(k[2]) * n_[1] + static_cast<std::size_t>(k[1])) * n_[0] +
                             static_cast<std::size_t>(k[0]);
    for (std::uint32_t j = start_[cell]; j < start_[cell + 1]; ++j) point(ids_[j]);
  }
  std::uint32_t index(double v, int a) const {
    const double t = std::floor((v - lo_[a]) * scale_[a]);
    return t <= 0 ? 0u : t >= n_[a] - 1 ? n_[a] - 1 : static_cast<std::uint32_t>(t);
  }
  std::uint32_t cell(const Vec& p) const {
    std::uint32_t c = 0;
    for (int a = kD - 1; a >= 0; --a) c = c * n_[a] + index(coordinate(p, a), a);
    return c;
  }
  std::array<double, 3> lo_{}, hi_{}, scale_{};
  std::array<std::uint32_t, 3> n_{1, 1, 1};
  std::vector<std::uint32_t> start_, ids_;
};

}  // namespace

std::array<std::uint32_t, 3> canonical_element(const std::array<std::uint32_t, 3>& e) { return canonical_triangle(e); }
std::array<std::uint32_t, 4> canonical_element(const std::array<std::uint32_t, 4>& e) { return canonical_tetrahedron(e); }

template <int kDim>
TileDelaunay<kDim>::TileDelaunay(std::uint32_t tile, std::vector<TileBox<Vec>> boxes, std::vector<std::uint32_t> own_ids,
                                 std::vector<Vec> own_points)
    : tile_(tile), boxes_(std::move(boxes)), own_ids_(std::move(own_ids)), own_points_(std::move(own_points)) {
  if (tile_ >= boxes_.size()) throw InputError("TileDelaunay: tile " + std::to_string(tile_) + " of " +
                                               std::to_string(boxes_.size()));
  if (own_ids_.size() != own_points_.size()) throw InputError("TileDelaunay: ids and points differ in number");
  if (!std::is_sorted(own_ids_.begin(), own_ids_.end())) throw InputError("TileDelaunay: own ids not ascending");
  sent_.assign(boxes_.size(), std::vector<std::uint8_t>(own_ids_.size(), 0));
  answered_empty_.resize(boxes_.size());
}

// The own points' hull vertices (all points on the hull's boundary, collinear and coplanar ones
// included) are what the hull questions of other tiles are answered from: every own point when
// they are too few or flat to have a hull.
template <int kDim>
void TileDelaunay<kDim>::find_own_hull() {
  const Local<kDim> own = triangulate(std::span<const Vec>(own_points_));
  std::vector<std::uint8_t> on_hull(own_ids_.size(), own.elements.empty() ? 1 : 0);
  for (const auto& h : own.hull)
    for (int i = 0; i < kDim; ++i) on_hull[h[i]] = 1;
  for (std::uint32_t i = 0; i < own_ids_.size(); ++i)
    if (on_hull[i]) own_hull_.push_back(i);
  own_hull_known_ = true;
}

template <int kDim>
auto TileDelaunay<kDim>::seed() -> std::vector<std::vector<Ghost>> {
  std::vector<std::vector<Ghost>> out(boxes_.size());
  const TileBox<Vec>& own = boxes_[tile_];
  if (own.empty || own_ids_.size() < 2) return out;
  // The mean spacing: the side of the box's share per point (the longest side over the count
  // for a flat box).
  const Vec side = own.hi - own.lo;
  double volume = side.x * side.y, longest = std::max(side.x, side.y);
  if constexpr (kDim == 3) volume *= side.z, longest = std::max(longest, side.z);
  const double n = static_cast<double>(own_ids_.size());
  const double spacing = volume > 0 ? std::pow(volume / n, 1.0 / kDim) : longest / n;
  const double reach2 = (kSeedLayers * spacing) * (kSeedLayers * spacing);
  for (std::uint32_t s = 0; s < boxes_.size(); ++s) {
    if (s == tile_ || boxes_[s].empty) continue;
    for (std::uint32_t i = 0; i < own_points_.size(); ++i) {
      if (box_distance2(boxes_[s], own_points_[i]) > reach2) continue;
      sent_[s][i] = 1;
      out[s].push_back(Ghost{own_ids_[i], tile_, own_points_[i]});
      ++counts_.ghosts_sent;
    }
  }
  return out;
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
  if (!own_hull_known_) find_own_hull();

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
  // An element asked about in an earlier round and still there had every answer
  // empty (a point sent in conflict with it would have removed it), and the answers stay empty:
  // only new ones are asked.
  const auto first_time = [&](const auto& local_ids) {
    Element key;
    for (int i = 0; i <= kDim; ++i) key[i] = local_ids_[local_ids[i]];
    std::sort(key.begin(), key.end());
    return asked_.insert(key).second;
  };
  std::vector<std::uint32_t> targets;
  for (const auto& e : local_elements_) {
    if (!has_own(e, kDim + 1)) continue;
    Question q{Question::Ball, {}};
    for (int i = 0; i <= kDim; ++i) q.points[i] = points[e[i]];
    const auto ball = safe_ball(q.points);
    targets.clear();
    for (std::uint32_t s = 0; s < boxes_.size(); ++s)
      if (s != tile_ && ball_meets(ball, boxes_[s])) targets.push_back(s);
    if (targets.empty() || !first_time(e)) continue;
    for (const std::uint32_t s : targets) ask[s].push_back(q);
  }
  for (const auto& h : local.hull) {
    // Asked again every round: a point sent on the facet's plane may leave the facet on the hull.
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
  const PointGrid<Vec> grid{std::span<const Vec>(own_points_)};
  const TileBox<Vec>& own_box = boxes_[tile_];
  std::vector<std::pair<double, std::uint32_t>> nearest;
  for (std::uint32_t s = 0; s < questions.size(); ++s) {
    std::vector<std::uint8_t>& sent = sent_[s];
    const auto send = [&](std::uint32_t i) {
      sent[i] = 1;
      out[s].push_back(Ghost{own_ids_[i], tile_, own_points_[i]});
      ++counts_.ghosts_sent;
    };
    std::unordered_set<std::string>& empty = answered_empty_[s];
    for (const Question& q : questions[s]) {
      std::string key(reinterpret_cast<const char*>(&q), sizeof(Question));
      if (empty.count(key) != 0) continue;
      const std::size_t sent_before = out[s].size();
      switch (q.kind) {
        case Question::Ball: {
          // The conflicting points nearest the element, at most kPerBall of them, found ring by
          // ring around its centroid: a large ball (an element on the hull of what the asker
          // knows) holds many points of which only those near the element become its
          // neighbours; the next round's smaller balls ask for what is still missing.
          const auto ball = safe_ball(q.points);
          Vec centroid = q.points[0];
          for (int k = 1; k <= kDim; ++k) centroid = centroid + q.points[k];
          centroid = (1.0 / (kDim + 1)) * centroid;
          nearest.clear();
          const bool bounded = std::isfinite(ball.radius);
          Vec lo = own_box.lo, hi = own_box.hi;
          if (bounded) {
            lo = ball.centre, hi = ball.centre;
            lo.x -= ball.radius, hi.x += ball.radius;
            lo.y -= ball.radius, hi.y += ball.radius;
            if constexpr (kDim == 3) lo.z -= ball.radius, hi.z += ball.radius;
          }
          grid.visit_rings(
              centroid, lo, hi,
              [&](const Vec& l, const Vec& h) {
                return !bounded || ball_meets(ball, TileBox<Vec>{l, h, false});
              },
              [&](std::uint32_t i) {
                if (!sent[i] && in_conflict(q.points, own_points_[i]))
                  nearest.push_back({norm(own_points_[i] - centroid), i});
              },
              [&](std::int64_t) { return nearest.size() >= kPerBall; });
          std::sort(nearest.begin(), nearest.end());
          for (std::size_t k = 0; k < nearest.size() && k < kPerBall; ++k) send(nearest[k].second);
          break;
        }
        case Question::Beyond: {
          // Every own hull vertex on or beyond the facet's line / plane: if an own point is beyond,
          // a hull vertex is (convexity), and the points on a supporting line / plane are hull
          // vertices; all of them at once, so that a straight stretch of the hull is not walked
          // one point a round.
          for (const std::uint32_t i : own_hull_)
            if (!sent[i] && beyond(q.points, own_points_[i])) send(i);
          break;
        }
        case Question::Everything:
          for (std::uint32_t i = 0; i < own_points_.size(); ++i)
            if (!sent[i]) send(i);
          break;
        default: throw InputError("TileDelaunay::answer: unknown question kind " + std::to_string(q.kind));
      }
      if (out[s].size() == sent_before) empty.insert(std::move(key));
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
