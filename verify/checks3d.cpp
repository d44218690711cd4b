#include "verify/checks3d.hpp"

#include "mesh/canonical_element.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr auto kFacet = T3::kFacetVertex;

std::string id_name(std::uint32_t v) { return v == kInf ? "inf" : std::to_string(v); }

std::string name(const T3& tet, std::uint32_t t) {
  const auto& v = tet.records()[t].vertex;
  return (tet.is_ghost(t) ? "ghost " : "tetrahedron ") + std::to_string(t) + " (" + id_name(v[0]) + "," +
         id_name(v[1]) + "," + id_name(v[2]) + "," + id_name(v[3]) + ")";
}

std::string facet_name(const T3& tet, std::uint32_t h) {
  const auto f = tet.facet_vertices(h);
  return "facet (" + id_name(f[0]) + "," + id_name(f[1]) + "," + id_name(f[2]) + ") of " +
         name(tet, T3::tetrahedron_of(h));
}

std::string edge_name(std::uint32_t a, std::uint32_t b) { return "edge (" + id_name(a) + "," + id_name(b) + ")"; }

std::uint32_t size32(const T3& tet) { return static_cast<std::uint32_t>(tet.tetrahedron_count()); }

// The predicates' precondition; adds one problem per offending point.
bool coordinates_valid(std::span<const Vec3> points, CheckReport3& r, const char* check) {
  bool valid = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const auto& [axis, c] :
         {std::pair{"x", points[i].x}, std::pair{"y", points[i].y}, std::pair{"z", points[i].z}}) {
      if (coordinate_in_range(c)) continue;
      r.add_problem(std::string(check) + ": point " + std::to_string(i) + ": coordinate " + axis + " is " +
                    coordinate_problem(c));
      valid = false;
    }
  }
  return valid;
}

// The structure's own combinatorial check; every other check indexes through twins and vertex
// ids and so runs only when it passes.
bool sound(const T3& tet, CheckReport3& r) {
  try {
    tet.check_topology();
  } catch (const InternalError& e) {
    r.add_problem(std::string("topology: ") + e.what());
    return false;
  }
  return true;
}

void count_elements(const T3& tet, CheckReport3& r) {
  r.points = tet.point_count();
  r.tetrahedra = tet.finite_tetrahedron_count();
  r.hull_facets = tet.tetrahedron_count() - r.tetrahedra;
}

// Facet i of t with vertex i appended: a positive tetrahedron iff p is strictly on t's side.
Sign side_of_facet(const T3& tet, std::uint32_t t, std::uint32_t i, const Vec3& p) {
  const auto P = tet.points();
  const auto& v = tet.records()[t].vertex;
  const auto& f = kFacet[i];
  return orient3d(P[v[f[0]]], P[v[f[1]]], P[v[f[2]]], p);
}

// --- topology -------------------------------------------------------------------------------------

// Tetrahedra of each vertex (the infinite vertex as id n), compressed rows.
struct VertexStars {
  std::vector<std::uint32_t> begin;  // vertex v: tets[begin[v] .. begin[v+1])
  std::vector<std::uint32_t> tets;

  explicit VertexStars(const T3& tet) {
    const std::size_t n = tet.point_count();
    const auto slot = [n](std::uint32_t v) { return v == kInf ? n : static_cast<std::size_t>(v); };
    begin.assign(n + 3, 0);
    for (const T3::Record& rec : tet.records())
      for (const std::uint32_t v : rec.vertex) ++begin[slot(v) + 2];
    for (std::size_t v = 2; v < begin.size(); ++v) begin[v] += begin[v - 1];
    tets.resize(begin.back());
    for (std::uint32_t t = 0; t < size32(tet); ++t)
      for (const std::uint32_t v : tet.records()[t].vertex) tets[begin[slot(v) + 1]++] = t;
    begin.pop_back();
  }
  std::span<const std::uint32_t> of(std::size_t slot) const {
    return std::span(tets).subspan(begin[slot], begin[slot + 1] - begin[slot]);
  }
};

