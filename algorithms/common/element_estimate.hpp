// How many elements a mesh of unit edges in a metric field will have, before any is made (issue
// 42: a size of 1e-9 on the unit square must be refused in a millisecond, not by std::bad_alloc
// after minutes). The count follows from the metric's complexity (Loseille and Alauzet 2011,
// "Continuous mesh framework", part I): a unit element has the measure of the regular simplex
// of unit edges in the metric, so a domain holds about
//   triangles     ~ ∫ √det M dx / (√3 / 4)        (2D),
//   tetrahedra    ~ ∫ √det M dx / (√2 / 12)       (3D),
// and at least as many elements as its boundary has unit edges (2D: the boundary's length in the
// metric) or half its unit triangles (3D: ∫ √det M|facet over the surface / (√3 / 4) / 2).
// The integrals run over the simplices of a mesh of the domain (the empty mesh) with the metric
// sampled at their corners, each simplex cut in 2^d by its edge midpoints where the density
// varies over it, down to a depth that keeps the samples under kSampleBudget: the estimate is
// within a small factor of the final count (a layer that no sample sees is caught by the
// meshers' own vertex bound at run time). Dimension-generic: the simplex is an array of 2, 3 or
// 4 points (segments, triangles, tetrahedra) in 2D or 3D.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>
#include <type_traits>

#include <unistd.h>

#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab::element_estimate {

inline constexpr double kUnitTriangleArea = 0.43301270189221935;       // √3 / 4
inline constexpr double kUnitTetrahedronVolume = 0.11785113019775793;  // √2 / 12
inline constexpr std::uint64_t kSampleBudget = std::uint64_t{1} << 16;

// Peak memory a mesher holds per output element: measured with `dtlab mesh --stats` (peak_rss_mb
// over the element count) at 145 B a triangle (data/square_disc.poly at --size 0.002, 5e5
// triangles) and 237 B a tetrahedron (data/quad_cube.off at 0.04, 1.3e6 tetrahedra) on
// 2026-12-07; the constants keep a factor of about 2.5 for other inputs and the estimate's spread.
// The default --max-elements is half this machine's memory divided by them (docs/cli.md).
inline constexpr double kBytesPerTriangle = 400.0;
inline constexpr double kBytesPerTetrahedron = 600.0;

// Half the physical memory over the bytes an element costs; 10^8 where the memory is unknown.
inline std::uint64_t default_max_elements(double bytes_per_element) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 100'000'000;
  return static_cast<std::uint64_t>(0.5 * static_cast<double>(pages) * static_cast<double>(page) / bytes_per_element);
}

// The subdivision depth at which `simplices` simplices cut in `children` each stay within the budget.
inline unsigned depth_for(std::uint64_t simplices, unsigned children) {
  unsigned depth = 0;
  double leaves = static_cast<double>(std::max<std::uint64_t>(simplices, 1));
  while (depth < 12 && leaves * children <= static_cast<double>(kSampleBudget)) leaves *= children, ++depth;
  return depth;
}

namespace detail {

template <class P>
P mid(const P& a, const P& b) {
  return 0.5 * (a + b);
}

// The 2, 4 or 8 children of a simplex cut at its edge midpoints (a tetrahedron's inner
// octahedron cut along one diagonal).
template <class P>
std::array<std::array<P, 2>, 2> children(const std::array<P, 2>& s) {
  const P m = mid(s[0], s[1]);
  return {{{s[0], m}, {m, s[1]}}};
}
template <class P>
std::array<std::array<P, 3>, 4> children(const std::array<P, 3>& s) {
  const P a = mid(s[1], s[2]), b = mid(s[0], s[2]), c = mid(s[0], s[1]);
  return {{{s[0], c, b}, {c, s[1], a}, {b, a, s[2]}, {a, b, c}}};
}
template <class P>
std::array<std::array<P, 4>, 8> children(const std::array<P, 4>& s) {
  const P m01 = mid(s[0], s[1]), m02 = mid(s[0], s[2]), m03 = mid(s[0], s[3]);
  const P m12 = mid(s[1], s[2]), m13 = mid(s[1], s[3]), m23 = mid(s[2], s[3]);
  return {{{s[0], m01, m02, m03},
           {m01, s[1], m12, m13},
           {m02, m12, s[2], m23},
           {m03, m13, m23, s[3]},
           {m01, m02, m03, m13},
           {m01, m02, m12, m13},
           {m02, m03, m13, m23},
           {m02, m12, m13, m23}}};
}

}  // namespace detail

