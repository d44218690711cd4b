// Facets of a PLC as triangles (facet_triangulation.hpp): exact planarity and simplicity checks,
// then the constrained Delaunay triangulation of each facet in its plane (book §3.4, §3.5;
// algorithms/constrained2d), and the optional merging of coplanar neighbour facets (TetGen's
// default, TetGen 1.5 manual §4.2.1, -M).
#include "algorithms/constrained3d/plc/facet_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/intersections.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

using Tri = std::array<std::uint32_t, 3>;

std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) noexcept {
  return u < v ? std::uint64_t{u} << 32 | v : std::uint64_t{v} << 32 | u;
}
std::uint64_t directed_key(std::uint32_t u, std::uint32_t v) noexcept { return std::uint64_t{u} << 32 | v; }

class Names {
 public:
  explicit Names(const FacetTriangulationOptions& o) : o_(o) {}
  std::string facet(std::size_t f) const { return o_.facet_name ? o_.facet_name(f) : "facet " + std::to_string(f + 1); }
  std::string vertex(std::uint32_t v) const { return std::to_string(std::uint64_t{v} + o_.first_vertex_number); }

 private:
  const FacetTriangulationOptions& o_;
};

// The drop axis of the plane through non-collinear a, b, c: the largest component of the normal
// (in doubles: a choice, not a decision), confirmed exactly: orient2d of the projected triangle is
// that component's sign, so it must not be 0 (if rounding chose a zero component, the exact
// first non-degenerate axis of kernel/intersections.hpp instead).
int drop_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double m[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  const int axis = m[0] >= m[1] && m[0] >= m[2] ? 0 : (m[1] >= m[2] ? 1 : 2);
  if (orient2d(project(a, axis), project(b, axis), project(c, axis)) != Sign::Zero) return axis;
  return projection_axis(a, b, c);
}

// One facet's vertices (in order of first appearance) with local numbers.
struct LocalVertices {
  std::vector<std::uint32_t> ids;
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  std::uint32_t add(std::uint32_t v) {
    const auto [it, inserted] = local.emplace(v, static_cast<std::uint32_t>(ids.size()));
    if (inserted) ids.push_back(v);
    return it->second;
  }
};

class FacetTriangulator {
 public:
  FacetTriangulator(const Plc3& plc, const FacetTriangulationOptions& options, FacetTriangulation& out)
      : plc_(plc), names_(options), out_(out), triangulate_nonplanar_(options.triangulate_nonplanar) {}

  void facet(std::size_t f) {
    const PlcFacet3& facet = plc_.facets[f];
    for (std::size_t p = 0; p < facet.polygons.size(); ++p) {
      if (facet.polygons[p].empty()) fail(f, polygon_name(f, p) + " has no corner");
      for (const std::uint32_t v : facet.polygons[p])
        if (v >= plc_.vertices.size())
          fail(f, polygon_name(f, p) + ": vertex " + names_.vertex(v) + " is out of range (" +
                      std::to_string(plc_.vertices.size()) + " vertices)");
    }
    const std::size_t largest = std::accumulate(facet.polygons.begin(), facet.polygons.end(), std::size_t{0},
                                                [](std::size_t m, const auto& p) { return std::max(m, p.size()); });
    if (largest < 3) {
      ++out_.segments_alone;
      return;
    }
    if (facet.polygons.size() == 1 && largest == 3 && facet.holes.empty()) {
      const auto& p = facet.polygons[0];
      emit({p[0], p[1], p[2]}, f);
      return;
    }
    ++out_.polygon_facets;
    triangulate_polygon_facet(f);
  }

 private:
  [[noreturn]] void fail(std::size_t f, const std::string& what) const {
    throw InputError(what, {static_cast<std::uint64_t>(f)});
  }
  std::string polygon_name(std::size_t f, std::size_t p) const {
    return names_.facet(f) + (plc_.facets[f].polygons.size() > 1 ? ", polygon " + std::to_string(p + 1) : "");
  }
  void emit(const Tri& t, std::size_t f) {
    out_.triangles.push_back(t);
    out_.triangle_refs.push_back(plc_.facets[f].marker);
    out_.triangle_facet.push_back(static_cast<std::uint32_t>(f));
  }