std::uint32_t local_index(const T3& tet, std::uint32_t t, std::uint32_t v) {
  const auto& w = tet.records()[t].vertex;
  for (std::uint32_t i = 0; i < 4; ++i)
    if (w[i] == v) return i;
  return 4;
}

// Walks the tetrahedra around edge (v, w) from t through the facets that hold the edge; returns
// how many it meets before coming back, at most `bound` + 1.
std::size_t shell_length(const T3& tet, std::uint32_t t, std::uint32_t v, std::uint32_t w, std::size_t bound) {
  const std::uint32_t iv = local_index(tet, t, v), iw = local_index(tet, t, w);
  std::uint32_t exit = 0;
  while (exit == iv || exit == iw) ++exit;
  std::uint32_t current = t;
  for (std::size_t length = 1; length <= bound; ++length) {
    const std::uint32_t g = tet.twin(T3::facet(current, exit));
    current = T3::tetrahedron_of(g);
    if (current == t) return length;
    const std::uint32_t entered = T3::index_in_tetrahedron(g);
    const std::uint32_t jv = local_index(tet, current, v), jw = local_index(tet, current, w);
    exit = 0;
    while (exit == entered || exit == jv || exit == jw) ++exit;
  }
  return bound + 1;
}

void topology(const T3& tet, CheckReport3& r) {
  count_elements(tet, r);
  const std::uint32_t count = size32(tet);
  if (count == 0) return;
  if (r.tetrahedra == 0) r.add_problem("topology: ghosts but no finite tetrahedron");
  for (std::uint32_t t = 0; t < count; ++t) {
    if (tet.is_ghost(t) && tet.is_ghost(T3::tetrahedron_of(tet.twin(T3::facet(t, 0))))) {
      r.add_problem("topology: the hull facet of " + name(tet, t) + " faces another ghost");
    }
  }

  // One connected piece.
  std::vector<char> reached(count, 0);
  std::vector<std::uint32_t> stack = {0};
  reached[0] = 1;
  std::size_t reached_count = 1;
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t u = tet.adjacent(t, i);
      if (reached[u]) continue;
      reached[u] = 1;
      ++reached_count;
      stack.push_back(u);
    }
  }
  if (reached_count != count) {
    r.add_problem("topology: only " + std::to_string(reached_count) + " of " + std::to_string(count) +
                  " tetrahedra are connected to tetrahedron 0 through facets");
  }

  // Edges (each one cycle of tetrahedra) and vertex links (Euler characteristic 2).
  const VertexStars stars(tet);
  const std::size_t n = tet.point_count();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> around;  // (other end, a tetrahedron)
  for (std::size_t slot = 0; slot <= n; ++slot) {
    const auto star = stars.of(slot);
    if (star.empty()) continue;
    const std::uint32_t v = slot == n ? kInf : static_cast<std::uint32_t>(slot);
    around.clear();
    for (const std::uint32_t t : star)
      for (const std::uint32_t w : tet.records()[t].vertex)
        if (w != v) around.emplace_back(w, t);
    std::sort(around.begin(), around.end());
    std::size_t degree = 0;
    for (std::size_t k = 0; k < around.size();) {
      std::size_t end = k;
      while (end < around.size() && around[end].first == around[k].first) ++end;
      const std::uint32_t w = around[k].first;
      ++degree;
      if (v < w) {  // each edge once, from its smaller end (kInf is the largest id)
        if (w != kInf) ++r.edges;
        const std::size_t shell = end - k;
        const std::size_t walked = shell_length(tet, around[k].second, v, w, shell);
        if (walked != shell) {
          r.add_problem("topology: the " + std::to_string(shell) + " tetrahedra around " + edge_name(v, w) +
                        " do not form one cycle (a walk around it from " + name(tet, around[k].second) +
                        " meets " + (walked > shell ? "more" : std::to_string(walked)) + ")");
        }
      }
      k = end;
    }
    if (v == kInf) r.hull_vertices = degree;
    // Link of v: `degree` vertices, star.size() triangles, 3/2 star.size() edges.
    if (star.size() % 2 != 0 || degree != star.size() / 2 + 2) {
      r.add_problem("topology: the link of vertex " + id_name(v) + " is not a sphere (" + std::to_string(degree) +
                    " vertices, " + std::to_string(star.size()) +
                    " triangles: Euler characteristic V - F/2 should be 2)");
    }
  }
}

