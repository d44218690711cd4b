// Exhaustive exact search for a tetrahedralization without Steiner points
// (exhaustive_tetrahedralization.hpp; book §3.5, Schönhardt 1928).
#include "verify/exhaustive_tetrahedralization.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "kernel/error.hpp"
#include "kernel/exact_rational.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

using Ids4 = std::array<std::uint32_t, 4>;
using Ids3 = std::array<std::uint32_t, 3>;

struct Q3 {
  Rational x, y, z;
};

Q3 exact(const Vec3& p) { return {Rational(p.x), Rational(p.y), Rational(p.z)}; }
Q3 minus(const Q3& a, const Q3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Rational dot(const Q3& a, const Q3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
bool is_zero(const Q3& a) { return a.x.is_zero() && a.y.is_zero() && a.z.is_zero(); }

// A convex polytope given by its vertices, with the directions its faces and edges span.
struct Polytope {
  std::vector<Q3> vertices;
  std::vector<Q3> face_normals;
  std::vector<Q3> edge_directions;
};

Polytope tetrahedron(const std::vector<Q3>& p, const Ids4& t) {
  Polytope s;
  for (const auto v : t) s.vertices.push_back(p[v]);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) s.edge_directions.push_back(minus(s.vertices[j], s.vertices[i]));
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (const auto& f : kFaces)
    s.face_normals.push_back(
        cross(minus(s.vertices[f[1]], s.vertices[f[0]]), minus(s.vertices[f[2]], s.vertices[f[0]])));
  return s;
}

Polytope triangle(const std::vector<Q3>& p, const Ids3& f) {
  Polytope s;
  for (const auto v : f) s.vertices.push_back(p[v]);
  for (int i = 0; i < 3; ++i) s.edge_directions.push_back(minus(s.vertices[(i + 1) % 3], s.vertices[i]));
  s.face_normals.push_back(cross(s.edge_directions[0], s.edge_directions[1]));
  return s;
}

// Weak separation along n: one polytope's projections all <= the other's.
bool separated_along(const Q3& n, const Polytope& a, const Polytope& b) {
  if (is_zero(n)) return false;
  Rational amin = dot(n, a.vertices[0]), amax = amin, bmin = dot(n, b.vertices[0]), bmax = bmin;
  for (const auto& v : a.vertices) {
    const Rational d = dot(n, v);
    if (d < amin) amin = d;
    if (d > amax) amax = d;
  }
  for (const auto& v : b.vertices) {
    const Rational d = dot(n, v);
    if (d < bmin) bmin = d;
    if (d > bmax) bmax = d;
  }
  return amax <= bmin || bmax <= amin;
}

// Interior of a (full-dimensional) against b (closed, or the interior of a full-dimensional
// one): disjoint iff some candidate axis separates them weakly (separating axis theorem on
// the Minkowski difference, whose facet normals are exactly these).
bool interiors_disjoint(const Polytope& a, const Polytope& b) {
  for (const auto& n : a.face_normals)
    if (separated_along(n, a, b)) return true;
  for (const auto& n : b.face_normals)
    if (separated_along(n, a, b)) return true;
  for (const auto& e : a.edge_directions)
    for (const auto& f : b.edge_directions)
      if (separated_along(cross(e, f), a, b)) return true;
  return false;
}

// Sign of the yz-orientation of (p, q, g + (0, δ, δ²)) for infinitesimal δ > 0.
int perturbed_side(const Q3& p, const Q3& q, const Q3& g) {
  const Rational dy = q.y - p.y, dz = q.z - p.z;
  const Sign s = (dy * (g.z - p.z) - dz * (g.y - p.y)).sign();
  if (s != Sign::Zero) return to_int(s);
  if (!dz.is_zero()) return -to_int(dz.sign());
  return to_int(dy.sign());
}

// g strictly inside the polyhedron, g on no boundary triangle: the parity of the crossings of
// the ray from g + (0, δ, δ²) in direction +x with the boundary (the perturbation keeps the
// ray off every edge and vertex).
bool inside(const std::vector<Q3>& p, std::span<const Ids3> faces, const Q3& g) {
  bool odd = false;
  for (const auto& f : faces) {
    const Q3 &a = p[f[0]], &b = p[f[1]], &c = p[f[2]];
    const Q3 n = cross(minus(b, a), minus(c, a));
    const int o = to_int(n.x.sign());  // the triangle's orientation seen along +x
    if (o == 0) continue;               // contains the x direction: the ray passes beside it
    if (perturbed_side(a, b, g) != o || perturbed_side(b, c, g) != o || perturbed_side(c, a, g) != o) continue;
    // The plane is crossed at g + s e_x with s = -n.(g - a) / n.x; g is not on it.
    const int side = to_int(dot(n, minus(g, a)).sign());
    DTLAB_ASSERT(side != 0);
    if (side != o) odd = !odd;
  }
  return odd;
}

struct Search {
  std::vector<Ids4> candidates;
  std::vector<std::vector<bool>> compatible;                 // interiors disjoint
  std::map<Ids3, std::vector<std::uint32_t>> by_face;        // sorted face -> candidates
  std::map<Ids3, int> needed;                                // sorted face -> chosen tetrahedra it still needs
  std::map<Ids3, int> boundary;                              // sorted boundary face -> 1
  std::vector<std::uint32_t> chosen;
  std::uint64_t nodes = 0, limit = 0;

  static std::array<Ids3, 4> faces_of(const Ids4& t) {
    std::array<Ids3, 4> f{{{t[1], t[2], t[3]}, {t[0], t[2], t[3]}, {t[0], t[1], t[3]}, {t[0], t[1], t[2]}}};
    for (auto& x : f) std::sort(x.begin(), x.end());
    return f;
  }

  bool fits(std::uint32_t c) const {
    for (const auto k : chosen)
      if (k == c || !compatible[c][k]) return false;
    return true;
  }

  bool run() {
    if (++nodes > limit)
      throw InputError("exhaustive tetrahedralization search: more than " + std::to_string(limit) + " nodes");
    // The open face with the fewest fitting candidates.
    const Ids3* best = nullptr;
    std::vector<std::uint32_t> best_options;
    for (const auto& [face, count] : needed) {
      if (count == 0) continue;
      std::vector<std::uint32_t> options;
      if (const auto it = by_face.find(face); it != by_face.end())
        for (const auto c : it->second)
          if (fits(c)) options.push_back(c);
      if (best == nullptr || options.size() < best_options.size()) {
        best = &face;
        best_options = std::move(options);
        if (best_options.empty()) return false;
      }
    }
    if (best == nullptr) return true;  // every face has its tetrahedra
    for (const auto c : best_options) {
      const auto faces = faces_of(candidates[c]);
      // A face already complete cannot take a third tetrahedron (disjoint interiors rule it out).
      if (std::any_of(faces.begin(), faces.end(), [&](const Ids3& f) {
            const auto it = needed.find(f);
            return it != needed.end() && it->second == 0;
          }))
        continue;
      chosen.push_back(c);
      for (const auto& f : faces) {
        const auto it = needed.find(f);
        if (it == needed.end()) {
          needed.emplace(f, 1);  // an interior face: needs its second tetrahedron
        } else {
          --it->second;
        }
      }
      if (run()) return true;
      for (const auto& f : faces) {
        const auto it = needed.find(f);
        if (boundary.count(f) == 0 && it->second == 1) {
          needed.erase(it);
        } else {
          ++it->second;
        }
      }
      chosen.pop_back();
    }
    return false;
  }
};

}  // namespace

