// The shared mutable 3D mesh (mesh3.hpp): storage, free lists, navigation (ball, shell), the
// visibility walk and the exact check, the counterpart of mesh/mesh2.cpp. Operators that change
// the mesh live in algorithms/ (one a file).
#include "mesh/mesh3.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/domain_vertices.hpp"
#include "mesh/edge_key.hpp"
#include "mesh/element_sets3.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {

namespace {

struct TripleHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const noexcept {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + k[1] * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + k[2] * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

std::array<std::uint32_t, 3> sorted(std::array<std::uint32_t, 3> v) noexcept {
  std::sort(v.begin(), v.end());
  return v;
}

// Same three vertices in opposite cyclic order.
bool reversed_facets(const std::array<std::uint32_t, 3>& f, const std::array<std::uint32_t, 3>& g) noexcept {
  for (int r = 0; r < 3; ++r)
    if (f[0] == g[r] && f[1] == g[(r + 2) % 3] && f[2] == g[(r + 1) % 3]) return true;
  return false;
}

// The tetrahedra already seen by a search around a vertex: a linear scan while few, beyond that
// a stamp per tetrahedron slot (balls are small; a degenerate vertex of high valence should not
// make it quadratic). The stamps are one array per thread, shared by every mesh: each search
// takes a stamp no earlier search took, so what other searches left is never mistaken for seen.
class SeenSet {
 public:
  explicit SeenSet(std::size_t capacity) : capacity_(capacity) {}
  bool insert(std::uint32_t t, const std::vector<std::uint32_t>& list) {
    if (list.size() < 48) return std::find(list.begin(), list.end(), t) == list.end();
    if (stamp_ == 0) {
      if (stamps_.size() < capacity_) stamps_.resize(capacity_, 0);
      if (++counter_ == 0) {  // wrapped: forget every stamp
        std::fill(stamps_.begin(), stamps_.end(), 0);
        counter_ = 1;
      }
      stamp_ = counter_;
      for (const std::uint32_t u : list) stamps_[u] = stamp_;
    }
    if (stamps_[t] == stamp_) return false;
    stamps_[t] = stamp_;
    return true;
  }

