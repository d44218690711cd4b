// Shared steps of boundary recovery (recovery.hpp; book §3.5.3, Ruppert 1995 and Shewchuk 2000
// for the split rules).
#include "algorithms/constrained3d/recovery/recovery.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <queue>
#include <set>
#include <string>

#include "algorithms/constrained3d/recovery/flip_recovery.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/rounding.hpp"
#include "mesh/element_sets3.hpp"
#include "mesh/navigation3.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
using St = std::array<Rational, 2>;

Rational orient_st(const St& p, const St& q, const St& r) {
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

// In-circle in (s, t), for p, q, r counter-clockwise: positive iff x is inside.
Sign incircle_st(const St& p, const St& q, const St& r, const St& x) {
  const Rational ax = p[0] - x[0], ay = p[1] - x[1], bx = q[0] - x[0], by = q[1] - x[1], cx = r[0] - x[0],
                 cy = r[1] - x[1];
  const Rational a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return (ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx)).sign();
}

// Whether p and q lie on one side of the triangle (in (s, t): t = 0, s + t = 1 or s = 0).
bool along_one_side(const St& p, const St& q) {
  return (p[1].sign() == Sign::Zero && q[1].sign() == Sign::Zero) ||
         (p[0].sign() == Sign::Zero && q[0].sign() == Sign::Zero) ||
         (p[0] + p[1] == Rational(1) && q[0] + q[1] == Rational(1));
}

Vec3 sub(const Vec3& a, const Vec3& b) { return a - b; }

// Circumcentre of a triangle in space, in doubles (a placement, not a decision).
Vec3 triangle_circumcenter(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), n = cross(ab, ac);
  const double d = 2 * dot(n, n);
  const Vec3 u = cross(n, ab), v = cross(ac, n);
  const double ac2 = dot(ac, ac), ab2 = dot(ab, ab);
  return {a.x + (ac2 * u.x + ab2 * v.x) / d, a.y + (ac2 * u.y + ab2 * v.y) / d, a.z + (ac2 * u.z + ab2 * v.z) / d};
}


std::uint64_t coordinate_hash(const Vec3& p) {
  std::uint64_t h = 0;
  for (const double x : {p.x, p.y, p.z}) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
  }
  return h;
}

}  // namespace

MeshIndex::MeshIndex(const Tetrahedralization3& mesh)
    : mesh_(mesh), incident_(vertex_tetrahedra(mesh, Incident::Last)), mark_(mesh.tetrahedron_count(), 0) {}

// Depth first over the tetrahedra holding u (nav3::search_ball); stops early where f returns true.
template <class F>
void MeshIndex::for_each_in_star(std::uint32_t u, F&& f) const {
  if (u >= incident_.size() || incident_[u] == T3::kNone) return;
  if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;
  nav3::search_ball<nav3::Order::DepthFirst>(mesh_, u, incident_[u], stack_, nav3::marking(mark_, stamp_), f);
}

bool MeshIndex::has_edge(std::uint32_t u, std::uint32_t v) const {
  if (u == T3::kInfinite) std::swap(u, v);
  bool found = false;
  for_each_in_star(u, [&](std::uint32_t t) {
    const auto& x = mesh_.records()[t].vertex;
    return found = std::find(x.begin(), x.end(), v) != x.end();
  });
  return found;
}

bool MeshIndex::has_face(std::uint32_t u, std::uint32_t v, std::uint32_t w) const {
  if (u == T3::kInfinite) std::swap(u, v);
  bool found = false;
  for_each_in_star(u, [&](std::uint32_t t) {
    const auto& x = mesh_.records()[t].vertex;
    return found = std::find(x.begin(), x.end(), v) != x.end() && std::find(x.begin(), x.end(), w) != x.end();
  });
  return found;
}

