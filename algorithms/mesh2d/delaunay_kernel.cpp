// The constrained, possibly anisotropic Delaunay kernel on Mesh2 (delaunay_kernel.hpp).
#include "algorithms/mesh2d/delaunay_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {


template <class T>
void grow_to(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(std::max(n, v.size() + v.size() / 2), 0);
}

}  // namespace

bool DelaunayKernel2::in_conflict(std::uint32_t t, const Vec2& p) const {
  const Vec2& a = mesh_.point(mesh_.vertex(t, 0));
  const Vec2& b = mesh_.point(mesh_.vertex(t, 1));
  const Vec2& c = mesh_.point(mesh_.vertex(t, 2));
  if (isotropic_) return incircle(a, b, c, p) == Sign::Positive;
  // In the metric at p: the images under M(p)^1/2, translated so that p is the origin.
  const Vec2 ia = transform(sqrt_m_, a - p), ib = transform(sqrt_m_, b - p), ic = transform(sqrt_m_, c - p);
  const Vec2 origin{0.0, 0.0};
  if (orient2d(ia, ib, ic) != Sign::Positive) return false;
  return incircle(ia, ib, ic, origin) == Sign::Positive;
}

bool DelaunayKernel2::faces_cavity_across_constraint(std::uint32_t t) const {
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t h = Mesh2::half_edge(t, i);
    if (mesh_.is_constrained(h) && mark_[Mesh2::triangle_of(mesh_.twin(h))] == stamp_) return true;
  }
  return false;
}

void DelaunayKernel2::stamp_grow() {
  grow_to(mark_, mesh_.triangle_capacity());
  grow_to(excluded_, mesh_.triangle_capacity());
  grow_to(vertex_mark_, mesh_.vertex_capacity());
}

void DelaunayKernel2::grow(std::uint32_t seed, const Vec2& p) {
  ++stamp_;
  if (stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(mark_.begin(), mark_.end(), 0);
    std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
    stamp_ = 1;
  }
  cavity_.clear();
  boundary_.clear();
  cavity_.push_back(seed);
  mark_[seed] = stamp_;
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::uint32_t t = cavity_[k];
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      const std::uint32_t u = Mesh2::triangle_of(mesh_.twin(h));
      if (mark_[u] == stamp_) continue;
      // A triangle joins only if no constrained edge of it faces the cavity: a constrained edge
      // is never inside a cavity.
      if (mesh_.is_constrained(h) || !mesh_.in_domain(u) || excluded_[u] == exclusion_stamp_ || !in_conflict(u, p) ||
          faces_cavity_across_constraint(u)) {
        boundary_.push_back(h);
        continue;
      }
      mark_[u] = stamp_;
      cavity_.push_back(u);
    }
  }
  // Half-edges found from a triangle that later joined the cavity are not boundary.
  std::erase_if(boundary_, [&](std::uint32_t h) { return mark_[Mesh2::triangle_of(mesh_.twin(h))] == stamp_; });
}

bool DelaunayKernel2::find_cavity(const Vec2& p, const Metric2& mp, std::uint32_t seed) {
  DTLAB_ASSERT(mesh_.in_domain(seed));
  isotropic_ = mp.is_scalar();
  if (!isotropic_) sqrt_m_ = power(mp, 0.5);
  stamp_grow();
  ++exclusion_stamp_;
  if (exclusion_stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(excluded_.begin(), excluded_.end(), 0);
    exclusion_stamp_ = 1;
  }
  for (std::uint32_t i = 0; i < 3; ++i) {
    if (mesh_.point(mesh_.vertex(seed, i)) == p) return false;
  }
  // Each correction removes one triangle for good, so the loop ends within the cavity's size.
  const std::size_t bound = 4 * mesh_.live_triangle_count() + 8;
  for (std::size_t round = 0; round < bound; ++round) {
    grow(seed, p);
    std::uint32_t offender = Mesh2::kNone;
    for (const std::uint32_t h : boundary_) {
      if (orient2d(mesh_.point(mesh_.origin(h)), mesh_.point(mesh_.destination(h)), p) != Sign::Positive) {
        offender = Mesh2::triangle_of(h);
        break;
      }
    }
    if (offender == Mesh2::kNone) {
      // No vertex of the cavity may be left inside it: each must be on its boundary.
      for (const std::uint32_t h : boundary_) vertex_mark_[mesh_.origin(h)] = stamp_;
      for (const std::uint32_t t : cavity_) {
        for (std::uint32_t i = 0; i < 3 && offender == Mesh2::kNone; ++i) {
          const std::uint32_t v = mesh_.vertex(t, i);
          if (vertex_mark_[v] == stamp_) continue;
          // Leave out a triangle around the enclosed vertex other than the seed.
          for (const std::uint32_t u : cavity_) {
            if (u != seed && (mesh_.vertex(u, 0) == v || mesh_.vertex(u, 1) == v || mesh_.vertex(u, 2) == v)) {
              offender = u;
              break;
            }
          }
          DTLAB_ASSERT(offender != Mesh2::kNone);
        }
      }
      if (offender == Mesh2::kNone) return true;
    }
    if (offender == seed) return false;  // p on an edge of the seed that cannot open
    excluded_[offender] = exclusion_stamp_;
    ++corrections_;
  }
  throw InternalError("DelaunayKernel2: the cavity correction did not end within its bound");
}

double DelaunayKernel2::nearest_cavity_vertex(const Vec2& p, const Metric2& mp) const {
  double best = std::numeric_limits<double>::infinity();
  for (const std::uint32_t h : boundary_) best = std::min(best, mp.length(mesh_.point(mesh_.origin(h)) - p));
  return best;
}

std::uint32_t DelaunayKernel2::commit(const Vec2& p, const Metric2& mp, std::uint8_t flags) {
  DTLAB_ASSERT(!cavity_.empty());
  std::vector<Side>& sides = sides_;
  sides.clear();
  for (const std::uint32_t h : boundary_) {
    sides.push_back({mesh_.origin(h), mesh_.destination(h), mesh_.twin(h), mesh_.is_constrained(h), mesh_.edge_ref(h)});
  }
  const int ref = mesh_.ref(cavity_.front());
  for (const std::uint32_t t : cavity_) mesh_.remove_triangle(t);
  const std::uint32_t v = mesh_.add_vertex(p, mp, flags);
  grow_to(vertex_slot_, mesh_.vertex_capacity());
  ball_.clear();
  for (const Side& s : sides) {
    const std::uint32_t t = mesh_.add_triangle(v, s.a, s.b, ref);
    mesh_.link(Mesh2::half_edge(t, 0), s.outside);
    mesh_.set_constraint(Mesh2::half_edge(t, 0), s.constrained, s.ref);
    vertex_slot_[s.a] = t;
    ball_.push_back(t);
  }
  // Triangle (v, a, b): edge 1 runs b -> v and faces the triangle (v, b, c), whose edge 2 runs v -> b.
  for (const std::uint32_t t : ball_) {
    const std::uint32_t b = mesh_.vertex(t, 2);
    mesh_.link(Mesh2::half_edge(t, 1), Mesh2::half_edge(vertex_slot_[b], 2));
  }
  return v;
}

}  // namespace dtlab
