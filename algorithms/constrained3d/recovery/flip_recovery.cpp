// Edge and triangle recovery by flips and edge removals (flip_recovery.hpp).
#include "algorithms/constrained3d/recovery/flip_recovery.hpp"

#include <algorithm>
#include <unordered_set>

#include "algorithms/shell/polygon_triangulations.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_sets3.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kNone = T3::kNone;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr auto kFacet = T3::kFacetVertex;
// Shells larger than this are not searched: Cat(n - 1) triangulations (4862 at n = 11). Up to
// kLargestFannedShell, only their fans are tried (a vertex of the ring joined to all others: the
// walk's own transformation, where a Steiner point just beside a hull edge in the plane of a
// flat face must fan that edge's shell, often more than 10 tetrahedra; Chazelle's polyhedron).
constexpr int kLargestShell = 10;
constexpr int kLargestFannedShell = 64;
// Steps of one walk or one triangle's recovery (each removes a tetrahedron from a pipe or an
// edge crossing a triangle; the bound only guards against a broken invariant).
constexpr int kSteps = 512;
// Link removals per edge recovery (remove_edge_after_link): on fandisk 2 gave 34 Steiner points and
// 821 M instructions, 4 gave 35 and 840 M, 16 gave 37 and 954 M (none: 64 and 827 M).
constexpr int kLinkRemovals = 2;

std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) noexcept {
  return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
}
// The index of kInfinite in tuple t, or 4 if it is a finite tetrahedron.
std::uint32_t infinite_index(const FlipMesh::Tuple& t) noexcept {
  for (std::uint32_t j = 0; j < 4; ++j)
    if (t[j] == kInf) return j;
  return 4;
}

// x, y, z on one line, exactly: every coordinate projection flat.
bool collinear(const Vec3& x, const Vec3& y, const Vec3& z) {
  return orient2d(Vec2{x.x, x.y}, Vec2{y.x, y.y}, Vec2{z.x, z.y}) == Sign::Zero &&
         orient2d(Vec2{x.y, x.z}, Vec2{y.y, y.z}, Vec2{z.y, z.z}) == Sign::Zero &&
         orient2d(Vec2{x.z, x.x}, Vec2{y.z, y.x}, Vec2{z.z, z.x}) == Sign::Zero;
}

std::array<std::uint32_t, 3> face_key(std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
  std::array<std::uint32_t, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

FlipRecovery::FlipRecovery(Tetrahedralization3& mesh, std::vector<std::uint64_t> protected_edges,
                           std::vector<std::array<std::uint32_t, 3>> protected_faces)
    : mesh_(mesh),
      records_(mesh.mutable_records()),
      flips_mesh_(mesh.mutable_records(), FlipMesh::Adopt{}),
      vertex_tet_(vertex_tetrahedra(mesh)),
      protected_edges_(std::move(protected_edges)),
      protected_faces_(std::move(protected_faces)) {}

// The sets hold only what the constructor's sorted lists do not (pieces made by splits).
void FlipRecovery::protect_edge(std::uint32_t u, std::uint32_t v) {
  const std::uint64_t k = edge_key(u, v);
  if (!std::binary_search(protected_edges_.begin(), protected_edges_.end(), k)) extra_edges_.insert(k);
}
void FlipRecovery::protect_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const auto k = face_key(a, b, c);
  if (!std::binary_search(protected_faces_.begin(), protected_faces_.end(), k)) extra_faces_.insert(k);
}

void FlipRecovery::unprotect_edge(std::uint32_t u, std::uint32_t v) { extra_edges_.erase(edge_key(u, v)); }
void FlipRecovery::unprotect_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  extra_faces_.erase(face_key(a, b, c));
}

bool FlipRecovery::is_protected_edge(std::uint32_t u, std::uint32_t v) const {
  const std::uint64_t k = edge_key(u, v);
  return std::binary_search(protected_edges_.begin(), protected_edges_.end(), k) ||
         extra_edges_.count(k) != 0;
}
bool FlipRecovery::is_protected_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  const auto k = face_key(a, b, c);
  return std::binary_search(protected_faces_.begin(), protected_faces_.end(), k) ||
         extra_faces_.count(k) != 0;
}