 private:
  static thread_local std::vector<std::uint32_t> stamps_;
  static thread_local std::uint32_t counter_;
  std::size_t capacity_;
  std::uint32_t stamp_ = 0;
};
thread_local std::vector<std::uint32_t> SeenSet::stamps_;
thread_local std::uint32_t SeenSet::counter_ = 0;

std::string vertex_name(std::uint32_t v) { return v == Mesh3::kInfinite ? std::string("infinite") : std::to_string(v); }

}  // namespace

Mesh3::Mesh3(const Tetrahedralization3& tet, std::span<const int> tetrahedron_refs,
             std::span<const MeshTriangle3> constrained, const Metric3& metric) {
  const std::size_t n = tet.point_count();
  const std::size_t nt = tet.tetrahedron_count();
  if (tetrahedron_refs.size() != nt) {
    throw InputError("Mesh3: " + std::to_string(tetrahedron_refs.size()) + " tetrahedron references for " +
                     std::to_string(nt) + " tetrahedra");
  }
  adopt_vertices(tet.points(), metric, vertex_tetrahedra(tet, Incident::First));
  anisotropic_slots_ = metric.is_scalar() ? 0 : n;
  changed_at_.assign(n, 0);
  vertices_.resize(4 * nt);
  neighbours_.resize(4 * nt);
  for (std::uint32_t t = 0; t < nt; ++t) {
    const auto& r = tet.records()[t];
    for (std::uint32_t i = 0; i < 4; ++i) {
      vertices_[4 * t + i] = r.vertex[i];
      neighbours_[4 * t + i] = r.neighbour[i];
    }
  }
  refs_.assign(tetrahedron_refs.begin(), tetrahedron_refs.end());
  facet_refs_.assign(vertices_.size(), kUnconstrained);
  for (std::uint32_t t = 0; t < nt; ++t)
    if (is_ghost(t)) refs_[t] = kExterior;
  if (constrained.empty()) return;
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, TripleHash> by_facet;
  by_facet.reserve(constrained.size() * 2);
  for (std::uint32_t i = 0; i < constrained.size(); ++i)
    by_facet.emplace(sorted({constrained[i].a, constrained[i].b, constrained[i].c}), i);
  std::vector<std::uint32_t> facet_of(constrained.size(), kNone);
  for (std::uint32_t h = 0; h < vertices_.size(); ++h) {
    if (is_ghost(tetrahedron_of(h)) && index_in_tetrahedron(h) != 0) continue;  // holds kInfinite
    const auto it = by_facet.find(sorted(facet_vertices(h)));
    if (it != by_facet.end()) facet_of[it->second] = h;
  }
  for (std::uint32_t i = 0; i < constrained.size(); ++i) {
    const MeshTriangle3& c = constrained[i];
    if (facet_of[i] == kNone) {
      throw InputError("Mesh3: constrained triangle " + std::to_string(i) + " (" + std::to_string(c.a) + ", " +
                           std::to_string(c.b) + ", " + std::to_string(c.c) + ") is not a facet of the tetrahedralization",
                       {i});
    }
    constrain_triangle(facet_of[i], c);
  }
}

void Mesh3::clear_constraints() {
  constrained_edges_ = {};
  std::fill(facet_refs_.begin(), facet_refs_.end(), kUnconstrained);
}

void Mesh3::constrain_triangle(std::uint32_t h, const MeshTriangle3& c) {
  set_facet_both(h, true, c.ref);
  for (const std::uint32_t v : {c.a, c.b, c.c}) vertex_flags_[v] |= kOnBoundary;
  set_constrained_edge(c.a, c.b, true);
  set_constrained_edge(c.b, c.c, true);
  set_constrained_edge(c.c, c.a, true);
}

std::uint32_t Mesh3::add_vertex(const Vec3& p, const Metric3& m, std::uint8_t flags) {
  DTLAB_ASSERT((flags & kDead) == 0);
  const std::uint32_t v = take_vertex_slot();
  points_[v] = p;
  replace_metric(v, m);
  vertex_flags_[v] = flags;
  touch(v);
  return v;
}

std::uint32_t Mesh3::take_vertex_slot() {
  const std::uint32_t v = take_slot(Tetrahedralization3::kMaxPoints);
  if (v == changed_at_.size()) changed_at_.push_back(epoch_);  // a new slot
  replace_metric(v, Metric3{});
  vertex_flags_[v] = kDead;
  return v;
}

void Mesh3::take_tetrahedron_slots(std::size_t k, std::vector<std::uint32_t>& out) {
  while (k > 0 && !free_tetrahedra_.empty()) {
    out.push_back(free_tetrahedra_.back());
    free_tetrahedra_.pop_back();
    --k;
  }
  const std::uint32_t first = grow_tetrahedra(k);
  for (std::size_t t = first; t < first + k; ++t) out.push_back(static_cast<std::uint32_t>(t));
}

std::uint32_t Mesh3::take_tetrahedron_slot() {
  if (free_tetrahedra_.empty()) return grow_tetrahedra(1);
  const std::uint32_t t = free_tetrahedra_.back();
  free_tetrahedra_.pop_back();
  return t;
}

std::uint32_t Mesh3::grow_tetrahedra(std::size_t k) {
  const std::size_t first = tetrahedron_capacity();
  DTLAB_ASSERT(first + k <= Tetrahedralization3::kMaxTetrahedra);
  vertices_.resize(vertices_.size() + 4 * k, kNone);
  neighbours_.resize(neighbours_.size() + 4 * k);
  facet_refs_.resize(facet_refs_.size() + 4 * k);
  refs_.resize(refs_.size() + k, 0);
  return static_cast<std::uint32_t>(first);
}

void Mesh3::fill_tetrahedron(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, int r) {
  DTLAB_ASSERT(b != kInfinite && c != kInfinite && d != kInfinite);
  DTLAB_ASSERT(a != kNone && a != b && a != c && a != d && b != c && b != d && c != d);
  const std::uint32_t v[4] = {a, b, c, d};
  for (std::uint32_t i = 0; i < 4; ++i) {
    vertices_[4 * t + i] = v[i];
    neighbours_[4 * t + i] = kNone;
    facet_refs_[4 * t + i] = kUnconstrained;
    if (v[i] != kInfinite) {
      vertex_element_[v[i]] = t;
      touch(v[i]);
    }
  }
  refs_[t] = r;
}

std::uint32_t Mesh3::add_tetrahedron(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, int r) {
  const std::uint32_t t = take_tetrahedron_slot();
  fill_tetrahedron(t, a, b, c, d, r);
  return t;
}

void Mesh3::kill_tetrahedron(std::uint32_t t) {
  DTLAB_ASSERT(t < tetrahedron_capacity() && is_alive(t));
  for (std::uint32_t i = 0; i < 4; ++i)
    if (vertices_[4 * t + i] != kInfinite) touch(vertices_[4 * t + i]);
  vertices_[4 * t] = kNone;
}

void Mesh3::remove_tetrahedron(std::uint32_t t) {
  kill_tetrahedron(t);
  free_tetrahedra_.push_back(t);
}

namespace {

// new_of[old] for an order of the live slots; InputError naming `what` when it is no permutation.
std::vector<std::uint32_t> inverse_order(std::span<const std::uint32_t> order, std::uint32_t capacity,
                                         std::uint32_t live, const auto& is_live, const char* what) {
  if (order.size() != live) {
    throw InputError(std::string("Mesh3::renumber: ") + what + " order lists " + std::to_string(order.size()) +
                     " entries for " + std::to_string(live) + " live ones");
  }
  std::vector<std::uint32_t> new_of(capacity, Mesh3::kNone);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t old = order[k];
    if (old >= capacity || !is_live(old) || new_of[old] != Mesh3::kNone) {
      throw InputError(std::string("Mesh3::renumber: ") + what + " " + std::to_string(old) + " (entry " +
                       std::to_string(k) + ") is dead, out of range or listed twice");
    }
    new_of[old] = static_cast<std::uint32_t>(k);
  }
  return new_of;
}

template <class T>
void permute(std::vector<T>& values, std::span<const std::uint32_t> order, std::size_t width = 1) {
  std::vector<T> moved(order.size() * width);
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t i = 0; i < width; ++i) moved[width * k + i] = values[width * order[k] + i];
  values = std::move(moved);
}

}  // namespace

