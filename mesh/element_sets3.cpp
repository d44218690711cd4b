#include "mesh/element_sets3.hpp"

#include <algorithm>
#include <string>
#include <unordered_set>

#include "kernel/error.hpp"
#include "kernel/intersections.hpp"
#include "kernel/predicates.hpp"
#include "mesh/navigation3.hpp"
#include "mesh/vertex_buckets.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;

std::uint32_t index_of(const T3& tet, std::uint32_t t, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 4; ++i)
    if (tet.vertex(t, i) == v) return i;
  return T3::kNone;
}

}  // namespace

std::vector<std::uint32_t> vertex_tetrahedra(const Tetrahedralization3& tet, Incident which) {
  std::vector<std::uint32_t> out(tet.point_count(), T3::kNone);
  const auto count = static_cast<std::uint32_t>(tet.tetrahedron_count());
  const bool finite_first = which == Incident::FirstFinite, last = which == Incident::Last;
  for (int pass = 0; pass < (finite_first ? 2 : 1); ++pass) {  // finite first: ghosts fill the gaps
    for (std::uint32_t t = 0; t < count; ++t) {
      if (finite_first && tet.is_ghost(t) != (pass == 1)) continue;
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t v = tet.vertex(t, i);
        if (v != T3::kInfinite && v < out.size() && (last || out[v] == T3::kNone)) out[v] = t;
      }
    }
  }
  return out;
}

void find_in_mesh(const Tetrahedralization3& tet, std::span<const std::array<std::uint32_t, 2>> edges,
                  std::span<const std::array<std::uint32_t, 3>> faces, std::vector<std::uint8_t>& edge_present,
                  std::vector<std::uint8_t>& face_present) {
  edge_present.assign(edges.size(), 0);
  face_present.assign(faces.size(), 0);
  const std::size_t n = tet.point_count();
  // Items by lowest vertex: edges first as k, faces as edges.size() + k.
  const auto lowest = [&](std::size_t item) {
    if (item < edges.size()) return std::min(edges[item][0], edges[item][1]);
    const auto& f = faces[item - edges.size()];
    return std::min({f[0], f[1], f[2]});
  };
  const VertexBuckets by_lowest = vertex_buckets(n, edges.size() + faces.size(), lowest);
  const auto& start = by_lowest.start;
  const auto& order = by_lowest.order;
  const std::vector<std::uint32_t> incident = vertex_tetrahedra(tet);
  const auto count = static_cast<std::uint32_t>(tet.tetrahedron_count());
  std::vector<std::uint32_t> mark(count, 0), found;
  std::uint32_t stamp = 0;
  for (std::uint32_t u = 0; u < n; ++u) {
    if (start[u] == start[u + 1] || incident[u] == T3::kNone) continue;
    ++stamp;
    nav3::ball(tet, u, incident[u], found, nav3::marking(mark, stamp));
    if (found.size() > count) throw InternalError("find_in_mesh: a vertex ball exceeds the mesh");
    const auto holds = [&](std::uint32_t t, std::uint32_t v) {
      return tet.vertex(t, 0) == v || tet.vertex(t, 1) == v || tet.vertex(t, 2) == v || tet.vertex(t, 3) == v;
    };
    for (std::uint32_t j = start[u]; j < start[u + 1]; ++j) {
      const std::uint32_t k = order[j];
      std::array<std::uint32_t, 2> rest;  // the item's other vertices (an edge's twice)
      if (k < edges.size()) {
        rest = {edges[k][0] ^ edges[k][1] ^ u, edges[k][0] ^ edges[k][1] ^ u};
      } else {
        const auto& f = faces[k - edges.size()];
        rest = f[0] == u ? std::array{f[1], f[2]} : f[1] == u ? std::array{f[0], f[2]} : std::array{f[0], f[1]};
      }
      bool present = false;
      for (std::size_t b = 0; b < found.size() && !present; ++b)
        present = !tet.is_ghost(found[b]) && holds(found[b], rest[0]) && holds(found[b], rest[1]);
      (k < edges.size() ? edge_present[k] : face_present[k - edges.size()]) = present;
    }
  }
}