void FlipRecovery::finish() { flips_mesh_.finish(); }

template <class Visit>
std::uint32_t FlipRecovery::search_ball_of(std::uint32_t u, std::vector<std::uint32_t>& list, Visit&& visit) {
  if (mark_.size() < records_.size()) mark_.resize(records_.size(), 0);
  ++stamp_;
  const std::uint32_t found = nav3::search_ball(mesh_, u, vertex_tet_[u], list, nav3::marking(mark_, stamp_), visit);
  if (list.size() > records_.size()) throw InternalError("flip recovery: a vertex ball exceeded the mesh");
  return found;
}

void FlipRecovery::ball_of(std::uint32_t u, std::vector<std::uint32_t>& out) {
  out.clear();
  if (u >= vertex_tet_.size() || vertex_tet_[u] == kNone) return;
  DTLAB_ASSERT(alive(vertex_tet_[u]));
  search_ball_of(u, out, [](std::uint32_t) { return false; });
}

std::uint32_t FlipRecovery::tetrahedron_with(std::uint32_t u, std::uint32_t v, std::uint32_t w) {
  // The search of ball_of (nav3::search_ball's breadth-first order), ending at the first
  // tetrahedron that holds v (and w). Written out, not through nav3::search_ball: the hot loop of
  // the 3D constrained methods (16 % of `constrain --method cdt`'s instructions), 15 % more
  // instructions through the generic search (callgrind, 2026-12-07).
  if (u >= vertex_tet_.size() || vertex_tet_[u] == kNone) return kNone;
  if (mark_.size() < records_.size()) mark_.resize(records_.size(), 0);
  ++stamp_;
  walk_.assign(1, vertex_tet_[u]);
  mark_[walk_[0]] = stamp_;
  for (std::size_t k = 0; k < walk_.size(); ++k) {
    const auto& rec = records_[walk_[k]];
    const auto& x = rec.vertex;
    if (x[0] != kInf) {
      const bool has_v = x[0] == v || x[1] == v || x[2] == v || x[3] == v;
      const bool has_w = w == kNone || x[0] == w || x[1] == w || x[2] == w || x[3] == w;
      if (has_v && has_w) return walk_[k];
    }
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (x[i] == u) continue;
      const std::uint32_t n = rec.neighbour[i] >> 2;
      if (mark_[n] != stamp_) mark_[n] = stamp_, walk_.push_back(n);
    }
  }
  if (walk_.size() > records_.size()) throw InternalError("flip recovery: a vertex ball exceeded the mesh");
  return kNone;
}

bool FlipRecovery::has_edge(std::uint32_t u, std::uint32_t v) { return tetrahedron_with(u, v) != kNone; }
bool FlipRecovery::has_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return tetrahedron_with(a, b, c) != kNone;
}

void FlipRecovery::replaced(std::span<const std::uint32_t> ids) {
  for (const std::uint32_t t : ids)
    for (const std::uint32_t v : records_[t].vertex) {
      if (v == kInf) continue;
      vertex_tet_[v] = t;
      if (marks_) {
        if (v >= marks_->size()) marks_->resize(v + 1, 0);
        (*marks_)[v] = 1;
      }
    }
}

bool FlipRecovery::flip23(std::uint32_t t, std::uint32_t i) {
  const auto rec = records_[t];
  const std::uint32_t g = rec.neighbour[i], t2 = g >> 2;
  const std::uint32_t p = rec.vertex[i], q = records_[t2].vertex[g & 3u];
  if (rec.vertex[0] == kInf || records_[t2].vertex[0] == kInf) return false;
  const std::uint32_t a = rec.vertex[kFacet[i][0]], b = rec.vertex[kFacet[i][1]], c = rec.vertex[kFacet[i][2]];
  if (is_protected_face(a, b, c)) return false;
  // pq through the open triangle abc: the two tetrahedra's union is convex across it.
  const Sign s1 = orient3d(P(p), P(q), P(a), P(b));
  if (s1 == Sign::Zero || orient3d(P(p), P(q), P(b), P(c)) != s1 || orient3d(P(p), P(q), P(c), P(a)) != s1)
    return false;
  std::array<Tuple, 3> fresh;
  const std::uint32_t ring[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t x = ring[k], y = ring[(k + 1) % 3];
    fresh[k] = orient3d(P(x), P(y), P(p), P(q)) == Sign::Positive ? Tuple{x, y, p, q} : Tuple{y, x, p, q};
  }
  const std::uint32_t old[2] = {t, t2};
  flips_mesh_.replace(old, fresh, ids_);
  replaced(ids_);
  ++flips_;
  return true;
}