void Mesh3::renumber(std::span<const std::uint32_t> vertex_order, std::span<const std::uint32_t> tetrahedron_order) {
  const std::vector<std::uint32_t> vertex_of = inverse_order(
      vertex_order, vertex_capacity(), live_vertex_count(), [&](std::uint32_t v) { return !is_dead_vertex(v); }, "vertex");
  const std::vector<std::uint32_t> tetrahedron_of_old =
      inverse_order(tetrahedron_order, tetrahedron_capacity(), live_tetrahedron_count(),
                    [&](std::uint32_t t) { return is_alive(t); }, "tetrahedron");
  auto new_vertex = [&](std::uint32_t v) { return v == kInfinite ? kInfinite : vertex_of[v]; };
  auto new_handle = [&](std::uint32_t h) { return 4 * tetrahedron_of_old[tetrahedron_of(h)] + index_in_tetrahedron(h); };
  permute(points_, vertex_order);
  permute(metrics_, vertex_order);
  anisotropic_slots_ = static_cast<std::uint64_t>(
      std::count_if(metrics_.begin(), metrics_.end(), [](const Metric3& m) { return !m.is_scalar(); }));
  permute(vertex_flags_, vertex_order);
  permute(changed_at_, vertex_order);
  permute(vertex_element_, vertex_order);
  for (std::uint32_t& t : vertex_element_) t = t == kNone ? kNone : tetrahedron_of_old[t];
  free_vertices_.clear();
  permute(vertices_, tetrahedron_order, 4);
  for (std::uint32_t& v : vertices_) v = new_vertex(v);
  permute(neighbours_, tetrahedron_order, 4);
  for (std::uint32_t& h : neighbours_) h = new_handle(h);
  permute(refs_, tetrahedron_order);
  permute(facet_refs_, tetrahedron_order, 4);
  free_tetrahedra_.clear();
  std::unordered_map<std::uint64_t, std::uint8_t> edges;
  edges.reserve(constrained_edges_.size());
  for (const auto& [key, value] : constrained_edges_) {
    edges.emplace(edge_key(vertex_of[static_cast<std::uint32_t>(key >> 32)], vertex_of[static_cast<std::uint32_t>(key)]),
                  value);
  }
  constrained_edges_ = std::move(edges);
}