// --- geometry ---------------------------------------------------------------------------------------

void orientation(const T3& tet, CheckReport3& r) {
  const auto P = tet.points();
  for (std::uint32_t t = 0; t < size32(tet); ++t) {
    if (tet.is_ghost(t)) continue;
    const auto& v = tet.records()[t].vertex;
    const Sign s = orient3d(P[v[0]], P[v[1]], P[v[2]], P[v[3]]);
    if (s == Sign::Negative) r.add_problem("orientation: " + name(tet, t) + " is negative");
    if (s == Sign::Zero) r.add_problem("orientation: " + name(tet, t) + " is flat (its vertices are coplanar)");
  }
}

void empty_sphere(const T3& tet, CheckReport3& r) {
  const auto P = tet.points();
  for (std::uint32_t t = 0; t < size32(tet); ++t) {
    if (tet.is_ghost(t)) continue;
    const auto& v = tet.records()[t].vertex;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = T3::facet(t, i), g = tet.twin(h);
      if (g < h || tet.is_ghost(T3::tetrahedron_of(g))) continue;
      ++r.interior_facets;
      ++r.insphere_tests;
      const std::uint32_t d = tet.apex(g);
      const Sign s = insphere_perturbed(P[v[0]], P[v[1]], P[v[2]], P[v[3]], P[d]);
      if (s == Sign::Positive) {
        r.add_problem("empty sphere: " + facet_name(tet, h) + " is not locally Delaunay: point " + std::to_string(d) +
                      " of " + name(tet, T3::tetrahedron_of(g)) + " is inside the sphere (perturbed insphere)");
      } else if (s == Sign::Zero) {
        r.add_problem("empty sphere: " + facet_name(tet, h) + ": perturbed insphere is zero (coplanar points)");
      }
    }
  }
}

void hull(const T3& tet, CheckReport3& r) {
  const auto P = tet.points();
  for (std::uint32_t t = 0; t < size32(tet); ++t) {
    if (!tet.is_ghost(t)) continue;
    const auto& v = tet.records()[t].vertex;  // (inf, a, b, c): orient3d(q, a, b, c) > 0 beyond
    const std::uint32_t below = tet.twin(T3::facet(t, 0));
    const std::uint32_t f = T3::tetrahedron_of(below);
    if (tet.is_ghost(f)) continue;  // reported by topology
    const std::uint32_t e = tet.apex(below);
    if (orient3d(P[e], P[v[1]], P[v[2]], P[v[3]]) != Sign::Negative) {
      r.add_problem("hull: point " + std::to_string(e) + " of " + name(tet, f) + " is not strictly inside the hull facet of " +
                    name(tet, t));
      continue;  // the remaining tests use e as a point strictly inside
    }
    const auto& w = tet.records()[f].vertex;
    for (std::uint32_t i = 1; i < 4; ++i) {
      const std::uint32_t g = tet.twin(T3::facet(t, i));
      const std::uint32_t d = tet.apex(g);
      if (d == kInf) continue;  // reported by topology (a ghost's neighbour across an edge facet is a ghost)
      const Sign s = orient3d(P[d], P[v[1]], P[v[2]], P[v[3]]);
      // The shared hull edge (a, b): the finite vertices of facet i.
      std::array<std::uint32_t, 2> edge{};
      for (std::size_t k = 0, m = 0; k < 3; ++k)
        if (kFacet[i][k] != 0) edge[m++] = v[kFacet[i][k]];
      const auto [a, b] = edge;
      if (s == Sign::Positive) {
        r.add_problem("hull: concave at " + edge_name(a, b) + ": point " + std::to_string(d) + " of " +
                      name(tet, T3::tetrahedron_of(g)) + " is beyond the hull facet of " + name(tet, t));
        continue;
      }
      if (s == Sign::Negative) continue;
      // Coplanar neighbours: they must lie on opposite sides of the edge, within the plane.
      const Sign own = orient3d(P[a], P[b], P[e], P[v[i]]);
      const Sign other = orient3d(P[a], P[b], P[e], P[d]);
      if (own == Sign::Zero || other == Sign::Zero || own == other) {
        r.add_problem("hull: folded at " + edge_name(a, b) + ": the hull facets of " + name(tet, t) + " and " +
                      name(tet, T3::tetrahedron_of(g)) + " are coplanar and not on opposite sides of the edge");
        continue;
      }
      if (std::find(w.begin(), w.end(), d) != w.end()) continue;
      ++r.insphere_tests;
      const Sign conflict = insphere_perturbed(P[w[0]], P[w[1]], P[w[2]], P[w[3]], P[d]);
      if (conflict == Sign::Positive) {
        r.add_problem("hull: ghost rule broken at " + edge_name(a, b) + ": point " + std::to_string(d) +
                      ", coplanar with the hull facet of " + name(tet, t) + ", is inside its circle (perturbed insphere with " +
                      name(tet, f) + ")");
      } else if (conflict == Sign::Zero) {
        r.add_problem("hull: perturbed insphere of point " + std::to_string(d) + " against " + name(tet, f) + " is zero");
      }
    }
  }
}

