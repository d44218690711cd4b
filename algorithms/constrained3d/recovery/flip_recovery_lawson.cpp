// Lawson's flips with constraints (FlipRecovery::make_constrained_delaunay, flip_recovery.hpp):
// what turns a recovered tetrahedralization into a constrained Delaunay one where flips can.
// Face abc between t = (a, b, c, p) and u = (a, b, c, d) is not locally Delaunay when d is
// strictly inside the sphere of t (exact insphere, no perturbation: a CDT allows cospherical
// vertices, and the input triangles may fix their choice; checks3d.hpp decides the same). It is
// flipped 2->3 when segment pd crosses its open interior, else 3->2 or 4->4 about the edge of
// abc that pd passes beyond or through (Joe 1991; the flips of flip_insertion.cpp), never
// removing a protected edge or face. A face that cannot be flipped now is tried again when the
// queue runs empty; the pass ends when a retry flips nothing. Each flip strictly lowers the
// lifted tetrahedralization, so no tetrahedralization repeats and the pass ends; the flip bound
// backs that up.
#include <algorithm>

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {
using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;
}  // namespace

bool FlipRecovery::lawson_step(std::uint32_t h, bool& blocked, std::array<std::uint32_t, 2>& blocking_edge,
                               bool& direct_blame) {
  blocked = false;
  const std::uint32_t t = h >> 2, i = h & 3u;
  const auto rec = records_[t];
  if (rec.vertex[0] == kInf || (t < lawson_skip_.size() && lawson_skip_[t])) return false;
  const std::uint32_t g = rec.neighbour[i], u = g >> 2;
  const std::uint32_t p = rec.vertex[i], d = records_[u].vertex[g & 3u];
  if (records_[u].vertex[0] == kInf) return false;  // a hull face
  const auto& v = rec.vertex;
  // Most faces pass this test: it comes before the search of the protected ones.
  if (insphere(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(d)) != Sign::Positive) return false;
  const std::uint32_t a = rec.vertex[kFacet[i][0]], b = rec.vertex[kFacet[i][1]], c = rec.vertex[kFacet[i][2]];
  if (is_protected_face(a, b, c)) return false;
  if (flip23(t, i)) return true;
  // (a, b, c, p) is positive: pd passes beyond edge xy of abc where (x, y, p, d) is positive
  // (abc listed as t lists it), through it where zero. Only such an edge can go.
  const std::uint32_t ring[3] = {a, b, c};
  blocking_edge = {kNone, kNone};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t x = ring[k], y = ring[(k + 1) % 3];
    const Sign side = orient3d(P(x), P(y), P(p), P(d));
    if (side == Sign::Negative) continue;
    if (flip_about_edge(t, x, y, p, d, side == Sign::Zero ? 4 : 3)) return true;
    if (blocking_edge[0] == kNone && is_protected_edge(x, y)) blocking_edge = {x, y};
  }
  direct_blame = blocking_edge[0] != kNone;
  if (!direct_blame) {
    // No constraint in the way of these flips: the longest protected edge of the two
    // tetrahedra, whose split changes them.
    const std::uint32_t w[5] = {a, b, c, p, d};
    double longest = -1;
    for (int j = 0; j < 5; ++j)
      for (int k = j + 1; k < 5; ++k) {
        if ((j == 3 && k == 4) || !is_protected_edge(w[j], w[k])) continue;
        const Vec3 e = P(w[k]) - P(w[j]);
        if (dot(e, e) > longest) longest = dot(e, e), blocking_edge = {w[j], w[k]};
      }
  }
  blocked = true;
  return false;
}

std::vector<FlipRecovery::NotLocallyDelaunay> FlipRecovery::make_constrained_delaunay(
    std::uint64_t max_flips, std::vector<std::uint8_t> skip) {
  // A flip's tetrahedra meet across faces that are no constraint, so they lie in one region
  // and so do the new ones, which take over their slots (and new slots, not skipped).
  lawson_skip_ = std::move(skip);
  // Faces are queued by handle with their vertices: a handle whose slot was reused since is
  // found again by a search of its first vertex's ball.
  struct Entry {
    std::uint32_t handle;
    std::array<std::uint32_t, 3> face;
    std::array<std::uint32_t, 2> blocking_edge{kNone, kNone};
    bool direct = false;
  };
  std::vector<Entry> queue, deferred;
  const auto skipped = [&](std::uint32_t t) { return t < lawson_skip_.size() && lawson_skip_[t] != 0; };
  // Each face of tetrahedron t (when `once`, only those whose neighbour is skipped or has a
  // larger id: each face once).
  const auto push_faces = [&](std::uint32_t t, bool once) {
    const auto& x = records_[t].vertex;
    if (x[0] == kInf || skipped(t)) return;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t n = records_[t].neighbour[i] >> 2;
      if (!once || n > t || skipped(n)) queue.push_back({4 * t + i, {x[kFacet[i][0]], x[kFacet[i][1]], x[kFacet[i][2]]}});
    }
  };
  for (std::uint32_t t = 0; t < flips_mesh_.slots(); ++t)
    if (!flips_mesh_.is_dead(t)) push_faces(t, true);
  // The handle of the face now, or kNone where it is gone.
  const auto locate = [&](const Entry& e) -> std::uint32_t {
    const std::uint32_t t = e.handle >> 2, i = e.handle & 3u;
    if (!flips_mesh_.is_dead(t)) {
      const auto& x = records_[t].vertex;
      const auto& f = kFacet[i];
      if (x[f[0]] == e.face[0] && x[f[1]] == e.face[1] && x[f[2]] == e.face[2]) return e.handle;
    }
    const std::uint32_t s = tetrahedron_with(e.face[0], e.face[1], e.face[2]);
    if (s == kNone) return kNone;
    const auto& x = records_[s].vertex;
    std::uint32_t j = 0;
    while (x[j] == e.face[0] || x[j] == e.face[1] || x[j] == e.face[2]) ++j;
    return 4 * s + j;
  };
  std::uint64_t flips = 0;
  bool progress = true;
  while (progress && flips <= max_flips) {
    progress = false;
    while (!queue.empty() && flips <= max_flips) {
      Entry e = queue.back();
      queue.pop_back();
      const std::uint32_t h = locate(e);
      if (h == kNone) continue;
      bool blocked = false;
      if (lawson_step(h, blocked, e.blocking_edge, e.direct)) {
        progress = true;
        ++flips;
        for (const std::uint32_t n : ids_) {  // push_faces leaves ids_ alone
          if (n < lawson_skip_.size()) lawson_skip_[n] = 0;
          push_faces(n, false);
        }
      } else if (blocked) {
        deferred.push_back(e);
      }
    }
    // Out of flips: what is still queued counts as left too.
    deferred.insert(deferred.end(), queue.begin(), queue.end());
    queue.clear();
    queue.swap(deferred);
  }
  // The faces left (each may have been deferred more than once).
  std::vector<NotLocallyDelaunay> left;
  for (const Entry& e : queue) {
    auto k = e.face;
    std::sort(k.begin(), k.end());
    left.push_back({k, e.blocking_edge, e.direct});
  }
  std::sort(left.begin(), left.end(), [](const auto& x, const auto& y) { return x.face < y.face; });
  left.erase(std::unique(left.begin(), left.end(), [](const auto& x, const auto& y) { return x.face == y.face; }),
             left.end());
  lawson_skip_.resize(flips_mesh_.slots(), 0);
  return left;
}

}  // namespace dtlab