bool Mesh3::is_constrained_edge(std::uint32_t a, std::uint32_t b) const {
  return constrained_edges_.count(edge_key(a, b)) != 0;
}

void Mesh3::set_constrained_edge(std::uint32_t a, std::uint32_t b, bool constrained) {
  DTLAB_ASSERT(a != b && a < kInfinite && b < kInfinite);
  if (constrained) {
    constrained_edges_.emplace(edge_key(a, b), 1);
  } else {
    constrained_edges_.erase(edge_key(a, b));
  }
}

void Mesh3::ball(std::uint32_t v, std::vector<std::uint32_t>& out) const {
  out.clear();
  DTLAB_ASSERT(v < vertex_capacity() && !is_dead_vertex(v));
  const std::uint32_t t0 = vertex_element_[v];
  DTLAB_ASSERT(t0 != kNone && is_alive(t0));
  // Breadth first: the order depends only on the structure, so it is deterministic. Each slot
  // enters once, so the search ends; the bound is checked after it, out of the hot loop.
  SeenSet seen(tetrahedron_capacity());
  nav3::ball(*this, v, t0, out, [&](std::uint32_t u) { return seen.insert(u, out); });
  if (out.size() > live_tetrahedron_count()) {
    throw InternalError("Mesh3::ball: the search around vertex " + std::to_string(v) + " passed " +
                        std::to_string(live_tetrahedron_count()) + " tetrahedra");
  }
}

std::uint32_t Mesh3::find_edge(std::uint32_t a, std::uint32_t b) const {
  if (a == b) return kNone;
  if (a == kInfinite) std::swap(a, b);
  if (a >= vertex_capacity() || is_dead_vertex(a)) return kNone;
  if (b != kInfinite && (b >= vertex_capacity() || is_dead_vertex(b))) return kNone;
  std::vector<std::uint32_t> around;
  ball(a, around);
  for (const std::uint32_t t : around) {
    for (std::uint32_t i = 0; i < 4; ++i)
      if (vertices_[4 * t + i] == b) return t;
  }
  return kNone;
}

std::uint32_t Mesh3::find_facet(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  if (a == b || b == c || a == c) return kNone;
  if (a == kInfinite) std::swap(a, b);
  if (a == kInfinite) std::swap(a, c);
  if (a >= vertex_capacity() || is_dead_vertex(a)) return kNone;
  std::vector<std::uint32_t> around;
  ball(a, around);
  for (const std::uint32_t t : around) {
    int hits = 0;
    std::uint32_t other = 4;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t v = vertices_[4 * t + i];
      if (v == a || v == b || v == c) {
        ++hits;
      } else {
        other = i;
      }
    }
    if (hits == 3) return 4 * t + other;
  }
  return kNone;
}

bool Mesh3::shell(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out, std::vector<std::uint32_t>* ring) const {
  out.clear();
  if (ring) ring->clear();
  const std::uint32_t t0 = find_edge(a, b);
  if (t0 == kNone) return false;
  shell_at(t0, a, b, out, ring);
  return true;
}

void Mesh3::shell_at(std::uint32_t t0, std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out,
                     std::vector<std::uint32_t>* ring) const {
  out.clear();
  if (ring) ring->clear();
  DTLAB_ASSERT(t0 < tetrahedron_capacity() && is_alive(t0));
  auto local = [&](std::uint32_t t, std::uint32_t v) {
    for (std::uint32_t i = 0; i < 4; ++i)
      if (vertices_[4 * t + i] == v) return i;
    throw InternalError("Mesh3::shell: tetrahedron " + std::to_string(t) + " lost vertex " + vertex_name(v));
  };
  // The walk of nav3::kShellStep; c is the vertex opposite the facet crossed next.
  const std::uint32_t k0 = nav3::kShellStep[local(t0, a)][local(t0, b)][0];
  std::uint32_t t = t0;
  std::uint32_t c = vertices_[4 * t0 + k0];
  const std::size_t bound = live_tetrahedron_count();
  do {
    out.push_back(t);
    if (ring) ring->push_back(c);
    if (out.size() > bound) {
      throw InternalError("Mesh3::shell: the tetrahedra around edge (" + vertex_name(a) + ", " + vertex_name(b) +
                          ") do not close");
    }
    // c must be the vertex kShellStep puts opposite the facet crossed next.
    const std::uint32_t* v = &vertices_[4 * t];
    const auto [ia, ib] = nav3::local_indices(v, a, b);
    if (ia == 4) local(t, a);  // throws
    if (ib == 4) local(t, b);
    const auto [k, l] = nav3::kShellStep[ia][ib];
    if (v[k] != c) local(t, c);  // throws when c is gone
    DTLAB_ASSERT(v[k] == c);
    c = v[l];
    t = tetrahedron_of(neighbours_[4 * t + k]);
  } while (t != t0);
}

