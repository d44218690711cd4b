// Insertion (Bowyer-Watson cavity) and removal (the link's Delaunay tetrahedralization restricted
// to the hole) on a Mesh3 under the kernel's perturbed in-sphere test; see dynamic_delaunay3.hpp
// for why the result is the tetrahedralization of the survivors built from scratch.
#include "algorithms/delaunay3d/dynamic_delaunay3.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"

namespace dtlab {
namespace {

constexpr std::uint32_t kInfinite = Mesh3::kInfinite;
constexpr std::uint32_t kNone = Mesh3::kNone;
using Triple = std::array<std::uint32_t, 3>;

std::string show(const Vec3& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

Triple sorted(Triple f) {
  std::sort(f.begin(), f.end());
  return f;
}

// f and g hold the same vertices in the same cyclic order.
bool same_cycle(const Triple& f, const Triple& g) {
  return f == g || f == Triple{g[1], g[2], g[0]} || f == Triple{g[2], g[0], g[1]};
}

}  // namespace

DynamicDelaunay3::DynamicDelaunay3(std::span<const Vec3> points, const Delaunay3dOptions& options)
    : link_options_(options) {
  link_options_.threads = 1;
  Delaunay3dResult r = delaunay3d(points, options);
  if (!r.duplicates.empty())
    throw DuplicatePointError("point " + std::to_string(r.duplicates[0]) + " repeats point " +
                                  std::to_string(r.duplicate_of[0]),
                              {r.duplicate_of[0], r.duplicates[0]});
  if (!r.degenerate_message.empty()) throw DegenerateRemovalError("no tetrahedron: " + r.degenerate_message, {});
  std::vector<int> refs(r.tetrahedralization.tetrahedron_count(), 0);
  mesh_ = Mesh3(r.tetrahedralization, refs, {});
  finite_ = r.tetrahedralization.finite_tetrahedron_count();
  hint_ = 0;
}

bool DynamicDelaunay3::contains(std::uint32_t v) const noexcept {
  return v < mesh_.vertex_capacity() && !mesh_.is_dead_vertex(v) && mesh_.vertex_tetrahedron(v) != kNone;
}

std::vector<std::array<std::uint32_t, 4>> DynamicDelaunay3::finite_tetrahedra() const {
  std::vector<std::array<std::uint32_t, 4>> out;
  out.reserve(finite_);
  for (std::uint32_t t = 0; t < mesh_.tetrahedron_capacity(); ++t)
    if (mesh_.is_alive(t) && !mesh_.is_ghost(t)) out.push_back(mesh_.tetrahedron(t));
  return out;
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

// Links the facets of the new tetrahedra `fresh` to each other and to the facet handles
// `outside` (in live tetrahedra around the change) by their vertex triples: each triple must
// occur exactly twice.
void DynamicDelaunay3::glue(std::span<const std::uint32_t> fresh, std::span<const std::uint32_t> outside) {
  static thread_local std::vector<std::pair<Triple, std::uint32_t>> open;
  open.clear();
  for (const std::uint32_t t : fresh)
    for (std::uint32_t i = 0; i < 4; ++i) open.emplace_back(sorted(mesh_.facet_vertices(4 * t + i)), 4 * t + i);
  for (const std::uint32_t h : outside) open.emplace_back(sorted(mesh_.facet_vertices(h)), h);
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
  check_coordinates(std::span<const Vec3>(&p, 1), "inserted point");
  const Mesh3::Location loc = mesh_.locate(p, hint_);
  if (loc.where == Mesh3::Where::Vertex)
    throw DuplicatePointError("inserted point " + show(p) + " is vertex " + std::to_string(loc.handle) + " already",
                              {loc.handle});
  const std::uint32_t start = loc.tetrahedron;
  DTLAB_ASSERT(in_conflict(start, p));
  epoch_ += 2;
  if (stamp_.size() < mesh_.tetrahedron_capacity()) stamp_.resize(mesh_.tetrahedron_capacity(), 0);
  static thread_local std::vector<Triple> faces;
  faces.clear();
  outside_.clear();
  cavity_.clear();
  stack_.assign(1, start);
  stamp_[start] = epoch_;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    DTLAB_ASSERT(cavity_.size() <= mesh_.live_tetrahedron_count());
    for (std::uint32_t h = 4 * t; h < 4 * t + 4; ++h) {
      const std::uint32_t g = mesh_.twin(h);
      const std::uint32_t u = Mesh3::tetrahedron_of(g);
      if (stamp_[u] == epoch_) continue;
      if (stamp_[u] != epoch_ + 1 && in_conflict(u, p)) {
        stamp_[u] = epoch_;
        stack_.push_back(u);
      } else {
        stamp_[u] = epoch_ + 1;
        faces.push_back(mesh_.facet_vertices(h));
        outside_.push_back(g);
      }
    }
  }
  stats_.cavity_tetrahedra += cavity_.size();
  for (const std::uint32_t t : cavity_) {
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_tetrahedron(t);
  }
  const std::uint32_t vp = mesh_.add_vertex(p, Metric3{}, 0);
  fresh_.clear();
  for (const Triple& f : faces) fresh_.push_back(add({f[0], f[1], f[2], vp}));  // p where the apex was
  glue(fresh_, outside_);
  hint_ = fresh_.front();
  ++stats_.inserted;
  return vp;
}

void DynamicDelaunay3::remove(std::uint32_t v) {
  if (!contains(v)) throw UnknownVertexError(v);
  mesh_.ball(v, ball_);
  // The link's finite vertices, sorted (D's vertex k is link[k]); the ball's boundary facets,
  // each as seen from v, and the handles outside them.
  std::vector<std::uint32_t> link;
  std::vector<Triple> faces;
  outside_.clear();
  std::uint64_t finite_in_ball = 0;
  for (const std::uint32_t t : ball_) {
    finite_in_ball += mesh_.is_ghost(t) ? 0 : 1;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t u = mesh_.vertex(t, i);
      if (u == v) {
        faces.push_back(mesh_.facet_vertices(4 * t + i));
        outside_.push_back(mesh_.twin(4 * t + i));
      } else if (u != kInfinite) {
        link.push_back(u);
      }
    }
  }
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  stats_.link_vertices += link.size();
  std::vector<Vec3> link_points;
  link_points.reserve(link.size());
  for (const std::uint32_t u : link) link_points.push_back(mesh_.point(u));
  Delaunay3dResult d;
  bool flat = link.size() < 4;
  if (!flat) {
    d = delaunay3d(link_points, link_options_);
    flat = !d.degenerate_message.empty();
  }
  if (flat && finite_in_ball == finite_)
    throw DegenerateRemovalError("removing vertex " + std::to_string(v) + " would leave " +
                                     std::to_string(link.size()) + " points, all coplanar: no tetrahedron",
                                 {v});

