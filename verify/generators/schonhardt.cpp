// Generators of the Schönhardt family (schonhardt.hpp): twisted prisms and their stacks
// (Schönhardt 1928; Rambau 2005), Bagemihl polyhedra and Chazelle's notched box (Chazelle
// 1984; book §3.5).
#include "verify/generators/schonhardt.hpp"

#include <cmath>
#include <algorithm>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

// Collects a surface: points merged by coordinates, each triangle turned so that its normal
// points along the face's outward direction (the generators' coordinates are small dyadic
// rationals or the prism's, where the cross product's sign is far from rounding).
class SurfaceBuilder {
 public:
  std::uint32_t id(const Vec3& p) {
    const auto key = std::make_tuple(p.x, p.y, p.z);
    const auto [it, inserted] = ids_.emplace(key, static_cast<std::uint32_t>(surface_.points.size()));
    if (inserted) surface_.points.push_back(p);
    return it->second;
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& outward) {
    const Vec3& p = surface_.points[a];
    const Vec3& q = surface_.points[b];
    const Vec3& r = surface_.points[c];
    const Vec3 u{q.x - p.x, q.y - p.y, q.z - p.z}, v{r.x - p.x, r.y - p.y, r.z - p.z};
    const Vec3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
    const double d = n.x * outward.x + n.y * outward.y + n.z * outward.z;
    if (d > 0) {
      surface_.triangles.push_back({a, b, c});
    } else {
      surface_.triangles.push_back({a, c, b});
    }
  }
  // A convex quadrilateral a b c d (in cyclic order), split along a-c.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, const Vec3& outward) {
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  }
  // The same by corner points, numbered in a fixed order: d, c, b, a (function arguments are
  // evaluated in an unspecified order, so quad(id(a), id(b), ...) numbered the vertices
  // differently with gcc and clang, and the methods, whose symbolic perturbation follows the
  // numbering, gave other counts on the same polyhedron; this is the order gcc used).
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& outward) {
    const std::uint32_t id = this->id(d), ic = this->id(c), ib = this->id(b), ia = this->id(a);
    quad(ia, ib, ic, id, outward);
  }
  // A convex polygon in cyclic order, fanned from its first vertex (whose two edges must
  // carry no vertex other than their ends, so that no fan triangle is flat).
  void fan(const std::vector<std::uint32_t>& polygon, const Vec3& outward) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) triangle(polygon[0], polygon[k], polygon[k + 1], outward);
  }
  ClosedSurface3 take() { return std::move(surface_); }

 private:
  ClosedSurface3 surface_;
  std::map<std::tuple<double, double, double>, std::uint32_t> ids_;
};

}  // namespace

ClosedSurface3 twisted_prism(const TwistedPrismOptions& o) {
  if (o.sides < 3) throw InputError("twisted prism: needs at least 3 sides, got " + std::to_string(o.sides));
  if (o.layers < 1) throw InputError("twisted prism: needs at least 1 layer, got " + std::to_string(o.layers));
  if (!(o.radius > 0) || !(o.layer_height > 0))
    throw InputError("twisted prism: radius and layer height must be positive");
  const int n = o.sides;
  const double twist = o.twist_degrees * std::numbers::pi / 180.0;
  ClosedSurface3 s;
  for (int layer = 0; layer <= o.layers; ++layer) {
    for (int k = 0; k < n; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / n + layer * twist;
      s.points.push_back({o.radius * std::cos(phi) + o.offset.x, o.radius * std::sin(phi) + o.offset.y,
                          layer * o.layer_height + o.offset.z});
    }
  }
  const auto vid = [n](int layer, int k) { return static_cast<std::uint32_t>(layer * n + (k % n)); };
  for (int k = 1; k + 1 < n; ++k) s.triangles.push_back({vid(0, 0), vid(0, k + 1), vid(0, k)});
  for (int k = 1; k + 1 < n; ++k) s.triangles.push_back({vid(o.layers, 0), vid(o.layers, k), vid(o.layers, k + 1)});
  for (int layer = 0; layer < o.layers; ++layer) {
    for (int k = 0; k < n; ++k) {
      const std::uint32_t b0 = vid(layer, k), b1 = vid(layer, k + 1), t0 = vid(layer + 1, k), t1 = vid(layer + 1, k + 1);
      if (o.diagonal == PrismDiagonal::ReflexDiagonal) {
        s.triangles.push_back({b0, b1, t1});
        s.triangles.push_back({b0, t1, t0});
      } else {
        s.triangles.push_back({b0, b1, t0});
        s.triangles.push_back({b1, t1, t0});
      }
    }
  }
  return s;
}

