// Insertion (Bowyer-Watson cavity) and removal (ear clipping of the hole, Devillers 2002) on a
// Mesh2 under the kernel's perturbed in-circle test; see dynamic_delaunay2.hpp for why the
// result is the triangulation of the survivors built from scratch.
#include "algorithms/delaunay2d/dynamic_delaunay2.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include "algorithms/common/conflict_cavity.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"

namespace dtlab {
namespace {

constexpr std::uint32_t kInfinite = Mesh2::kInfinite;
constexpr std::uint32_t kNone = Mesh2::kNone;


// w on the line ab (checked by the caller) and strictly between a and b.
bool strictly_between(const Vec2& a, const Vec2& b, const Vec2& w) noexcept {
  if (a.x != b.x) return (a.x < w.x && w.x < b.x) || (b.x < w.x && w.x < a.x);
  return (a.y < w.y && w.y < b.y) || (b.y < w.y && w.y < a.y);
}

// Is w in conflict with the ghost (kInfinite, a, b): beyond its hull edge b -> a, or strictly
// inside it (mesh/triangulation2.hpp).
bool ghost_conflict(const Vec2& a, const Vec2& b, const Vec2& w) noexcept {
  const Sign s = orient2d(a, b, w);
  return s == Sign::Positive || (s == Sign::Zero && strictly_between(a, b, w));
}

}  // namespace

DynamicDelaunay2::DynamicDelaunay2(std::span<const Vec2> points, const Delaunay2dOptions& options) {
  Delaunay2dResult r = delaunay2d(points, options);
  refuse_unusable_start(r, "triangle");
  adopt(r.triangulation, r.triangulation.triangle_count(), r.triangulation.finite_triangle_count());
}

bool DynamicDelaunay2::in_conflict(std::uint32_t t, const Vec2& p) const {
  const std::uint32_t a = mesh_.vertex(t, 0), b = mesh_.vertex(t, 1), c = mesh_.vertex(t, 2);
  if (a == kInfinite) return ghost_conflict(mesh_.point(b), mesh_.point(c), p);
  return incircle_perturbed(mesh_.point(a), mesh_.point(b), mesh_.point(c), p) == Sign::Positive;
}

// Triangle (a, b, c), counter-clockwise, rotated so that kInfinite comes first.
std::uint32_t DynamicDelaunay2::add(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (b == kInfinite) std::tie(a, b, c) = std::tuple{b, c, a};
  if (c == kInfinite) std::tie(a, b, c) = std::tuple{c, a, b};
  const bool ghost = a == kInfinite;
  if (!ghost) ++finite_;
  return mesh_.add_triangle(a, b, c, ghost ? Mesh2::kExterior : 0);
}

std::uint32_t DynamicDelaunay2::insert(const Vec2& p) {
  const std::uint32_t start = insertion_start(p);
  DTLAB_ASSERT(in_conflict(start, p));

  // The cavity: the triangles in conflict with p, connected through their edges (a disk, star-
  // shaped from p, under a genuine perturbation). stamp_: epoch_ inside, epoch_ + 1 tested outside.
  epoch_ += 2;
  if (stamp_.size() < mesh_.triangle_capacity()) stamp_.resize(mesh_.triangle_capacity(), 0);
  struct Boundary {
    std::uint32_t origin, destination, outside;
  };
  static thread_local std::vector<Boundary> boundary;
  conflict_cavity<3>(mesh_, start, [&](std::uint32_t t) { return in_conflict(t, p); }, stamp_, epoch_,
                     mesh_.live_triangle_count(), cavity_, stack_, handles_);
  boundary.clear();
  for (const std::uint32_t h : handles_) boundary.push_back({mesh_.origin(h), mesh_.destination(h), mesh_.twin(h)});
  stats_.cavity_triangles += cavity_.size();
  for (const std::uint32_t t : cavity_) {
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_triangle(t);
  }
  const std::uint32_t vp = mesh_.add_vertex(p, Metric2{}, 0);
  // One new triangle (p, o, d) per boundary edge o -> d; around p they meet at o and d.
  static thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> from_p, to_p;
  from_p.clear();
  to_p.clear();
  for (const Boundary& e : boundary) {
    const std::uint32_t t = add(vp, e.origin, e.destination);
    mesh_.link(nav2::opposite(mesh_, t, vp), e.outside);
    from_p.emplace_back(e.origin, nav2::opposite(mesh_, t, e.destination));   // p -> o
    to_p.emplace_back(e.destination, nav2::opposite(mesh_, t, e.origin));     // d -> p
    hint_ = t;
  }
  std::sort(from_p.begin(), from_p.end());
  std::sort(to_p.begin(), to_p.end());
  for (std::size_t k = 0; k < from_p.size(); ++k) {
    DTLAB_ASSERT(from_p[k].first == to_p[k].first);
    mesh_.link(from_p[k].second, to_p[k].second);
  }
  ++stats_.inserted;
  return vp;
}

void DynamicDelaunay2::check_removable(std::uint32_t v, const std::vector<std::uint32_t>& ball) const {
  std::uint64_t finite_in_ball = 0;
  for (const std::uint32_t h : ball) finite_in_ball += mesh_.is_ghost(Mesh2::triangle_of(h)) ? 0 : 1;
  if (finite_in_ball < finite_) return;  // a triangle without v survives
  // Every survivor is then on v's link: are they all on one line?
  std::vector<std::uint32_t> rest;
  for (const std::uint32_t h : ball)
    if (mesh_.origin(h) != kInfinite) rest.push_back(mesh_.origin(h));
  bool collinear = true;
  for (std::size_t k = 2; k < rest.size() && collinear; ++k)
    collinear = orient2d(mesh_.point(rest[0]), mesh_.point(rest[1]), mesh_.point(rest[k])) == Sign::Zero;
  if (collinear)
    throw DegenerateRemovalError("removing vertex " + std::to_string(v) + " would leave " +
                                     std::to_string(rest.size()) + " points, all collinear: no triangle",
                                 {v});
}

// Is the ear at polygon[i] (with its neighbours) a triangle of the survivors' Delaunay
// triangulation: convex (finite) and in conflict with no other polygon vertex.
bool DynamicDelaunay2::is_delaunay_ear(const std::vector<std::uint32_t>& polygon, std::size_t i) {
  ++stats_.ear_tests;
  const std::size_t n = polygon.size();
  const std::size_t ip = (i + n - 1) % n, in = (i + 1) % n;
  std::uint32_t a = polygon[ip], b = polygon[i], c = polygon[in];
  if (b == kInfinite) std::tie(a, b, c) = std::tuple{b, c, a};
  if (c == kInfinite) std::tie(a, b, c) = std::tuple{c, a, b};
  const Vec2& B = mesh_.point(b);
  const Vec2& C = mesh_.point(c);
  if (a == kInfinite) {
    for (std::size_t k = 0; k < n; ++k) {
      if (k == ip || k == i || k == in || polygon[k] == kInfinite) continue;
      if (ghost_conflict(B, C, mesh_.point(polygon[k]))) return false;
    }
    return true;
  }
  const Vec2& A = mesh_.point(a);
  if (orient2d(A, B, C) != Sign::Positive) return false;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == ip || k == i || k == in || polygon[k] == kInfinite) continue;
    if (incircle_perturbed(A, B, C, mesh_.point(polygon[k])) == Sign::Positive) return false;
  }
  return true;
}