template <class Accept>
bool FlipRecovery::remove_edge(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, Accept&& accept) {
  if (is_protected_edge(e0, e1)) return false;
  const std::vector<std::uint32_t> sh = shell(mesh_, t, e0, e1);
  const int n = static_cast<int>(sh.size());
  if (n < 3 || n > kLargestFannedShell) return false;
  // ring[k]: the vertex shared by shell tetrahedra k and k + 1 besides e0, e1.
  std::vector<std::uint32_t> ring(n);
  for (int k = 0; k < n; ++k) {
    const auto& x = records_[sh[k]].vertex;
    const auto& y = records_[sh[(k + 1) % n]].vertex;
    ring[k] = kNone;
    for (const std::uint32_t v : x)
      if (v != e0 && v != e1 && std::find(y.begin(), y.end(), v) != y.end()) ring[k] = v;
    if (ring[k] == kNone) return false;
    if (is_protected_face(e0, e1, ring[k])) return false;
  }
  // (a, b, ring[k], ring[k + 1]) positive: read off a finite tetrahedron of the shell.
  std::uint32_t a = e0, b = e1;
  {
    int k = 0;
    while (k < n && (ring[k] == kInf || ring[(k + 1) % n] == kInf)) ++k;
    if (k == n) return false;
    const Sign turn = orient3d(P(a), P(b), P(ring[k]), P(ring[(k + 1) % n]));
    if (turn == Sign::Zero) return false;
    if (turn == Sign::Negative) std::swap(a, b);
  }
  // A new tetrahedron is valid if positive; a new ghost (the edge is on the hull) if its hull
  // facet is a proper triangle with no vertex of the shell strictly beyond it, so that the hull
  // stays convex (tetrahedralization3.hpp: orient3d(q, x, y, z) > 0 for q beyond facet xyz).
  const auto valid_tuple = [&](const Tuple& tuple) {
    const std::uint32_t m = infinite_index(tuple);
    if (m == 4) return orient3d(P(tuple[0]), P(tuple[1]), P(tuple[2]), P(tuple[3])) == Sign::Positive;
    const Vec3 &x = P(tuple[1 ^ m]), &y = P(tuple[2 ^ m]), &z = P(tuple[3 ^ m]);
    if (collinear(x, y, z)) return false;
    for (const std::uint32_t p : ring)
      if (p != kInf && orient3d(P(p), x, y, z) == Sign::Positive) return false;
    return orient3d(P(a), x, y, z) != Sign::Positive && orient3d(P(b), x, y, z) != Sign::Positive;
  };
  // Triangle (i, j, k) of the ring polygon, increasing: (w_i, w_j, w_k, b) and (w_k, w_j, w_i, a)
  // both valid. Cached: a triangle occurs in many triangulations.
  std::vector<std::int8_t> valid(static_cast<std::size_t>(n * n * n), -1);
  const auto is_valid = [&](const PolygonTriangle& tr) {
    std::int8_t& v = valid[(tr[0] * n + tr[1]) * n + tr[2]];
    if (v < 0) {
      const std::uint32_t wi = ring[tr[0]], wj = ring[tr[1]], wk = ring[tr[2]];
      v = valid_tuple({wi, wj, wk, b}) && valid_tuple({wk, wj, wi, a});
    }
    return v == 1;
  };
  std::vector<PolygonTriangle> chosen;
  if (n <= kLargestShell) {
    chosen = find_polygon_triangulation(n, is_valid,
                                        [&](const std::vector<PolygonTriangle>& tris) { return accept(ring, tris); });
  } else {
    std::vector<PolygonTriangle> fan;
    for (int r = 0; r < n && chosen.empty(); ++r) {
      fan.clear();
      for (int k = 1; k + 1 < n; ++k) {
        std::array<int, 3> tr{r, (r + k) % n, (r + k + 1) % n};
        std::sort(tr.begin(), tr.end());
        fan.push_back({static_cast<std::uint8_t>(tr[0]), static_cast<std::uint8_t>(tr[1]), static_cast<std::uint8_t>(tr[2])});
        if (!is_valid(fan.back())) break;
      }
      if (fan.size() == static_cast<std::size_t>(n - 2) && is_valid(fan.back()) && accept(ring, fan)) chosen = fan;
    }
  }
  if (chosen.empty()) return false;
  std::vector<Tuple> fresh;
  fresh.reserve(2 * chosen.size());
  for (const PolygonTriangle& tr : chosen) {
    fresh.push_back({ring[tr[0]], ring[tr[1]], ring[tr[2]], b});
    fresh.push_back({ring[tr[2]], ring[tr[1]], ring[tr[0]], a});
  }
  flips_mesh_.replace(sh, fresh, ids_);
  replaced(ids_);
  ++removals_;
  return true;
}