ClosedSurface3 schonhardt_polyhedron(double twist_degrees) {
  return twisted_prism({.sides = 3, .twist_degrees = twist_degrees});
}

ClosedSurface3 bagemihl_polyhedron(int vertices, double twist_degrees, double bend) {
  if (vertices < 6) throw InputError("Bagemihl polyhedron: needs at least 6 vertices, got " + std::to_string(vertices));
  if (!(twist_degrees > 0 && twist_degrees < 60))
    throw InputError("Bagemihl polyhedron: the twist must be in (0, 60) degrees, got " + std::to_string(twist_degrees));
  if (!(bend > 0 && bend <= 0.5))
    throw InputError("Bagemihl polyhedron: the bend must be in (0, 1/2], got " + std::to_string(bend));
  ClosedSurface3 s = schonhardt_polyhedron(twist_degrees);
  // twisted_prism's ids: b_k = k, t_k = 3 + k. The two triangles at the side edge b_2 t_2 are
  // (b_1, b_2, t_2) and (b_2, t_0, t_2) (sides 1 and 2, reflex diagonals).
  constexpr std::uint32_t b1 = 1, b2 = 2, t0 = 3, t2 = 5;
  const auto find = [&s](std::uint32_t p, std::uint32_t q, std::uint32_t r) {  // any rotation of (p, q, r)
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      const auto& t = s.triangles[i];
      for (int k = 0; k < 3; ++k)
        if (t[k] == p && t[(k + 1) % 3] == q && t[(k + 2) % 3] == r) return i;
    }
    throw std::logic_error("bagemihl_polyhedron: a triangle of Schönhardt's polyhedron is not where expected");
  };
  const std::size_t i1 = find(b1, b2, t2), i2 = find(t0, t2, b2);
  const Vec3 a = s.points[b2], c = s.points[t2], e = c - a;
  const auto unit = [](const Vec3& v) {
    const double l = std::sqrt(dot(v, v));
    return Vec3{v.x / l, v.y / l, v.z / l};
  };
  const Vec3 u = unit(Vec3{0, 0, 0.5} - 0.5 * (a + c));  // towards the axis, from the edge's midpoint
  const Vec3 w = unit(cross(e, u));
  const int m = vertices - 6;
  std::vector<std::uint32_t> chain{b2};  // b_2, c_1, .., c_m, t_2
  for (int j = 1; j <= m; ++j) {
    const double t = double(j) / (m + 1), p = bend * 4 * t * (1 - t), q = bend * t * (1 - t) * (2 * t - 1);
    chain.push_back(static_cast<std::uint32_t>(s.points.size()));
    s.points.push_back(a + t * e + p * u + q * w);
  }
  chain.push_back(t2);
  // (b_1, b_2, t_2) becomes the fan from b_1 over the chain, (b_2, t_0, t_2) = (t_0, t_2, b_2)
  // the fan from t_0 over it backwards: the orientation of each is kept.
  s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(std::max(i1, i2)));
  s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(std::min(i1, i2)));
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) s.triangles.push_back({b1, chain[k], chain[k + 1]});
  for (std::size_t k = chain.size() - 1; k > 0; --k) s.triangles.push_back({t0, chain[k], chain[k - 1]});
  return s;
}

