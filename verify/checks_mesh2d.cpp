// The exact checks of a 2D mesh (checks_mesh2d.hpp).
#include "verify/checks_mesh2d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "kernel/constructions.hpp"
#include "kernel/predicates.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

namespace {

std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; }

ReportCounts counts_of(const MeshCheckReport2& r) {
  return {{"vertices", r.vertices},   {"triangles", r.triangles},     {"edges", r.edges},
          {"segments", r.segments},   {"chain_edges", r.chain_edges}, {"region_checks", r.region_checks},
          {"exterior_segments", r.exterior_segments}};
}

// The triangle of `empty` whose interior meets the interior of the ccw triangle abc next to a,
// just counter-clockwise of the direction ab; kNone where that is outside the hull. Exact
// orient2d only: no point is constructed, so a sliver whose centroid would round across a
// constrained edge (crossings of a segment soup round within ulps of each other) is placed
// right. Once the output's edges follow the constrained ones, the interior of abc lies in one
// region, and any triangle that meets it tells which.
std::uint32_t triangle_beside(const Mesh2& empty, const Vec2& a, const Vec2& b, const Vec2& c, std::uint32_t& hint) {
  const Mesh2::Location loc = empty.locate(a, hint);
  if (loc.where == Mesh2::Where::Outside) return Mesh2::kNone;
  if (loc.where == Mesh2::Where::Triangle) return loc.triangle;
  if (loc.where == Mesh2::Where::Edge) {
    // a inside the edge pq, whose triangle (left of p -> q) is triangle_of(h): abc lies on the
    // side of c (b may lie on the edge's line; c cannot as well, abc being ccw).
    const std::uint32_t h = loc.handle;
    const Vec2 &p = empty.point(empty.origin(h)), &q = empty.point(empty.destination(h));
    Sign side = orient2d(p, q, b);
    if (side == Sign::Zero) side = orient2d(p, q, c);
    const std::uint32_t t = side == Sign::Positive ? Mesh2::triangle_of(h) : Mesh2::triangle_of(empty.twin(h));
    return empty.is_ghost(t) ? Mesh2::kNone : t;
  }
  // a at a vertex: the triangle (a, p, q) around it whose angle holds the direction ab, from ap
  // included to aq excluded (each angle is below pi, so the two signs decide).
  std::vector<std::uint32_t> ring;
  empty.ball(loc.handle, ring);
  for (const std::uint32_t h : ring) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    if (empty.is_ghost(t)) continue;
    const Vec2 &p = empty.point(empty.origin(h)), &q = empty.point(empty.destination(h));
    if (orient2d(a, p, b) != Sign::Negative && orient2d(a, b, q) == Sign::Positive) return t;
  }
  return Mesh2::kNone;
}

}  // namespace

