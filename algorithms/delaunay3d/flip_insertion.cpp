// Insertion by splitting and flipping (flip_insertion.hpp). Point p is located by a visibility
// walk, the tetrahedra whose closure holds it are split (1->4 inside, 2->6 on a facet, n->2n on
// an edge: the cone from p over the boundary of their union, so that no flat tetrahedron ever
// exists), and the link facets (the facets opposite p) are flipped until each is locally
// Delaunay. A link facet abc of (a, b, c, p) with apex d across is flipped when p is in
// conflict with (a, b, c, d): the perturbed in-sphere test, or the ghost rule of
// incremental.cpp for a ghost, so that every decision is the one the cavity of "incremental"
// makes and the result is the same unique tetrahedralization. Where segment pd meets the plane
// of abc decides the flip: inside the triangle 2->3; beyond edge ab 3->2 if ab has three
// tetrahedra; on edge ab (p, d, a, b coplanar) 4->4 if ab has four. Otherwise the facet is
// deferred; Edelsbrunner & Shah show another one is flippable, and the deferred ones are tried
// again when the queue runs empty (first in, first out: fewer facets meet a blocked edge than
// last in, first out, 3.8 against 6.3 per uniform point). Ghosts flip like finite tetrahedra, with the orientation of
// flip_orientation.hpp. Every flip removes a tetrahedron that existed before p (one in conflict
// with p), which bounds the flips of one insertion.
#include "algorithms/delaunay3d/flip_insertion.hpp"

#include <bit>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {
using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;
}  // namespace

FlipInserter::FlipInserter(const Vec3* points, std::vector<T3::Record>& records, std::array<std::uint32_t, 4> first)
    : p_(points), first_(first), mesh_(records), orientation_(points, first) {
  old_.reserve(64);
  ids_.reserve(64);
  queue_.reserve(256);
  deferred_.reserve(64);
  retry_.reserve(64);
  fresh_.reserve(64);
}

void FlipInserter::start() {
  const std::array<std::uint32_t, 4>& v = first_;
  fresh_.clear();
  fresh_.push_back(v);
  // The ghost across facet i holds the facet as the tetrahedron lists it (tetrahedralization3.hpp).
  for (const auto& f : kFacet) fresh_.push_back({kInf, v[f[0]], v[f[1]], v[f[2]]});
  old_.clear();
  mesh_.replace(old_, fresh_, ids_);
  last_ = ids_[0];
}

void FlipInserter::insert(std::uint32_t p) {
  split(locate(p), p);
  restore_delaunay(p);
}

Sign FlipInserter::facet_side(std::uint32_t t, std::uint32_t i, std::uint32_t p) const noexcept {
  const auto& v = mesh_.records()[t].vertex;
  const auto& f = kFacet[i];
  return orientation_.orient(v[f[0]], v[f[1]], v[f[2]], p);
}

// Visibility walk from the last insertion, through ghosts too (each is a cone from the interior
// point of flip_orientation.hpp), to the tetrahedron whose closure holds p. The triangulation is
// regular as seen from that centre, so the walk does not cycle (Edelsbrunner 1990); a step bound
// backs that up.
FlipInserter::Location FlipInserter::locate(std::uint32_t p) const {
  const T3::Record* r = mesh_.records();
  std::uint32_t t = last_;
  if (r[t].vertex[0] == kInf) t = r[t].neighbour[0] >> 2;
  std::uint32_t entered = 4;  // the facet the walk came in through (4: none)
  const std::size_t bound = mesh_.slots();
  for (std::size_t steps = 0; steps <= bound; ++steps) {
    std::uint32_t zero = 0, next = kNone;
    for (std::uint32_t k = 1; k <= 4; ++k) {
      const std::uint32_t i = (entered + k) & 3u;
      if (i == entered) continue;
      const Sign s = facet_side(t, i, p);
      if (s == Sign::Negative) {
        next = r[t].neighbour[i];
        break;
      }
      if (s == Sign::Zero) zero |= 1u << i;
    }
    if (next == kNone) return {t, zero};
    t = next >> 2, entered = next & 3u;
  }
  throw InternalError("3D Delaunay flip: the walk to point (rank " + std::to_string(p) + ") exceeded its bound of " +
                      std::to_string(bound) + " steps");
}

// The tetrahedra around edge ab, starting with t, into old_.
void FlipInserter::collect_shell(std::uint32_t t, std::uint32_t a, std::uint32_t b) {
  const T3::Record* r = mesh_.records();
  old_.clear();
  old_.push_back(t);
  std::uint32_t leave = 0;
  while (r[t].vertex[leave] == a || r[t].vertex[leave] == b) ++leave;
  std::uint32_t u = t;
  const std::size_t bound = mesh_.slots();
  for (std::size_t steps = 0; steps <= bound; ++steps) {
    const std::uint32_t next = r[u].neighbour[leave];
    u = next >> 2;
    if (u == t) return;
    old_.push_back(u);
    // Leave u through its other facet holding ab: the one opposite its other non-edge vertex.
    const std::uint32_t entered = next & 3u;
    leave = 0;
    while (leave == entered || r[u].vertex[leave] == a || r[u].vertex[leave] == b) ++leave;
  }
  throw InternalError("3D Delaunay flip: the tetrahedra around an edge do not close up");
}

