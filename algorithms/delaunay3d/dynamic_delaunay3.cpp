// Insertion (Bowyer-Watson cavity) and removal (the link's Delaunay tetrahedralization restricted
// to the hole) on a Mesh3 under the kernel's perturbed in-sphere test; see dynamic_delaunay3.hpp
// for why the result is the tetrahedralization of the survivors built from scratch.
#include "algorithms/delaunay3d/dynamic_delaunay3.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "algorithms/common/conflict_cavity.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {
namespace {

constexpr std::uint32_t kInfinite = Mesh3::kInfinite;
constexpr std::uint32_t kNone = Mesh3::kNone;
using Triple = std::array<std::uint32_t, 3>;


Triple sorted(Triple f) {
  std::sort(f.begin(), f.end());
  return f;
}

// The local index of v in tetrahedron t.
std::uint32_t nav3_index_of(const Mesh3& m, std::uint32_t t, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 4; ++i)
    if (m.vertex(t, i) == v) return i;
  throw InternalError("remove: vertex " + std::to_string(v) + " is not in a tetrahedron of its ball");
}

// f and g hold the same vertices in the same cyclic order.
bool same_cycle(const Triple& f, const Triple& g) {
  return f == g || f == Triple{g[1], g[2], g[0]} || f == Triple{g[2], g[0], g[1]};
}

}  // namespace

void DynamicDelaunay3::FacetIndex::reset(std::size_t entries) {
  std::size_t size = 64;
  while (size < 2 * entries) size *= 2;
  if (slots_.size() < size || ++stamp_ == 0) {
    slots_.assign(std::max(size, slots_.size()), Slot{{}, kNone, 0});
    stamp_ = 1;
  }
}

std::size_t DynamicDelaunay3::FacetIndex::slot_of(const Triple& key) const noexcept {
  const std::uint64_t h = (key[0] * 0x9E3779B97F4A7C15ull) ^ (key[1] * 0xC2B2AE3D27D4EB4Full) ^
                          (key[2] * 0x165667B19E3779F9ull);
  return static_cast<std::size_t>(h >> 32) & (slots_.size() - 1);
}

void DynamicDelaunay3::FacetIndex::insert(const Triple& key, std::uint32_t handle) {
  for (std::size_t k = slot_of(key), probes = 0; probes < slots_.size(); k = (k + 1) & (slots_.size() - 1), ++probes) {
    Slot& s = slots_[k];
    if (s.stamp != stamp_) {
      s = {key, handle, stamp_};
      return;
    }
    if (s.key == key) return;  // the facet's other side: one handle is enough
  }
  throw InternalError("FacetIndex: full");
}

std::uint32_t DynamicDelaunay3::FacetIndex::find(const Triple& key) const {
  for (std::size_t k = slot_of(key), probes = 0; probes < slots_.size(); k = (k + 1) & (slots_.size() - 1), ++probes) {
    const Slot& s = slots_[k];
    if (s.stamp != stamp_) return kNone;
    if (s.key == key) return s.handle;
  }
  return kNone;
}

DynamicDelaunay3::DynamicDelaunay3(std::span<const Vec3> points, const Delaunay3dOptions& options)
    : link_options_(options) {
  link_options_.threads = 1;
  Delaunay3dResult r = delaunay3d(points, options);
  refuse_unusable_start(r, "tetrahedron");
  adopt(r.tetrahedralization, r.tetrahedralization.tetrahedron_count(), r.tetrahedralization.finite_tetrahedron_count());
}

// The ghost rule of algorithms/delaunay3d/cavity_kernel.hpp: beyond the hull facet, or on its
// plane and in conflict with the finite tetrahedron across it.
bool DynamicDelaunay3::in_conflict(std::uint32_t t, const Vec3& p) const {
  const std::array<std::uint32_t, 4> v = mesh_.tetrahedron(t);
  if (v[0] != kInfinite)
    return insphere_perturbed(mesh_.point(v[0]), mesh_.point(v[1]), mesh_.point(v[2]), mesh_.point(v[3]), p) ==
           Sign::Positive;
  const Sign side = orient3d(p, mesh_.point(v[1]), mesh_.point(v[2]), mesh_.point(v[3]));
  if (side != Sign::Zero) return side == Sign::Positive;
  const std::array<std::uint32_t, 4> w = mesh_.tetrahedron(mesh_.adjacent(t, 0));
  return insphere_perturbed(mesh_.point(w[0]), mesh_.point(w[1]), mesh_.point(w[2]), mesh_.point(w[3]), p) ==
         Sign::Positive;
}