Mesh3::Location Mesh3::locate(const Vec3& p, std::uint32_t start, bool stop_at_constraints, const Region* region) const {
  DTLAB_ASSERT(start < tetrahedron_capacity() && is_alive(start));
  std::uint32_t t = start;
  if (is_ghost(t)) t = tetrahedron_of(neighbours_[4 * t]);
  if (region != nullptr && !in_region(t, *region)) return {Where::Inside, t, kNone, true};
  // Stochastic (the first facet tested at random), stopped at constraints or the region's edge.
  std::uint64_t rng = 0x9E3779B97F4A7C15ull ^ (static_cast<std::uint64_t>(start) * 0xBF58476D1CE4E5B9ull);
  const auto first = [&rng](std::uint64_t) {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return static_cast<std::uint32_t>(rng % 4);
  };
  const auto beyond = [&](std::uint32_t h) {
    const bool stop = (stop_at_constraints && is_constrained(h)) ||
                      (region != nullptr && !in_region(tetrahedron_of(neighbours_[h]), *region));
    return stop ? nav3::Beyond::Stop : nav3::Beyond::Cross;
  };
  const nav3::Walk w = nav3::visibility_walk(*this, p, t, 64ull * live_tetrahedron_count() + 64, first, beyond);
  t = w.tetrahedron;
  if (w.end == nav3::Walk::End::Bound)
    throw InternalError("Mesh3::locate: no tetrahedron found for (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                        ", " + std::to_string(p.z) + ") within the step bound");
  if (w.end == nav3::Walk::End::Ghost) return {Where::Outside, t, kNone, false};
  if (w.end == nav3::Walk::End::Stopped) return {Where::Inside, t, kNone, true};
  std::uint32_t zero_mask = w.zero_facets;
  // came_from was skipped: p is not strictly beyond it (we came from there), but it may be on it.
  if (w.came_from != kNone) {
    const auto f = facet_vertices(w.came_from);
    if (orient3d(points_[f[0]], points_[f[1]], points_[f[2]], p) == Sign::Zero)
      zero_mask |= 1u << index_in_tetrahedron(w.came_from);
  }
  const int zeros = std::popcount(zero_mask);
  if (zeros == 0) return {Where::Inside, t, kNone, false};
  if (zeros == 1) return {Where::Facet, t, 4 * t + static_cast<std::uint32_t>(std::countr_zero(zero_mask)), false};
  if (zeros == 2) {
    // The edge lies on both zero facets: its vertices are the two not opposite them.
    Location loc{Where::Edge, t, kNone, false};
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (zero_mask & (1u << i)) continue;
      (loc.edge_a == kNone ? loc.edge_a : loc.edge_b) = vertices_[4 * t + i];
    }
    return loc;
  }
  // Three zero facets meet at the one vertex none of them is opposite: p is that vertex.
  for (std::uint32_t i = 0; i < 4; ++i)
    if (!(zero_mask & (1u << i))) return {Where::Vertex, t, vertices_[4 * t + i], false};
  throw InternalError("Mesh3::locate: p is on all four facets of tetrahedron " + std::to_string(t));
}

