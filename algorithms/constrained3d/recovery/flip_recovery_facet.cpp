// Facet insertion by cavity retriangulation (FlipRecovery::insert_facet, flip_recovery.hpp).
// The cavity is found from its edges: with the facet's boundary edges present and no vertex
// inside it, a tetrahedron whose interior meets the facet has an edge through the open
// interior of a piece or of a diagonal, or (where the mesh triangulates the facet's plane
// otherwise) an edge between two facet vertices that is none of the pieces' edges.
#include <algorithm>
#include <map>
#include <unordered_set>

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery/gift_wrapping.hpp"
#include "kernel/error.hpp"
#include "kernel/intersections.hpp"
#include "kernel/predicates.hpp"
#include "kernel/predicates/perturbation.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
using Face = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr auto kFacet = T3::kFacetVertex;

std::uint64_t key2(std::uint32_t u, std::uint32_t v) noexcept {
  return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
}
Face sorted3(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Segments pq and xy (four distinct points) cross at a point inside both, coplanar: decided in
// a coordinate plane onto which their plane projects without degenerating (any projection in
// which some orientation is non-zero).
bool segments_cross3(const Vec3& p, const Vec3& q, const Vec3& x, const Vec3& y) {
  if (orient3d(p, q, x, y) != Sign::Zero) return false;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec2 P = project(p, axis), Q = project(q, axis), X = project(x, axis), Y = project(y, axis);
    const Sign d1 = orient2d(X, Y, P), d2 = orient2d(X, Y, Q), d3 = orient2d(P, Q, X), d4 = orient2d(P, Q, Y);
    if (d1 == Sign::Zero && d2 == Sign::Zero && d3 == Sign::Zero && d4 == Sign::Zero) continue;
    return d1 != Sign::Zero && d2 == -d1 && d3 != Sign::Zero && d4 == -d3;
  }
  return false;  // all four on one line
}

}  // namespace

bool FlipRecovery::conflicts_with_facet(std::uint32_t p, std::uint32_t q, std::span<const Face> pieces,
                                        const std::set<std::uint64_t>& facet_edges,
                                        const std::set<std::uint64_t>& diagonals,
                                        const std::set<std::uint32_t>& facet_vertices) const {
  if (p == kInf || q == kInf || facet_edges.count(key2(p, q))) return false;
  if (facet_vertices.count(p) && facet_vertices.count(q)) return true;  // a chord of the facet, no piece's edge
  for (const Face& t : pieces) {
    if (std::find(t.begin(), t.end(), p) != t.end() || std::find(t.begin(), t.end(), q) != t.end()) continue;
    if (crosses(p, q, t[0], t[1], t[2])) return true;
  }
  for (const std::uint64_t d : diagonals) {
    const auto x = static_cast<std::uint32_t>(d >> 32), y = static_cast<std::uint32_t>(d);
    if (x != p && x != q && y != p && y != q && segments_cross3(P(p), P(q), P(x), P(y))) return true;
  }
  return false;
}