MeshCheckReport2 check_mesh2d(const ConstrainedInput2& input, const Constrained2dResult& cdt, const MeshData2& out,
                              std::uint32_t first_number) {
  MeshCheckReport2 r;
  r.vertices = out.vertices.size();
  r.triangles = out.triangles.size();
  r.edges = out.edges.size();
  r.segments = input.segments.size();
  const auto name = [&](std::size_t i) { return std::to_string(i + first_number); };
  // Validity.
  {
    std::vector<Vec2> sorted(out.vertices);
    std::sort(sorted.begin(), sorted.end(), [](const Vec2& a, const Vec2& b) { return a < b; });
    for (std::size_t i = 1; i < sorted.size(); ++i) {
      if (sorted[i] == sorted[i - 1]) r.add_problem("two output vertices at (" + std::to_string(sorted[i].x) + ", " + std::to_string(sorted[i].y) + ")");
    }
  }
  std::unordered_map<std::uint64_t, std::uint32_t> half_edges;  // directed edge -> triangle
  half_edges.reserve(out.triangles.size() * 4);
  for (std::uint32_t t = 0; t < out.triangles.size(); ++t) {
    const auto& v = out.triangles[t];
    if (std::max({v[0], v[1], v[2]}) >= out.vertices.size()) {
      r.add_problem("triangle " + std::to_string(t + 1) + " uses a vertex out of range");
      continue;
    }
    if (orient2d(out.vertices[v[0]], out.vertices[v[1]], out.vertices[v[2]]) != Sign::Positive) {
      r.add_problem("triangle " + std::to_string(t + 1) + " is not strictly counter-clockwise");
    }
    r.area += signed_area(out.vertices[v[0]], out.vertices[v[1]], out.vertices[v[2]]);
    for (int i = 0; i < 3; ++i) {
      if (!half_edges.emplace(key(v[i], v[(i + 1) % 3]), t).second) {
        r.add_problem("edge (" + std::to_string(v[i] + 1) + ", " + std::to_string(v[(i + 1) % 3] + 1) +
                      ") is in two triangles with the same orientation (triangle " + std::to_string(t + 1) + ")");
      }
    }
  }
  std::unordered_map<std::uint64_t, int> edge_ref;  // undirected (min, max) -> ref
  std::vector<std::vector<std::uint32_t>> edge_adj(out.vertices.size());
  for (std::size_t e = 0; e < out.edges.size(); ++e) {
    const auto [a, b] = out.edges[e];
    if (std::max(a, b) >= out.vertices.size()) {
      r.add_problem("edge " + std::to_string(e + 1) + " uses a vertex out of range");
      continue;
    }
    if (!half_edges.count(key(a, b)) && !half_edges.count(key(b, a))) {
      r.add_problem("edge " + std::to_string(e + 1) + " is not an edge of the triangles");
    }
    edge_ref[key(std::min(a, b), std::max(a, b))] = out.edge_refs.empty() ? 0 : out.edge_refs[e];
    edge_adj[a].push_back(b);
    edge_adj[b].push_back(a);
  }
  for (const auto& [k, t] : half_edges) {
    const std::uint32_t a = static_cast<std::uint32_t>(k >> 32), b = static_cast<std::uint32_t>(k);
    if (!half_edges.count(key(b, a)) && !edge_ref.count(key(std::min(a, b), std::max(a, b)))) {
      r.add_problem("boundary edge (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) + ") of triangle " +
                    std::to_string(t + 1) + " is not an output edge");
    }
  }
  // Regions, coverage and constraints, against the input's constrained Delaunay triangulation.
  const auto cdt_points = cdt.triangulation.points();
  for (const auto& t : cdt.triangles) r.domain_area += signed_area(cdt_points[t[0]], cdt_points[t[1]], cdt_points[t[2]]);
  if (cdt.triangles.empty()) {
    if (!out.triangles.empty()) r.add_problem("the output has triangles but the input's domain has none");
    return r;
  }
  const Mesh2 empty(cdt.triangulation, cdt.slot_regions, {});  // the regions per slot; no constraint marks needed
  // Constraints: every piece of an input segment in the empty mesh (split at input vertices and
  // crossings) with the domain on a side is a chain of output Edges, each step forward along the
  // piece, carrying the marker of one of the segments along it; pieces outside the domain are
  // not meshed.
  std::map<std::pair<double, double>, std::uint32_t> by_point;
  for (std::uint32_t v = 0; v < out.vertices.size(); ++v) by_point[{out.vertices[v].x, out.vertices[v].y}] = v;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<int>> piece_markers;
  for (const ConstrainedEdge2& e : cdt.constrained_edges) piece_markers[{e.a, e.b}].push_back(e.marker);
  for (const ConstrainedEdge2& e : cdt.shared_edges) piece_markers[{e.a, e.b}].push_back(e.marker);
  std::unordered_map<std::uint64_t, std::vector<int>> allowed;
  // Chain vertices off their piece's line by rounding (a resampled boundary's cut points).
  std::vector<std::uint8_t> rounded(out.vertices.size(), 0);
  std::vector<std::uint8_t> segment_seen(input.segments.size(), 0);
  for (const ConstrainedEdge2& e : cdt.constrained_edges) {
    const std::uint32_t h = empty.find_half_edge(e.a, e.b);
    if (h == Mesh2::kNone) {
      r.add_problem("segment " + name(e.segment) + ": a piece is not an edge of the empty mesh");
      continue;
    }
    if (!empty.in_domain(Mesh2::triangle_of(h)) && !empty.in_domain(Mesh2::triangle_of(empty.twin(h)))) continue;
    segment_seen[e.segment] = 1;
    const Vec2 A = cdt_points[e.a], B = cdt_points[e.b];
    const auto ia = by_point.find({A.x, A.y}), ib = by_point.find({B.x, B.y});
    if (ia == by_point.end() || ib == by_point.end()) {
      r.add_problem("segment " + name(e.segment) + ": an end of a piece is not an output vertex");
      continue;
    }
    const std::vector<int>& markers = piece_markers[{e.a, e.b}];
    const Vec2 dir = B - A;
    const double scale = std::max({std::fabs(A.x), std::fabs(A.y), std::fabs(B.x), std::fabs(B.y), 1e-300});
    std::uint32_t v = ia->second;
    double progress = 0.0;
    bool reached = false;
    for (std::size_t steps = 0; steps <= out.vertices.size(); ++steps) {
      if (v == ib->second) {
        reached = true;
        break;
      }
      std::uint32_t best = UINT32_MAX;
      double best_progress = 2.0;
      bool best_exact = true;
      for (const std::uint32_t w : edge_adj[v]) {
        const Vec2 P = out.vertices[w];
        const double t = dot(P - A, dir) / dot(dir, dir);
        if (!(t > progress && t <= 1.0 + 1e-15)) continue;
        // On the piece: exactly, or (a cut point of a resampled boundary, rounded) within a few
        // ulps of its line.
        const bool exact = orient2d(A, B, P) == Sign::Zero;
        const bool on = exact || std::fabs(cross(dir, P - A)) / norm(dir) <= 8.0 * 2.220446049250313e-16 * scale;
        // A step exactly on the piece before one within ulps of it: crossings of a soup that round
        // within ulps of each other put another piece's end that close, and taking it would stall.
        if (on && (best == UINT32_MAX || (exact && !best_exact) || (exact == best_exact && t < best_progress))) {
          best = w;
          best_progress = t;
          best_exact = exact;
        }
      }
      if (best == UINT32_MAX) break;
      if (!best_exact) rounded[best] = 1;
      ++r.chain_edges;
      auto& list = allowed[key(std::min(v, best), std::max(v, best))];
      list.insert(list.end(), markers.begin(), markers.end());
      v = best;
      progress = best_progress;
    }
    if (!reached) r.add_problem("segment " + name(e.segment) + " is not a chain of output edges");
  }
  for (std::size_t s = 0; s < input.segments.size(); ++s) r.exterior_segments += !segment_seen[s];
  // Regions: where the three vertices are exact (input points, crossings, field points, points
  // exactly on a piece), the triangle of the empty mesh beside the first one, found by exact
  // orient2d alone; the centroid's where a vertex is a rounded cut point, which may lie outside
  // the input's domain by ulps (the centroid of such a triangle, not a sliver, lies well inside).
  std::uint32_t hint = 0;
  while (hint < empty.triangle_capacity() && !empty.in_domain(hint)) ++hint;
  for (std::uint32_t t = 0; t < out.triangles.size(); ++t) {
    const auto& v = out.triangles[t];
    if (std::max({v[0], v[1], v[2]}) >= out.vertices.size()) continue;
    const Vec2 &a = out.vertices[v[0]], &b = out.vertices[v[1]], &c = out.vertices[v[2]];
    if (orient2d(a, b, c) != Sign::Positive) continue;  // reported above
    std::uint32_t beside = Mesh2::kNone;
    if (!rounded[v[0]] && !rounded[v[1]] && !rounded[v[2]]) {
      beside = triangle_beside(empty, a, b, c, hint);
    } else {
      const Mesh2::Location loc = empty.locate((1.0 / 3.0) * (a + b + c), hint);
      if (loc.where != Mesh2::Where::Outside) beside = loc.triangle;
    }
    ++r.region_checks;
    if (beside == Mesh2::kNone || !empty.in_domain(beside)) {
      r.add_problem("triangle " + std::to_string(t + 1) + " lies outside the domain");
      continue;
    }
    hint = beside;
    const int want = empty.ref(beside);
    const int got = out.triangle_refs.empty() ? 0 : out.triangle_refs[t];
    if (want != got) {
      r.add_problem("triangle " + std::to_string(t + 1) + " has reference " + std::to_string(got) + ", its region " +
                    std::to_string(want));
    }
  }
  for (const auto& [k, markers] : allowed) {
    const int ref = edge_ref.at(k);
    if (std::find(markers.begin(), markers.end(), ref) == markers.end()) {
      r.add_problem("edge (" + std::to_string((k >> 32) + 1) + ", " + std::to_string((k & 0xFFFFFFFFu) + 1) +
                    ") has reference " + std::to_string(ref) + ", which no segment along it has");
    }
  }
  if (std::fabs(r.area - r.domain_area) > 1e-9 * std::max(std::fabs(r.domain_area), 1e-300)) {
    r.add_problem("the triangles' area " + std::to_string(r.area) + " differs from the domain's " +
                  std::to_string(r.domain_area));
  }
  return r;
}

std::string to_json(const MeshCheckReport2& r) { return report_json(r, counts_of(r)); }
std::string to_text(const MeshCheckReport2& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