void DynamicDelaunay2::remove(std::uint32_t v) {
  if (!contains(v)) throw UnknownVertexError(v);
  mesh_.ball(v, ball_);
  check_removable(v, ball_);
  // The hole's polygon, counter-clockwise, and the twin outside each of its edges.
  polygon_.clear();
  outside_.clear();
  for (const std::uint32_t h : ball_) {
    polygon_.push_back(mesh_.origin(h));
    outside_.push_back(mesh_.twin(h));
  }
  for (const std::uint32_t h : ball_) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_triangle(t);
  }
  mesh_.remove_vertex(v);
  // Clip Delaunay ears until a triangle is left; outside_[k] is the twin of edge k -> k+1.
  std::size_t i = 0, failures = 0;
  while (polygon_.size() > 3) {
    const std::size_t n = polygon_.size();
    if (failures > n) throw InternalError("remove: no Delaunay ear in the hole of vertex " + std::to_string(v));
    i %= n;
    if (!is_delaunay_ear(polygon_, i)) {
      ++i, ++failures;
      continue;
    }
    const std::size_t ip = (i + n - 1) % n;
    const std::uint32_t x = polygon_[ip], y = polygon_[i], z = polygon_[(i + 1) % n];
    const std::uint32_t t = add(x, y, z);
    mesh_.link(nav2::opposite(mesh_, t, z), outside_[ip]);  // x -> y
    mesh_.link(nav2::opposite(mesh_, t, x), outside_[i]);   // y -> z
    outside_[ip] = nav2::opposite(mesh_, t, y);             // z -> x, the new polygon edge x -> z seen from outside
    polygon_.erase(polygon_.begin() + static_cast<std::ptrdiff_t>(i));
    outside_.erase(outside_.begin() + static_cast<std::ptrdiff_t>(i));
    i = i > 0 ? i - 1 : polygon_.size() - 1;
    failures = 0;
    hint_ = t;
  }
  const std::uint32_t x = polygon_[0], y = polygon_[1], z = polygon_[2];
  if (x != kInfinite && y != kInfinite && z != kInfinite)
    DTLAB_ASSERT(orient2d(mesh_.point(x), mesh_.point(y), mesh_.point(z)) == Sign::Positive);
  const std::uint32_t t = add(x, y, z);
  mesh_.link(nav2::opposite(mesh_, t, z), outside_[0]);
  mesh_.link(nav2::opposite(mesh_, t, x), outside_[1]);
  mesh_.link(nav2::opposite(mesh_, t, y), outside_[2]);
  hint_ = t;
  ++stats_.removed;
}

Delaunay2dRemoval delaunay2d_remove(std::span<const Vec2> points, std::span<const std::uint32_t> indices,
                                     const Delaunay2dOptions& options) {
  return remove_points<DynamicDelaunay2, 3, DynamicDelaunay2Stats>(points, indices, options);
}

}  // namespace dtlab