// The cone from p over the boundary of the tetrahedra whose closure holds p. Their facets
// through p are the shared ones; every other facet has p strictly on its inner side, so the
// cone's tetrahedra are positive.
void FlipInserter::split(const Location& at, std::uint32_t p) {
  const T3::Record* r = mesh_.records();
  const std::uint32_t t = at.tetrahedron;
  const int zeros = std::popcount(at.zero_facets);
  std::uint32_t a = kNone, b = kNone;  // the edge p lies on
  std::uint32_t shared = kNone;        // the facet p lies on (handle in t)
  if (zeros == 0) {
    mesh_.split14(t, p, ids_);
    ++counts_.splits[0];
    commit(p);
    return;
  }
  if (zeros == 1) {
    shared = 4 * t + static_cast<std::uint32_t>(std::countr_zero(at.zero_facets));
    old_.assign({t, r[t].neighbour[shared & 3u] >> 2});
  } else if (zeros == 2) {
    std::uint32_t k = 0;
    while (at.zero_facets & (1u << k)) ++k;
    std::uint32_t l = k + 1;
    while (at.zero_facets & (1u << l)) ++l;
    a = r[t].vertex[k], b = r[t].vertex[l];
    collect_shell(t, a, b);
  } else {
    throw InternalError("3D Delaunay flip: point (rank " + std::to_string(p) + ") lies on three facets of a tetrahedron");
  }
  fresh_.clear();
  for (const std::uint32_t o : old_) {
    const auto& v = r[o].vertex;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const bool inner = zeros == 1 ? (4 * o + i == shared || r[o].neighbour[i] == shared)
                                    : zeros == 2 && v[i] != a && v[i] != b;
      if (inner) continue;
      const auto& f = kFacet[i];
      fresh_.push_back({v[f[0]], v[f[1]], v[f[2]], p});
    }
  }
  mesh_.replace(old_, fresh_, ids_);
  ++counts_.splits[zeros];
  commit(p);
}

// The link facets of the new tetrahedra join the queue.
void FlipInserter::commit(std::uint32_t p) {
  const T3::Record* r = mesh_.records();
  for (const std::uint32_t t : ids_) {
    std::uint32_t i = 0;
    while (r[t].vertex[i] != p) ++i;
    queue_.push_back(4 * t + i);
    // The tetrahedron across is read when the facet comes off the queue: ask for it now.
    __builtin_prefetch(r + (r[t].neighbour[i] >> 2));
  }
  last_ = ids_.back();
}

void FlipInserter::restore_delaunay(std::uint32_t p) {
  // Every flip removes at least one tetrahedron that existed before p went in.
  flips_left_ = mesh_.live_count() + 64;
  deferred_.clear();
  for (;;) {
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const std::uint32_t h = queue_[head];
      if (try_flip(h, p) == Outcome::Blocked) deferred_.push_back(h);
    }
    queue_.clear();
    if (deferred_.empty()) return;
    retry_.swap(deferred_);
    deferred_.clear();
    bool progress = false;
    for (const std::uint32_t h : retry_) {
      ++counts_.retried;
      const Outcome o = try_flip(h, p);
      progress |= o == Outcome::Flipped;
      if (o == Outcome::Blocked) deferred_.push_back(h);
    }
    if (!progress && !deferred_.empty())
      throw InternalError("3D Delaunay flip: inserting point (rank " + std::to_string(p) + ") left " +
                          std::to_string(deferred_.size()) + " link facets not locally Delaunay and none flippable");
  }
}

// The ghost rule of incremental.cpp: strictly beyond the hull facet, or on its plane and inside
// the sphere of the finite tetrahedron across it under the perturbation. That tetrahedron existed
// before p (no tetrahedron through p has a facet whose plane holds p).
bool FlipInserter::conflicts(std::uint32_t t, std::uint32_t p) const noexcept {
  const T3::Record* r = mesh_.records();
  const auto& v = r[t].vertex;
  const Vec3& q = p_[p];
  if (v[0] != kInf) return insphere_perturbed(p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]], q) == Sign::Positive;
  const Sign side = orient3d(q, p_[v[1]], p_[v[2]], p_[v[3]]);
  if (side != Sign::Zero) return side == Sign::Positive;
  const auto& w = r[r[t].neighbour[0] >> 2].vertex;
  return insphere_perturbed(p_[w[0]], p_[w[1]], p_[w[2]], p_[w[3]], q) == Sign::Positive;
}