// ∫ density over the simplex s: `measure(s)` its length, area or volume, `density(p)` the
// integrand at a point (√det M, or the metric length per unit length on a segment). A simplex
// whose corner densities differ by more than 25 % is cut, `depth` levels at most; a leaf counts
// its measure times the mean of its corners' densities (an infinite or NaN density makes the
// result infinite: refused by the caller).
template <class P, std::size_t K, class Density, class Measure>
double integrate(const std::array<P, K>& s, const Density& density, const Measure& measure, unsigned depth) {
  double lo = 0, hi = 0, sum = 0;
  for (std::size_t i = 0; i < K; ++i) {
    const double d = density(s[i]);
    if (!(d < HUGE_VAL)) return HUGE_VAL;
    lo = i == 0 ? d : std::min(lo, d);
    hi = i == 0 ? d : std::max(hi, d);
    sum += d;
  }
  if (depth == 0 || hi <= 1.25 * lo) return measure(s) * sum / static_cast<double>(K);
  double total = 0;
  for (const auto& child : detail::children(s)) total += integrate(child, density, measure, depth - 1);
  return total;
}

// The measures of simplices in 2D and 3D (kernel/vec.hpp's products).
template <class P>
double length(const std::array<P, 2>& s) {
  return norm(s[1] - s[0]);
}
inline double area(const std::array<Vec2, 3>& s) { return 0.5 * std::abs(cross(s[1] - s[0], s[2] - s[0])); }
inline double area(const std::array<Vec3, 3>& s) { return 0.5 * norm(cross(s[1] - s[0], s[2] - s[0])); }
inline double volume(const std::array<Vec3, 4>& s) {
  return std::abs(dot(s[1] - s[0], cross(s[2] - s[0], s[3] - s[0]))) / 6.0;
}

// √det M (the metric's volume density), infinite where det overflows or M is not SPD.
template <class Metric>
double volume_density(const Metric& m) {
  const double det = m.determinant();
  return det > 0.0 && det < HUGE_VAL ? std::sqrt(det) : HUGE_VAL;
}
// The metric length per unit length along the unit direction t.
template <class Metric, class V>
double length_density(const Metric& m, const V& t) {
  const double l = m.length(t);
  return l >= 0.0 && l < HUGE_VAL ? l : HUGE_VAL;
}
// √det of M restricted to the plane of a facet with unit normal n (the facet's area density):
// det(M|plane) = nᵀ adj(M) n for the unit normal n.
inline double facet_density(const Metric3& m, const Vec3& n) {
  const double a = m.m[0], b = m.m[1], c = m.m[2], d = m.m[3], e = m.m[4], f = m.m[5];  // m11 m12 m22 m13 m23 m33
  const double c11 = c * f - e * e, c22 = a * f - d * d, c33 = a * c - b * b;  // the adjugate's entries
  const double c12 = d * e - b * f, c13 = b * e - c * d, c23 = b * d - a * e;
  const double det = c11 * n.x * n.x + c22 * n.y * n.y + c33 * n.z * n.z + 2.0 * (c12 * n.x * n.y + c13 * n.x * n.z + c23 * n.y * n.z);
  return det > 0.0 && det < HUGE_VAL ? std::sqrt(det) : HUGE_VAL;
}

// The refusal: the estimate past the limit, with both in the message, for `what` ("triangles" or
// "tetrahedra") and the place `where` ("mesh2d").
inline void check_limit(const std::string& where, double estimate, std::uint64_t limit, const std::string& what,
                        const std::string& detail) {
  if (estimate <= static_cast<double>(limit)) return;
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", estimate);
  throw InputError(where + ": the size or metric asks for about " + text + " " + what + " (" + detail +
                   "), more than the limit of " + std::to_string(limit) +
                   " (max_elements, --max-elements; by default half this machine's memory at the bytes an element "
                   "costs): give a larger size or raise the limit");
}

// The estimate over the domain of a mesh (its in-domain simplices and its constrained boundary
// pieces beside them), the metric from `metric_at(point)`.
struct Estimate {
  double elements = 0;  // the larger of the two counts below
  double complexity = 0;  // ∫ √det M over the domain
  double boundary = 0;    // the boundary's measure in the metric (2D: length; 3D: area)
  std::string detail() const {
    char text[160];
    std::snprintf(text, sizeof text, "metric complexity %.3g over the domain, boundary %.3g in the metric", complexity,
                  boundary);
    return text;
  }
};

