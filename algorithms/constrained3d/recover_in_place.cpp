// Method "recover" in place (recover.cpp): one tetrahedralization, transformed by flips
// (flip_recovery.hpp) and split at Steiner points without any Delaunay insertion, as TetGen
// does. Edges: every missing piece recovered by flips along its pipe (tried again while flips for
// the others succeed), else split where its walk stopped, into the mesh, and its halves tried
// again. Triangles: each is given the Delaunay triangulation of its vertices in its own plane
// (facet_delaunay_pieces: well-shaped pieces, which flips make far more often than the thin
// ones of an ear-clipping; Chazelle's polyhedron with n = 2 went from 775 Steiner points to 36);
// every triangle of it is recovered by flips (its new edges first, then the face), and where one
// is not, a Steiner point of the input triangle goes where a mesh edge crosses it (else its
// centroid) and the triangulation is made again.
// Gives up (returning why, or throwing InputError) where a point cannot be placed or a triangle
// stays missing after its share of points; the caller then takes the rounds of recover.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "algorithms/constrained3d/recovery/recovery.hpp"
#include "kernel/error.hpp"
#include "kernel/rounding.hpp"
#include "mesh/element_sets3.hpp"

namespace dtlab {

namespace {

using Tri = std::array<std::uint32_t, 3>;

// Where to split piece i of edge e that flips could not make: where it meets the face its walk
// stopped at (TetGen's choice: the pipe is cut there), kept in the middle three quarters of the
// piece; the usual split (concentric shells, midpoint) if there is no such face. A placement in
// doubles: any parameter inside the piece gives an exact point of the edge.
double split_at_block(const Constrained3dContext& c, std::uint32_t e, std::size_t i, const std::array<std::uint32_t, 3>& block) {
  const auto [x, y, z] = block;
  if (x == Tetrahedralization3::kNone || x == Tetrahedralization3::kInfinite || y == Tetrahedralization3::kInfinite ||
      z == Tetrahedralization3::kInfinite)
    return edge_split_parameter(c, e, i);
  const auto P = c.mesh.points();
  const ConstraintEdge3& edge = c.edges[e];
  const Vec3 &u = P[edge.chain[i]], &v = P[edge.chain[i + 1]];
  const Vec3 n = cross(P[y] - P[x], P[z] - P[x]);
  const double du = dot(n, u - P[x]), dv = dot(n, v - P[x]);
  if (!(du != dv) || !std::isfinite(du) || !std::isfinite(dv)) return edge_split_parameter(c, e, i);
  const double lambda = std::clamp(du / (du - dv), 0.125, 0.875);
  const double t0 = edge.t[i], t1 = edge.t[i + 1];
  const double t = t0 + lambda * (t1 - t0);
  return t0 < t && t < t1 ? t : edge_split_parameter(c, e, i);
}

// Where an edge of the mesh crosses sub-triangle t of facet f, in f's (s, t), computed in doubles
// (a placement: the point made is the exact facet point at these parameters), with that edge;
// nothing if no edge crosses t or the point found is not strictly inside t.
struct Crossing {
  std::array<double, 2> at;
  std::array<std::uint32_t, 2> edge;
};
std::optional<Crossing> crossing_in_triangle(const Constrained3dContext& c, FlipRecovery& recovery, std::uint32_t f,
                                             const FacetParameters& st, const Tri& t) {
  const auto [p, q] = recovery.crossing_edge(t[0], t[1], t[2]);
  if (p == Tetrahedralization3::kNone) return std::nullopt;
  const auto P = c.mesh.points();
  const auto& corners = c.facets[f].corners;
  const Vec3 A = P[corners[0]], e1 = P[corners[1]] - A, e2 = P[corners[2]] - A;
  const Vec3 n = cross(e1, e2);
  const double dp = dot(n, P[p] - A), dq = dot(n, P[q] - A);
  if (!(dp != dq)) return std::nullopt;
  const Vec3 x = P[p] + (dp / (dp - dq)) * (P[q] - P[p]) - A;
  // x = s e1 + t e2: the 2 x 2 normal equations.
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2), r1 = dot(x, e1), r2 = dot(x, e2);
  const double det = g11 * g22 - g12 * g12;
  if (!(det > 0)) return std::nullopt;
  const std::array<double, 2> at{(r1 * g22 - r2 * g12) / det, (r2 * g11 - r1 * g12) / det};
  if (!std::isfinite(at[0]) || !std::isfinite(at[1])) return std::nullopt;
  // Strictly inside t, exactly.
  const Rational S(at[0]), T(at[1]);
  for (int r = 0; r < 3; ++r) {
    const auto &u = st.at(t[r]), &v = st.at(t[(r + 1) % 3]);
    if (((v[0] - u[0]) * (T - u[1]) - (v[1] - u[1]) * (S - u[0])).sign() != Sign::Positive) return std::nullopt;
  }
  return Crossing{at, {p, q}};
}

// Where x + lambda (y - x) meets line ab (coplanar_edge_crossing: all four in one plane), kept in
// the middle seven eighths of xy; nothing where no mesh edge in its plane crosses xy.
std::optional<double> coplanar_crossing(const Constrained3dContext& c, FlipRecovery& recovery, std::uint32_t x,
                                         std::uint32_t y) {
  const auto [a, b] = recovery.coplanar_edge_crossing(x, y);
  if (a == Tetrahedralization3::kNone) return std::nullopt;
  const auto P = c.mesh.points();
  const Vec3 m = cross(P[y] - P[x], P[b] - P[a]);
  const double den = dot(m, m);
  const double lambda = dot(cross(P[a] - P[x], P[b] - P[a]), m) / den;
  if (!(den > 0) || !std::isfinite(lambda)) return std::nullopt;
  return std::clamp(lambda, 0.0625, 0.9375);
}

// Where sub-triangle t has an edge missing that a mesh edge in its plane crosses (on a flat face
// of the hull, or a flat part of the surface): the point where they cross, in the facet's (s, t),
// kept in the middle seven eighths of the edge; the point splits that mesh edge, one crossing
// fewer.
std::optional<std::array<double, 2>> crossing_in_plane(const Constrained3dContext& c, FlipRecovery& recovery,
                                                           const FacetParameters& st, const Tri& t) {
  for (int r = 0; r < 3; ++r) {
    const std::uint32_t x = t[r], y = t[(r + 1) % 3];
    if (recovery.has_edge(x, y)) continue;
    const auto lambda = coplanar_crossing(c, recovery, x, y);
    if (!lambda) continue;
    const auto &sx = st.at(x), &sy = st.at(y);
    const Rational L(*lambda);
    return std::array<double, 2>{round_to_double(sx[0] + L * (sy[0] - sx[0])), round_to_double(sx[1] + L * (sy[1] - sx[1]))};
  }
  return std::nullopt;
}

}  // namespace