bool FlipRecovery::flip_about_edge(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, std::uint32_t p,
                                   std::uint32_t d, std::size_t shell_size) {
  if (shell(mesh_, t, e0, e1).size() != shell_size) return false;
  // Three tetrahedra: the one triangle. Four (p, d and e0, e1 coplanar): the diagonal pd.
  const auto with_pd = [&](const std::vector<std::uint32_t>& ring, const std::vector<PolygonTriangle>& tris) {
    const auto ip = std::find(ring.begin(), ring.end(), p), id = std::find(ring.begin(), ring.end(), d);
    if (ip == ring.end() || id == ring.end()) return false;
    const auto rp = static_cast<std::uint8_t>(ip - ring.begin()), rd = static_cast<std::uint8_t>(id - ring.begin());
    return std::any_of(tris.begin(), tris.end(), [&](const PolygonTriangle& tr) {
      return (tr[0] == rp || tr[1] == rp || tr[2] == rp) && (tr[0] == rd || tr[1] == rd || tr[2] == rd);
    });
  };
  return remove_edge(t, e0, e1, with_pd);
}

template <class Accept>
bool FlipRecovery::remove_edge_after_link(std::uint32_t t, std::uint32_t e0, std::uint32_t e1, Accept&& accept) {
  if (is_protected_edge(e0, e1)) return false;
  std::vector<std::uint32_t> link;
  for (const std::uint32_t s : shell(mesh_, t, e0, e1))
    for (const std::uint32_t w : records_[s].vertex)
      if (w != e0 && w != e1 && w != kInf && std::find(link.begin(), link.end(), w) == link.end()) link.push_back(w);
  const auto any = [](const std::vector<std::uint32_t>&, const std::vector<PolygonTriangle>&) { return true; };
  for (const std::uint32_t w : link)
    for (const std::uint32_t x : {e0, e1}) {
      if (link_budget_ <= 0) return false;
      if (is_protected_edge(x, w)) continue;
      const std::uint32_t tx = tetrahedron_with(x, w);
      if (tx == kNone || !remove_edge(tx, x, w, any)) continue;
      --link_budget_;
      const std::uint32_t te = tetrahedron_with(e0, e1);
      if (te != kNone) remove_edge(te, e0, e1, accept);
      return true;
    }
  return false;
}