// --- exact coverage ----------------------------------------------------------------------------------

// An mpz_t for the duration of one check.
class Integer {
 public:
  Integer() noexcept { mpz_init(v_); }
  ~Integer() { mpz_clear(v_); }
  Integer(const Integer&) = delete;
  Integer& operator=(const Integer&) = delete;
  mpz_ptr get() noexcept { return v_; }
  mpz_srcptr get() const noexcept { return v_; }

 private:
  mpz_t v_;
};

// Coordinates as integers: every double is an integer mantissa times 2^e, so scaling all of them
// by 2^-e_min makes them integers, and determinants keep their signs and ratios.
class ScaledPoints {
 public:
  explicit ScaledPoints(std::span<const Vec3> points) : points_(points) {
    int low = std::numeric_limits<int>::max();
    for (const Vec3& p : points)
      for (const double c : {p.x, p.y, p.z}) {
        if (c == 0.0) continue;
        int e = 0;
        std::frexp(c, &e);
        low = std::min(low, e - 53);
      }
    shift_ = low == std::numeric_limits<int>::max() ? 0 : -low;
  }
  // out[0..2] = the coordinates of point v, as integers.
  void load(std::uint32_t v, Integer* out) const {
    const Vec3& p = points_[v];
    mpz_set_d(out[0].get(), std::ldexp(p.x, shift_));
    mpz_set_d(out[1].get(), std::ldexp(p.y, shift_));
    mpz_set_d(out[2].get(), std::ldexp(p.z, shift_));
  }

 private:
  std::span<const Vec3> points_;
  int shift_ = 0;
};

// sum += det(q - p, r - p, s - p) for integer points, with scratch space.
struct Determinant {
  Integer p[3], q[3], r[3], s[3], minor[3];

  void add(mpz_ptr sum) {
    for (int k = 0; k < 3; ++k) {
      mpz_sub(q[k].get(), q[k].get(), p[k].get());
      mpz_sub(r[k].get(), r[k].get(), p[k].get());
      mpz_sub(s[k].get(), s[k].get(), p[k].get());
    }
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      mpz_mul(minor[k].get(), r[i].get(), s[j].get());
      mpz_submul(minor[k].get(), r[j].get(), s[i].get());
      mpz_addmul(sum, q[k].get(), minor[k].get());
    }
  }
};