void MeshIndex::ring(std::uint32_t u, std::uint32_t v, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (u == T3::kInfinite) std::swap(u, v);
  for_each_in_star(u, [&](std::uint32_t t) {
    const auto& x = mesh_.records()[t].vertex;
    if (std::find(x.begin(), x.end(), v) == x.end()) return false;
    for (const std::uint32_t w : x)
      if (w != u && w != v && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    return false;
  });
}

double edge_split_parameter(const Constrained3dContext& c, std::uint32_t e, std::size_t i) {
  const ConstraintEdge3& edge = c.edges[e];
  const double t0 = edge.t[i], t1 = edge.t[i + 1];
  const bool from_a = i == 0, from_b = i + 2 == edge.chain.size();
  double t = t0 + (t1 - t0) / 2;
  if (from_a != from_b) {
    const auto p = c.mesh.points();
    const Vec3 d = sub(p[edge.b], p[edge.a]);
    const double length = std::sqrt(dot(d, d));
    const double piece = (t1 - t0) * length;
    // The power of two in [piece / 3, 2 piece / 3].
    const double shell = std::exp2(std::ceil(std::log2(piece / 3)));
    const double shell_t = from_a ? shell / length : 1 - shell / length;
    if (shell_t > t0 && shell_t < t1) t = shell_t;
  }
  if (!(t > t0 && t < t1))
    throw InputError("constrained3d: the edge between vertices " + std::to_string(edge.a + 1) + " and " +
                         std::to_string(edge.b + 1) + " (of triangle " + std::to_string(edge.face + 1) +
                         ") cannot be split further in doubles",
                     {edge.face});
  return t;
}

std::vector<MissingPiece> edge_pieces_flips_cannot_make(const Constrained3dContext& c, FlipRecovery& recovery, int passes,
                                                        const std::vector<std::uint8_t>* present) {
  std::vector<MissingPiece> failed, still;
  const auto attempt = [&](std::uint32_t e, std::uint32_t i, std::vector<MissingPiece>& out) {
    const auto& chain = c.edges[e].chain;
    // (Flips never remove a protected edge, and a split would have made two pieces.)
    if (present != nullptr && chain.size() == 2 && (*present)[e]) return;
    if (!recovery.has_edge(chain[i], chain[i + 1]) && !recovery.recover_edge(chain[i], chain[i + 1]))
      out.push_back({e, i, recovery.blocking_face()});
  };
  for (std::uint32_t e = 0; e < c.edges.size(); ++e)
    for (std::uint32_t i = 0; i + 1 < c.edges[e].chain.size(); ++i) attempt(e, i, failed);
  for (int pass = 0; pass < passes && !failed.empty(); ++pass) {
    still.clear();
    for (const MissingPiece& m : failed) attempt(m.edge, m.index, still);
    const bool progress = still.size() < failed.size();
    failed.swap(still);
    if (!progress) break;
  }
  return failed;
}

FacetParameters facet_parameters(const Constrained3dContext& c, std::uint32_t f) {
  const ConstraintFacet3& facet = c.facets[f];
  static const std::array<std::array<int, 2>, 3> kCorner = {{{0, 0}, {1, 0}, {0, 1}}};
  FacetParameters st;
  for (int k = 0; k < 3; ++k) {
    const ConstraintEdge3& edge = c.edges[facet.edges[k]];
    const auto& p0 = kCorner[k];
    const auto& p1 = kCorner[(k + 1) % 3];
    for (std::size_t j = 0; j < edge.chain.size(); ++j) {
      const Rational t = facet.reversed[k] ? Rational(1) - Rational(edge.t[j]) : Rational(edge.t[j]);
      st.emplace(edge.chain[j], St{Rational(p0[0]) + t * Rational(p1[0] - p0[0]), Rational(p0[1]) + t * Rational(p1[1] - p0[1])});
    }
  }
  for (std::size_t j = 0; j < facet.interior.size(); ++j)
    st.emplace(facet.interior[j], St{Rational(facet.interior_st[j][0]), Rational(facet.interior_st[j][1])});
  return st;
}

std::vector<std::array<std::uint32_t, 2>> facet_boundary(const Constrained3dContext& c, std::uint32_t f) {
  const ConstraintFacet3& facet = c.facets[f];
  std::vector<std::array<std::uint32_t, 2>> pieces;
  for (int k = 0; k < 3; ++k) {
    std::vector<std::uint32_t> chain = c.edges[facet.edges[k]].chain;
    if (facet.reversed[k]) std::reverse(chain.begin(), chain.end());
    for (std::size_t j = 0; j + 1 < chain.size(); ++j) pieces.push_back({chain[j], chain[j + 1]});
  }
  return pieces;
}

std::vector<std::uint64_t> edge_piece_keys(const Constrained3dContext& c) {
  std::vector<std::uint64_t> keys;
  for (const ConstraintEdge3& e : c.edges)
    for (std::size_t i = 0; i + 1 < e.chain.size(); ++i) keys.push_back(MeshIndex::key(e.chain[i], e.chain[i + 1]));
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::vector<std::array<std::uint32_t, 3>> facet_piece_keys(const Constrained3dContext& c) {
  std::vector<std::array<std::uint32_t, 3>> keys;
  for (const ConstraintFacet3& f : c.facets)
    for (auto k : f.pieces) {
      std::sort(k.begin(), k.end());
      keys.push_back(k);
    }
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::size_t facet_vertex_count(const Constrained3dContext& c, std::uint32_t f) {
  const ConstraintFacet3& facet = c.facets[f];
  std::size_t n = facet.interior.size();
  for (const std::uint32_t e : facet.edges) n += c.edges[e].chain.size() - 1;
  return n;
}

bool facet_still_covered(const Constrained3dContext& c, std::uint32_t f, const MeshIndex& index) {
  const ConstraintFacet3& facet = c.facets[f];
  if (facet.pieces.empty() || facet.pieces_vertex_count != facet_vertex_count(c, f)) return false;
  for (const auto& p : facet.pieces)
    if (!index.has_face(p[0], p[1], p[2])) return false;
  return true;
}

namespace {

// The gift-wrapping in (s, t) that cover_facet and facet_delaunay_pieces share: from facet f's
// boundary pieces, across each open directed piece (u, v), the triangle (u, v, apex(u, v, outer))
// (outer: the boundary pieces). A piece with no apex (kNone), or whose triangle would overlap
// one taken before, goes to `missing`. The pieces when none is missing and they triangulate the
// triangle exactly; else nothing.
template <class Apex>
std::optional<std::vector<std::array<std::uint32_t, 3>>> wrap_facet(const Constrained3dContext& c, std::uint32_t f,
                                                                   const FacetParameters& st, Apex&& apex,
                                                                   std::vector<std::array<std::uint32_t, 2>>& missing) {
  const auto boundary = facet_boundary(c, f);
  std::set<std::array<std::uint32_t, 2>> covered;  // directed pieces with their face
  const std::set<std::array<std::uint32_t, 2>> outer(boundary.begin(), boundary.end());
  std::queue<std::array<std::uint32_t, 2>> open;
  for (const auto& b : boundary) open.push(b);
  std::vector<std::array<std::uint32_t, 3>> pieces;
  const std::size_t missing_before = missing.size();
  std::size_t steps = 0;
  while (!open.empty()) {
    const auto [u, v] = open.front();
    open.pop();
    if (covered.count({u, v})) continue;
    if (++steps > 4 * st.size() * st.size() + 16) throw InternalError("constrained3d: facet cover did not end");
    const std::uint32_t w = apex(u, v, outer);
    if (w == T3::kNone || covered.count({v, w}) || covered.count({w, u})) {  // none, or overlapping
      missing.push_back({u, v});
      continue;
    }
    covered.insert({u, v});
    covered.insert({v, w});
    covered.insert({w, u});
    pieces.push_back({u, v, w});
    if (!outer.count({v, w})) open.push({w, v});
    if (!outer.count({w, u})) open.push({u, w});
  }
  if (missing.size() != missing_before) return std::nullopt;
  // Every piece positive in (s, t), each directed side used once: the pieces cover the triangle
  // with degree 1 exactly when their doubled areas add up to the triangle's, 1.
  Rational area;
  for (const auto& p : pieces) area += orient_st(st.at(p[0]), st.at(p[1]), st.at(p[2]));
  if (area != Rational(1)) {
    missing.push_back(boundary.front());
    return std::nullopt;
  }
  return pieces;
}

}  // namespace

bool cover_facet(Constrained3dContext& c, std::uint32_t f, const MeshIndex& index,
                 std::vector<std::array<std::uint32_t, 2>>& missing) {
  // A triangle with no Steiner point is covered exactly when it is a mesh face.
  if (facet_vertex_count(c, f) == 3) {
    const auto& k = c.facets[f].corners;
    if (index.has_face(k[0], k[1], k[2])) {
      c.facets[f].pieces.assign(1, k);
      c.facets[f].pieces_vertex_count = 3;
      return true;
    }
  }
  const FacetParameters st = facet_parameters(c, f);
  std::vector<std::uint32_t> ring;
  // Across (u, v): the mesh face on its left whose third vertex is on f, the one whose (s, t)
  // circle holds no other such vertex.
  const auto apex = [&](std::uint32_t u, std::uint32_t v, const std::set<std::array<std::uint32_t, 2>>& outer) {
    const St &pu = st.at(u), &pv = st.at(v);
    std::uint32_t best = T3::kNone;
    index.ring(u, v, ring);
    for (const std::uint32_t w : ring) {
      const auto it = st.find(w);
      if (it == st.end() || orient_st(pu, pv, it->second).sign() != Sign::Positive) continue;
      // A mesh edge along a side that skips a vertex on it (rounded Steiner points lie just off
      // the side) is no piece: its far side is outside the triangle.
      if ((along_one_side(pv, it->second) && !outer.count({v, w})) ||
          (along_one_side(it->second, pu) && !outer.count({w, u})))
        continue;
      if (best == T3::kNone || incircle_st(pu, pv, st.at(best), it->second) == Sign::Positive) best = w;
    }
    return best;
  };
  auto pieces = wrap_facet(c, f, st, apex, missing);
  if (!pieces) return false;
  c.facets[f].pieces = std::move(*pieces);
  c.facets[f].pieces_vertex_count = facet_vertex_count(c, f);
  return true;
}

std::vector<std::array<std::uint32_t, 3>> facet_delaunay_pieces(const Constrained3dContext& c, std::uint32_t f) {
  return facet_delaunay_pieces(c, f, facet_parameters(c, f));
}

std::vector<std::array<std::uint32_t, 3>> facet_delaunay_pieces(const Constrained3dContext& c, std::uint32_t f,
                                                                const FacetParameters& st) {
  // The metric of the triangle's plane in (s, t): |s e1 + t e2|^2, e1 = B - A, e2 = C - A, exact.
  const auto p = c.mesh.points();
  const auto& k = c.facets[f].corners;
  const ExactPoint3 A = to_exact(p[k[0]]), B = to_exact(p[k[1]]), C = to_exact(p[k[2]]);
  const Rational e1[3] = {B.x - A.x, B.y - A.y, B.z - A.z}, e2[3] = {C.x - A.x, C.y - A.y, C.z - A.z};
  const Rational g11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
  const Rational g12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  const Rational g22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  std::unordered_map<std::uint32_t, Rational> lift;
  for (const auto& [v, x] : st) lift.emplace(v, g11 * x[0] * x[0] + Rational(2) * g12 * x[0] * x[1] + g22 * x[1] * x[1]);
  // In-circle of x against (u, v, w) counter-clockwise, perturbed: det [s t h 1] of the four
  // rows; when zero, the sign of the cofactor (-1)^i orient(the other three) of the row with
  // the smallest vertex id that is non-zero (the lifting raised by eps^rank, smallest id first).
  const auto inside = [&](std::uint32_t u, std::uint32_t v, std::uint32_t w, std::uint32_t x) {
    const std::array<std::uint32_t, 4> ids{u, v, w, x};
    const St& px = st.at(x);
    const Rational& hx = lift.at(x);
    Rational m[3][3];
    for (int r = 0; r < 3; ++r) {
      const St& q = st.at(ids[r]);
      m[r][0] = q[0] - px[0], m[r][1] = q[1] - px[1], m[r][2] = lift.at(ids[r]) - hx;
    }
    const Rational det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det.sign() != Sign::Zero) return det.sign() == Sign::Positive;
    std::array<int, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return ids[a] < ids[b]; });
    for (const int i : order) {
      std::array<std::uint32_t, 3> rest{};
      for (int j = 0, n = 0; j < 4; ++j)
        if (j != i) rest[n++] = ids[j];
      const Sign o = orient_st(st.at(rest[0]), st.at(rest[1]), st.at(rest[2])).sign();
      if (o == Sign::Zero) continue;
      return (i % 2 == 0 ? o : -o) == Sign::Positive;
    }
    throw InternalError("facet_delaunay_pieces: four collinear vertices in an in-circle test");
  };
  const auto apex = [&](std::uint32_t u, std::uint32_t v, const std::set<std::array<std::uint32_t, 2>>&) {
    std::uint32_t w = T3::kNone;
    for (const auto& [x, px] : st)
      if (orient_st(st.at(u), st.at(v), px).sign() == Sign::Positive && (w == T3::kNone || inside(u, v, w, x))) w = x;
    return w;
  };
  std::vector<std::array<std::uint32_t, 2>> missing;
  auto pieces = wrap_facet(c, f, st, apex, missing);
  if (!pieces)
    throw InternalError("facet_delaunay_pieces: the gift-wrapping of triangle " + std::to_string(f + 1) + " failed");
  return std::move(*pieces);
}