bool FlipRecovery::advance(std::uint32_t u, std::uint32_t v) {
  ball_of(u, ball_);
  const std::vector<std::uint32_t> ball = ball_;
  for (const std::uint32_t t : ball) {
    const auto& x = records_[t].vertex;
    if (x[0] == kInf) continue;
    std::uint32_t i = 0;
    while (x[i] != u) ++i;
    const std::uint32_t a = x[kFacet[i][0]], b = x[kFacet[i][1]], c = x[kFacet[i][2]];
    const Sign tau = orient3d(P(u), P(a), P(b), P(c));
    if (tau == Sign::Zero) continue;
    // v = u + alpha (a - u) + beta (b - u) + gamma (c - u): the signs below are those of
    // gamma, alpha, beta times tau; uv leaves t through abc, an edge of it or a vertex.
    const Sign s[3] = {orient3d(P(u), P(a), P(b), P(v)), orient3d(P(u), P(b), P(c), P(v)),
                       orient3d(P(u), P(c), P(a), P(v))};
    int zeros = 0, against = 0;
    for (const Sign si : s) zeros += si == Sign::Zero, against += si != Sign::Zero && si != tau;
    if (against > 0) continue;
    if (zeros > 1) return false;  // through a vertex of abc
    // The shell's polygon fanned from u: every new tetrahedron holds u, so uv starts in one of
    // them and leaves the former shell at once; the shell held t and the next tetrahedron of
    // the pipe (uv leaves t through the edge, or through abc into the tetrahedron beyond, which
    // holds all three edges of abc).
    const auto fan_from_u = [&](const std::vector<std::uint32_t>& ring, const std::vector<PolygonTriangle>& tris) {
      const auto at = std::find(ring.begin(), ring.end(), u);
      if (at == ring.end()) return false;
      const auto r = static_cast<std::uint8_t>(at - ring.begin());
      return std::all_of(tris.begin(), tris.end(),
                         [&](const PolygonTriangle& tr) { return tr[0] == r || tr[1] == r || tr[2] == r; });
    };
    // Where v is on the shell's polygon too, any retriangulation with the diagonal uv makes the
    // edge at once (the two diagonals of a planar quadrilateral, as flat CAD faces give).
    const auto has_uv = [&](const std::vector<std::uint32_t>& ring, const std::vector<PolygonTriangle>& tris) {
      const auto iu = std::find(ring.begin(), ring.end(), u), iv = std::find(ring.begin(), ring.end(), v);
      if (iu == ring.end() || iv == ring.end()) return false;
      const auto ru = static_cast<std::uint8_t>(iu - ring.begin()), rv = static_cast<std::uint8_t>(iv - ring.begin());
      return std::any_of(tris.begin(), tris.end(), [&](const PolygonTriangle& tr) {
        const bool hu = tr[0] == ru || tr[1] == ru || tr[2] == ru, hv = tr[0] == rv || tr[1] == rv || tr[2] == rv;
        return hu && hv;
      });
    };
    const auto toward_v = [&](const std::vector<std::uint32_t>& ring, const std::vector<PolygonTriangle>& tris) {
      return has_uv(ring, tris) || fan_from_u(ring, tris);
    };
    bool moved;
    if (zeros == 0) {
      // Not convex across abc: one of its edges is reflex; remove one of them instead.
      moved = flip23(t, i) || remove_edge(t, a, b, toward_v) || remove_edge(t, b, c, toward_v) ||
              remove_edge(t, c, a, toward_v) ||
              (deep_ && (remove_edge_after_link(t, a, b, toward_v) || remove_edge_after_link(t, b, c, toward_v) ||
                         remove_edge_after_link(t, c, a, toward_v)));
      // (remove_edge_after_link is true whenever it changed the mesh, so t is intact for the next)
    } else {
      const std::uint32_t e0 = s[0] == Sign::Zero ? a : s[1] == Sign::Zero ? b : c;
      const std::uint32_t e1 = s[0] == Sign::Zero ? b : s[1] == Sign::Zero ? c : a;
      moved = remove_edge(t, e0, e1, toward_v) || (deep_ && remove_edge_after_link(t, e0, e1, toward_v));
    }
    if (!moved && block_[0] == kNone) block_ = {a, b, c};
    return moved;
  }
  return false;
}

bool FlipRecovery::recover_edge(std::uint32_t u, std::uint32_t v) {
  block_ = {kNone, kNone, kNone};
  link_budget_ = kLinkRemovals;
  for (int step = 0; step < kSteps; ++step) {
    if (has_edge(u, v)) return true;
    if (!advance(u, v) && !advance(v, u)) return false;
  }
  return has_edge(u, v);
}