void Mesh3::check() const {
  auto fail = [](const std::string& what) { throw InternalError("Mesh3::check: " + what); };
  const std::uint32_t nt = tetrahedron_capacity();
  if (neighbours_.size() != vertices_.size() || facet_refs_.size() != vertices_.size() || refs_.size() != nt)
    fail("array sizes differ");
  std::vector<std::uint8_t> free_t(nt, 0);
  for (const std::uint32_t t : free_tetrahedra_) {
    if (t >= nt || is_alive(t) || free_t[t]) fail("free tetrahedron list holds " + std::to_string(t));
    free_t[t] = 1;
  }
  std::vector<std::uint8_t> free_v(vertex_capacity(), 0);
  for (const std::uint32_t v : free_vertices_) {
    if (v >= vertex_capacity() || !is_dead_vertex(v) || free_v[v]) fail("free vertex list holds " + std::to_string(v));
    free_v[v] = 1;
  }
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v)
    if (is_dead_vertex(v) && !free_v[v]) fail("dead vertex " + std::to_string(v) + " not in the free list");
  std::vector<std::uint8_t> used(vertex_capacity(), 0);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (!is_alive(t)) {
      if (!free_t[t]) fail("dead tetrahedron " + std::to_string(t) + " not in the free list");
      continue;
    }
    const std::string name = "tetrahedron " + std::to_string(t);
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = 4 * t + i;
      const std::uint32_t v = vertices_[h];
      if (v == kInfinite) {
        if (i != 0) fail("kInfinite at index " + std::to_string(i) + " of " + name);
      } else {
        if (v >= vertex_capacity() || is_dead_vertex(v)) fail(name + " uses dead vertex " + std::to_string(v));
        used[v] = 1;
      }
      for (std::uint32_t j = i + 1; j < 4; ++j)
        if (vertices_[4 * t + j] == v) fail(name + " repeats vertex " + vertex_name(v));
      const std::uint32_t g = neighbours_[h];
      if (g == kNone || g >= vertices_.size() || !is_alive(tetrahedron_of(g)) || tetrahedron_of(g) == t)
        fail("facet " + std::to_string(h) + " of " + name + " has no live twin");
      if (neighbours_[g] != h) fail("facet " + std::to_string(h) + " twin not symmetric");
      if (!reversed_facets(facet_vertices(h), facet_vertices(g)))
        fail("facet " + std::to_string(h) + " twin is not the same facet in opposite orientation");
      if (facet_refs_[g] != facet_refs_[h]) fail("facet " + std::to_string(h) + " constrained differently from its twin");
    }
    if (!is_ghost(t)) {
      const auto v = tetrahedron(t);
      if (orient3d(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]]) != Sign::Positive)
        fail(name + " (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ", " +
             std::to_string(v[3]) + ") is not positive");
    } else if (refs_[t] != kExterior) {
      fail("ghost " + name + " has a reference other than kExterior");
    }
  }
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v) {
    if (is_dead_vertex(v)) continue;
    const std::uint32_t t = vertex_element_[v];
    if (t == kNone || t >= nt || !is_alive(t) ||
        (vertices_[4 * t] != v && vertices_[4 * t + 1] != v && vertices_[4 * t + 2] != v && vertices_[4 * t + 3] != v))
      fail("vertex_tetrahedron of vertex " + std::to_string(v) + " is stale");
    if (!used[v]) fail("live vertex " + std::to_string(v) + " is used by no tetrahedron");
  }
  // Sorted, so that the first problem named does not depend on the hash table's order.
  std::vector<std::uint64_t> edges;
  edges.reserve(constrained_edges_.size());
  for (const auto& [key, value] : constrained_edges_) edges.push_back(key);
  std::sort(edges.begin(), edges.end());
  for (const std::uint64_t key : edges) {
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    if (find_edge(a, b) == kNone)
      fail("constrained edge (" + std::to_string(a) + ", " + std::to_string(b) + ") is not an edge of the mesh");
  }
}

MeshData3 Mesh3::domain(std::vector<std::uint32_t>* vertex_ids) const {
  // A facet as seen from the domain side with the smaller slot.
  const auto emit_facet = [this](MeshData3& out, std::span<const std::uint32_t> number, std::uint32_t h) {
    const auto f = facet_vertices(h);
    out.triangles.push_back({number[f[0]], number[f[1]], number[f[2]]});
    out.triangle_refs.push_back(facet_refs_[h]);
  };
  return mesh_domain<4, MeshData3>(*this, vertices_, neighbours_, refs_, &MeshData3::tetrahedra,
                                   &MeshData3::tetrahedron_refs, vertex_ids,
                                   [this](std::uint32_t h) { return is_constrained(h); }, emit_facet);
}

}  // namespace dtlab