void coverage(const T3& tet, CheckReport3& r) {
  const auto P = tet.points();
  const std::uint32_t count = size32(tet);
  // Degree at one point: x strictly inside some finite tetrahedron must lie in no other one.
  constexpr int kTries = 16;
  int tries = 0;
  for (std::uint32_t t0 = 0; t0 < count && tries < kTries; ++t0) {
    if (tet.is_ghost(t0)) continue;
    ++tries;
    const auto& v = tet.records()[t0].vertex;
    const Vec3 x = 0.25 * (((P[v[0]] + P[v[1]]) + P[v[2]]) + P[v[3]]);
    bool inside = true;
    for (std::uint32_t i = 0; i < 4 && inside; ++i) inside = side_of_facet(tet, t0, i, x) == Sign::Positive;
    if (!inside) continue;  // a sliver whose rounded centroid left it: try another
    std::vector<std::uint32_t> holders;
    for (std::uint32_t t = 0; t < count; ++t) {
      if (tet.is_ghost(t) || t == t0) continue;
      bool holds = true;
      for (std::uint32_t i = 0; i < 4 && holds; ++i) holds = side_of_facet(tet, t, i, x) != Sign::Negative;
      if (holds) holders.push_back(t);
    }
    if (!holders.empty()) {
      std::string who;
      for (std::size_t k = 0; k < holders.size() && k < 4; ++k) who += (k ? ", " : " ") + name(tet, holders[k]);
      r.add_problem("coverage: the centroid of " + name(tet, t0) + " lies in " + std::to_string(holders.size()) +
                    " other tetrahedra (overlap):" + who);
    }
    break;
  }

  // Volume: sum over the finite tetrahedra == volume enclosed by the hull facets, exactly.
  const ScaledPoints Z(P);
  Determinant det;
  Integer tetrahedra, enclosed;
  std::uint32_t origin = kInf;
  for (std::uint32_t t = 0; t < count; ++t) {
    const auto& v = tet.records()[t].vertex;
    if (!tet.is_ghost(t)) {
      Z.load(v[0], det.p), Z.load(v[1], det.q), Z.load(v[2], det.r), Z.load(v[3], det.s);
      det.add(tetrahedra.get());
      continue;
    }
    if (origin == kInf) origin = v[1];
    // Outward facet (a, b, c) of ghost (inf, a, b, c): det(a - o, c - o, b - o) is its cone's 6 x volume.
    Z.load(origin, det.p), Z.load(v[1], det.q), Z.load(v[3], det.r), Z.load(v[2], det.s);
    det.add(enclosed.get());
  }
  if (mpz_cmp(tetrahedra.get(), enclosed.get()) != 0) {
    r.add_problem("coverage: the exact volume of the finite tetrahedra differs from the exact volume enclosed by "
                  "the hull facets (holes or overlaps)");
  }
  if (r.tetrahedra > 0 && mpz_sgn(tetrahedra.get()) <= 0) r.add_problem("coverage: the total volume is not positive");
}

// --- references -------------------------------------------------------------------------------------

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::Zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::Zero &&
         orient2d({a.x, a.z}, {b.x, b.z}, {c.x, c.z}) == Sign::Zero;
}