std::uint32_t FlipRecovery::insert_point(const Vec3& p, std::uint32_t near) {
  // Search: from the ball of `near`, across every facet p lies strictly beyond.
  ball_of(near < vertex_tet_.size() ? near : 0, ball_);
  if (mark_.size() < records_.size()) mark_.resize(records_.size(), 0);
  ++stamp_;
  stack_.assign(ball_.begin(), ball_.end());
  for (const std::uint32_t t : stack_) mark_[t] = stamp_;
  std::uint32_t found = kNone;
  std::array<Sign, 4> side{};
  for (std::size_t k = 0; k < stack_.size() && found == kNone; ++k) {
    const std::uint32_t t = stack_[k];
    const auto& rec = records_[t];
    if (rec.vertex[0] == kInf) continue;
    bool inside = true;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto& f = kFacet[i];
      side[i] = orient3d(P(rec.vertex[f[0]]), P(rec.vertex[f[1]]), P(rec.vertex[f[2]]), p);
      if (side[i] != Sign::Negative) continue;
      inside = false;
      const std::uint32_t n = rec.neighbour[i] >> 2;
      if (mark_[n] != stamp_) mark_[n] = stamp_, stack_.push_back(n);
    }
    if (inside) found = t;
  }
  if (found == kNone) return kNone;  // outside the hull
  const auto rec = records_[found];
  std::vector<std::uint32_t> zero;
  for (std::uint32_t i = 0; i < 4; ++i)
    if (side[i] == Sign::Zero) zero.push_back(i);
  if (zero.size() > 2) return kNone;  // a vertex
  const auto pid = static_cast<std::uint32_t>(mesh_.point_count());
  std::vector<std::uint32_t> old;
  std::vector<Tuple> fresh;
  // Tetrahedron t's facets but the ones listed, each with p: positive, p being strictly on
  // the inner side of each.
  const auto cone = [&](std::uint32_t t, std::uint32_t skip_a, std::uint32_t skip_b) {
    const auto& x = records_[t].vertex;
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (x[i] == skip_a || x[i] == skip_b) continue;  // the facet opposite skip_a: the one p lies on
      const auto& f = kFacet[i];
      fresh.push_back({x[f[0]], x[f[1]], x[f[2]], pid});
    }
  };
  if (zero.empty()) {
    old = {found};
    const auto& f = kFacet;
    for (std::uint32_t i = 0; i < 4; ++i) fresh.push_back({rec.vertex[f[i][0]], rec.vertex[f[i][1]], rec.vertex[f[i][2]], pid});
  } else if (zero.size() == 1) {
    // On the facet opposite vertex i: both tetrahedra, less that facet.
    const std::uint32_t i = zero[0];
    const auto& f = kFacet[i];
    const std::uint32_t a = rec.vertex[f[0]], b = rec.vertex[f[1]], c = rec.vertex[f[2]];
    const std::uint32_t t2 = rec.neighbour[i] >> 2;
    if (is_protected_face(a, b, c)) return kNone;
    const std::uint32_t apex2 = records_[t2].vertex[rec.neighbour[i] & 3u];
    old = {found, t2};
    cone(found, rec.vertex[i], kNone);
    cone(t2, apex2, kNone);
  } else {
    // On the edge shared by the two zero facets: every tetrahedron of its shell, less the faces
    // through the edge.
    std::uint32_t e[2], m = 0;
    for (std::uint32_t i = 0; i < 4; ++i)
      if (i != zero[0] && i != zero[1]) e[m++] = rec.vertex[i];
    if (is_protected_edge(e[0], e[1])) return kNone;
    const std::vector<std::uint32_t> sh = shell(mesh_, found, e[0], e[1]);
    for (const std::uint32_t t : sh) {
      const auto& x = records_[t].vertex;
      for (const std::uint32_t w : x)
        if (w != e[0] && w != e[1] && is_protected_face(e[0], e[1], w)) return kNone;
    }
    old = sh;
    for (const std::uint32_t t : sh) {
      // The facets opposite e0 and e1 (each holds the other end and the two ring vertices).
      const auto& x = records_[t].vertex;
      for (std::uint32_t i = 0; i < 4; ++i) {
        if (x[i] != e[0] && x[i] != e[1]) continue;
        const auto& f = kFacet[i];
        fresh.push_back({x[f[0]], x[f[1]], x[f[2]], pid});
      }
    }
  }
  mesh_.mutable_points().push_back(p);
  vertex_tet_.push_back(kNone);
  // Every new tetrahedron proper, or the location was wrong.
  for (const Tuple& t : fresh)
    if (!proper(t)) {
      mesh_.mutable_points().pop_back();
      vertex_tet_.pop_back();
      return kNone;
    }
  flips_mesh_.replace(old, fresh, ids_);
  replaced(ids_);
  return pid;
}

