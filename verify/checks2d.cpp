#include "verify/checks2d.hpp"

#include "mesh/canonical_element.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "kernel/coordinate_range.hpp"
#include "kernel/predicates.hpp"
#include "verify/hull2d.hpp"

namespace dtlab {

namespace {

std::string name(std::span<const TriangleIds> triangles, std::size_t t) {
  const TriangleIds& v = triangles[t];
  return "triangle " + std::to_string(t) + " (" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," +
         std::to_string(v[2]) + ")";
}

std::string edge_name(std::uint32_t a, std::uint32_t b) {
  return "edge (" + std::to_string(a) + "," + std::to_string(b) + ")";
}

bool ids_valid(const TriangleIds& t, std::size_t n) {
  return t[0] < n && t[1] < n && t[2] < n && t[0] != t[1] && t[1] != t[2] && t[2] != t[0];
}

// One message for the triangles a geometric check had to leave out (check_topology2 names them).
void note_skipped_invalid(CheckReport2& r, std::span<const TriangleIds> triangles, std::size_t n,
                          const char* check) {
  std::size_t bad = 0;
  for (const TriangleIds& t : triangles) bad += ids_valid(t, n) ? 0 : 1;
  if (bad > 0) {
    r.add_problem(std::string(check) + ": " + std::to_string(bad) +
                  " triangles with invalid or repeated vertex ids not checked");
  }
}

// The predicates' precondition; adds one problem per offending point.
bool coordinates_valid(std::span<const Vec2> points, CheckReport2& r, const char* check) {
  bool valid = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const auto& [axis, c] : {std::pair{"x", points[i].x}, std::pair{"y", points[i].y}}) {
      if (coordinate_in_range(c)) continue;
      r.add_problem(std::string(check) + ": point " + std::to_string(i) + ": coordinate " + axis + " is " +
                    coordinate_problem(c));
      valid = false;
    }
  }
  return valid;
}

// Edge k of a triangle runs from t[k] to t[k+1 mod 3]; t[k+2 mod 3] is opposite it.
struct HalfEdge {
  std::uint32_t lo, hi;  // the edge's end points, smaller first
  std::uint32_t tri;
  std::uint8_t k;
  std::uint32_t from(std::span<const TriangleIds> ts) const { return ts[tri][k]; }
  std::uint32_t to(std::span<const TriangleIds> ts) const { return ts[tri][(k + 1) % 3]; }
  std::uint32_t apex(std::span<const TriangleIds> ts) const { return ts[tri][(k + 2) % 3]; }
};

// The half-edges of the valid triangles, grouped by undirected edge.
struct EdgeTable {
  std::vector<HalfEdge> half;
  std::vector<std::size_t> group_begin;  // group g is half[group_begin[g] .. group_begin[g+1])

  // Counting sort on the smaller end, then a small sort within each bucket: linear in the
  // number of half-edges plus the buckets' (vertex degrees') sorting.
  EdgeTable(std::span<const TriangleIds> triangles, std::size_t n) {
    std::vector<std::size_t> bucket(n + 1, 0);
    for (const TriangleIds& t : triangles) {
      if (!ids_valid(t, n)) continue;
      for (int k = 0; k < 3; ++k) ++bucket[std::min(t[k], t[(k + 1) % 3]) + 1];
    }
    for (std::size_t v = 0; v < n; ++v) bucket[v + 1] += bucket[v];
    half.resize(bucket[n]);
    std::vector<std::size_t> fill(bucket.begin(), bucket.end() - 1);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (!ids_valid(triangles[t], n)) continue;
      for (std::uint8_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
        half[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t), k};
      }
    }
    const auto less = [](const HalfEdge& x, const HalfEdge& y) {
      return std::tie(x.hi, x.tri, x.k) < std::tie(y.hi, y.tri, y.k);
    };
    for (std::size_t v = 0; v < n; ++v) {
      std::sort(half.begin() + static_cast<std::ptrdiff_t>(bucket[v]),
                half.begin() + static_cast<std::ptrdiff_t>(bucket[v + 1]), less);
    }
    group_begin.reserve(half.size() / 2 + 2);
    for (std::size_t i = 0; i < half.size(); ++i) {
      if (i == 0 || half[i].lo != half[i - 1].lo || half[i].hi != half[i - 1].hi) group_begin.push_back(i);
    }
    group_begin.push_back(half.size());
  }
  std::size_t groups() const { return group_begin.size() - 1; }
  std::span<const HalfEdge> group(std::size_t g) const {
    return std::span(half).subspan(group_begin[g], group_begin[g + 1] - group_begin[g]);
  }
};