void request_facet_point(const Constrained3dContext& c, std::uint32_t f, const FacetParameters& st,
                         std::array<std::uint32_t, 2> piece, std::vector<EdgeSplit>& splits,
                         std::vector<FacetPoint>& points) {
  const ConstraintFacet3& facet = c.facets[f];
  const auto p = c.mesh.points();
  const auto [u, v] = piece;
  const St &pu = st.at(u), &pv = st.at(v);
  // The Delaunay apex: the smallest signed offset of the circumcentre from the midpoint of
  // (u, v) towards the left, in the plane of the triangle.
  const Vec3 normal = cross(p[facet.corners[1]] - p[facet.corners[0]], p[facet.corners[2]] - p[facet.corners[0]]);
  const Vec3 left = cross(normal, p[v] - p[u]);
  const Vec3 mid = 0.5 * (p[u] + p[v]);
  std::uint32_t w = T3::kNone;
  double best = 0;
  for (const auto& [x, px] : st) {
    if (orient_st(pu, pv, px).sign() != Sign::Positive) continue;
    const double offset = dot(triangle_circumcenter(p[u], p[v], p[x]) - mid, left);
    if (w == T3::kNone || offset < best || (offset == best && x < w)) w = x, best = offset;
  }
  DTLAB_ASSERT(w != T3::kNone);
  // The circumcentre as (s, t): least squares on the triangle's edge vectors.
  const Vec3 A = p[facet.corners[0]], e1 = sub(p[facet.corners[1]], A), e2 = sub(p[facet.corners[2]], A);
  const Vec3 d = sub(triangle_circumcenter(p[u], p[v], p[w]), A);
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2), r1 = dot(e1, d), r2 = dot(e2, d);
  const double det = g11 * g22 - g12 * g12;
  double s = (r1 * g22 - r2 * g12) / det, t = (g11 * r2 - g12 * r1) / det;
  const auto inside = [](double s0, double t0) {
    return std::isfinite(s0) && std::isfinite(t0) && s0 > 0 && t0 > 0 &&
           Rational(s0) + Rational(t0) < Rational(1);
  };
  // The centroid of (u, v, w) is inside the triangle.
  const St& pw = st.at(w);
  const Rational third(1, 3);
  const double cs = round_to_double((pu[0] + pv[0] + pw[0]) * third);
  const double ct = round_to_double((pu[1] + pv[1] + pw[1]) * third);
  if (!inside(cs, ct))
    throw InputError("constrained3d: triangle " + std::to_string(f + 1) + " cannot be recovered in doubles", {f});
  // Ruppert's rule: the boundary pieces (but those ending at x_vertex) whose closed diametral
  // ball holds x are split instead; true if there is one.
  const auto split_encroached = [&](const ExactPoint3& x, std::uint32_t x_vertex) {
    bool encroached = false;
    for (int k = 0; k < 3; ++k) {
      const ConstraintEdge3& edge = c.edges[facet.edges[k]];
      for (std::size_t j = 0; j + 1 < edge.chain.size(); ++j) {
        if (edge.chain[j] == x_vertex || edge.chain[j + 1] == x_vertex) continue;
        const ExactPoint3 a = to_exact(p[edge.chain[j]]), b = to_exact(p[edge.chain[j + 1]]);
        const Rational dot_ab = (x.x - a.x) * (x.x - b.x) + (x.y - a.y) * (x.y - b.y) + (x.z - a.z) * (x.z - b.z);
        if (dot_ab.sign() != Sign::Positive) {
          splits.push_back({facet.edges[k], edge_split_parameter(c, facet.edges[k], j)});
          encroached = true;
        }
      }
    }
    return encroached;
  };
  if (!inside(s, t)) {
    // The circumcentre is beyond the triangle's boundary: where the apex itself encroaches a
    // boundary piece, that piece is split (else centroids crowd towards it round after round:
    // boxes with internal walls did that); otherwise the centroid.
    if (!split_encroached(to_exact(p[w]), w)) points.push_back({f, cs, ct, cs, ct, piece});
    return;
  }
  const bool encroached = split_encroached(exact_facet_point(p, facet.corners, s, t), T3::kNone);
  if (!encroached) points.push_back({f, s, t, cs, ct, piece});
}