std::uint32_t FlipRecovery::split_crossed_face(std::uint32_t u, std::uint32_t v, const std::array<std::uint32_t, 3>& abc,
                                               const Vec3& p) {
  const auto [a, b, c] = abc;
  for (const std::uint32_t x : abc)
    if (x == kNone || x == kInf) return kNone;
  // uv through the open triangle: the three sides seen along uv turn the same way.
  const Sign s = orient3d(P(u), P(v), P(a), P(b));
  if (s == Sign::Zero || orient3d(P(u), P(v), P(b), P(c)) != s || orient3d(P(u), P(v), P(c), P(a)) != s) return kNone;
  if (is_protected_face(a, b, c)) return kNone;
  const std::uint32_t t = tetrahedron_with(a, b, c);
  if (t == kNone) return kNone;
  const auto rec = records_[t];
  std::uint32_t i = 0;
  while (rec.vertex[i] == a || rec.vertex[i] == b || rec.vertex[i] == c) ++i;
  const std::uint32_t t2 = rec.neighbour[i] >> 2;
  if (records_[t2].vertex[0] == kInf) return kNone;
  // Each tetrahedron's facets other than abc (those opposite a, b and c), coned to p.
  const auto pid = static_cast<std::uint32_t>(mesh_.point_count());
  std::vector<Tuple> fresh;
  for (const std::uint32_t s2 : {t, t2}) {
    const auto& x = records_[s2].vertex;
    for (std::uint32_t j = 0; j < 4; ++j)
      if (x[j] == a || x[j] == b || x[j] == c) fresh.push_back({x[kFacet[j][0]], x[kFacet[j][1]], x[kFacet[j][2]], pid});
  }
  mesh_.mutable_points().push_back(p);
  if (!std::all_of(fresh.begin(), fresh.end(), [&](const Tuple& x) { return proper(x); })) {
    mesh_.mutable_points().pop_back();
    return kNone;
  }
  vertex_tet_.push_back(kNone);
  const std::uint32_t old[2] = {t, t2};
  flips_mesh_.replace(old, fresh, ids_);
  replaced(ids_);
  return pid;
}

bool FlipRecovery::proper(const Tuple& t) const {
  const std::uint32_t m = infinite_index(t);
  if (m == 4) return orient3d(P(t[0]), P(t[1]), P(t[2]), P(t[3])) == Sign::Positive;
  return !collinear(P(t[1 ^ m]), P(t[2 ^ m]), P(t[3 ^ m]));
}

std::uint32_t FlipRecovery::split_edge_at(std::uint32_t a, std::uint32_t b, const Vec3& p,
                                          std::vector<std::array<std::uint32_t, 2>>* children) {
  const std::uint32_t t = tetrahedron_with(a, b);
  if (t == kNone) return kNone;
  const auto pid = static_cast<std::uint32_t>(mesh_.point_count());
  const std::vector<std::uint32_t> sh = shell(mesh_, t, a, b);
  std::vector<Tuple> fresh;
  for (const std::uint32_t s : sh) {
    // The facets opposite a and b, each with p.
    const auto& x = records_[s].vertex;
    for (std::uint32_t i = 0; i < 4; ++i)
      if (x[i] == a || x[i] == b) fresh.push_back({x[kFacet[i][0]], x[kFacet[i][1]], x[kFacet[i][2]], pid});
    // On the hull: p beyond a hull facet at ab would leave the hull non-convex.
    if (x[0] == kInf && orient3d(p, P(x[1]), P(x[2]), P(x[3])) == Sign::Positive)
      return kNone;
  }
  mesh_.mutable_points().push_back(p);
  if (!std::all_of(fresh.begin(), fresh.end(), [&](const Tuple& x) { return proper(x); })) {
    mesh_.mutable_points().pop_back();
    return kNone;
  }
  vertex_tet_.push_back(kNone);
  flips_mesh_.replace(sh, fresh, ids_);
  replaced(ids_);
  if (children)
    for (std::size_t k = 0; k < ids_.size(); ++k) children->push_back({ids_[k], sh[k / 2]});  // two from each
  return pid;
}

