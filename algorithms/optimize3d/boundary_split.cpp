// Split of constrained edges for 3D adaptation (book §9.3.1, the edge split of §8.3.6 carried to
// the boundary): both halves of each boundary facet keep its reference, the new vertex lies on the
// boundary: at the metric midpoint of the segment, or on the surface's geometric support
// (algorithms/surface/surface_support3.hpp) over it.
#include "algorithms/optimize3d/boundary_split.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/surface/surface_support3.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

// Six times the volume under which a tetrahedron counts as flat, per cubed longest edge (a
// regular one has 0.7; 1e-5 is a dihedral angle of about 1e-5 rad).
constexpr double kFlatVolume = 1e-5;

double length_of(const Mesh3& mesh, std::uint32_t a, std::uint32_t b) {
  return dtlab::edge_length(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b));
}

std::array<std::uint32_t, 4> substitute(std::array<std::uint32_t, 4> t, std::uint32_t from, std::uint32_t to) {
  for (auto& v : t)
    if (v == from) v = to;
  return t;
}

bool positive(const Mesh3& mesh, const std::array<std::uint32_t, 4>& t, std::uint32_t m, const Vec3& pm) {
  for (const auto v : t)
    if (v == Mesh3::kInfinite) return true;  // ghosts: no orientation
  auto p = [&](std::uint32_t v) { return v == m ? pm : mesh.point(v); };
  return orient3d(p(t[0]), p(t[1]), p(t[2]), p(t[3])) == Sign::Positive;
}

}  // namespace