SteinerInserter::SteinerInserter(Constrained3dContext& c) : c_(c), inserter_(c.mesh) {}

void SteinerInserter::index_points() const {
  if (indexed_) return;
  indexed_ = true;
  const auto p = c_.mesh.points();
  by_coordinates_.reserve(p.size());
  for (std::uint32_t v = 0; v < p.size(); ++v) by_coordinates_[coordinate_hash(p[v])].push_back(v);
}

bool SteinerInserter::is_vertex(const Vec3& p) const {
  index_points();
  const auto it = by_coordinates_.find(coordinate_hash(p));
  if (it == by_coordinates_.end()) return false;
  for (const std::uint32_t v : it->second)
    if (c_.mesh.points()[v] == p) return true;
  return false;
}

std::uint32_t SteinerInserter::add_vertex(const Vec3& p, const std::string& what, std::uint32_t item,
                                          std::uint32_t hint) {
  if (c_.steiner.size() >= c_.steiner_limit)
    throw InputError("constrained3d: " + what + " needs more than the limit of " + std::to_string(c_.steiner_limit) +
                         " Steiner points",
                     {item});
  if (!coordinate_in_range(p.x) || !coordinate_in_range(p.y) || !coordinate_in_range(p.z))
    throw InputError("constrained3d: a Steiner point of " + what + " is out of the supported coordinate range",
                     {item});
  index_points();
  auto& same = by_coordinates_[coordinate_hash(p)];
  for (const std::uint32_t v : same)
    if (c_.mesh.points()[v] == p)
      throw InputError("constrained3d: a Steiner point of " + what + " rounds onto vertex " + std::to_string(v + 1) +
                           "; the input is too fine for doubles there",
                       {item});
  const std::uint32_t id = place_ ? place_(p, hint) : inserter_.insert(p);
  if (id == Tetrahedralization3::kNone)
    throw InputError("constrained3d: a Steiner point of " + what +
                         " cannot be placed in the transformed tetrahedralization (on a constraint or the hull)",
                     {item});
  same.push_back(id);
  return id;
}