FlipInserter::Outcome FlipInserter::try_flip(std::uint32_t h, std::uint32_t p) {
  const T3::Record* r = mesh_.records();
  const std::uint32_t t = h >> 2, i = h & 3u;
  if (mesh_.is_dead(t) || r[t].vertex[i] != p) return Outcome::Done;  // flipped away since pushed
  const std::uint32_t g = r[t].neighbour[i];
  const std::uint32_t u = g >> 2, d = r[u].vertex[g & 3u];
  if (!conflicts(u, p)) return Outcome::Done;
  if (flips_left_ == 0)
    throw InternalError("3D Delaunay flip: inserting point (rank " + std::to_string(p) + ") exceeded its bound of flips");

  // Facet (v0, v1, v2) as t lists it, so (v0, v1, v2, p) is positive; edge k runs from v[k] to
  // v[k + 1] and f = v[k + 2] is opposite it.
  const auto& fi = kFacet[i];
  const std::array<std::uint32_t, 3> v = {r[t].vertex[fi[0]], r[t].vertex[fi[1]], r[t].vertex[fi[2]]};
  // An edge with three tetrahedra t, u and (e0, e1, p, d) is reflex (segment pd passes beyond
  // it), so 2->3 is out and only 3->2 about such an edge can apply.
  bool degree3 = false;
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t w = r[t].neighbour[fi[(k + 2) % 3]];
    if (r[w >> 2].vertex[w & 3u] != d) continue;
    degree3 = true;
    if (flip32(t, u, w >> 2, v[k], v[(k + 1) % 3], v[(k + 2) % 3], p, d)) return Outcome::Flipped;
  }
  if (!degree3) {
    // Where segment pd crosses the plane of the facet, edge by edge: inside (negative), on the
    // edge's line (zero), beyond it (positive: the edge has more than three tetrahedra, blocked).
    int zeros = 0;
    std::uint32_t zero_edge = 0;
    bool reflex = false;
    for (std::uint32_t k = 0; k < 3 && !reflex; ++k) {
      const Sign o = orientation_.orient(v[k], v[(k + 1) % 3], p, d);
      reflex = o == Sign::Positive;
      if (o == Sign::Zero) ++zeros, zero_edge = k;
    }
    if (!reflex && zeros == 0) {
      mesh_.flip23(t, u, v, p, d, ids_);
      --flips_left_;
      ++counts_.flips23;
      commit(p);
      return Outcome::Flipped;
    }
    // On a line through the infinite vertex means p, d and the finite end collinear; then p is
    // outside the sphere and never gets here.
    const std::uint32_t k = zero_edge;
    if (!reflex && zeros == 1 && v[k] != kInf && v[(k + 1) % 3] != kInf &&
        flip44(t, u, fi[(k + 2) % 3], v[k], v[(k + 1) % 3], v[(k + 2) % 3], p, d))
      return Outcome::Flipped;
  }
  ++counts_.blocked;
  return Outcome::Blocked;
}

// Edge e0e1 of facet (e0, e1, f) has three tetrahedra: t1 = (e0, e1, f, p), t2 across the facet
// with apex d, and t3 = (e0, e1, p, d). They become (f, d, p, e0) and (d, f, p, e1) if segment
// e0e1 crosses triangle fdp, i.e. if both are positive.
bool FlipInserter::flip32(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t e0, std::uint32_t e1,
                          std::uint32_t f, std::uint32_t p, std::uint32_t d) {
  if (orientation_.orient(f, d, p, e0) != Sign::Positive || orientation_.orient(d, f, p, e1) != Sign::Positive)
    return false;
  mesh_.flip32(t1, t2, t3, e0, e1, f, p, d, ids_);
  --flips_left_;
  ++counts_.flips32;
  commit(p);
  return true;
}

// Segment pd crosses edge e0e1 (p, d, e0, e1 coplanar) and the edge has four tetrahedra: t1, t2,
// t4 = (e0, e1, p, x) across t1's facet opposite f and t3 = (e0, e1, d, x) across t2's. Around
// the edge they come in the order f, p, x, d; edge e0e1 gives way to edge pd.
bool FlipInserter::flip44(std::uint32_t t1, std::uint32_t t2, std::uint32_t f_in_t1, std::uint32_t e0,
                          std::uint32_t e1, std::uint32_t f, std::uint32_t p, std::uint32_t d) {
  const T3::Record* r = mesh_.records();
  const std::uint32_t w4 = r[t1].neighbour[f_in_t1];
  const std::uint32_t t4 = w4 >> 2, x = r[t4].vertex[w4 & 3u];
  std::uint32_t f_in_t2 = 0;
  while (r[t2].vertex[f_in_t2] != f) ++f_in_t2;
  const std::uint32_t w3 = r[t2].neighbour[f_in_t2];
  const std::uint32_t t3 = w3 >> 2;
  if (r[t3].vertex[w3 & 3u] != x) return false;
  fresh_.assign({{e1, f, d, p}, {f, e0, d, p}, {e0, x, d, p}, {x, e1, d, p}});
  for (const FlipMesh::Tuple& n : fresh_)
    if (orientation_.orient(n[0], n[1], n[2], n[3]) != Sign::Positive)
      throw InternalError("3D Delaunay flip: a 4->4 flip would make a tetrahedron that is not positive");
  mesh_.flip44(t1, t2, t3, t4, e0, e1, f, x, p, d, ids_);
  --flips_left_;
  ++counts_.flips44;
  commit(p);
  return true;
}

}  // namespace dtlab