  // Planarity against the first three non-collinear vertices; returns the drop axis (of a
  // non-planar facet under triangulate_nonplanar: the largest component of its first polygon's
  // Newell normal).
  int plane_of(std::size_t f, const std::vector<std::uint32_t>& ids) {
    const auto& P = plc_.vertices;
    const Vec3& a = P[ids[0]];
    std::size_t ib = 0, ic = 0;
    for (std::size_t i = 1; i < ids.size() && ib == 0; ++i)
      if (!(P[ids[i]] == a)) ib = i;
    for (std::size_t i = ib + 1; ib != 0 && i < ids.size() && ic == 0; ++i)
      if (!collinear3(a, P[ids[ib]], P[ids[i]])) ic = i;
    if (ic == 0) fail(f, names_.facet(f) + " is degenerate: all its vertices lie on one line (no area)");
    const Vec3& b = P[ids[ib]];
    const Vec3& c = P[ids[ic]];
    const Vec3 n = cross(b - a, c - a);
    std::size_t off = 0, farthest = 0;
    double distance = -1.0;
    for (std::size_t i = 1; i < ids.size(); ++i) {
      if (orient3d(a, b, c, P[ids[i]]) == Sign::Zero) continue;
      ++off;
      const double d = std::fabs(dot(n, P[ids[i]] - a)) / std::sqrt(dot(n, n));
      if (d > distance) distance = d, farthest = i;
    }
    if (off > 0 && triangulate_nonplanar_) {
      const PlcFacet3& facet = plc_.facets[f];
      for (const auto& poly : facet.polygons) {
        if (poly.size() < 3) continue;
        Vec3 newell{0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < poly.size(); ++i) newell = newell + cross(P[poly[i]], P[poly[(i + 1) % poly.size()]]);
        const double m[3] = {std::fabs(newell.x), std::fabs(newell.y), std::fabs(newell.z)};
        if (!(std::max({m[0], m[1], m[2]}) > 0.0)) break;
        ++out_.nonplanar_facets;
        return m[0] >= m[1] && m[0] >= m[2] ? 0 : (m[1] >= m[2] ? 1 : 2);
      }
    }
    if (off > 0) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3g", distance);
      fail(f, names_.facet(f) + " is not planar: " + std::to_string(off) + " of its vertices lie off the plane of vertices " +
                  names_.vertex(ids[0]) + ", " + names_.vertex(ids[ib]) + ", " + names_.vertex(ids[ic]) +
                  " (decided exactly), the farthest vertex " + names_.vertex(ids[farthest]) + " at distance " + buf);
    }
    return drop_axis(a, b, c);
  }

  // Simplicity of polygon p (3 or more corners) of facet f, on its projected corners.
  void check_simple(std::size_t f, std::size_t p, int axis) const {
    const auto& poly = plc_.facets[f].polygons[p];
    const std::size_t n = poly.size();
    std::vector<std::uint32_t> sorted = poly;
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end())
      fail(f, polygon_name(f, p) + " touches itself: vertex " + names_.vertex(*repeated) +
                  " is two of its corners (not a simple polygon)");
    std::vector<Vec2> q(n);
    for (std::size_t i = 0; i < n; ++i) q[i] = project(plc_.vertices[poly[i]], axis);
    bool flat = true;
    for (std::size_t i = 2; i < n && flat; ++i) flat = orient2d(q[0], q[1], q[i]) == Sign::Zero;
    if (flat) fail(f, polygon_name(f, p) + " is degenerate: all its corners lie on one line (no area)");
    // Edge i runs from corner i to corner i + 1; pairs whose x-extents overlap, by a sweep.
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto lo = [&](std::size_t i) { return std::min(q[i].x, q[(i + 1) % n].x); };
    const auto hi = [&](std::size_t i) { return std::max(q[i].x, q[(i + 1) % n].x); };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
    const auto edge = [&](std::size_t i) {
      std::string text = names_.vertex(poly[i]);
      text += ", ";
      text += names_.vertex(poly[(i + 1) % n]);
      return "(" + text + ")";
    };
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = order[k];
      for (std::size_t m = k + 1; m < n && lo(order[m]) <= hi(i); ++m) {
        const std::size_t j = order[m];
        const Vec2 &a = q[i], &b = q[(i + 1) % n], &c = q[j], &d = q[(j + 1) % n];
        if ((i + 1) % n == j || (j + 1) % n == i) {
          // Consecutive edges share one corner s; they overlap iff the other ends lie on one ray from s.
          const bool j_follows = (i + 1) % n == j;
          const Vec2& s = j_follows ? b : a;
          const Vec2& u = j_follows ? a : b;
          const Vec2& w = j_follows ? d : c;
          if (orient2d(u, s, w) == Sign::Zero && (on_segment2(w, s, u) || on_segment2(u, s, w)))
            fail(f, polygon_name(f, p) + " touches itself: its edges " + edge(i) + " and " + edge(j) +
                        " overlap (it folds back along a line; not a simple polygon)");
          continue;
        }
        if (!segments_intersect2(a, b, c, d)) continue;
        const bool crossing = to_int(orient2d(a, b, c)) * to_int(orient2d(a, b, d)) < 0 &&
                              to_int(orient2d(c, d, a)) * to_int(orient2d(c, d, b)) < 0;
        fail(f, polygon_name(f, p) + (crossing ? " crosses itself: its edges " : " touches itself: its edges ") +
                    edge(i) + " and " + edge(j) + (crossing ? " cross" : " meet") + " (not a simple polygon)");
      }
    }
  }

  void triangulate_polygon_facet(std::size_t f) {
    const PlcFacet3& facet = plc_.facets[f];
    LocalVertices lv;
    for (const auto& poly : facet.polygons)
      for (const std::uint32_t v : poly) lv.add(v);
    const int axis = plane_of(f, lv.ids);
    std::vector<Vec2> points(lv.ids.size());
    for (std::size_t i = 0; i < lv.ids.size(); ++i) points[i] = project(plc_.vertices[lv.ids[i]], axis);
    // Two vertices of one plane with one projection are one point.
    {
      std::vector<std::uint32_t> by(points.size());
      std::iota(by.begin(), by.end(), 0u);
      std::sort(by.begin(), by.end(), [&](std::uint32_t a, std::uint32_t b) { return points[a] < points[b]; });
      for (std::size_t k = 1; k < by.size(); ++k)
        if (points[by[k]] == points[by[k - 1]])
          fail(f, names_.facet(f) + ": vertices " + names_.vertex(std::min(lv.ids[by[k]], lv.ids[by[k - 1]])) +
                      " and " + names_.vertex(std::max(lv.ids[by[k]], lv.ids[by[k - 1]])) + " are at the same point");
    }
    std::vector<std::array<std::uint32_t, 2>> segments;
    int turn = 0;  // the facet's turn in the projection: its first polygon of 3 or more corners
    for (std::size_t p = 0; p < facet.polygons.size(); ++p) {
      const auto& poly = facet.polygons[p];
      if (poly.size() == 2 && poly[0] == poly[1])
        fail(f, polygon_name(f, p) + " is a segment from vertex " + names_.vertex(poly[0]) + " to itself");
      if (poly.size() == 2) segments.push_back({lv.local[poly[0]], lv.local[poly[1]]});
      if (poly.size() < 3) continue;
      check_simple(f, p, axis);
      for (std::size_t i = 0; i < poly.size(); ++i)
        segments.push_back({lv.local[poly[i]], lv.local[poly[(i + 1) % poly.size()]]});
      if (turn == 0) {
        // At the lowest corner (lexicographically) a simple polygon turns its own way, never flat.
        const std::size_t n = poly.size();
        std::size_t low = 0;
        for (std::size_t i = 1; i < n; ++i)
          if (points[lv.local[poly[i]]] < points[lv.local[poly[low]]]) low = i;
        turn = to_int(orient2d(points[lv.local[poly[(low + n - 1) % n]]], points[lv.local[poly[low]]],
                                points[lv.local[poly[(low + 1) % n]]]));
        DTLAB_ASSERT(turn != 0);
      }
    }
    std::vector<Vec2> holes;
    for (const Vec3& h : facet.holes) holes.push_back(project(h, axis));
    Constrained2dOptions options;
    options.method = "cdt";
    options.first_number = 1;
    Constrained2dResult r;
    try {
      r = constrained2d({.points = points, .segments = segments, .segment_markers = {}, .holes = holes, .regions = {}},
                        options);
    } catch (const InputError& e) {  // a zero-length segment, a hole point out of range: in the facet's terms
      fail(f, names_.facet(f) + " (its vertices and edges numbered from 1 in order of appearance): " + e.what());
    }
    if (r.triangulation.point_count() != points.size())
      fail(f, names_.facet(f) + ": its polygons cross each other (" +
                  std::to_string(r.triangulation.point_count() - points.size()) +
                  " crossing point(s); a facet's polygons may share corners and edges only)");
    for (const std::string& m : r.messages)
      if (m.starts_with("hole ")) out_.messages.push_back(names_.facet(f) + ": " + m);
    if (r.triangles.empty()) out_.messages.push_back(names_.facet(f) + " has no area left once its holes are removed");
    for (const auto& t : r.triangles) {
      const Tri g{lv.ids[t[0]], lv.ids[t[1]], lv.ids[t[2]]};
      emit(turn > 0 ? g : Tri{g[0], g[2], g[1]}, f);
    }
  }

  const Plc3& plc_;
  Names names_;
  FacetTriangulation& out_;
  bool triangulate_nonplanar_ = false;
};