bool SteinerInserter::insert_split(const EdgeSplit& r) {
  const auto p = c_.mesh.points();
  ConstraintEdge3& edge = c_.edges[r.edge];
  const auto at = std::lower_bound(edge.t.begin(), edge.t.end(), r.t);
  if (at != edge.t.end() && *at == r.t) return false;
  const RoundedPoint3 x = point_on_segment(p[edge.a], p[edge.b], Rational(r.t));
  const std::string what = "the edge between vertices " + std::to_string(edge.a + 1) + " and " +
                           std::to_string(edge.b + 1) + " (of triangle " + std::to_string(edge.face + 1) + ")";
  SteinerPoint3 s{.kind = SteinerPoint3::Kind::OnEdge, .owner = edge.face, .support = {edge.a, edge.b, 0},
                  .parameters = {r.t, 0}};
  const auto pos = at - edge.t.begin();
  const std::uint32_t id = add_vertex(x.point, what, edge.face, edge.a);
  if (!steiner_point_within_rounding_bound(c_.mesh.points(), s, x.point)) ++rounding_failed_;
  c_.steiner.push_back(s);
  edge.t.insert(edge.t.begin() + pos, r.t);
  edge.chain.insert(edge.chain.begin() + pos, id);
  return true;
}

void request_missing_facet_points(Constrained3dContext& c, const MeshIndex& index, std::vector<EdgeSplit>& splits,
                                  std::vector<FacetPoint>& points) {
  std::vector<std::array<std::uint32_t, 2>> missing;
  for (std::uint32_t f = 0; f < c.facets.size(); ++f) {
    missing.clear();
    if (facet_still_covered(c, f, index) || cover_facet(c, f, index, missing)) continue;
    const FacetParameters st = facet_parameters(c, f);
    for (const auto& m : missing) request_facet_point(c, f, st, m, splits, points);
  }
}