void unreferenced(const T3& tet, std::span<const std::uint32_t> duplicates, bool coordinates_ok, CheckReport3& r) {
  const auto P = tet.points();
  const std::size_t n = P.size();
  r.points = n;
  r.duplicates = duplicates.size();
  constexpr std::uint32_t kNone = T3::kNone;
  std::vector<std::uint32_t> first_tetrahedron(n, kNone);
  bool any_finite = false;
  for (std::uint32_t t = 0; t < size32(tet); ++t) {
    if (tet.is_ghost(t)) continue;
    any_finite = true;
    for (const std::uint32_t v : tet.records()[t].vertex)
      if (v < n && first_tetrahedron[v] == kNone) first_tetrahedron[v] = t;
  }
  r.referenced_points = static_cast<std::size_t>(
      std::count_if(first_tetrahedron.begin(), first_tetrahedron.end(), [](std::uint32_t t) { return t != kNone; }));

  std::vector<char> is_duplicate(n, 0);
  for (const std::uint32_t d : duplicates) {
    if (d >= n) {
      r.add_problem("references: duplicate index " + std::to_string(d) + " out of range (" + std::to_string(n) +
                    " points)");
    } else if (is_duplicate[d]) {
      r.add_problem("references: point " + std::to_string(d) + " is listed twice as a duplicate");
    } else {
      is_duplicate[d] = 1;
      if (first_tetrahedron[d] != kNone) {
        r.add_problem("references: duplicate point " + std::to_string(d) + " is a vertex of " +
                      name(tet, first_tetrahedron[d]));
      }
    }
  }
  std::vector<std::uint32_t> kept;
  for (std::uint32_t i = 0; i < n; ++i)
    if (!is_duplicate[i]) kept.push_back(i);
  if (any_finite) {
    for (const std::uint32_t i : kept) {
      if (first_tetrahedron[i] == kNone) {
        r.add_problem("references: point " + std::to_string(i) +
                      " is a vertex of no tetrahedron and is not listed as a duplicate");
      }
    }
  }
  if (!coordinates_ok) return;

  std::vector<std::uint32_t> by_position = kept;
  std::sort(by_position.begin(), by_position.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto c = P[a] <=> P[b];
    return c < 0 || (c == 0 && a < b);
  });
  for (std::size_t i = 1; i < by_position.size(); ++i) {
    if (P[by_position[i]] == P[by_position[i - 1]]) {
      r.add_problem("references: points " + std::to_string(by_position[i - 1]) + " and " +
                    std::to_string(by_position[i]) + " coincide and neither is listed as a duplicate");
    }
  }
  const auto position_less = [&](std::uint32_t a, const Vec3& p) { return (P[a] <=> p) < 0; };
  for (const std::uint32_t d : duplicates) {
    if (d >= n) continue;
    const auto it = std::lower_bound(by_position.begin(), by_position.end(), P[d], position_less);
    if (it == by_position.end() || P[*it] != P[d]) {
      r.add_problem("references: point " + std::to_string(d) +
                    " is listed as a duplicate but coincides with no kept point");
    }
  }

  // No tetrahedra: right only when the kept points are coplanar.
  if (!any_finite && kept.size() >= 4) {
    const std::uint32_t a = kept[0];
    const auto b = std::find_if(kept.begin(), kept.end(), [&](std::uint32_t i) { return P[i] != P[a]; });
    if (b == kept.end()) return;
    const auto c = std::find_if(kept.begin(), kept.end(), [&](std::uint32_t i) { return !collinear(P[a], P[*b], P[i]); });
    if (c == kept.end()) return;
    const auto d = std::find_if(kept.begin(), kept.end(),
                                [&](std::uint32_t i) { return orient3d(P[a], P[*b], P[*c], P[i]) != Sign::Zero; });
    if (d != kept.end()) {
      r.add_problem("references: no tetrahedra, yet points " + std::to_string(a) + ", " + std::to_string(*b) + ", " +
                    std::to_string(*c) + " and " + std::to_string(*d) + " are not coplanar");
    }
  }
}

// Runs `check` on a structure that passes the preconditions of the geometric checks.
template <class Check>
CheckReport3 geometric(const T3& tet, const char* what, Check&& check) {
  CheckReport3 r;
  count_elements(tet, r);
  if (!coordinates_valid(tet.points(), r, what) || !sound(tet, r)) return r;
  check(tet, r);
  return r;
}

}  // namespace

CheckReport3 check_topology3(const Tetrahedralization3& tet) {
  CheckReport3 r;
  count_elements(tet, r);
  if (sound(tet, r)) topology(tet, r);
  return r;
}

CheckReport3 check_orientation3(const Tetrahedralization3& tet) { return geometric(tet, "orientation", orientation); }

