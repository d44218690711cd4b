// Collapse of a boundary vertex along its boundary (book §9.3.1, the coarsening half of local
// adaptation; §8.3.5's reduction applied to a constrained edge): a vertex v inside a boundary
// piece (kOnBoundary, not kFixed, exactly two constrained edges vu and vw of one reference) is
// removed and its triangles on both sides of the boundary, ghosts and exterior ones included,
// take w; the two boundary edges become one, uw, with their reference. The domain changes only by
// the triangle (u, v, w): the collapse is allowed when v lies within `boundary_deviation` of the
// segment uw (0: exactly on it, decided by orient2d), as MMG bounds boundary changes by its
// Hausdorff parameter (Dapogny, Dobrzynski, Frey 2014). Validity as in collapse.cpp: the link
// condition, every new finite triangle positive (exact orient2d), no new domain edge longer than
// the unit bound, the domain triangles' worst Q_K bounded.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using optimize2d_detail::edge_length;
using optimize2d_detail::NewTriangle;
using optimize2d_detail::quality;

namespace {

constexpr double kRejected = std::numeric_limits<double>::infinity();

// The two boundary neighbours of v (ends of its constrained edges) and their reference, when v is
// a boundary vertex that may be removed: live, kOnBoundary, not kFixed, exactly two constrained
// edges, of one reference.
struct BoundaryNeighbours {
  std::uint32_t ends[2] = {Mesh2::kNone, Mesh2::kNone};
  int ref = 0;
};
bool boundary_neighbours(const Mesh2& mesh, std::uint32_t v, const std::vector<std::uint32_t>& ring,
                         BoundaryNeighbours& out) {
  if ((mesh.flags(v) & Mesh2::kOnBoundary) == 0 || (mesh.flags(v) & Mesh2::kFixed) != 0) return false;
  int found = 0;
  for (const std::uint32_t h : ring) {
    // In triangle (v, a, b), h = a -> b: prev(h) is the edge v -> a.
    const std::uint32_t spoke = Mesh2::prev(h);
    if (!mesh.is_constrained(spoke)) continue;
    const std::uint32_t a = mesh.origin(h);
    if (a == Mesh2::kInfinite) return false;
    // Each constrained edge is seen from both of its sides when both are finite triangles: once.
    if (found > 0 && (out.ends[0] == a || (found > 1 && out.ends[1] == a))) continue;
    if (found == 2) return false;  // a third boundary piece meets v: a corner
    if (found == 1 && mesh.edge_ref(spoke) != out.ref) return false;
    out.ref = mesh.edge_ref(spoke);
    out.ends[found++] = a;
  }
  return found == 2;
}

// Distance of p to the segment ab.
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) noexcept {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  double t = len2 > 0.0 ? dot(p - a, d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 q = a + t * d;
  return std::sqrt(dot(p - q, p - q));
}

// The worst domain Q_K after collapsing v onto w, or kRejected; `out` gets the new triangles.
double simulate(const Mesh2& mesh, std::uint32_t v, std::uint32_t w, std::uint32_t u,
                const std::vector<std::uint32_t>& ring, const CollapseOptions& options,
                std::vector<NewTriangle>& out) {
  out.clear();
  if (options.boundary_deviation > 0.0) {
    if (!(segment_distance(mesh.point(v), mesh.point(u), mesh.point(w)) <= options.boundary_deviation))
      return kRejected;
  } else if (orient2d(mesh.point(u), mesh.point(w), mesh.point(v)) != Sign::Zero) {
    return kRejected;
  }
  // The vertices opposite edge vw (one per side; kInfinite for a ghost) may be shared; any other
  // common neighbour of v and w would give a doubled edge (the link condition).
  std::vector<std::uint32_t> opposite, around_v;
  for (const std::uint32_t h : ring) {
    const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
    if (a == w) opposite.push_back(b);
    if (b == w) opposite.push_back(a);
    around_v.push_back(a);
  }
  if (opposite.size() != 2) return kRejected;
  std::sort(around_v.begin(), around_v.end());
  std::vector<std::uint32_t> ring_w;
  mesh.ball(w, ring_w);
  for (const std::uint32_t h : ring_w) {
    const std::uint32_t c = mesh.origin(h);
    if (c == v || c == Mesh2::kInfinite || c == opposite[0] || c == opposite[1]) continue;
    if (std::binary_search(around_v.begin(), around_v.end(), c)) return kRejected;
  }
  double before = 0.0, after = 0.0;
  for (const std::uint32_t h : ring) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
    const bool domain = mesh.in_domain(t);
    if (domain) before = std::max(before, quality(mesh, v, a, b));
    if (a == w || b == w) continue;  // the two triangles of vw disappear
    const int ref = mesh.ref(t);
    if (a == Mesh2::kInfinite) {
      out.push_back({Mesh2::kInfinite, b, w, ref});  // ghost (kInfinite, b, v) becomes (kInfinite, b, w)
      continue;
    }
    if (b == Mesh2::kInfinite) {
      out.push_back({Mesh2::kInfinite, w, a, ref});  // ghost (kInfinite, v, a)
      continue;
    }
    if (orient2d(mesh.point(w), mesh.point(a), mesh.point(b)) != Sign::Positive) return kRejected;
    if (domain) {
      for (const std::uint32_t x : {a, b}) {
        if (x != u && edge_length(mesh, w, x) > std::max(options.long_length, edge_length(mesh, v, x)))
          return kRejected;
      }
      after = std::max(after, quality(mesh, w, a, b));
    }
    out.push_back({w, a, b, ref});
  }
  return after <= std::max(before, options.quality_limit) ? after : kRejected;
}

}  // namespace