// True iff a group is an interior edge: two half-edges in opposite directions.
bool is_interior(std::span<const HalfEdge> g, std::span<const TriangleIds> ts) {
  return g.size() == 2 && g[0].from(ts) == g[1].to(ts);
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Each vertex's link (the edges opposite it in its triangles, oriented) must be one path or
// one cycle; given the edge checks, anything else is a pinch (several fans at one vertex).
void check_vertex_links(std::span<const TriangleIds> ts, std::size_t n, CheckReport2& r) {
  std::vector<std::size_t> begin(n + 1, 0);
  for (const TriangleIds& t : ts) {
    if (!ids_valid(t, n)) continue;
    for (std::uint32_t v : t) ++begin[v + 1];
  }
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link(begin[n]);
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  for (const TriangleIds& t : ts) {
    if (!ids_valid(t, n)) continue;
    for (int k = 0; k < 3; ++k) link[fill[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  }
  std::vector<std::uint32_t> targets;
  for (std::uint32_t v = 0; v < n; ++v) {
    const auto first = link.begin() + static_cast<std::ptrdiff_t>(begin[v]);
    const auto last = link.begin() + static_cast<std::ptrdiff_t>(begin[v + 1]);
    if (first == last) continue;
    std::sort(first, last);
    if (std::adjacent_find(first, last, [](auto& a, auto& b) { return a.first == b.first; }) != last) {
      continue;  // a directed edge used twice: reported by the edge check
    }
    targets.clear();
    for (auto it = first; it != last; ++it) targets.push_back(it->second);
    std::sort(targets.begin(), targets.end());
    std::size_t starts = 0;
    std::uint32_t start = first->first;
    for (auto it = first; it != last; ++it) {
      if (!std::binary_search(targets.begin(), targets.end(), it->first)) {
        ++starts;
        start = it->first;
      }
    }
    const std::size_t size = static_cast<std::size_t>(last - first);
    std::size_t walked = 0;
    std::uint32_t cur = start;
    while (walked <= size) {
      const auto it = std::lower_bound(first, last, std::pair{cur, std::uint32_t{0}});
      if (it == last || it->first != cur) break;
      cur = it->second;
      ++walked;
      if (starts == 0 && cur == start) break;
    }
    if (starts > 1 || walked != size) {
      r.add_problem("topology: vertex " + std::to_string(v) + " is not manifold: its " + std::to_string(size) +
                    " triangles form more than one fan");
    }
  }
}

CheckReport2 topology(std::span<const Vec2> points, std::span<const TriangleIds> ts, const EdgeTable& edges) {
  CheckReport2 r;
  const std::size_t n = points.size();
  r.points = n;
  r.triangles = ts.size();
  for (std::size_t t = 0; t < ts.size(); ++t) {
    const TriangleIds& v = ts[t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) {
      r.add_problem("topology: " + name(ts, t) + " has a vertex id out of range (" + std::to_string(n) + " points)");
    } else if (!ids_valid(v, n)) {
      r.add_problem("topology: " + name(ts, t) + " repeats a vertex");
    }
  }

  UnionFind components(ts.size());
  std::vector<char> on_boundary(n, 0), referenced(n, 0);
  std::size_t boundary_vertices = 0;
  for (std::size_t g = 0; g < edges.groups(); ++g) {
    const auto group = edges.group(g);
    const HalfEdge& e = group[0];
    if (group.size() == 1) {
      ++r.boundary_edges;
      for (std::uint32_t v : {e.lo, e.hi}) {
        if (!on_boundary[v]) ++boundary_vertices;
        on_boundary[v] = 1;
      }
    } else if (is_interior(group, ts)) {
      ++r.interior_edges;
      components.unite(group[0].tri, group[1].tri);
    } else if (group.size() == 2) {
      r.add_problem("topology: " + edge_name(e.lo, e.hi) + " has the same direction in " + name(ts, group[0].tri) +
                    " and " + name(ts, group[1].tri) + " (inconsistent orientation or overlap)");
    } else {
      std::string who;
      for (const HalfEdge& h : group) {
        who += ' ';
        who += std::to_string(h.tri);
      }
      r.add_problem("topology: " + edge_name(e.lo, e.hi) + " is shared by " + std::to_string(group.size()) +
                    " triangles (non-manifold):" + who);
    }
  }
  check_vertex_links(ts, n, r);

  std::size_t valid = 0;
  std::size_t component_count = 0;
  for (std::size_t t = 0; t < ts.size(); ++t) {
    if (!ids_valid(ts[t], n)) continue;
    ++valid;
    for (std::uint32_t v : ts[t]) {
      if (!referenced[v]) ++r.referenced_points;
      referenced[v] = 1;
    }
    if (components.find(static_cast<std::uint32_t>(t)) == t) ++component_count;
  }
  if (component_count > 1) {
    r.add_problem("topology: the triangles form " + std::to_string(component_count) +
                  " edge-connected components, not one");
  }
  if (valid > 0 && r.problem_count == 0) {
    // A triangulated disk: V - E + F = 1, equivalently F = 2V - 2 - h with one boundary loop.
    const auto v = static_cast<std::int64_t>(r.referenced_points);
    const auto e = static_cast<std::int64_t>(r.interior_edges + r.boundary_edges);
    const auto f = static_cast<std::int64_t>(valid);
    const auto h = static_cast<std::int64_t>(boundary_vertices);
    if (v - e + f != 1 || f != 2 * v - 2 - h || static_cast<std::int64_t>(r.boundary_edges) != h) {
      r.add_problem("topology: not a triangulated disk: " + std::to_string(v) + " vertices, " + std::to_string(e) +
                    " edges, " + std::to_string(f) + " triangles, " + std::to_string(h) +
                    " boundary vertices (expected V-E+F = 1 and F = 2V-2-h)");
    }
  }
  return r;
}

CheckReport2 orientation(std::span<const Vec2> points, std::span<const TriangleIds> ts) {
  CheckReport2 r;
  r.points = points.size();
  r.triangles = ts.size();
  note_skipped_invalid(r, ts, points.size(), "orientation");
  if (!coordinates_valid(points, r, "orientation")) return r;
  for (std::size_t t = 0; t < ts.size(); ++t) {
    if (!ids_valid(ts[t], points.size())) continue;
    const Sign s = orient2d(points[ts[t][0]], points[ts[t][1]], points[ts[t][2]]);
    if (s == Sign::Negative) r.add_problem("orientation: " + name(ts, t) + " is clockwise");
    if (s == Sign::Zero) r.add_problem("orientation: " + name(ts, t) + " is flat (its vertices are collinear)");
  }
  return r;
}

CheckReport2 empty_circle(std::span<const Vec2> points, std::span<const TriangleIds> ts, const EdgeTable& edges) {
  CheckReport2 r;
  r.points = points.size();
  r.triangles = ts.size();
  note_skipped_invalid(r, ts, points.size(), "empty circle");
  if (!coordinates_valid(points, r, "empty circle")) return r;
  std::size_t not_ccw = 0;
  for (std::size_t g = 0; g < edges.groups(); ++g) {
    const auto group = edges.group(g);
    if (!is_interior(group, ts)) continue;
    // The incircle sign means "inside" only for a counter-clockwise triangle: take a side that is.
    std::size_t side = 0;
    const auto ccw = [&](std::size_t s) {
      const TriangleIds& t = ts[group[s].tri];
      return orient2d(points[t[0]], points[t[1]], points[t[2]]) == Sign::Positive;
    };
    if (!ccw(0)) side = 1;
    if (!ccw(side)) {
      ++not_ccw;
      continue;
    }
    const TriangleIds& t = ts[group[side].tri];
    const std::uint32_t d = group[1 - side].apex(ts);
    ++r.incircle_tests;
    const Sign s = incircle_perturbed(points[t[0]], points[t[1]], points[t[2]], points[d]);
    if (s == Sign::Positive) {
      r.add_problem("empty circle: " + edge_name(group[0].lo, group[0].hi) + " is not locally Delaunay: point " +
                    std::to_string(d) + " of triangle " + std::to_string(group[1 - side].tri) +
                    " is inside the circumcircle of " + name(ts, group[side].tri) + " (perturbed incircle)");
    } else if (s == Sign::Zero) {
      r.add_problem("empty circle: " + edge_name(group[0].lo, group[0].hi) +
                    ": perturbed incircle is zero (collinear points)");
    }
  }
  if (not_ccw > 0) {
    r.add_problem("empty circle: " + std::to_string(not_ccw) +
                  " interior edges not checked: neither triangle is counter-clockwise");
  }
  return r;
}

CheckReport2 hull_coverage(std::span<const Vec2> points, std::span<const TriangleIds> ts, const EdgeTable& edges) {
  CheckReport2 r;
  const std::size_t n = points.size();
  r.points = n;
  r.triangles = ts.size();
  note_skipped_invalid(r, ts, n, "hull");
  if (!coordinates_valid(points, r, "hull")) return r;

  std::vector<std::uint32_t> referenced;
  std::vector<char> seen(n, 0);
  for (const TriangleIds& t : ts) {
    if (!ids_valid(t, n)) continue;
    for (std::uint32_t v : t) {
      if (!seen[v]) referenced.push_back(v);
      seen[v] = 1;
    }
  }
  r.referenced_points = referenced.size();
  if (referenced.empty()) return r;  // nothing to cover; check_unreferenced judges an empty result

  const Hull2 hull = convex_hull_with_collinear(points, referenced);
  if (hull.collinear) {
    r.add_problem("hull: the referenced points are collinear, yet there are triangles");
    return r;
  }
  r.hull_points = hull.cycle.size();

  // Directed edges (from, to, triangle), compared on (from, to).
  using Directed = std::array<std::uint32_t, 3>;
  std::vector<Directed> hull_edges, boundary;
  for (std::size_t i = 0; i < hull.cycle.size(); ++i) {
    hull_edges.push_back({hull.cycle[i], hull.cycle[(i + 1) % hull.cycle.size()], 0});
  }
  for (std::size_t g = 0; g < edges.groups(); ++g) {
    const auto group = edges.group(g);
    if (group.size() == 1) boundary.push_back({group[0].from(ts), group[0].to(ts), group[0].tri});
  }
  r.boundary_edges = boundary.size();
  std::sort(hull_edges.begin(), hull_edges.end());
  std::sort(boundary.begin(), boundary.end());
  const auto less = [](const Directed& x, const Directed& y) { return std::tie(x[0], x[1]) < std::tie(y[0], y[1]); };
  std::size_t i = 0, j = 0;
  while (i < hull_edges.size() || j < boundary.size()) {
    if (j == boundary.size() || (i < hull_edges.size() && less(hull_edges[i], boundary[j]))) {
      r.add_problem("hull: convex hull " + edge_name(hull_edges[i][0], hull_edges[i][1]) +
                    " is not a boundary edge of the triangulation");
      ++i;
    } else if (i == hull_edges.size() || less(boundary[j], hull_edges[i])) {
      r.add_problem("hull: boundary " + edge_name(boundary[j][0], boundary[j][1]) + " of " +
                    name(ts, boundary[j][2]) + " is not a convex hull edge (a hole, a concavity or a missing triangle)");
      ++j;
    } else {
      ++i;
      ++j;
    }
  }
  return r;
}

}  // namespace

CheckReport2 check_topology2(std::span<const Vec2> points, std::span<const TriangleIds> triangles) {
  return topology(points, triangles, EdgeTable(triangles, points.size()));
}

CheckReport2 check_orientation2(std::span<const Vec2> points, std::span<const TriangleIds> triangles) {
  return orientation(points, triangles);
}

CheckReport2 check_empty_circle2(std::span<const Vec2> points, std::span<const TriangleIds> triangles) {
  return empty_circle(points, triangles, EdgeTable(triangles, points.size()));
}

CheckReport2 check_hull_coverage2(std::span<const Vec2> points, std::span<const TriangleIds> triangles) {
  return hull_coverage(points, triangles, EdgeTable(triangles, points.size()));
}

CheckReport2 check_unreferenced(std::span<const Vec2> points, std::span<const TriangleIds> triangles,
                                std::span<const std::uint32_t> duplicates) {
  CheckReport2 r;
  const std::size_t n = points.size();
  r.points = n;
  r.triangles = triangles.size();
  r.duplicates = duplicates.size();
  note_skipped_invalid(r, triangles, n, "references");

  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> first_triangle(n, kNone);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!ids_valid(triangles[t], n)) continue;
    for (std::uint32_t v : triangles[t]) {
      if (first_triangle[v] == kNone) first_triangle[v] = static_cast<std::uint32_t>(t);
    }
  }
  std::vector<char> is_duplicate(n, 0);
  for (std::uint32_t d : duplicates) {
    if (d >= n) {
      r.add_problem("references: duplicate index " + std::to_string(d) + " out of range (" + std::to_string(n) +
                    " points)");
    } else if (is_duplicate[d]) {
      r.add_problem("references: point " + std::to_string(d) + " is listed twice as a duplicate");
    } else {
      is_duplicate[d] = 1;
      if (first_triangle[d] != kNone) {
        r.add_problem("references: duplicate point " + std::to_string(d) + " is a vertex of " +
                      name(triangles, first_triangle[d]));
      }
    }
  }

  std::vector<std::uint32_t> kept;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!is_duplicate[i]) kept.push_back(i);
  }
  if (!triangles.empty()) {
    for (std::uint32_t i : kept) {
      if (first_triangle[i] == kNone) {
        r.add_problem("references: point " + std::to_string(i) +
                      " is a vertex of no triangle and is not listed as a duplicate");
      }
    }
  }
  if (!coordinates_valid(points, r, "references")) return r;

  // Coincidences: among the kept points none, and each duplicate on some kept point.
  std::vector<std::uint32_t> by_position = kept;
  std::sort(by_position.begin(), by_position.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto c = points[a] <=> points[b];
    return c < 0 || (c == 0 && a < b);
  });
  for (std::size_t i = 1; i < by_position.size(); ++i) {
    if (points[by_position[i]] == points[by_position[i - 1]]) {
      r.add_problem("references: points " + std::to_string(by_position[i - 1]) + " and " +
                    std::to_string(by_position[i]) + " coincide and neither is listed as a duplicate");
    }
  }
  const auto position_less = [&](std::uint32_t a, const Vec2& p) { return (points[a] <=> p) < 0; };
  for (std::uint32_t d : duplicates) {
    if (d >= n) continue;
    const auto it = std::lower_bound(by_position.begin(), by_position.end(), points[d], position_less);
    if (it == by_position.end() || points[*it] != points[d]) {
      r.add_problem("references: point " + std::to_string(d) +
                    " is listed as a duplicate but coincides with no kept point");
    }
  }

  // No triangles: right only for collinear input.
  if (triangles.empty() && by_position.size() >= 3) {
    const std::uint32_t a = by_position.front();
    const std::uint32_t b = by_position.back();
    for (std::uint32_t c : by_position) {
      if (orient2d(points[a], points[b], points[c]) != Sign::Zero) {
        r.add_problem("references: no triangles, yet points " + std::to_string(a) + ", " + std::to_string(b) +
                      " and " + std::to_string(c) + " are not collinear");
        break;
      }
    }
  }
  return r;
}

CheckReport2 verify_delaunay2d(std::span<const Vec2> points, std::span<const TriangleIds> triangles,
                               std::span<const std::uint32_t> duplicates) {
  CheckReport2 r;
  r.points = points.size();
  r.triangles = triangles.size();
  if (!coordinates_valid(points, r, "input")) return r;
  const EdgeTable edges(triangles, points.size());
  r.merge(topology(points, triangles, edges));
  r.merge(orientation(points, triangles));
  r.merge(empty_circle(points, triangles, edges));
  r.merge(hull_coverage(points, triangles, edges));
  r.merge(check_unreferenced(points, triangles, duplicates));
  return r;
}

std::vector<TriangleIds> canonical_triangle_set(std::span<const TriangleIds> triangles) {
  std::vector<TriangleIds> out;
  out.reserve(triangles.size());
  for (const TriangleIds& t : triangles) out.push_back(canonical_triangle(t));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace dtlab