// A positive tetrahedron, permuted evenly so that kInfinite (if there) comes first.
std::uint32_t DynamicDelaunay3::add(std::array<std::uint32_t, 4> v) {
  if (v[1] == kInfinite) v = {v[1], v[0], v[3], v[2]};
  if (v[2] == kInfinite) v = {v[2], v[3], v[0], v[1]};
  if (v[3] == kInfinite) v = {v[3], v[2], v[1], v[0]};
  const bool ghost = v[0] == kInfinite;
  if (!ghost) ++finite_;
  return mesh_.add_tetrahedron(v[0], v[1], v[2], v[3], ghost ? Mesh3::kExterior : 0);
}

// Links the facet handles `handles` in pairs by their vertex triples: each triple must occur
// exactly twice.
void DynamicDelaunay3::glue(std::span<const std::uint32_t> handles) {
  static thread_local std::vector<std::pair<Triple, std::uint32_t>> open;
  open.clear();
  for (const std::uint32_t h : handles) open.emplace_back(sorted(mesh_.facet_vertices(h)), h);
  std::sort(open.begin(), open.end());
  for (std::size_t k = 0; k < open.size(); k += 2) {
    if (k + 1 >= open.size() || open[k].first != open[k + 1].first || (k + 2 < open.size() && open[k + 2].first == open[k].first))
      throw InternalError("dynamic Delaunay 3D: facet (" + std::to_string(open[k].first[0]) + ", " +
                          std::to_string(open[k].first[1]) + ", " + std::to_string(open[k].first[2]) +
                          ") does not close the new tetrahedra");
    mesh_.link(open[k].second, open[k + 1].second);
  }
}

std::uint32_t DynamicDelaunay3::insert(const Vec3& p) {
  const std::uint32_t start = insertion_start(p);
  DTLAB_ASSERT(in_conflict(start, p));
  epoch_ += 2;
  if (stamp_.size() < mesh_.tetrahedron_capacity()) stamp_.resize(mesh_.tetrahedron_capacity(), 0);
  conflict_cavity<4>(mesh_, start, [&](std::uint32_t t) { return in_conflict(t, p); }, stamp_, epoch_,
                     mesh_.live_tetrahedron_count(), cavity_, stack_, queue_);
  static thread_local std::vector<Triple> faces;
  faces.clear();
  outside_.clear();
  for (const std::uint32_t h : queue_) faces.push_back(mesh_.facet_vertices(h)), outside_.push_back(mesh_.twin(h));
  stats_.cavity_tetrahedra += cavity_.size();
  for (const std::uint32_t t : cavity_) {
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_tetrahedron(t);
  }
  const std::uint32_t vp = mesh_.add_vertex(p, Metric3{}, 0);
  open_.assign(outside_.begin(), outside_.end());
  for (const Triple& f : faces) {
    const std::uint32_t t = add({f[0], f[1], f[2], vp});  // p where the apex was
    for (std::uint32_t i = 0; i < 4; ++i) open_.push_back(4 * t + i);
    hint_ = t;
  }
  glue(open_);
  ++stats_.inserted;
  return vp;
}

