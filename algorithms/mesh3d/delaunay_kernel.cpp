// The constrained, possibly anisotropic Delaunay kernel on Mesh3 (delaunay_kernel.hpp).
#include "algorithms/mesh3d/delaunay_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/edge_key.hpp"

namespace dtlab {

namespace {

template <class T>
void grow_to(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(std::max(n, v.size() + v.size() / 2), 0);
}

}  // namespace

bool DelaunayKernel3::in_conflict(std::uint32_t t, const Vec3& p) const {
  const Vec3& a = mesh_.point(mesh_.vertex(t, 0));
  const Vec3& b = mesh_.point(mesh_.vertex(t, 1));
  const Vec3& c = mesh_.point(mesh_.vertex(t, 2));
  const Vec3& d = mesh_.point(mesh_.vertex(t, 3));
  if (isotropic_) return insphere(a, b, c, d, p) == Sign::Positive;
  // In the metric at p: the images under M(p)^1/2, translated so that p is the origin.
  const Vec3 ia = transform(sqrt_m_, a - p), ib = transform(sqrt_m_, b - p), ic = transform(sqrt_m_, c - p),
             id = transform(sqrt_m_, d - p);
  const Vec3 origin{0.0, 0.0, 0.0};
  if (orient3d(ia, ib, ic, id) != Sign::Positive) return false;
  return insphere(ia, ib, ic, id, origin) == Sign::Positive;
}

bool DelaunayKernel3::faces_cavity_across_constraint(std::uint32_t t) const {
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t h = Mesh3::facet(t, i);
    if (mesh_.is_constrained(h) && mark_[Mesh3::tetrahedron_of(mesh_.twin(h))] == stamp_) return true;
  }
  return false;
}

void DelaunayKernel3::grow(std::uint32_t seed, const Vec3& p) {
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
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(t, i);
      const std::uint32_t u = Mesh3::tetrahedron_of(mesh_.twin(h));
      if (mark_[u] == stamp_) continue;
      if (mesh_.is_constrained(h) || !mesh_.in_domain(u) || excluded_[u] == exclusion_stamp_ || !in_conflict(u, p) ||
          faces_cavity_across_constraint(u)) {
        boundary_.push_back(h);
        continue;
      }
      if (region_ != nullptr && !mesh_.in_region(u, *region_)) {
        left_region_ = true;
        return;
      }
      mark_[u] = stamp_;
      cavity_.push_back(u);
    }
  }
  // Facets found from a tetrahedron whose neighbour joined later are not boundary.
  std::erase_if(boundary_, [&](std::uint32_t h) { return mark_[Mesh3::tetrahedron_of(mesh_.twin(h))] == stamp_; });
}

std::uint32_t DelaunayKernel3::find_offender(std::uint32_t seed, const Vec3& p) {
  for (const std::uint32_t h : boundary_) {
    const auto f = mesh_.facet_vertices(h);
    if (orient3d(mesh_.point(f[0]), mesh_.point(f[1]), mesh_.point(f[2]), p) != Sign::Positive) {
      return Mesh3::tetrahedron_of(h);
    }
  }
  // No vertex of the cavity may be left inside it: each must be on its boundary.
  for (const std::uint32_t h : boundary_) {
    for (const std::uint32_t v : mesh_.facet_vertices(h)) vertex_mark_[v] = stamp_;
  }
  for (const std::uint32_t t : cavity_) {
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t v = mesh_.vertex(t, i);
      if (vertex_mark_[v] == stamp_) continue;
      // Leave out a tetrahedron around the enclosed vertex other than the seed.
      for (const std::uint32_t u : cavity_) {
        if (u == seed) continue;
        const auto w = mesh_.tetrahedron(u);
        if (w[0] == v || w[1] == v || w[2] == v || w[3] == v) return u;
      }
      DTLAB_ASSERT(false);
    }
  }
  return Mesh3::kNone;
}

bool DelaunayKernel3::find_cavity(const Vec3& p, const Metric3& mp, std::uint32_t seed) {
  DTLAB_ASSERT(mesh_.in_domain(seed));
  isotropic_ = mp.is_scalar();
  if (!isotropic_) sqrt_m_ = power(mp, 0.5);
  grow_to(mark_, mesh_.tetrahedron_capacity());
  grow_to(excluded_, mesh_.tetrahedron_capacity());
  grow_to(vertex_mark_, mesh_.vertex_capacity());
  ++exclusion_stamp_;
  if (exclusion_stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(excluded_.begin(), excluded_.end(), 0);
    exclusion_stamp_ = 1;
  }
  for (std::uint32_t i = 0; i < 4; ++i) {
    if (mesh_.point(mesh_.vertex(seed, i)) == p) return false;
  }
  // Each correction removes one tetrahedron for good, so the loop ends within the cavity's size.
  const std::size_t bound = 4 * static_cast<std::size_t>(mesh_.live_tetrahedron_count()) + 8;
  left_region_ = false;
  for (std::size_t round = 0; round < bound; ++round) {
    grow(seed, p);
    if (left_region_) return false;
    const std::uint32_t offender = find_offender(seed, p);
    if (offender == Mesh3::kNone) return true;
    if (offender == seed) return false;  // p on a facet of the seed that cannot open
    excluded_[offender] = exclusion_stamp_;
    ++corrections_;
  }
  throw InternalError("DelaunayKernel3: the cavity correction did not end within its bound");
}