ClosedSurface3 chazelle_polyhedron(int n, double gap) {
  if (n < 1) throw InputError("Chazelle polyhedron: needs at least 1 notch, got " + std::to_string(n));
  int exponent = 0;
  if (!(gap > 0 && gap <= 1) || std::frexp(gap, &exponent) != 0.5)
    throw InputError("Chazelle polyhedron: the gap must be a power of two in (0, 1]");
  const double L = n + 1, H = 4, w = 0.25, zb = 2 - gap / 2, zt = 2 + gap / 2;
  // The notched outline shared by the front/back faces (bottom notches, (x, z)) and by the
  // left/right faces (top notches, (y, z)).
  std::vector<std::array<double, 2>> bottom_chain{{0, 0}}, top_chain{{0, H}};
  for (int i = 1; i <= n; ++i) {
    bottom_chain.insert(bottom_chain.end(), {{i - w, 0}, {double(i), zb}, {i + w, 0}});
    top_chain.insert(top_chain.end(), {{i - w, H}, {double(i), zt}, {i + w, H}});
  }
  bottom_chain.push_back({L, 0});
  top_chain.push_back({L, H});

  SurfaceBuilder b;
  // Front (y = 0) and back (y = L): vertical strips between the bottom outline and the top edge.
  for (const double y : {0.0, L}) {
    const Vec3 out{0, y == 0 ? -1.0 : 1.0, 0};
    for (std::size_t k = 0; k + 1 < bottom_chain.size(); ++k) {
      const auto [x0, z0] = bottom_chain[k];
      const auto [x1, z1] = bottom_chain[k + 1];
      b.quad({x0, y, z0}, {x1, y, z1}, {x1, y, H}, {x0, y, H}, out);
    }
  }
  // Left (x = 0) and right (x = L): strips between the bottom edge and the top outline.
  for (const double x : {0.0, L}) {
    const Vec3 out{x == 0 ? -1.0 : 1.0, 0, 0};
    for (std::size_t k = 0; k + 1 < top_chain.size(); ++k) {
      const auto [y0, z0] = top_chain[k];
      const auto [y1, z1] = top_chain[k + 1];
      b.quad({x, y0, 0}, {x, y1, 0}, {x, y1, z1}, {x, y0, z0}, out);
    }
  }
  // Bottom (z = 0): strips x in [lo, hi] between the bottom notches; the outer two carry the
  // left/right faces' vertices on their side edge, so each is fanned from a clean corner.
  for (int s = 0; s <= n; ++s) {
    const double lo = s == 0 ? 0 : s + w, hi = s == n ? L : s + 1 - w;
    std::vector<std::uint32_t> ring{b.id({lo, 0, 0}), b.id({hi, 0, 0})};
    if (s == n)
      for (std::size_t k = 1; k + 1 < top_chain.size(); ++k) ring.push_back(b.id({hi, top_chain[k][0], 0}));
    ring.push_back(b.id({hi, L, 0}));
    ring.push_back(b.id({lo, L, 0}));
    if (s == 0)
      for (std::size_t k = top_chain.size() - 2; k >= 1; --k) ring.push_back(b.id({lo, top_chain[k][0], 0}));
    // s == 0: start at (hi, 0); else at (lo, 0).
    if (s == 0) std::rotate(ring.begin(), ring.begin() + 1, ring.end());
    b.fan(ring, {0, 0, -1});
  }
  // Top (z = H): strips y in [lo, hi] between the top notches, the outer two carrying the
  // front/back faces' vertices.
  for (int s = 0; s <= n; ++s) {
    const double lo = s == 0 ? 0 : s + w, hi = s == n ? L : s + 1 - w;
    std::vector<std::uint32_t> ring{b.id({0, lo, H})};
    if (s == 0)
      for (std::size_t k = 1; k + 1 < bottom_chain.size(); ++k) ring.push_back(b.id({bottom_chain[k][0], lo, H}));
    ring.push_back(b.id({L, lo, H}));
    ring.push_back(b.id({L, hi, H}));
    if (s == n)
      for (std::size_t k = bottom_chain.size() - 2; k >= 1; --k) ring.push_back(b.id({bottom_chain[k][0], hi, H}));
    ring.push_back(b.id({0, hi, H}));
    // s == 0: start at (L, hi) (its edges are clean); else at (0, lo).
    if (s == 0) std::rotate(ring.begin(), ring.end() - 2, ring.end());
    b.fan(ring, {0, 0, 1});
  }
  // The wedges' slopes.
  for (int i = 1; i <= n; ++i) {
    b.quad({i - w, 0, 0}, {double(i), 0, zb}, {double(i), L, zb}, {i - w, L, 0}, {zb, 0, -w});
    b.quad({i + w, 0, 0}, {double(i), 0, zb}, {double(i), L, zb}, {i + w, L, 0}, {-zb, 0, -w});
    b.quad({0, i - w, H}, {0, double(i), zt}, {L, double(i), zt}, {L, i - w, H}, {0, H - zt, w});
    b.quad({0, i + w, H}, {0, double(i), zt}, {L, double(i), zt}, {L, i + w, H}, {0, zt - H, w});
  }
  return b.take();
}

}  // namespace dtlab