ExhaustiveTetrahedralizationResult find_tetrahedralization_without_steiner(std::span<const Vec3> points,
                                                                           std::span<const Ids3> faces,
                                                                           std::uint64_t node_limit) {
  const std::size_t n = points.size();
  if (n > 16) throw InputError("exhaustive tetrahedralization search: at most 16 vertices, got " + std::to_string(n));
  std::vector<Q3> p;
  for (const auto& v : points) p.push_back(exact(v));

  // Completeness: no plane through four vertices may cut the vertex set.
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c) {
        for (std::uint32_t d = c + 1; d < n; ++d) {
          if (orient3d(points[a], points[b], points[c], points[d]) != Sign::Zero) continue;
          bool pos = false, neg = false;
          for (std::uint32_t e = 0; e < n; ++e) {
            const Sign s = orient3d(points[a], points[b], points[c], points[e]);
            pos |= s == Sign::Positive, neg |= s == Sign::Negative;
          }
          // Collinear a, b, c make every orient3d zero: such a plane is decided by another triple.
          if (pos && neg)
            throw InputError("exhaustive tetrahedralization search: vertices " + std::to_string(a) + ", " +
                                 std::to_string(b) + ", " + std::to_string(c) + ", " + std::to_string(d) +
                                 " span a plane that cuts the polyhedron; the face-to-face search would not be complete",
                             {a, b, c, d});
        }
      }

  Search s;
  s.limit = node_limit;
  std::vector<Polytope> boundary_triangles;
  for (const auto& f : faces) {
    boundary_triangles.push_back(triangle(p, f));
    Ids3 key = f;
    std::sort(key.begin(), key.end());
    s.boundary[key] = 1;
    s.needed[key] = 1;
  }
  std::vector<Polytope> shapes;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c)
        for (std::uint32_t d = c + 1; d < n; ++d) {
          const Sign o = orient3d(points[a], points[b], points[c], points[d]);
          if (o == Sign::Zero) continue;
          const Ids4 t = o == Sign::Positive ? Ids4{a, b, c, d} : Ids4{a, b, d, c};
          Polytope shape = tetrahedron(p, t);
          bool clear = true;
          for (const auto& f : boundary_triangles)
            if (!interiors_disjoint(shape, f)) {
              clear = false;
              break;
            }
          if (!clear) continue;
          Q3 g{p[a].x + p[b].x + p[c].x + p[d].x, p[a].y + p[b].y + p[c].y + p[d].y,
               p[a].z + p[b].z + p[c].z + p[d].z};
          const Rational quarter(1, 4);
          g = {g.x * quarter, g.y * quarter, g.z * quarter};
          if (!inside(p, faces, g)) continue;
          s.candidates.push_back(t);
          shapes.push_back(std::move(shape));
        }
  const std::size_t m = s.candidates.size();
  s.compatible.assign(m, std::vector<bool>(m, false));
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) s.compatible[i][j] = s.compatible[j][i] = interiors_disjoint(shapes[i], shapes[j]);
  for (std::uint32_t c = 0; c < m; ++c)
    for (const auto& f : Search::faces_of(s.candidates[c])) s.by_face[f].push_back(c);

  ExhaustiveTetrahedralizationResult r;
  r.candidates = m;
  r.exists = s.run();
  r.nodes = s.nodes;
  if (r.exists)
    for (const auto c : s.chosen) r.tetrahedra.push_back(s.candidates[c]);
  return r;
}

}  // namespace dtlab