double DelaunayKernel3::nearest_cavity_vertex(const Vec3& p, const Metric3& mp) const {
  double best = std::numeric_limits<double>::infinity();
  for (const std::uint32_t h : boundary_) {
    for (const std::uint32_t v : mesh_.facet_vertices(h)) best = std::min(best, mp.length(mesh_.point(v) - p));
  }
  return best;
}

std::uint32_t DelaunayKernel3::commit(const Vec3& p, const Metric3& mp, std::uint8_t flags) {
  DTLAB_ASSERT(!cavity_.empty());
  const std::uint32_t v = mesh_.add_vertex(p, mp, flags);
  plan_slots(cavity_, boundary_.size(), slots_);
  commit_into(cavity_, boundary_, v, slots_);
  give_back_unused(slots_, boundary_.size());
  return v;
}

// The cavity's slots last first, then taken ones: the order in which removing the cavity and
// adding the ball one tetrahedron at a time (the free list is a stack) would reuse them.
void DelaunayKernel3::plan_slots(std::span<const std::uint32_t> cavity, std::size_t ball_size,
                                 std::vector<std::uint32_t>& slots, std::vector<std::uint32_t>* pool) {
  slots.assign(cavity.rbegin(), cavity.rend());
  while (slots.size() < ball_size) {
    if (pool == nullptr) {
      slots.push_back(mesh_.take_tetrahedron_slot());
    } else {
      DTLAB_ASSERT(!pool->empty());
      slots.push_back(pool->back());
      pool->pop_back();
    }
  }
}

// The slots past the ball, in the order in which removing the cavity would have freed them.
void DelaunayKernel3::give_back_unused(std::span<const std::uint32_t> slots, std::size_t ball_size,
                                       std::vector<std::uint32_t>* pool) {
  for (std::size_t k = slots.size(); k > ball_size; --k) {
    if (pool == nullptr)
      mesh_.give_back_tetrahedron_slot(slots[k - 1]);
    else
      pool->push_back(slots[k - 1]);
  }
}

void DelaunayKernel3::commit_into(std::span<const std::uint32_t> cavity, std::span<const std::uint32_t> boundary,
                                  std::uint32_t v, std::span<const std::uint32_t> slots) {
  DTLAB_ASSERT(!cavity.empty() && slots.size() == std::max(cavity.size(), boundary.size()));
  sides_.clear();
  for (const std::uint32_t h : boundary) {
    const auto f = mesh_.facet_vertices(h);
    sides_.push_back({f[0], f[1], f[2], mesh_.twin(h), mesh_.is_constrained(h), mesh_.facet_ref(h)});
  }
  const int ref = mesh_.ref(cavity.front());
  for (const std::uint32_t t : cavity) mesh_.kill_tetrahedron(t);
  ball_.clear();
  laterals_.clear();
  // Boundary facet (a, b, c), turned counter-clockwise seen from inside: the new tetrahedron is
  // (v, a, c, b), whose facet 0 (v1 v3 v2 = a b c) is the boundary facet; its facets 2 (v b a),
  // 1 (v c b) and 3 (v a c) stand on the boundary edges ab, bc and ca.
  for (std::size_t k = 0; k < sides_.size(); ++k) {
    const Side& s = sides_[k];
    const std::uint32_t t = slots[k];
    mesh_.fill_tetrahedron(t, v, s.a, s.c, s.b, ref);
    mesh_.link(Mesh3::facet(t, 0), s.outside);
    mesh_.set_facet(Mesh3::facet(t, 0), s.constrained, s.ref);
    for (std::uint32_t i = 1; i < 4; ++i) mesh_.set_facet(Mesh3::facet(t, i), false);
    laterals_.push_back({edge_key(s.a, s.b), Mesh3::facet(t, 2)});
    laterals_.push_back({edge_key(s.b, s.c), Mesh3::facet(t, 1)});
    laterals_.push_back({edge_key(s.c, s.a), Mesh3::facet(t, 3)});
    ball_.push_back(t);
  }
  // Each lateral edge is shared by exactly two new tetrahedra (the cavity's boundary is a closed
  // surface): matched through a small open-addressing table keyed by the edge.
  const std::size_t capacity = std::bit_ceil(2 * laterals_.size());
  const int shift = 64 - std::countr_zero(capacity);
  table_.assign(capacity, kNone);
  std::size_t links = 0;
  for (std::uint32_t k = 0; k < laterals_.size(); ++k) {
    const std::uint64_t edge = laterals_[k].edge;
    std::size_t slot = static_cast<std::size_t>((edge * 0x9E3779B97F4A7C15ull) >> shift) & (capacity - 1);
    while (table_[slot] != kNone && laterals_[table_[slot]].edge != edge) slot = (slot + 1) & (capacity - 1);
    if (table_[slot] == kNone) {
      table_[slot] = k;
      continue;
    }
    Lateral& other = laterals_[table_[slot]];
    DTLAB_ASSERT(other.handle != kNone);  // a third facet on one edge: the cavity was not closed
    mesh_.link(other.handle, laterals_[k].handle);
    other.handle = kNone;
    ++links;
  }
  DTLAB_ASSERT(2 * links == laterals_.size());
}

}  // namespace dtlab