void SteinerInserter::throw_stuck() const {
  // No triangle was stuck: every point asked for was one placed in an earlier round.
  if (stuck_facet_ == Tetrahedralization3::kNone)
    throw InputError("constrained3d: the boundary cannot be recovered: every Steiner point asked for is a vertex already");
  throw InputError("constrained3d: triangle " + std::to_string(stuck_facet_ + 1) +
                       " cannot be recovered: its Steiner points round onto existing vertices",
                   {stuck_facet_});
}

std::size_t SteinerInserter::insert(const std::vector<EdgeSplit>& splits, const std::vector<FacetPoint>& points) {
  std::size_t count = 0;
  const auto p = [&] { return c_.mesh.points(); };
  for (const auto& r : splits) count += insert_split(r);
  for (const auto& r : points) {
    ConstraintFacet3& facet = c_.facets[r.facet];
    // The same point asked for twice in a round (two missing pieces of one triangle): once.
    if (std::find(facet.interior_st.begin(), facet.interior_st.end(), std::array<double, 2>{r.s, r.t}) !=
        facet.interior_st.end())
      continue;
    for (const auto [s0, t0] : {std::array<double, 2>{r.s, r.t}, std::array<double, 2>{r.fallback_s, r.fallback_t}}) {
      const Vec3 x = round_point(exact_facet_point(p(), facet.corners, s0, t0));
      if (is_vertex(x) && (s0 != r.fallback_s || t0 != r.fallback_t)) continue;
      if (is_vertex(x)) {
        // Both placements are taken: split the missing piece itself if it is on the boundary.
        bool split = false;
        for (const std::uint32_t e : facet.edges) {
          const auto& chain = c_.edges[e].chain;
          for (std::size_t j = 0; j + 1 < chain.size() && !split; ++j)
            if (MeshIndex::key(chain[j], chain[j + 1]) == MeshIndex::key(r.piece[0], r.piece[1])) {
              count += insert_split({e, edge_split_parameter(c_, e, j)});
              split = true;
            }
        }
        if (split) break;
        stuck_facet_ = r.facet;  // nothing to place: the caller decides whether that stalls it
        break;
      }
      SteinerPoint3 s{.kind = SteinerPoint3::Kind::OnFace, .owner = r.facet, .support = facet.corners,
                      .parameters = {s0, t0}};
      const std::uint32_t id = add_vertex(x, "triangle " + std::to_string(r.facet + 1), r.facet, facet.corners[0]);
      if (!steiner_point_within_rounding_bound(p(), s, x)) ++rounding_failed_;
      c_.steiner.push_back(s);
      facet.interior.push_back(id);
      facet.interior_st.push_back({s0, t0});
      ++count;
      break;
    }
  }
  inserter_.compact();  // the recovery reads the mesh between rounds
  return count;
}

}  // namespace dtlab