bool FlipRecovery::insert_facet(std::span<const Face> pieces, std::string& why) {
  std::map<std::uint64_t, int> uses;
  std::set<std::uint32_t> facet_vertices;
  for (const Face& t : pieces)
    for (int k = 0; k < 3; ++k) {
      ++uses[key2(t[k], t[(k + 1) % 3])];
      facet_vertices.insert(t[k]);
    }
  std::set<std::uint64_t> facet_edges, diagonals;
  for (const auto& [k, n] : uses) {
    if (n > 2) throw InternalError("insert_facet: an edge of the pieces is on more than two of them");
    facet_edges.insert(k);
    if (n == 2) diagonals.insert(k);
  }
  const auto protect_all = [&] {
    for (const Face& t : pieces) protect_face(t[0], t[1], t[2]);
  };
  if (std::all_of(pieces.begin(), pieces.end(), [&](const Face& t) { return has_face(t[0], t[1], t[2]); })) {
    protect_all();
    return true;
  }
  // The cavity: from the balls of the facet's vertices, across every tetrahedron with a
  // conflicting edge.
  std::unordered_set<std::uint32_t> seen, in_cavity;
  std::vector<std::uint32_t> queue, cavity;
  for (const std::uint32_t v : facet_vertices) {
    ball_of(v, ball_);
    for (const std::uint32_t t : ball_)
      if (seen.insert(t).second) queue.push_back(t);
  }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const std::uint32_t t = queue[k];
    const auto rec = records_[t];
    bool conflict = false;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint32_t p = rec.vertex[i], q = rec.vertex[j];
        if (!conflicts_with_facet(p, q, pieces, facet_edges, diagonals, facet_vertices)) continue;
        if (is_protected_edge(p, q)) {
          why = "constraint edge (" + std::to_string(p + 1) + ", " + std::to_string(q + 1) + ") crosses it";
          return false;
        }
        conflict = true;
      }
    if (!conflict) continue;
    if (rec.vertex[0] == kInf) {
      why = "its cavity reaches the convex hull";
      return false;
    }
    cavity.push_back(t);
    in_cavity.insert(t);
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t n = rec.neighbour[i] >> 2;
      if (seen.insert(n).second) queue.push_back(n);
    }
  }
  if (cavity.empty()) {
    why = "its pieces are missing but no tetrahedron crosses it";
    return false;
  }
  // The front: the cavity's outer faces, and both sides of the constraint triangles in it.
  std::set<Face> piece_keys;
  for (const Face& t : pieces) piece_keys.insert(sorted3(t));
  std::vector<Face> front;
  std::set<std::uint32_t> vertices;
  std::set<std::uint64_t> kept_edges;  // protected edges of the cavity, which must survive
  for (const std::uint32_t t : cavity) {
    const auto& rec = records_[t];
    for (int i = 0; i < 4; ++i) {
      vertices.insert(rec.vertex[i]);
      for (int j = i + 1; j < 4; ++j)
        if (is_protected_edge(rec.vertex[i], rec.vertex[j])) kept_edges.insert(key2(rec.vertex[i], rec.vertex[j]));
      const Face f{rec.vertex[kFacet[i][0]], rec.vertex[kFacet[i][1]], rec.vertex[kFacet[i][2]]};
      if (!in_cavity.count(rec.neighbour[i] >> 2) || piece_keys.count(sorted3(f)) || is_protected_face(f[0], f[1], f[2]))
        front.push_back(f);
    }
  }
  for (const Face& t : pieces)
    if (!has_face(t[0], t[1], t[2])) {
      front.push_back(t);
      front.push_back({t[0], t[2], t[1]});
    }
  const std::vector<std::uint32_t> cavity_vertices(vertices.begin(), vertices.end());
  std::vector<Tuple> fresh = gift_wrap_cavity(mesh_.points(), front, cavity_vertices, why);
  if (fresh.empty()) return false;
  for (const Tuple& t : fresh)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) kept_edges.erase(key2(t[i], t[j]));
  if (!kept_edges.empty()) {
    const std::uint64_t e = *kept_edges.begin();
    why = "its cavity's filling loses constraint edge (" + std::to_string((e >> 32) + 1) + ", " +
          std::to_string((e & 0xFFFFFFFFu) + 1) + ")";
    return false;
  }
  // Constrained Delaunay across every facet of the filling that is no constraint (between two
  // new tetrahedra, or a new one and the one outside the cavity): gift-wrapping completes on
  // some cavities that have no CDT (with rounded Steiner points the facets are not exactly
  // planar), and then this finds the witness.
  std::map<Face, std::uint32_t> outside_apex;  // the cavity's outer faces, with the apex beyond
  for (const std::uint32_t t : cavity) {
    const auto& rec = records_[t];
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t g = rec.neighbour[i], n = g >> 2;
      if (in_cavity.count(n)) continue;
      outside_apex[sorted3({rec.vertex[kFacet[i][0]], rec.vertex[kFacet[i][1]], rec.vertex[kFacet[i][2]]})] =
          records_[n].vertex[g & 3u];
    }
  }
  std::map<Face, std::uint32_t> first_side;  // face -> index of the new tetrahedron seen first
  const auto violates = [&](const Tuple& t, std::uint32_t x) {
    return x != kInf && insphere_perturbed(P(t[0]), P(t[1]), P(t[2]), P(t[3]), P(x)) == Sign::Positive;
  };
  for (std::uint32_t k = 0; k < fresh.size(); ++k) {
    const Tuple& t = fresh[k];
    for (int i = 0; i < 4; ++i) {
      const Face f = sorted3({t[kFacet[i][0]], t[kFacet[i][1]], t[kFacet[i][2]]});
      if (piece_keys.count(f) || is_protected_face(f[0], f[1], f[2])) continue;
      std::uint32_t beyond = kInf;
      if (const auto out = outside_apex.find(f); out != outside_apex.end()) {
        beyond = out->second;
      } else if (const auto [it, inserted] = first_side.emplace(f, k); !inserted) {
        const Tuple& u = fresh[it->second];
        for (const std::uint32_t x : u)
          if (std::find(t.begin(), t.end(), x) == t.end()) beyond = x;
      }
      if (violates(t, beyond)) {
        why = "the filling of its cavity is not constrained Delaunay (vertex " + std::to_string(beyond + 1) +
              " is in the sphere of a new tetrahedron)";
        return false;
      }
    }
  }
  flips_mesh_.replace(cavity, fresh, ids_);
  replaced(ids_);
  protect_all();
  return true;
}

}  // namespace dtlab