void DynamicDelaunay3::remove(std::uint32_t v) {
  if (!contains(v)) throw UnknownVertexError(v);
  // The ball, searched with this structure's stamps (Mesh3::ball's list scan is quadratic).
  epoch_ += 2;
  if (stamp_.size() < mesh_.tetrahedron_capacity()) stamp_.resize(mesh_.tetrahedron_capacity(), 0);
  nav3::ball(mesh_, v, mesh_.vertex_tetrahedron(v), ball_, nav3::marking(stamp_, epoch_));
  DTLAB_ASSERT(ball_.size() <= mesh_.live_tetrahedron_count());
  // The link's finite vertices (D's vertex k is link_[k]); the ball's boundary facets, each as
  // seen from v, in D's numbering (kInfinite kept), and the handles outside them.
  if (local_.size() < mesh_.vertex_capacity()) local_.resize(mesh_.vertex_capacity(), kNone);
  link_.clear();
  faces_.clear();
  outside_.clear();
  std::uint64_t finite_in_ball = 0;
  const auto local = [&](std::uint32_t u) {
    if (u == kInfinite) return kInfinite;
    if (local_[u] == kNone) local_[u] = static_cast<std::uint32_t>(link_.size()), link_.push_back(u);
    return local_[u];
  };
  for (const std::uint32_t t : ball_) {
    finite_in_ball += mesh_.is_ghost(t) ? 0 : 1;
    const std::uint32_t i = nav3_index_of(mesh_, t, v);
    const Triple f = mesh_.facet_vertices(4 * t + i);
    faces_.push_back({local(f[0]), local(f[1]), local(f[2])});
    outside_.push_back(mesh_.twin(4 * t + i));
  }
  link_points_.clear();
  for (const std::uint32_t u : link_) link_points_.push_back(mesh_.point(u)), local_[u] = kNone;
  stats_.link_vertices += link_.size();
  Delaunay3dResult d;
  bool flat = link_.size() < 4;
  if (!flat) {
    d = delaunay3d(link_points_, link_options_);
    flat = !d.degenerate_message.empty();
  }
  if (flat && finite_in_ball == finite_)
    throw DegenerateRemovalError("removing vertex " + std::to_string(v) + " would leave " +
                                     std::to_string(link_.size()) + " points, all coplanar: no tetrahedron",
                                 {v});
  const auto mesh_id = [&](std::uint32_t u) { return u == kInfinite ? kInfinite : link_[u]; };
  if (flat) {
    // v on the hull above a flat link: each finite boundary facet becomes a hull facet.
    ++stats_.flat_links;
    remove_ball(v);
    open_.clear();
    for (const Triple& f : faces_) {
      if (f[0] == kInfinite || f[1] == kInfinite || f[2] == kInfinite) continue;
      const std::uint32_t t = add({mesh_id(f[0]), mesh_id(f[1]), mesh_id(f[2]), kInfinite});
      for (std::uint32_t i = 0; i < 4; ++i) open_.push_back(4 * t + i);
    }
    open_.insert(open_.end(), outside_.begin(), outside_.end());
    hint_ = Mesh3::tetrahedron_of(open_.front());
    glue(open_);
    ++stats_.removed;
    return;
  }

  // D's tetrahedra inside the hole: from the v side of each finite boundary facet, across facets
  // that are not boundary facets; a ghost of D is a facet of the new hull and is not crossed.
  const Tetrahedralization3& D = d.tetrahedralization;
  const std::uint32_t nd = static_cast<std::uint32_t>(D.tetrahedron_count());
  facets_.reset(4 * nd);
  for (std::uint32_t h = 0; h < 4 * nd; ++h) facets_.insert(sorted(D.facet_vertices(h)), h);
  boundary_.assign(4 * nd, kNone);  // a boundary facet of D: the index of its outside handle
  made_.assign(nd, kNone);          // a tetrahedron of D kept: its new tetrahedron
  queue_.clear();
  for (std::uint32_t k = 0; k < faces_.size(); ++k) {
    const Triple& f = faces_[k];
    // A boundary facet through kInfinite borders the new hull; its ghost is reached from inside.
    if (f[0] == kInfinite || f[1] == kInfinite || f[2] == kInfinite) continue;
    std::uint32_t h = facets_.find(sorted(f));
    if (h == kNone)
      throw InternalError("remove: a boundary facet of vertex " + std::to_string(v) +
                          "'s ball is not in its link's tetrahedralization");
    if (!same_cycle(D.facet_vertices(h), f)) h = D.twin(h);
    boundary_[h] = k;
    const std::uint32_t t = Tetrahedralization3::tetrahedron_of(h);
    if (made_[t] == kNone) made_[t] = 0, queue_.push_back(t);
  }
  for (std::size_t k = 0; k < queue_.size(); ++k) {
    const std::uint32_t t = queue_[k];
    if (D.is_ghost(t)) continue;
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (boundary_[4 * t + i] != kNone) continue;
      const std::uint32_t u = D.adjacent(t, i);
      if (made_[u] == kNone) made_[u] = 0, queue_.push_back(u);
    }
  }
  remove_ball(v);
  for (const std::uint32_t t : queue_)
    made_[t] = add({mesh_id(D.vertex(t, 0)), mesh_id(D.vertex(t, 1)), mesh_id(D.vertex(t, 2)), mesh_id(D.vertex(t, 3))});
  // Links: D's own between kept tetrahedra (their vertex order is D's), the boundary facets to
  // the handles outside, and by vertex triples the rim of the new hull to the ghosts around it.
  open_.clear();
  for (const std::uint32_t t : queue_) {
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = 4 * t + i, mine = 4 * made_[t] + i;
      if (boundary_[h] != kNone) {
        mesh_.link(mine, outside_[boundary_[h]]);
        continue;
      }
      const std::uint32_t g = D.twin(h);
      const std::uint32_t u = Tetrahedralization3::tetrahedron_of(g);
      if (made_[u] != kNone) mesh_.link(mine, 4 * made_[u] + (g & 3u));
      else open_.push_back(mine);
    }
  }
  for (std::uint32_t k = 0; k < faces_.size(); ++k) {
    const Triple& f = faces_[k];
    if (f[0] == kInfinite || f[1] == kInfinite || f[2] == kInfinite) open_.push_back(outside_[k]);
  }
  glue(open_);
  hint_ = made_[queue_.front()];
  ++stats_.removed;
}

void DynamicDelaunay3::remove_ball(std::uint32_t v) {
  for (const std::uint32_t t : ball_) {
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_tetrahedron(t);
  }
  mesh_.remove_vertex(v);
}

Delaunay3dRemoval delaunay3d_remove(std::span<const Vec3> points, std::span<const std::uint32_t> indices,
                                     const Delaunay3dOptions& options) {
  return remove_points<DynamicDelaunay3, 4, DynamicDelaunay3Stats>(points, indices, options);
}

}  // namespace dtlab