CheckReport3 check_empty_sphere3(const Tetrahedralization3& tet) {
  return geometric(tet, "empty sphere", [](const T3& t, CheckReport3& r) { empty_sphere(t, r); });
}

CheckReport3 check_constrained_delaunay3(std::span<const Vec3> points,
                                         std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                         const std::function<bool(std::array<std::uint32_t, 3>)>& constrained) {
  CheckReport3 r;
  r.tetrahedra = tetrahedra.size();
  struct Side {
    std::array<std::uint32_t, 3> face;  // sorted
    std::uint32_t tetrahedron, apex;
  };
  std::vector<Side> sides;
  sides.reserve(4 * tetrahedra.size());
  for (std::uint32_t t = 0; t < tetrahedra.size(); ++t)
    for (std::uint32_t i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> f;
      for (std::uint32_t j = 0, k = 0; j < 4; ++j)
        if (j != i) f[k++] = tetrahedra[t][j];
      std::sort(f.begin(), f.end());
      sides.push_back({f, t, tetrahedra[t][i]});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.face < y.face; });
  for (std::size_t k = 0; k + 1 < sides.size(); ++k) {
    if (sides[k].face != sides[k + 1].face) continue;
    const Side &x = sides[k], &y = sides[k + 1];
    if (constrained(x.face)) continue;
    ++r.interior_facets;
    ++r.insphere_tests;
    const auto& v = tetrahedra[x.tetrahedron];
    if (insphere(points[v[0]], points[v[1]], points[v[2]], points[v[3]], points[y.apex]) == Sign::Positive)
      r.add_problem("constrained Delaunay: facet (" + std::to_string(x.face[0]) + ", " + std::to_string(x.face[1]) + ", " +
                    std::to_string(x.face[2]) + ") is not locally Delaunay: point " + std::to_string(y.apex) +
                    " of tetrahedron " + std::to_string(y.tetrahedron) + " is strictly inside the sphere of tetrahedron " +
                    std::to_string(x.tetrahedron));
  }
  return r;
}

CheckReport3 check_hull3(const Tetrahedralization3& tet) { return geometric(tet, "hull", hull); }

CheckReport3 check_coverage3(const Tetrahedralization3& tet) { return geometric(tet, "coverage", coverage); }

CheckReport3 check_unreferenced3(const Tetrahedralization3& tet, std::span<const std::uint32_t> duplicates) {
  CheckReport3 r;
  count_elements(tet, r);
  const bool coordinates_ok = coordinates_valid(tet.points(), r, "references");
  unreferenced(tet, duplicates, coordinates_ok, r);
  return r;
}

CheckReport3 verify_delaunay3d(std::span<const Vec3> points, const Tetrahedralization3& tet,
                               std::span<const std::uint32_t> duplicates) {
  CheckReport3 r;
  count_elements(tet, r);
  if (!coordinates_valid(points, r, "input")) return r;
  const auto stored = tet.points();
  if (!std::equal(points.begin(), points.end(), stored.begin(), stored.end())) {
    r.add_problem("input: the tetrahedralization holds " + std::to_string(stored.size()) +
                  " points that are not the " + std::to_string(points.size()) + " input points");
    return r;
  }
  unreferenced(tet, duplicates, true, r);
  if (!sound(tet, r)) return r;
  topology(tet, r);
  orientation(tet, r);
  empty_sphere(tet, r);
  hull(tet, r);
  coverage(tet, r);
  return r;
}

std::vector<TetrahedronIds> canonical_tetrahedron_set(std::span<const TetrahedronIds> tetrahedra) {
  std::vector<TetrahedronIds> out;
  out.reserve(tetrahedra.size());
  for (const TetrahedronIds& t : tetrahedra) out.push_back(canonical_tetrahedron(t));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<TetrahedronIds> canonical_tetrahedron_set(const Tetrahedralization3& tet) {
  return canonical_tetrahedron_set(tet.finite_tetrahedra());
}

}  // namespace dtlab