bool try_boundary_collapse(Mesh2& mesh, std::uint32_t v, const CollapseOptions& options) {
  if (v >= mesh.vertex_capacity() || mesh.is_dead_vertex(v)) return false;
  std::vector<std::uint32_t> ring;
  mesh.ball(v, ring);
  BoundaryNeighbours nb;
  if (!boundary_neighbours(mesh, v, ring, nb)) return false;
  // The boundary u - v - w would close into a loop of two edges.
  const std::uint32_t existing = mesh.find_half_edge(nb.ends[0], nb.ends[1]);
  if (existing != Mesh2::kNone && mesh.is_constrained(existing)) return false;
  std::vector<NewTriangle> created[2];
  double result[2] = {kRejected, kRejected};
  for (int k = 0; k < 2; ++k)
    result[k] = simulate(mesh, v, nb.ends[k], nb.ends[1 - k], ring, options, created[k]);
  const int best = result[1] < result[0] ? 1 : 0;
  if (result[best] == kRejected) return false;
  std::vector<std::uint32_t> old_triangles;
  for (const std::uint32_t e : ring) old_triangles.push_back(Mesh2::triangle_of(e));
  const std::uint32_t w = nb.ends[best], u = nb.ends[1 - best];
  const MeshEdge2 joined{u, w, nb.ref};
  std::vector<std::uint32_t> slots;
  optimize2d_detail::replace_triangles(mesh, old_triangles, created[best], {&joined, 1}, slots);
  // uw may also be an edge the old set shared with the outside (a thin exterior triangle (u, w,
  // v) removed): the constraint is set on it in every case.
  const std::uint32_t h = mesh.find_half_edge(u, w);
  DTLAB_ASSERT(h != Mesh2::kNone);
  mesh.set_constraint_both(h, true, nb.ref);
  mesh.remove_vertex(v);
  return true;
}

std::uint64_t boundary_collapse_pass(Mesh2& mesh, const CollapseOptions& options) {
  // Boundary edges shorter than short_length, shortest first; ties by the vertex pair.
  using Entry = std::tuple<double, std::uint32_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  auto consider = [&](std::uint32_t h) {
    if (!mesh.is_constrained(h)) return;
    const std::uint32_t u = mesh.origin(h), w = mesh.destination(h);
    if (u == Mesh2::kInfinite || w == Mesh2::kInfinite) return;
    const double length = edge_length(mesh, u, w);
    if (length < options.short_length) queue.emplace(length, std::min(u, w), std::max(u, w));
  };
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) consider(Mesh2::half_edge(t, i));
  }
  std::uint64_t collapses = 0;
  std::vector<std::uint32_t> ring;
  const std::uint64_t bound = 10ull * mesh.live_triangle_count() + 1000;
  for (std::uint64_t pops = 0; !queue.empty() && pops < bound; ++pops) {
    const std::uint32_t x = std::get<1>(queue.top()), y = std::get<2>(queue.top());
    queue.pop();
    if (mesh.is_dead_vertex(x) || mesh.is_dead_vertex(y)) continue;
    const std::uint32_t h = mesh.find_half_edge(x, y);
    if (h == Mesh2::kNone || !mesh.is_constrained(h)) continue;
    // The end whose removal is allowed and better; try_boundary_collapse picks the direction
    // along the boundary, which may keep the other neighbour.
    std::uint32_t removed = Mesh2::kNone;
    for (const std::uint32_t end : {x, y}) {
      if (try_boundary_collapse(mesh, end, options)) {
        removed = end;
        break;
      }
    }
    if (removed == Mesh2::kNone) continue;
    ++collapses;
    const std::uint32_t kept = removed == x ? y : x;
    if (mesh.is_dead_vertex(kept)) continue;
    mesh.ball(kept, ring);
    for (const std::uint32_t e : ring) consider(Mesh2::prev(e));
  }
  return collapses;
}

}  // namespace dtlab