// --- Merging coplanar facets ---------------------------------------------------------------------

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Triangles s and t across edge (u, v) (s holds u -> v): in one plane, on either side of the
// edge, so that joining them makes a flat quadrilateral, not a fold.
bool coplanar_across(const std::vector<Vec3>& P, std::uint32_t u, std::uint32_t v, std::uint32_t ws,
                     std::uint32_t wt) {
  if (collinear3(P[u], P[v], P[ws]) || collinear3(P[u], P[v], P[wt])) return false;
  if (orient3d(P[u], P[v], P[ws], P[wt]) != Sign::Zero) return false;
  const int axis = projection_axis(P[u], P[v], P[ws]);
  const Vec2 a = project(P[u], axis), b = project(P[v], axis);
  const Sign s = orient2d(a, b, project(P[ws], axis)), t = orient2d(a, b, project(P[wt], axis));
  return t != Sign::Zero && t != s;
}

class CoplanarMerger {
 public:
  CoplanarMerger(const Plc3& plc, FacetTriangulation& out)
      : P_(plc.vertices), out_(out) {}

  void run() {
    const std::size_t n = out_.triangles.size();
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    // (undirected key, triangle, side k): every triangle edge.
    std::vector<std::array<std::uint64_t, 2>> edges;
    edges.reserve(3 * n);
    for (std::uint32_t t = 0; t < n; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        edges.push_back({edge_key(out_.triangles[t][k], out_.triangles[t][(k + 1) % 3]), std::uint64_t{t} << 2 | k});
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i + 1;
      while (j < edges.size() && edges[j][0] == edges[i][0]) ++j;
      if (j - i == 2) {
        const auto s = static_cast<std::uint32_t>(edges[i][1] >> 2), t = static_cast<std::uint32_t>(edges[i + 1][1] >> 2);
        const auto ks = static_cast<int>(edges[i][1] & 3), kt = static_cast<int>(edges[i + 1][1] & 3);
        const Tri &S = out_.triangles[s], &T = out_.triangles[t];
        const std::uint32_t u = S[ks], v = S[(ks + 1) % 3];
        // Consistently turned: t holds v -> u.
        if (out_.triangle_refs[s] == out_.triangle_refs[t] && T[kt] == v && T[(kt + 1) % 3] == u &&
            coplanar_across(P_, u, v, S[(ks + 2) % 3], T[(kt + 2) % 3])) {
          joined_.insert(edges[i][0]);
          parent[find_root(parent, s)] = find_root(parent, t);
        }
      }
      i = j;
    }
    // Groups, in order of their first triangle; only those spanning two or more facets change.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> groups;
    for (std::uint32_t t = 0; t < n; ++t) groups[find_root(parent, t)].push_back(t);
    FacetTriangulation next;
    std::vector<std::uint8_t> done(n, 0);
    std::size_t kept_apart = 0;
    for (std::uint32_t t = 0; t < n; ++t) {
      if (done[t]) continue;
      const std::vector<std::uint32_t>& group = groups[find_root(parent, t)];
      std::vector<std::uint32_t> facets;
      for (const std::uint32_t g : group) facets.push_back(out_.triangle_facet[g]), done[g] = 1;
      std::sort(facets.begin(), facets.end());
      facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
      std::vector<Tri> merged;
      if (facets.size() > 1 && retriangulate(group, merged)) {
        for (const Tri& m : merged) {
          next.triangles.push_back(m);
          next.triangle_refs.push_back(out_.triangle_refs[t]);
          next.triangle_facet.push_back(facets.front());
        }
        out_.merged_facets += facets.size();
        next.merged.push_back(std::move(facets));
        continue;
      }
      if (facets.size() > 1) ++kept_apart;
      for (const std::uint32_t g : group) {
        next.triangles.push_back(out_.triangles[g]);
        next.triangle_refs.push_back(out_.triangle_refs[g]);
        next.triangle_facet.push_back(out_.triangle_facet[g]);
      }
    }
    out_.triangles = std::move(next.triangles);
    out_.triangle_refs = std::move(next.triangle_refs);
    out_.triangle_facet = std::move(next.triangle_facet);
    out_.merged = std::move(next.merged);
    if (kept_apart > 0)
      out_.messages.push_back(std::to_string(kept_apart) +
                              " group(s) of coplanar facets kept apart: their joint triangulation would not keep "
                              "their triangle count (overlapping or touching input)");
  }