std::uint32_t try_boundary_split3(Mesh3& mesh, std::uint32_t a, std::uint32_t b, const MetricField3& field,
                                  const Split3Options& options, const SurfaceSupport3* support) {
  if (a == Mesh3::kInfinite || b == Mesh3::kInfinite || !mesh.is_constrained_edge(a, b)) return Mesh3::kNone;
  std::vector<std::uint32_t> shell, ring;
  if (!mesh.shell(a, b, shell, &ring)) return Mesh3::kNone;
  // m before it exists: a number no vertex has, Mesh3::kInfinite and kNone excluded (this was
  // kInfinite itself, so the orientation test below took every new tetrahedron for a ghost).
  constexpr std::uint32_t kProbe = 0xFFFFFFFDu;
  static_assert(kProbe != Mesh3::kInfinite && kProbe != Mesh3::kNone);
  // A shell holding a flat tetrahedron (two boundary facets coplanar up to rounding: the two
  // triangles of a rotated box's face) is not split: every piece would be as flat, and field
  // points would follow on its edges in the facets' plane; the optimization removes the one
  // tetrahedron, not its pieces.
  for (const std::uint32_t t : shell) {
    if (!mesh.in_domain(t)) continue;
    const auto v = mesh.tetrahedron(t);
    const Vec3 &p0 = mesh.point(v[0]), &p1 = mesh.point(v[1]), &p2 = mesh.point(v[2]), &p3 = mesh.point(v[3]);
    double longest = 0;
    for (const auto& [x, y] : {std::pair{p0, p1}, {p0, p2}, {p0, p3}, {p1, p2}, {p1, p3}, {p2, p3}})
      longest = std::max(longest, norm(y - x));
    if (std::fabs(dot(p1 - p0, cross(p2 - p0, p3 - p0))) < kFlatVolume * longest * longest * longest) return Mesh3::kNone;
  }
  const Vec3 midpoint = metric_midpoint3(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b));
  if (midpoint == mesh.point(a) || midpoint == mesh.point(b)) return Mesh3::kNone;
  // The rounded midpoint lies off the line ab by up to an ulp; where ab is an edge of a nearly
  // flat tetrahedron (two boundary facets coplanar up to rounding) one of its halves can then be
  // negative. The points one ulp away in each coordinate are tried next: the first whose halves
  // are all positive (exact orient3d) is m.
  const auto all_positive = [&](const Vec3& p) {
    for (const std::uint32_t t : shell) {
      const auto v = mesh.tetrahedron(t);
      if (!positive(mesh, substitute(v, b, kProbe), kProbe, p) || !positive(mesh, substitute(v, a, kProbe), kProbe, p))
        return false;
    }
    return true;
  };
  Vec3 pm = midpoint;
  if (support != nullptr) {
    // On the support or not at all: a chord point would leave the wall there for good, while the
    // operators between two passes may free the support's point (a sliver at the wall removed).
    const Vec3 on_surface = support->project(midpoint).surface;
    if (on_surface == mesh.point(a) || on_surface == mesh.point(b) || !all_positive(on_surface)) return Mesh3::kNone;
    pm = on_surface;
  }
  if (!all_positive(pm)) {
    bool found = false;
    for (int k = 1; k < 27 && !found; ++k) {
      const auto nudge = [](double x, int step) {
        return step == 0 ? x : std::nextafter(x, step > 0 ? HUGE_VAL : -HUGE_VAL);
      };
      const Vec3 p{nudge(midpoint.x, k % 3 - 1), nudge(midpoint.y, k / 3 % 3 - 1), nudge(midpoint.z, k / 9 - 1)};
      if (p == midpoint || p == mesh.point(a) || p == mesh.point(b)) continue;
      if (all_positive(p)) pm = p, found = true;
    }
    if (!found) return Mesh3::kNone;
  }
  const Metric3 mm = field ? field(pm) : interpolate(mesh.metric(a), mesh.metric(b), 0.5);
  // The constrained facets (a, b, c) of the shell, by their third vertex c.
  std::vector<std::pair<std::uint32_t, int>> facets;  // third vertex, reference
  std::vector<std::uint32_t> domain_old;
  std::vector<NewTetrahedron> fresh;
  double after = 0.0;
  for (const std::uint32_t t : shell) {
    const auto v = mesh.tetrahedron(t);
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t c = v[i];
      if (c == a || c == b) continue;
      const std::uint32_t h = Mesh3::facet(t, i);
      // Facet opposite c holds a, b and the fourth vertex d.
      if (!mesh.is_constrained(h)) continue;
      std::uint32_t d = Mesh3::kNone;
      for (std::uint32_t j = 0; j < 4; ++j)
        if (v[j] != a && v[j] != b && v[j] != c) d = v[j];
      if (std::find_if(facets.begin(), facets.end(), [&](const auto& f) { return f.first == d; }) == facets.end())
        facets.emplace_back(d, mesh.facet_ref(h));
    }
    const auto h1 = substitute(v, b, kProbe), h2 = substitute(v, a, kProbe);
    if (mesh.in_domain(t)) {
      domain_old.push_back(t);
      for (const auto w : v)
        if (w != a && w != b &&
            dtlab::edge_length(pm, mm, mesh.point(w), mesh.metric(w)) < options.short_length)
          return Mesh3::kNone;
      auto q = [&](const std::array<std::uint32_t, 4>& n) {
        auto p = [&](std::uint32_t w) { return w == kProbe ? pm : mesh.point(w); };
        auto g = [&](std::uint32_t w) { return w == kProbe ? mm : mesh.metric(w); };
        return quality_in(p(n[0]), p(n[1]), p(n[2]), p(n[3]), g(n[0]), g(n[1]), g(n[2]), g(n[3]));
      };
      after = std::max({after, q(h1), q(h2)});
    }
  }
  // Longest-edge bisection (Rivara): ab is split only where it is the longest edge of each
  // constrained facet beside it, so that no facet is cut across its shorter sides into needles
  // (boundary_split_pass3 comes back to ab once the longer edge is split).
  const double ab = length_of(mesh, a, b);
  for (const auto& [d, ref] : facets)
    if (d != Mesh3::kInfinite && std::max(length_of(mesh, a, d), length_of(mesh, b, d)) > ab) return Mesh3::kNone;
  if (!domain_old.empty() && after > std::max(worst_quality(mesh, domain_old), options.quality_limit))
    return Mesh3::kNone;
  const std::uint32_t m = mesh.add_vertex(pm, mm, static_cast<std::uint8_t>(Mesh3::kOnBoundary | Mesh3::kFixed));
  for (const std::uint32_t t : shell) {
    const auto v = mesh.tetrahedron(t);
    fresh.push_back({substitute(v, b, m), mesh.ref(t)});
    fresh.push_back({substitute(v, a, m), mesh.ref(t)});
  }
  std::vector<std::uint32_t> slots;
  replace_tetrahedra(mesh, shell, fresh, slots);
  // The halves of each constrained facet keep its reference (replace_tetrahedra left the facets
  // shared by two new tetrahedra unconstrained).
  for (const std::uint32_t t : slots) {
    const auto v = mesh.tetrahedron(t);
    for (std::uint32_t i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> f{};
      int n = 0;
      for (std::uint32_t j = 0; j < 4; ++j)
        if (j != i) f[n++] = v[j];
      if (std::find(f.begin(), f.end(), m) == f.end()) continue;
      const bool has_a = std::find(f.begin(), f.end(), a) != f.end(), has_b = std::find(f.begin(), f.end(), b) != f.end();
      if (has_a == has_b) continue;
      const std::uint32_t c = f[0] != m && f[0] != a && f[0] != b ? f[0] : f[1] != m && f[1] != a && f[1] != b ? f[1] : f[2];
      for (const auto& [third, ref] : facets)
        if (third == c) mesh.set_facet_both(Mesh3::facet(t, i), true, ref);
    }
  }
  mesh.set_constrained_edge(a, b, false);
  mesh.set_constrained_edge(a, m, true);
  mesh.set_constrained_edge(m, b, true);
  for (const auto& f : facets)
    if (f.first != Mesh3::kInfinite) mesh.set_constrained_edge(m, f.first, true);
  return m;
}