  // The new tetrahedra, in mesh ids.
  std::vector<std::array<std::uint32_t, 4>> made;
  if (flat) {
    // v on the hull above a flat link: each finite boundary facet becomes a hull facet.
    ++stats_.flat_links;
    for (const Triple& f : faces)
      if (f[0] != kInfinite && f[1] != kInfinite && f[2] != kInfinite) made.push_back({f[0], f[1], f[2], kInfinite});
  } else {
    const Tetrahedralization3& D = d.tetrahedralization;
    const auto id = [&](std::uint32_t u) {
      return u == kInfinite ? kInfinite
                            : static_cast<std::uint32_t>(std::lower_bound(link.begin(), link.end(), u) - link.begin());
    };
    std::vector<std::pair<Triple, std::uint32_t>> index;  // D's facets by sorted triple
    index.reserve(4 * D.tetrahedron_count());
    for (std::uint32_t h = 0; h < 4 * D.tetrahedron_count(); ++h) index.emplace_back(sorted(D.facet_vertices(h)), h);
    std::sort(index.begin(), index.end());
    std::vector<std::uint8_t> boundary(4 * D.tetrahedron_count(), 0), taken(D.tetrahedron_count(), 0);
    std::vector<std::uint32_t> queue;
    for (const Triple& f : faces) {
      // A boundary facet through kInfinite borders the new hull; its ghost is reached from inside.
      if (f[0] == kInfinite || f[1] == kInfinite || f[2] == kInfinite) continue;
      const Triple g{id(f[0]), id(f[1]), id(f[2])};
      const Triple key = sorted(g);
      auto it = std::lower_bound(index.begin(), index.end(), std::pair{key, 0u});
      std::uint32_t found = kNone;
      for (; it != index.end() && it->first == key; ++it)
        if (same_cycle(D.facet_vertices(it->second), g)) found = it->second;
      if (found == kNone)
        throw InternalError("remove: a boundary facet of vertex " + std::to_string(v) +
                            "'s ball is not in its link's tetrahedralization");
      boundary[found] = 1;
      const std::uint32_t t = Tetrahedralization3::tetrahedron_of(found);
      if (!taken[t]) taken[t] = 1, queue.push_back(t);
    }
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const std::uint32_t t = queue[k];
      if (D.is_ghost(t)) continue;  // a facet of the new hull: its ghost comes in, nothing beyond
      for (std::uint32_t i = 0; i < 4; ++i) {
        if (boundary[4 * t + i]) continue;
        const std::uint32_t u = D.adjacent(t, i);
        if (!taken[u]) taken[u] = 1, queue.push_back(u);
      }
    }
    for (const std::uint32_t t : queue) {
      std::array<std::uint32_t, 4> q{};
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t u = D.vertex(t, i);
        q[i] = u == kInfinite ? kInfinite : link[u];
      }
      made.push_back(q);
    }
  }

  for (const std::uint32_t t : ball_) {
    if (!mesh_.is_ghost(t)) --finite_;
    mesh_.remove_tetrahedron(t);
  }
  mesh_.remove_vertex(v);
  fresh_.clear();
  for (const auto& q : made) fresh_.push_back(add(q));
  glue(fresh_, outside_);
  hint_ = fresh_.front();
  ++stats_.removed;
}

std::uint32_t DynamicDelaunay3::move(std::uint32_t v, const Vec3& p) {
  if (!contains(v)) throw UnknownVertexError(v);
  if (mesh_.point(v) == p) return v;
  check_coordinates(std::span<const Vec3>(&p, 1), "moved point");
  const Mesh3::Location loc = mesh_.locate(p, hint_);
  if (loc.where == Mesh3::Where::Vertex)
    throw DuplicatePointError("vertex " + std::to_string(v) + " cannot move to " + show(p) + ": vertex " +
                                  std::to_string(loc.handle) + " is there",
                              {loc.handle});
  remove(v);
  return insert(p);
}

Delaunay3dRemoval delaunay3d_remove(std::span<const Vec3> points, std::span<const std::uint32_t> indices,
                                     const Delaunay3dOptions& options) {
  return remove_points<DynamicDelaunay3, 4, DynamicDelaunay3Stats>(points, indices, options);
}

}  // namespace dtlab
