// Corners and the smooth support of a 2D boundary (boundary_curve2.hpp).
#include "algorithms/adapt/boundary_curve2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace dtlab {

namespace {

// The other ends of the constrained edges at v (each edge once: edge v -> a is prev(h) of the
// ball half-edge h = a -> b), at most `limit` of them, and whether their references agree.
struct BoundaryStar {
  std::vector<std::uint32_t> ends;
  bool one_ref = true;
};
BoundaryStar boundary_star(const Mesh2& mesh, std::uint32_t v, std::vector<std::uint32_t>& ring) {
  BoundaryStar star;
  mesh.ball(v, ring);
  int ref = 0;
  for (const std::uint32_t h : ring) {
    const std::uint32_t spoke = Mesh2::prev(h);
    if (!mesh.is_constrained(spoke)) continue;
    if (star.ends.empty())
      ref = mesh.edge_ref(spoke);
    else if (mesh.edge_ref(spoke) != ref)
      star.one_ref = false;
    star.ends.push_back(mesh.origin(h));
  }
  return star;
}

// The boundary neighbour of v other than `from`, when v is not a corner and has one.
std::uint32_t next_along(const Mesh2& mesh, std::uint32_t v, std::uint32_t from) {
  if ((mesh.flags(v) & Mesh2::kFixed) != 0) return Mesh2::kNone;
  std::vector<std::uint32_t> ring;
  const BoundaryStar star = boundary_star(mesh, v, ring);
  if (star.ends.size() != 2) return Mesh2::kNone;
  const std::uint32_t other = star.ends[0] == from ? star.ends[1] : star.ends[0];
  return other == Mesh2::kInfinite ? Mesh2::kNone : other;
}

// The unit tangent at p of the circle through p, q, r (oriented from q toward r as the polygon
// runs q, p, r when p is between them, or along p -> r when `p_is_end`); the chord's direction
// when the three are (nearly) collinear.
Vec2 circle_tangent(const Vec2& q, const Vec2& p, const Vec2& r, bool p_is_end) {
  const Vec2 d1 = q - p, d2 = r - p;
  const double c = cross(d1, d2);
  const double l1 = dot(d1, d1), l2 = dot(d2, d2);
  const Vec2 along = p_is_end ? d2 : r - q;
  const double along_len = norm(along);
  if (!(along_len > 0.0)) return {0.0, 0.0};
  if (std::fabs(c) <= 1e-12 * std::sqrt(l1 * l2)) return (1.0 / along_len) * along;
  // Circumcentre relative to p (2 centre . d1 = l1, 2 centre . d2 = l2):
  // (l1 R(d2) - l2 R(d1)) / (2 c) with R(x) = (x.y, -x.x).
  const Vec2 centre{(l1 * d2.y - l2 * d1.y) / (2.0 * c), (l2 * d1.x - l1 * d2.x) / (2.0 * c)};
  Vec2 t{-centre.y, centre.x};  // perpendicular to the radius
  const double tl = norm(t);
  if (!(tl > 0.0)) return (1.0 / along_len) * along;
  t = (1.0 / tl) * t;
  return dot(t, along) < 0.0 ? -1.0 * t : t;
}

}  // namespace

std::uint32_t mark_boundary_corners(Mesh2& mesh, double ridge_angle_degrees) {
  const double cos_limit = std::cos(std::clamp(ridge_angle_degrees, 0.0, 180.0) * std::numbers::pi / 180.0);
  std::uint32_t corners = 0;
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v) || (mesh.flags(v) & Mesh2::kOnBoundary) == 0) continue;
    const BoundaryStar star = boundary_star(mesh, v, ring);
    bool corner = star.ends.size() != 2 || !star.one_ref;
    if (!corner) {
      // The turn at v: the angle between the incoming edge (a -> v) and the outgoing (v -> b).
      const Vec2 in = mesh.point(v) - mesh.point(star.ends[0]), out = mesh.point(star.ends[1]) - mesh.point(v);
      const double turn_cos = dot(in, out) / (norm(in) * norm(out));
      corner = !(turn_cos >= cos_limit);
    }
    const std::uint8_t f = mesh.flags(v);
    mesh.set_flags(v, corner ? static_cast<std::uint8_t>(f | Mesh2::kFixed) : static_cast<std::uint8_t>(f & ~Mesh2::kFixed));
    if (corner) ++corners;
  }
  return corners;
}

Vec2 boundary_support_point(const Mesh2& mesh, std::uint32_t h, double s) {
  const std::uint32_t a = mesh.origin(h), b = mesh.destination(h);
  const Vec2 &pa = mesh.point(a), &pb = mesh.point(b);
  const Vec2 chord = pb - pa;
  const double length = norm(chord);
  const std::uint32_t before = next_along(mesh, a, b), after = next_along(mesh, b, a);
  if (!(length > 0.0) || (before == Mesh2::kNone && after == Mesh2::kNone)) return pa + s * chord;
  // Unit tangents at a and b, both oriented from a toward b; at a corner end, the tangent there
  // of the circle through the edge and the other end's next neighbour.
  const Vec2 ta = before != Mesh2::kNone ? circle_tangent(mesh.point(before), pa, pb, false)
                                         : circle_tangent(mesh.point(after), pa, pb, true);
  const Vec2 tb = after != Mesh2::kNone ? circle_tangent(pa, pb, mesh.point(after), false)
                                        : -1.0 * circle_tangent(mesh.point(before), pb, pa, true);
  // The arc's angle is the angle between the end tangents; the Bezier fit of a circular arc of
  // angle theta has its control points at 4/3 tan(theta/4) R from the ends, R = chord / (2
  // sin(theta/2)): a Hermite tangent of length chord * 2 tan(theta/4) / sin(theta/2).
  const double theta = std::acos(std::clamp(dot(ta, tb), -1.0, 1.0));
  if (theta > std::numbers::pi / 2.0) return pa + s * chord;  // too sharp for one edge: no guess
  const double scale = theta > 1e-8 ? 2.0 * std::tan(theta / 4.0) / std::sin(theta / 2.0) : 1.0;
  const Vec2 ma = (length * scale) * ta, mb = (length * scale) * tb;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = -2.0 * s3 + 3.0 * s2,
               h11 = s3 - s2;
  return h00 * pa + h10 * ma + h01 * pb + h11 * mb;
}

}  // namespace dtlab