 private:
  // The constrained Delaunay triangulation of the group's vertices, its unjoined edges as
  // constraints, keeping the side of each boundary edge that its triangle lay on. False (and
  // `result` unusable) where it adds a point or changes the triangle count.
  bool retriangulate(const std::vector<std::uint32_t>& group, std::vector<Tri>& result) const {
    LocalVertices lv;
    for (const std::uint32_t g : group)
      for (const std::uint32_t v : out_.triangles[g]) lv.add(v);
    const Tri& first = out_.triangles[group.front()];
    const int axis = drop_axis(P_[first[0]], P_[first[1]], P_[first[2]]);
    std::vector<Vec2> points(lv.ids.size());
    for (std::size_t i = 0; i < lv.ids.size(); ++i) points[i] = project(P_[lv.ids[i]], axis);
    const bool positive =
        orient2d(points[lv.local.at(first[0])], points[lv.local.at(first[1])], points[lv.local.at(first[2])]) ==
        Sign::Positive;
    std::vector<std::array<std::uint32_t, 2>> segments;
    std::vector<std::uint64_t> seeds;  // directed local edges with an inside triangle on their left
    std::unordered_set<std::uint64_t> segment_keys;
    for (const std::uint32_t g : group)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = out_.triangles[g][k], v = out_.triangles[g][(k + 1) % 3];
        if (joined_.count(edge_key(u, v))) continue;
        const std::uint32_t a = lv.local.at(u), b = lv.local.at(v);
        if (segment_keys.insert(edge_key(a, b)).second) segments.push_back({a, b});
        seeds.push_back(positive ? directed_key(a, b) : directed_key(b, a));
      }
    Constrained2dOptions options;
    options.method = "cdt";
    options.keep_exterior = true;
    const Constrained2dResult r = constrained2d({.points = points, .segments = segments, .segment_markers = {}, .holes = {}, .regions = {}}, options);
    if (r.triangulation.point_count() != points.size()) return false;
    std::unordered_map<std::uint64_t, std::uint32_t> by_edge;  // directed edge -> its triangle (ccw)
    for (std::uint32_t t = 0; t < r.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) by_edge[directed_key(r.triangles[t][k], r.triangles[t][(k + 1) % 3])] = t;
    std::unordered_set<std::uint64_t> constrained;
    for (const ConstrainedEdge2& e : r.constrained_edges) constrained.insert(edge_key(e.a, e.b));
    std::vector<std::uint8_t> inside(r.triangles.size(), 0);
    std::vector<std::uint32_t> stack;
    for (const std::uint64_t s : seeds) {
      const auto it = by_edge.find(s);
      if (it != by_edge.end() && !inside[it->second]) inside[it->second] = 1, stack.push_back(it->second);
    }
    while (!stack.empty()) {
      const Tri t = r.triangles[stack.back()];
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = t[k], v = t[(k + 1) % 3];
        if (constrained.count(edge_key(u, v))) continue;
        const auto it = by_edge.find(directed_key(v, u));
        if (it != by_edge.end() && !inside[it->second]) inside[it->second] = 1, stack.push_back(it->second);
      }
    }
    result.clear();
    std::vector<std::uint8_t> used(points.size(), 0);
    for (std::uint32_t t = 0; t < r.triangles.size(); ++t) {
      if (!inside[t]) continue;
      const Tri& l = r.triangles[t];
      for (const std::uint32_t v : l) used[v] = 1;
      const Tri g{lv.ids[l[0]], lv.ids[l[1]], lv.ids[l[2]]};
      result.push_back(positive ? g : Tri{g[0], g[2], g[1]});
    }
    return result.size() == group.size() && std::find(used.begin(), used.end(), 0) == used.end();
  }

  const std::vector<Vec3>& P_;
  FacetTriangulation& out_;
  std::unordered_set<std::uint64_t> joined_;  // edges across which triangles were joined
};

}  // namespace

FacetTriangulation triangulate_facets(const Plc3& plc, const FacetTriangulationOptions& options) {
  check_coordinates(plc.vertices, "PLC vertex");
  for (const PlcFacet3& f : plc.facets) check_coordinates(f.holes, "facet hole point");
  FacetTriangulation out;
  out.triangles.reserve(plc.facets.size());
  FacetTriangulator triangulator(plc, options, out);
  for (std::size_t f = 0; f < plc.facets.size(); ++f) triangulator.facet(f);
  if (options.merge_coplanar) CoplanarMerger(plc, out).run();
  if (out.nonplanar_facets > 0) {
    out.messages.push_back(std::to_string(out.nonplanar_facets) +
                           " facet(s) not planar, triangulated in their projection (as asked)");
  }
  return out;
}

}  // namespace dtlab