std::uint64_t long_constrained_edges(const Mesh3& mesh, double long_length) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const auto v = mesh.tetrahedron(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto [a, b] = std::minmax(v[i], v[j]);
        if (mesh.is_constrained_edge(a, b) && length_of(mesh, a, b) > long_length) edges.emplace_back(a, b);
      }
  }
  std::sort(edges.begin(), edges.end());
  return static_cast<std::uint64_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
}

std::uint64_t boundary_split_pass3(Mesh3& mesh, const MetricField3& field, const Split3Options& options,
                                   const SurfaceSupport3* support) {
  using Item = std::tuple<double, std::uint32_t, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::less<>> queue;
  auto consider = [&](std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    if (!mesh.is_constrained_edge(a, b)) return;
    const double l = length_of(mesh, a, b);
    if (l > options.long_length) queue.emplace(l, a, b);
  };
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const auto v = mesh.tetrahedron(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) consider(v[i], v[j]);
  }
  std::uint64_t splits = 0;
  std::vector<std::uint32_t> ball;
  while (!queue.empty()) {  // bounded: each split adds a vertex, max_vertices stops it
    const auto [l, a, b] = queue.top();
    queue.pop();
    if (mesh.live_vertex_count() >= options.max_vertices) break;
    if (mesh.is_dead_vertex(a) || mesh.is_dead_vertex(b) || !mesh.is_constrained_edge(a, b) || length_of(mesh, a, b) != l)
      continue;
    const std::uint32_t m = try_boundary_split3(mesh, a, b, field, options, support);
    if (m == Mesh3::kNone) continue;
    ++splits;
    // The halves, the edges that cut the facets of ab (m to each facet's third vertex), and the
    // facets' other edges (refused before while ab, longer, was not split).
    mesh.ball(m, ball);
    for (const std::uint32_t t : ball) {
      const auto v = mesh.tetrahedron(t);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (v[i] != Mesh3::kInfinite && v[j] != Mesh3::kInfinite) consider(v[i], v[j]);
    }
  }
  return splits;
}

}  // namespace dtlab