template <class Mesh, class MetricAt>
Estimate estimate_elements(const Mesh& mesh, const MetricAt& metric_at) {
  Estimate e;
  const auto volume_at = [&](const auto& p) { return volume_density(metric_at(p)); };
  if constexpr (std::is_same_v<Mesh, Mesh2>) {
    std::uint64_t n = 0;
    for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) n += mesh.in_domain(t);
    const unsigned depth = depth_for(n, 4);
    for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const std::array<Vec2, 3> s{mesh.point(mesh.vertex(t, 0)), mesh.point(mesh.vertex(t, 1)), mesh.point(mesh.vertex(t, 2))};
      e.complexity += integrate(s, volume_at, [](const auto& x) { return area(x); }, depth);
      for (std::uint32_t i = 0; i < 3; ++i) {  // the boundary edge opposite vertex i, once
        const std::uint32_t h = 3 * t + i, twin = mesh.twin(h);
        if (!mesh.is_constrained(h) || (mesh.in_domain(Mesh2::triangle_of(twin)) && twin < h)) continue;
        const std::array<Vec2, 2> edge{mesh.point(mesh.origin(h)), mesh.point(mesh.destination(h))};
        const double l = length(edge);
        if (l == 0.0) continue;
        const Vec2 u = (1.0 / l) * (edge[1] - edge[0]);
        e.boundary += integrate(edge, [&](const Vec2& p) { return length_density(metric_at(p), u); },
                                [](const auto& x) { return length(x); }, depth_for(n, 2));
      }
    }
    e.elements = std::max(e.complexity / kUnitTriangleArea, e.boundary);
  } else {
    std::uint64_t n = 0;
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) n += mesh.in_domain(t);
    const unsigned depth = depth_for(n, 8);
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const auto v = mesh.tetrahedron(t);
      const std::array<Vec3, 4> s{mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
      e.complexity += integrate(s, volume_at, [](const auto& x) { return volume(x); }, depth);
      for (std::uint32_t i = 0; i < 4; ++i) {  // the boundary facet opposite vertex i, once
        const std::uint32_t h = Mesh3::facet(t, i), twin = mesh.twin(h);
        if (!mesh.is_constrained(h) || (mesh.in_domain(Mesh3::tetrahedron_of(twin)) && twin < h)) continue;
        const auto f = mesh.facet_vertices(h);
        const std::array<Vec3, 3> facet{mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2])};
        const double a2 = 2.0 * area(facet);
        if (a2 == 0.0) continue;
        const Vec3 normal = (1.0 / a2) * cross(facet[1] - facet[0], facet[2] - facet[0]);
        e.boundary += integrate(facet, [&](const Vec3& p) { return facet_density(metric_at(p), normal); },
                                [](const auto& x) { return area(x); }, depth_for(n, 4));
      }
    }
    e.elements = std::max(e.complexity / kUnitTetrahedronVolume, 0.5 * e.boundary / kUnitTriangleArea);
  }
  return e;
}

// The check every operation that works toward a metric makes first (the meshers, the
// optimization with splits, adaptation): the estimate over `mesh`'s domain, refused past
// `max_elements` with `where` in the message. max_elements 0: the machine's default for the
// dimension; kNoElementLimit: no estimate (a caller that made it already). Returns the limit used
// (kNoElementLimit when none) and the estimate.
struct Checked {
  std::uint64_t limit = 0;
  Estimate estimate;
};
inline constexpr std::uint64_t kNoElementLimit = ~std::uint64_t{0};

template <class Mesh, class MetricAt>
Checked check_elements(const std::string& where, const Mesh& mesh, const MetricAt& metric_at, std::uint64_t max_elements) {
  constexpr bool kPlanar = std::is_same_v<Mesh, Mesh2>;
  Checked c;
  if (max_elements == kNoElementLimit) {
    c.limit = kNoElementLimit;
    return c;
  }
  c.limit = max_elements ? max_elements : default_max_elements(kPlanar ? kBytesPerTriangle : kBytesPerTetrahedron);
  c.estimate = estimate_elements(mesh, metric_at);
  check_limit(where, c.estimate.elements, c.limit, kPlanar ? "triangles" : "tetrahedra", c.estimate.detail());
  return c;
}

}  // namespace dtlab::element_estimate