std::string recover_in_place(Constrained3dContext& c) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
  auto start = Clock::now();
  // Which input edges and (unsplit) triangles the tetrahedralization has now, in one pass of
  // ball searches: they are protected, flips keep protected edges and faces, and a point never
  // goes onto one, so what is found here stays; only the others are searched and recovered one
  // by one (a surface the Delaunay tetrahedralization holds costs this pass and little more).
  std::vector<std::uint8_t> edge_found, face_found;
  {
    std::vector<std::array<std::uint32_t, 2>> edges;
    std::vector<Tri> faces;
    edges.reserve(c.edges.size());
    for (const ConstraintEdge3& e : c.edges) edges.push_back({e.chain.front(), e.chain.back()});
    faces.reserve(c.facets.size());
    for (const ConstraintFacet3& f : c.facets) faces.push_back(f.corners);
    find_in_mesh(c.mesh, edges, faces, edge_found, face_found);
  }  // (read only for an edge still of one piece and a triangle still of three vertices)
  std::vector<std::uint64_t> protected_edges = edge_piece_keys(c);
  std::vector<Tri> protected_faces;
  for (const ConstraintFacet3& f : c.facets) {
    Tri k = f.corners;
    std::sort(k.begin(), k.end());
    protected_faces.push_back(k);
  }
  std::sort(protected_faces.begin(), protected_faces.end());
  FlipRecovery recovery(c.mesh, std::move(protected_edges), std::move(protected_faces));
  recovery.allow_link_removals(true);
  recovery.record_changes(&c.changed);
  SteinerInserter inserter(c);
  // An edge split placed where its walk stopped goes in by splitting that face where it can
  // (split_crossed_face); any other point into the tetrahedron, face or edge that holds it.
  constexpr std::uint32_t kNone = Tetrahedralization3::kNone;
  std::array<std::uint32_t, 3> on_face{kNone, kNone, kNone};
  std::array<std::uint32_t, 2> on_piece{kNone, kNone};
  // A triangle's point placed where a mesh edge crosses it splits that edge, for the same reason:
  // inserted into the tetrahedron holding it, the rounded point kept the edge beside it, crossing
  // the triangle's new pieces there (Chazelle's polyhedron, n = 5: a triangle still missing
  // after 16 points). Never a protected edge (a constraint's piece).
  std::map<std::array<double, 3>, std::array<std::uint32_t, 2>> crossed_edge;  // by the rounded point
  inserter.set_placement([&](const Vec3& p, std::uint32_t near) {
    if (on_face[0] != kNone)
      if (const std::uint32_t id = recovery.split_crossed_face(on_piece[0], on_piece[1], on_face, p); id != kNone) return id;
    if (const auto it = crossed_edge.find({p.x, p.y, p.z}); it != crossed_edge.end()) {
      const auto [a, b] = it->second;
      if (!recovery.is_protected_edge(a, b))
        if (const std::uint32_t id = recovery.split_edge_at(a, b, p); id != kNone) return id;
    }
    return recovery.insert_point(p, near);
  });
  constexpr int kEdgePasses = 3;  // passes over the failed pieces before any is split

  // Edges. Each round splits the pieces that flips could not make (tried again while flips for
  // others succeed); the Steiner limit (in the inserter) bounds the rounds.
  std::vector<EdgeSplit> splits;
  const std::vector<FacetPoint> none;
  // Past as many Steiner points as the input has edges and triangles, the rounds of recover.cpp
  // take over (the bound at which they call on method conforming): at Chazelle n = 8 the edge
  // phase went on to 2,004 points, the triangles' then failed, and that attempt doubled the time.
  const auto too_many = [&] { return c.steiner.size() > c.edges.size() + c.facets.size(); };
  const std::string too_many_why = "more Steiner points than the input has edges and triangles";
  for (;;) {
    ++c.rounds;
    if (too_many()) return too_many_why;
    splits.clear();
    for (const MissingPiece& m : edge_pieces_flips_cannot_make(c, recovery, kEdgePasses, &edge_found))
      splits.push_back({m.edge, split_at_block(c, m.edge, m.index, m.block)});  // where its walk stopped
    if (splits.empty()) break;
    // One at a time: a split point that lands on another constraint (two edges a hair apart, as
    // in Chazelle's polyhedron) is moved along its piece, towards either end, before giving up.
    std::size_t added = 0;
    for (const EdgeSplit& split : splits) {
      const auto& t = c.edges[split.edge].t;
      const auto at = std::lower_bound(t.begin(), t.end(), split.t);
      if (at == t.begin() || at == t.end()) return "an edge split outside its piece";
      const double lo = *(at - 1), hi = *at;
      // Flips for the pieces split before may let this one be made now.
      const auto& chain = c.edges[split.edge].chain;
      const auto piece = static_cast<std::size_t>(at - t.begin());
      if (recovery.has_edge(chain[piece - 1], chain[piece]) || recovery.recover_edge(chain[piece - 1], chain[piece])) continue;
      // Where its walk stops now: the splits before may have removed the face where it stopped
      // when the round began (a point there would go beside the faces that replaced it).
      const std::array<std::uint32_t, 3> block = recovery.blocking_face();
      const double at_block = split_at_block(c, split.edge, piece - 1, block);
      bool placed = false;
      for (int k = 0; k < 7 && !placed; ++k) {
        const double w = k == 0 ? 0.0 : std::ldexp(k % 2 ? 1.0 : -1.0, -(k + 3) / 2);  // 0, +-1/4, +-1/8, +-1/16
        const double tk = at_block + w * (hi - lo);
        if (!(lo < tk && tk < hi)) continue;
        if (k == 0) on_face = block, on_piece = {chain[piece - 1], chain[piece]};
        try {
          added += inserter.insert({{split.edge, tk}}, none);
          placed = true;
        } catch (const InputError&) {
        }
        on_face = {kNone, kNone, kNone};
      }
      if (!placed)
        return "a Steiner point of the edge between vertices " + std::to_string(c.edges[split.edge].a + 1) + " and " +
               std::to_string(c.edges[split.edge].b + 1) + " lands on another constraint or the hull";
    }
    if (added == 0 && !splits.empty()) continue;  // every piece was made meanwhile: look again
    for (const ConstraintEdge3& e : c.edges)  // the new pieces (an edge never split is protected already)
      if (e.chain.size() > 2)
        for (std::size_t i = 0; i + 1 < e.chain.size(); ++i) recovery.protect_edge(e.chain[i], e.chain[i + 1]);
  }
  c.edge_seconds += seconds(start);
  start = Clock::now();

  // Triangles: a few points each at most, past which the rounds are left to do it.
  std::vector<FacetPoint> points;
  std::vector<std::uint32_t> tries(c.facets.size(), 0);
  std::vector<std::size_t> done(c.facets.size(), 0);  // the vertex count when last recovered whole
  struct Made {
    std::vector<Tri> pieces;  // recovered and protected
    std::size_t vertex_count = 0;  // of the triangulation they belong to
    std::size_t count = 0;         // that triangulation's pieces (facet_delaunay_pieces), kept for the end
  };
  std::vector<Made> made(c.facets.size());
  constexpr std::uint32_t kPointsPerTriangle = 16;
  bool inserted = false;  // a triangle's point went in
  for (;;) {
    ++c.rounds;
    if (too_many()) return too_many_why;
    points.clear();
    bool edges_missing = false;
    for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
      // Recovered before, with no point on it since: its faces are protected, so still there.
      const std::size_t vertex_count = facet_vertex_count(c, f);
      if (done[f] == vertex_count) continue;
      // Pieces made for fewer vertices belong to another triangulation of the triangle: their
      // faces and diagonals are no constraints now (the Delaunay pieces change around a new point).
      if (!made[f].pieces.empty() && made[f].vertex_count != vertex_count) {
        std::vector<std::uint64_t> boundary;
        for (const auto& [u, v] : facet_boundary(c, f)) boundary.push_back(MeshIndex::key(u, v));
        for (const Tri& t : made[f].pieces) {
          recovery.unprotect_face(t[0], t[1], t[2]);
          for (int r = 0; r < 3; ++r)
            if (std::find(boundary.begin(), boundary.end(), MeshIndex::key(t[r], t[(r + 1) % 3])) == boundary.end())
              recovery.unprotect_edge(t[r], t[(r + 1) % 3]);
        }
        made[f].pieces.clear();
      }
      // The exact (s, t) only where the triangle has Steiner points or needs one.
      std::optional<FacetParameters> parameters;
      const auto st_of = [&]() -> const FacetParameters& {
        if (!parameters) parameters = facet_parameters(c, f);
        return *parameters;
      };
      const std::vector<Tri> tris =
          vertex_count == 3 ? std::vector<Tri>{c.facets[f].corners} : facet_delaunay_pieces(c, f, st_of());
      bool all_made = true;
      for (const Tri& t : tris) {
        bool ok = (vertex_count == 3 && face_found[f]) || recovery.has_face(t[0], t[1], t[2]);
        if (!ok) {
          ok = true;
          for (int r = 0; r < 3 && ok; ++r)
            ok = recovery.has_edge(t[r], t[(r + 1) % 3]) || recovery.recover_edge(t[r], t[(r + 1) % 3]);
          if (ok) ok = recovery.recover_face(t[0], t[1], t[2]);
        }
        if (ok) {
          // (A triangle with no Steiner point: its edges and face are protected since the start.)
          if (vertex_count > 3) {
            for (int r = 0; r < 3; ++r) recovery.protect_edge(t[r], t[(r + 1) % 3]);
            recovery.protect_face(t[0], t[1], t[2]);
            made[f].pieces.push_back(t), made[f].vertex_count = vertex_count, made[f].count = tris.size();
          }
          continue;
        }
        all_made = false;
        if (++tries[f] > kPointsPerTriangle)
          return "triangle " + std::to_string(f + 1) + " is still missing after " + std::to_string(kPointsPerTriangle) +
                 " Steiner points";
        // The centroid of the missing triangle, in (s, t) rounded to doubles; first, where an edge
        // crosses it, that crossing (TetGen's choice: the point cuts the edge's pipe there).
        const FacetParameters& st = st_of();
        const auto &a = st.at(t[0]), &b = st.at(t[1]), &d = st.at(t[2]);
        const double s = round_to_double((a[0] + b[0] + d[0]) / Rational(3));
        const double tt = round_to_double((a[1] + b[1] + d[1]) / Rational(3));
        FacetPoint point{.facet = f, .s = s, .t = tt, .fallback_s = s, .fallback_t = tt, .piece = {t[0], t[1]}};
        if (const auto cross = crossing_in_triangle(c, recovery, f, st, t)) {
          point.s = cross->at[0], point.t = cross->at[1];
          const Vec3 x = round_point(exact_facet_point(c.mesh.points(), c.facets[f].corners, point.s, point.t));
          crossed_edge[{x.x, x.y, x.z}] = cross->edge;
        } else if (const auto along = crossing_in_plane(c, recovery, st, t)) {
          point.s = (*along)[0], point.t = (*along)[1];
        }
        points.push_back(point);
        break;  // one point per triangle and round
      }
      if (all_made) done[f] = vertex_count;
    }
    // A boundary piece a facet point's fallback split goes back to the edges' flips above; a
    // piece missing now makes the rounds take over. (Before any point, every piece is still
    // there: the edge pass made them all, protected, and flips keep protected edges.)
    if (inserted) {
      for (const ConstraintEdge3& e : c.edges)
        for (std::size_t i = 0; i + 1 < e.chain.size() && !edges_missing; ++i) {
          if (recovery.has_edge(e.chain[i], e.chain[i + 1]) || recovery.recover_edge(e.chain[i], e.chain[i + 1]))
            recovery.protect_edge(e.chain[i], e.chain[i + 1]);
          else
            edges_missing = true;
        }
    }
    if (edges_missing) return "an edge piece made by a triangle's point is missing";
    if (points.empty()) break;
    const std::size_t added = inserter.insert({}, points);
    crossed_edge.clear();
    if (added == 0) return "triangle points repeat points already there";
    inserted = true;
  }
  recovery.finish();
  c.face_seconds += seconds(start);

  // The pieces of every triangle: those recovered, each checked a face of the final mesh (a
  // triangulation of the triangle in its plane, so they cover it); found in the mesh otherwise.
  // (Found, a face that joins its vertices off the pieces, a sliver of rounded Steiner points
  // a hair off the plane, can mislead the search: couplingdown.off did that.)
  // A triangle with no Steiner point, recovered whole, none of whose vertices is in a tetrahedron
  // made since the start (c.changed: a flip or a split that removed its face would have made
  // tetrahedra on all three), is the face it was when it was found: no search.
  const auto unchanged = [&](std::uint32_t v) { return v >= c.changed.size() || !c.changed[v]; };
  const MeshIndex index(c.mesh);
  std::vector<std::array<std::uint32_t, 2>> missing;
  for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
    const std::size_t vertex_count = facet_vertex_count(c, f);
    const auto& corners = c.facets[f].corners;
    if (vertex_count == 3 && done[f] == 3 && unchanged(corners[0]) && unchanged(corners[1]) && unchanged(corners[2])) {
      c.facets[f].pieces.assign(1, corners);
      c.facets[f].pieces_vertex_count = 3;
      continue;
    }
    auto& pieces = made[f].pieces;
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    if (vertex_count > 3 && done[f] == vertex_count && made[f].vertex_count == vertex_count &&
        pieces.size() == made[f].count &&
        std::all_of(pieces.begin(), pieces.end(), [&](const Tri& t) { return index.has_face(t[0], t[1], t[2]); })) {
      c.facets[f].pieces = pieces;
      c.facets[f].pieces_vertex_count = vertex_count;
      continue;
    }
    missing.clear();
    if (!cover_facet(c, f, index, missing)) return "triangle " + std::to_string(f + 1) + " is not covered by its pieces";
  }
  c.rounding_checks_failed = inserter.rounding_checks_failed();
  return {};
}

}  // namespace dtlab