std::vector<std::uint32_t> ball(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t v) {
  if (tetrahedron >= tet.tetrahedron_count() || index_of(tet, tetrahedron, v) == T3::kNone)
    throw InternalError("ball: tetrahedron " + std::to_string(tetrahedron) + " does not have vertex " +
                        std::to_string(v));
  std::vector<std::uint32_t> out;
  std::unordered_set<std::uint32_t> seen;
  nav3::search_ball(
      tet, v, tetrahedron, out, [&](std::uint32_t u) { return seen.insert(u).second; },
      [&](std::uint32_t t) {
        if (index_of(tet, t, v) == T3::kNone)
          throw InternalError("ball of vertex " + std::to_string(v) + ": tetrahedron " + std::to_string(t) +
                              " reached through a facet holding it lacks it (broken adjacency)");
        return false;
      });
  if (out.size() > tet.tetrahedron_count())
    throw InternalError("ball of vertex " + std::to_string(v) + " exceeds the tetrahedron count");
  return out;
}

std::vector<std::uint32_t> shell(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t a,
                                 std::uint32_t b) {
  if (a == b || tetrahedron >= tet.tetrahedron_count() || index_of(tet, tetrahedron, a) == T3::kNone ||
      index_of(tet, tetrahedron, b) == T3::kNone)
    throw InternalError("shell: tetrahedron " + std::to_string(tetrahedron) + " does not have edge [" +
                        std::to_string(a) + ", " + std::to_string(b) + "]");
  std::vector<std::uint32_t> out;
  std::uint32_t t = tetrahedron;
  do {
    out.push_back(t);
    if (out.size() > tet.tetrahedron_count())
      throw InternalError("shell of edge [" + std::to_string(a) + ", " + std::to_string(b) +
                          "] does not close (broken adjacency)");
    const auto [ia, ib] = nav3::local_indices(tet.records()[t].vertex.data(), a, b);
    if (ia == 4 || ib == 4)
      throw InternalError("shell of edge [" + std::to_string(a) + ", " + std::to_string(b) + "]: tetrahedron " +
                          std::to_string(t) + " lacks an endpoint (broken adjacency)");
    t = tet.adjacent(t, nav3::kShellStep[ia][ib][0]);
  } while (t != tetrahedron);
  return out;
}

std::vector<std::uint32_t> pipe(const Tetrahedralization3& tet, std::uint32_t tetrahedron, std::uint32_t a,
                                std::uint32_t b) {
  if (a == b || a >= tet.point_count() || b >= tet.point_count())
    throw InternalError("pipe: [" + std::to_string(a) + ", " + std::to_string(b) + "] is no segment between two vertices");
  const auto P = tet.points();
  // Whether the open segment (a, b) meets closed finite tetrahedron t.
  const auto meets = [&](std::uint32_t t) {
    if (tet.is_ghost(t)) return false;
    const std::uint32_t ia = index_of(tet, t, a), ib = index_of(tet, t, b);
    if (ia != T3::kNone && ib != T3::kNone) return true;  // [a, b] is its edge
    if (ia != T3::kNone || ib != T3::kNone) {
      // From its vertex s towards the other end e: into the closed cone of t at s, i.e. e on
      // the inner side (or on) each facet through s (facet i, listed, has t on its positive side).
      const std::uint32_t is = ia != T3::kNone ? ia : ib, e = ia != T3::kNone ? b : a;
      for (std::uint32_t i = 0; i < 4; ++i) {
        if (i == is) continue;
        const auto& f = T3::kFacetVertex[i];
        if (orient3d(P[tet.vertex(t, f[0])], P[tet.vertex(t, f[1])], P[tet.vertex(t, f[2])], P[e]) == Sign::Negative)
          return false;
      }
      return true;
    }
    // Neither end is in t (a vertex lies in no other tetrahedron), so the segment meets it iff
    // it meets one of its facets.
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto& f = T3::kFacetVertex[i];
      if (segment_meets_triangle3(P[a], P[b], P[tet.vertex(t, f[0])], P[tet.vertex(t, f[1])], P[tet.vertex(t, f[2])]))
        return true;
    }
    return false;
  };
  std::vector<std::uint32_t> out, queue = ball(tet, tetrahedron, a);
  std::unordered_set<std::uint32_t> seen(queue.begin(), queue.end());
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const std::uint32_t t = queue[k];
    if (!meets(t)) continue;
    out.push_back(t);
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t u = tet.adjacent(t, i);
      if (seen.insert(u).second) queue.push_back(u);
    }
    if (queue.size() > tet.tetrahedron_count()) throw InternalError("pipe: the search exceeds the tetrahedron count");
  }
  return out;
}

}  // namespace dtlab
