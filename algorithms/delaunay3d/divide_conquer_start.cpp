// First hull facet of variant "divide-conquer" (divide_conquer_start.hpp).
#include "algorithms/delaunay3d/divide_conquer_start.hpp"

#include <tuple>

#include "algorithms/delaunay3d/divide_conquer_search.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"

namespace dtlab::dewall {

namespace {

bool lex_less(const Vec3& p, const Vec3& q) noexcept { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); }

// (b - a) x (c - a) = 0: its components are the orientations of the three axis projections.
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) noexcept {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::Zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::Zero &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::Zero;
}

// Gift wrapping about the line (a, b): the point w off the line with orient3d(a, b, w, q) >= 0
// for every q. Valid when the points off the line lie strictly on one side of some plane
// through it: their angles about the line then span less than a half-turn, and orient3d orders
// them, so one scan keeps the extreme.
std::uint32_t wrap(std::span<const Vec3> points, const Vec3& a, const Vec3& b) {
  std::uint32_t w = kNone;
  for (std::uint32_t r = 0; r < points.size(); ++r) {
    if (collinear(a, b, points[r])) continue;
    if (w == kNone || orient3d(a, b, points[w], points[r]) == Sign::Negative) w = r;
  }
  DTLAB_ASSERT(w != kNone);
  return w;
}

// A point of the plane (a, b, w) off the line (a, w), or kNone.
std::uint32_t off_line_in_plane(std::span<const Vec3> points, const Vec3& a, const Vec3& b, std::uint32_t w) {
  for (std::uint32_t r = 0; r < points.size(); ++r)
    if (orient3d(a, b, points[w], points[r]) == Sign::Zero && !collinear(a, points[w], points[r])) return r;
  return kNone;
}

// Three non-collinear points spanning a plane that has every point on one closed side.
std::array<std::uint32_t, 3> supporting_plane(std::span<const Vec3> P) {
  const auto n = static_cast<std::uint32_t>(P.size());
  std::uint32_t e0 = 0;
  for (std::uint32_t r = 1; r < n; ++r)
    if (lex_less(P[r], P[e0])) e0 = r;
  const Vec3& a = P[e0];
  // The plane x = a.x supports; Q0 = the points on it.
  std::uint32_t j = kNone;
  for (std::uint32_t r = 0; r < n && j == kNone; ++r)
    if (r != e0 && P[r].x == a.x) j = r;
  if (j != kNone) {
    for (std::uint32_t r = 0; r < n; ++r)
      if (P[r].x == a.x && !collinear(a, P[j], P[r])) return {e0, j, r};
    // Q0 lies on the line (e0, j); every other point has x > a.x.
    return {e0, j, wrap(P, a, P[j])};
  }
  // Q0 = {e0}: turn the plane about the line through e0 parallel to the y axis (u is exact).
  const Vec3 u{a.x, a.y != 0.0 ? -a.y : 1.0, a.z};
  const std::uint32_t w = wrap(P, a, u);
  const std::uint32_t k = off_line_in_plane(P, a, u, w);
  if (k != kNone) return {e0, w, k};
  // The new plane holds only the line (e0, w): turn it about that line.
  return {e0, w, wrap(P, a, P[w])};
}

}  // namespace

std::array<std::uint32_t, 3> first_hull_facet(std::span<const Vec3> P) {
  const auto n = static_cast<std::uint32_t>(P.size());
  const auto plane = supporting_plane(P);
  const Vec3 &pa = P[plane[0]], &pb = P[plane[1]], &pc = P[plane[2]];
  std::uint32_t d = kNone;
  for (std::uint32_t r = 0; r < n && d == kNone; ++r)
    if (orient3d(pa, pb, pc, P[r]) != Sign::Zero) d = r;
  DTLAB_ASSERT(d != kNone);
  const Vec3& pd = P[d];
  auto on_plane = [&](std::uint32_t r) { return orient3d(pa, pb, pc, P[r]) == Sign::Zero; };

  // e0: the lexicographically smallest point of all, which the plane holds (supporting_plane
  // starts from it). From e0 every other point lies in a lexicographically positive direction,
  // so two points on one line through e0 are on one ray, and the nearer is the smaller.
  const std::uint32_t e0 = plane[0];
  std::uint32_t e1 = kNone;
  for (std::uint32_t r = 0; r < n; ++r) {
    if (r == e0 || !on_plane(r)) continue;
    if (e1 == kNone) {
      e1 = r;
      continue;
    }
    const Sign s = orient3d(P[e0], P[e1], P[r], pd);
    if (s == Sign::Negative || (s == Sign::Zero && lex_less(P[r], P[e1]))) e1 = r;
  }
  DTLAB_ASSERT(e1 != kNone);

  // Every point of the plane is now on d's side of the line (e0, e1) or on it; the triangle on
  // the edge is the one whose perturbed circle holds no other point on that side.
  std::uint32_t best = kNone;
  for (std::uint32_t r = 0; r < n; ++r) {
    if (!on_plane(r) || orient3d(P[e0], P[e1], P[r], pd) != Sign::Positive) continue;
    if (best == kNone || insphere_perturbed(P[e0], P[e1], P[best], pd, P[r]) == Sign::Positive) best = r;
  }
  DTLAB_ASSERT(best != kNone);
  return {e0, e1, best};
}

}  // namespace dtlab::dewall