bool FlipRecovery::crosses(std::uint32_t p, std::uint32_t q, std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  const Sign op = orient3d(P(a), P(b), P(c), P(p));
  if (op == Sign::Zero || orient3d(P(a), P(b), P(c), P(q)) != -op) return false;
  const Sign s1 = orient3d(P(p), P(q), P(a), P(b));
  return s1 != Sign::Zero && orient3d(P(p), P(q), P(b), P(c)) == s1 && orient3d(P(p), P(q), P(c), P(a)) == s1;
}

void FlipRecovery::crossing_edges(std::uint32_t a, std::uint32_t b, std::uint32_t c,
                                  std::vector<std::array<std::uint32_t, 3>>& out) {
  out.clear();
  std::vector<std::uint32_t> seeds;
  for (const std::uint32_t v : {a, b, c}) {
    ball_of(v, ball_);
    seeds.insert(seeds.end(), ball_.begin(), ball_.end());
  }
  if (mark_.size() < records_.size()) mark_.resize(records_.size(), 0);
  ++stamp_;
  stack_.clear();
  for (const std::uint32_t t : seeds)
    if (mark_[t] != stamp_) mark_[t] = stamp_, stack_.push_back(t);
  std::unordered_set<std::uint64_t> tested, crossing;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    const auto rec = records_[t];
    if (rec.vertex[0] == kInf) continue;
    bool any = false;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint32_t p = rec.vertex[i], q = rec.vertex[j];
        if (p == a || p == b || p == c || q == a || q == b || q == c) continue;
        const std::uint64_t k = edge_key(p, q);
        if (tested.insert(k).second && crosses(p, q, a, b, c)) {
          crossing.insert(k);
          out.push_back({std::min(p, q), std::max(p, q), t});
        }
        any = any || crossing.count(k) != 0;
      }
    if (!any) continue;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t n = rec.neighbour[i] >> 2;
      if (mark_[n] != stamp_) mark_[n] = stamp_, stack_.push_back(n);
    }
  }
  std::sort(out.begin(), out.end());
}

std::array<std::uint32_t, 2> FlipRecovery::crossing_edge(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::vector<std::array<std::uint32_t, 3>> crossing;
  crossing_edges(a, b, c, crossing);
  if (crossing.empty()) return {kNone, kNone};
  return {crossing.front()[0], crossing.front()[1]};
}

bool FlipRecovery::recover_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (!has_edge(a, b) || !has_edge(b, c) || !has_edge(c, a)) return false;
  std::vector<std::array<std::uint32_t, 3>> crossing;
  for (int step = 0; step < kSteps; ++step) {
    if (has_face(a, b, c)) return true;
    crossing_edges(a, b, c, crossing);
    bool progress = false;
    for (const auto& [p, q, t] : crossing) {
      if (!alive(t)) continue;
      // No new edge (a diagonal of the shell's polygon) may cross abc: the crossings decrease.
      progress = remove_edge(t, p, q, [&](const std::vector<std::uint32_t>& ring, const std::vector<PolygonTriangle>& tris) {
        const int n = static_cast<int>(ring.size());
        for (const PolygonTriangle& tr : tris)
          for (int x = 0; x < 3; ++x)
            for (int y = x + 1; y < 3; ++y) {
              const int i = tr[x], j = tr[y];
              if (j - i == 1 || (i == 0 && j == n - 1)) continue;  // a side of the polygon
              if (crosses(ring[i], ring[j], a, b, c)) return false;
            }
        return true;
      });
      if (progress) break;
    }
    if (!progress) return has_face(a, b, c);
  }
  return has_face(a, b, c);
}

}  // namespace dtlab
