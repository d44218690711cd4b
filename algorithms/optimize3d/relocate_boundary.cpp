// Boundary vertex relocation on the geometric support (relocate_boundary.hpp): the §8.4
// relaxation toward a target, the target taken in the vertex's tangent plane and every candidate
// put back on the support, so that a curved wall stays on its curve while its vertices move.
#include "algorithms/optimize3d/relocate_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/surface/surface_support3.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

constexpr double kRadians = 0.017453292519943295769;  // pi / 180

// A constrained facet at v: its two other vertices (a, b) and its normal, turned into the domain.
struct FanFacet {
  std::uint32_t a, b;
  Vec3 normal;
};

// What the relocation needs of v's surroundings: its whole ball, the domain part, the boundary
// fan and its tangent plane.
struct BoundaryStar {
  std::vector<std::uint32_t> ball, domain, ghosts;  // ghosts: v is a hull vertex
  std::vector<std::uint32_t> neighbours;            // v's neighbours in the domain, sorted
  std::vector<std::array<std::uint32_t, 3>> opposite;  // per finite ball tetrahedron: its facet opposite v
  std::vector<FanFacet> fan;
  Vec3 normal{0.0, 0.0, 0.0};  // unit
  double shortest = 0.0;       // the fan's shortest edge from v
};

// The facets of v's ball that hold v and are constrained, each once, oriented into the domain.
// False when one lies between two references or beside no domain tetrahedron on either side.
bool collect_fan(const Mesh3& mesh, std::uint32_t v, BoundaryStar& s) {
  s.fan.clear();
  int ref = 0;
  bool ref_set = false;
  for (const std::uint32_t t : s.ball) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t j = 0; j < 4; ++j) {
      if (mesh.vertex(t, j) == v) continue;
      const std::uint32_t h = Mesh3::facet(t, j);
      if (!mesh.is_constrained(h)) continue;
      if (ref_set && mesh.facet_ref(h) != ref) return false;
      ref = mesh.facet_ref(h), ref_set = true;
      const auto f = mesh.facet_vertices(h);  // (f0, f1, f2, apex) positive: the normal points into t
      const Vec3 n = cross(mesh.point(f[1]) - mesh.point(f[0]), mesh.point(f[2]) - mesh.point(f[0]));
      std::array<std::uint32_t, 2> ab{};
      int k = 0;
      for (const std::uint32_t w : f)
        if (w != v) ab[k++] = w;
      const bool seen = std::any_of(s.fan.begin(), s.fan.end(), [&](const FanFacet& g) {
        return (g.a == ab[0] && g.b == ab[1]) || (g.a == ab[1] && g.b == ab[0]);
      });
      if (seen) return false;  // the same facet from both sides: an internal interface, kept
      s.fan.push_back({ab[0], ab[1], n});
    }
  }
  return !s.fan.empty();
}

// Whether the fan is one closed disk around v whose adjacent facets turn by less than the ridge
// angle (v on no ridge nor corner); sets the unit normal and the shortest edge from v.
bool smooth_closed_fan(const Mesh3& mesh, std::uint32_t v, double ridge_angle_degrees, BoundaryStar& s) {
  const std::size_t n = s.fan.size();
  if (n < 3) return false;
  const double cos_ridge = std::cos(ridge_angle_degrees * kRadians);
  // Walk the fan from its first facet across the edges v-w: each w must be shared by exactly two
  // facets, and the walk must come back after visiting all n (one disk, not two touching at v).
  std::vector<std::uint8_t> used(n, 0);
  std::size_t current = 0;
  std::uint32_t next = s.fan[0].b;
  used[0] = 1;
  for (std::size_t step = 1; step < n; ++step) {
    std::size_t found = n;
    for (std::size_t k = 0; k < n; ++k) {
      if (k == current || (s.fan[k].a != next && s.fan[k].b != next)) continue;
      if (found != n || used[k]) return false;  // a third facet at edge v-next, or a cycle too short
      found = k;
    }
    if (found == n) return false;  // an open fan: v on the boundary of the surface
    const Vec3 &p = s.fan[current].normal, &q = s.fan[found].normal;
    if (dot(p, q) < cos_ridge * norm(p) * norm(q)) return false;
    used[found] = 1;
    current = found;
    next = s.fan[found].a == next ? s.fan[found].b : s.fan[found].a;
  }
  if (next != s.fan[0].a) return false;
  const Vec3 &p = s.fan[current].normal, &q = s.fan[0].normal;
  if (dot(p, q) < cos_ridge * norm(p) * norm(q)) return false;
  Vec3 sum{0.0, 0.0, 0.0};
  s.shortest = HUGE_VAL;
  for (const FanFacet& f : s.fan) {
    sum = sum + f.normal;
    s.shortest = std::min(s.shortest, norm(mesh.point(f.a) - mesh.point(v)));
  }
  const double length = norm(sum);
  if (!(length > 0.0)) return false;
  s.normal = (1.0 / length) * sum;
  return true;
}

double& coordinate(Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
double coordinate(const Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// The facet of t opposite v, in kFacetVertex order: (f0, f1, f2, v) is positive.
std::array<std::uint32_t, 3> facet_opposite(const Mesh3& mesh, std::uint32_t t, std::uint32_t v) {
  for (std::uint32_t i = 0; i < 4; ++i)
    if (mesh.vertex(t, i) == v) return mesh.facet_vertices(Mesh3::facet(t, i));
  return {Mesh3::kNone, Mesh3::kNone, Mesh3::kNone};
}

// Per support vertex: on a ridge or a corner. The support's patches at such a vertex take its
// one-sided normal (surface_support3.hpp) and lie off a curved wall by up to half a facet's turn
// (a cylinder of 24 facets a circle: 3.2e-3 measured, its facets' sagitta 2.1e-3), so no
// candidate is taken there.
std::vector<std::uint8_t> feature_vertices(const SurfaceSupport3& support) {
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < support.triangle_count(); ++t)
    for (const std::uint32_t w : support.triangle(t)) n = std::max(n, w + 1);
  std::vector<std::uint8_t> feature(n, 0);
  for (std::uint32_t t = 0; t < support.triangle_count(); ++t) {
    const auto& tv = support.triangle(t);
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (support.is_corner(tv[i])) feature[tv[i]] = 1;
      if (support.is_ridge(t, i)) feature[tv[i]] = feature[tv[(i + 1) % 3]] = 1;
    }
  }
  return feature;
}

// How many edges from a point p (metric m) to `neighbours` have metric length in the unit band.
std::size_t unit_edges_at(const Mesh3& mesh, std::span<const std::uint32_t> neighbours, const Vec3& p, const Metric3& m) {
  std::size_t n = 0;
  for (const std::uint32_t u : neighbours) {
    const double l = dtlab::edge_length(p, m, mesh.point(u), mesh.metric(u));
    n += l >= kShortEdgeLength && l <= kLongEdgeLength ? 1 : 0;
  }
  return n;
}

// Whether the hull stays convex with v at `moved`: no vertex of the ghosts at v, nor of the
// ghosts beside them (across the hull edges), strictly beyond a hull facet at v (a ghost
// (kInfinite, a, b, c) has orient3d(q, a, b, c) > 0 for q beyond its facet: tetrahedralization3.hpp).
// On the facet's plane is allowed: a flat face of the hull stays flat.
bool hull_stays_convex(const Mesh3& mesh, std::uint32_t v, const Vec3& moved, std::span<const std::uint32_t> ghosts) {
  const auto at = [&](std::uint32_t w) -> const Vec3& { return w == v ? moved : mesh.point(w); };
  for (const std::uint32_t g : ghosts) {
    const auto f = mesh.tetrahedron(g);  // (kInfinite, a, b, c)
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t n = i == 0 ? g : mesh.adjacent(g, i);
      for (const std::uint32_t x : mesh.tetrahedron(n)) {
        if (x == Mesh3::kInfinite || x == f[1] || x == f[2] || x == f[3]) continue;
        if (orient3d(at(x), at(f[1]), at(f[2]), at(f[3])) == Sign::Positive) return false;
      }
    }
  }
  return true;
}

bool relocate_on_support(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const SurfaceSupport3& support,
                         std::span<const std::uint8_t> feature, const BoundaryRelocate3Options& options,
                         BoundaryStar& s) {
  mesh.ball(v, s.ball);
  s.domain.clear();
  s.ghosts.clear();
  for (const std::uint32_t t : s.ball) {
    if (mesh.in_domain(t)) s.domain.push_back(t);
    if (mesh.is_ghost(t)) s.ghosts.push_back(t);
  }
  if (s.domain.empty() || !collect_fan(mesh, v, s) || !smooth_closed_fan(mesh, v, options.ridge_angle_degrees, s))
    return false;
  double before = 0.0;
  for (const std::uint32_t t : s.domain) before = std::max(before, tetrahedron_quality(mesh, t));
  const double bound = before * (1.0 - options.margin);
  const Vec3 p = mesh.point(v);
  const auto in_plane = [&](const Vec3& x) { return x - dot(x - p, s.normal) * s.normal; };
  Vec3 centroid{0.0, 0.0, 0.0};
  for (const FanFacet& f : s.fan) centroid = centroid + mesh.point(f.a);
  centroid = (1.0 / static_cast<double>(s.fan.size())) * centroid;
  const std::array<Vec3, 2> targets{in_plane(optimal_point(mesh, v, s.domain)), in_plane(centroid)};
  // A planar fan (every link vertex in the plane of its first facet, exactly) stays planar: the
  // coordinates v shares with its whole link are copied (a face x = c keeps x = c), and a
  // candidate is kept only in the plane of each facet, exactly (else a rotated face would get
  // vertices off it by a rounding, and flat tetrahedra with them).
  bool planar = true;
  std::array<bool, 3> shared{true, true, true};
  for (const FanFacet& f : s.fan) {
    planar = planar && orient3d(p, mesh.point(s.fan[0].a), mesh.point(s.fan[0].b), mesh.point(f.a)) == Sign::Zero;
    for (int axis = 0; axis < 3; ++axis) shared[axis] = shared[axis] && coordinate(mesh.point(f.a), axis) == coordinate(p, axis);
  }
  const auto in_face = [&](Vec3 x) {
    if (!planar) return std::optional<Vec3>{x};
    for (int axis = 0; axis < 3; ++axis)
      if (shared[axis]) coordinate(x, axis) = coordinate(p, axis);
    for (const FanFacet& f : s.fan)
      if (orient3d(p, mesh.point(f.a), mesh.point(f.b), x) != Sign::Zero) return std::optional<Vec3>{};
    return std::optional<Vec3>{x};
  };
  s.neighbours.clear();
  for (const std::uint32_t t : s.domain)
    for (const std::uint32_t u : mesh.tetrahedron(t))
      if (u != v) s.neighbours.push_back(u);
  std::sort(s.neighbours.begin(), s.neighbours.end());
  s.neighbours.erase(std::unique(s.neighbours.begin(), s.neighbours.end()), s.neighbours.end());
  const std::size_t unit_before = unit_edges_at(mesh, s.neighbours, p, mesh.metric(v));
  std::vector<std::array<std::uint32_t, 3>>& opposite = s.opposite;
  opposite.clear();
  for (const std::uint32_t t : s.ball)
    if (!mesh.is_ghost(t)) opposite.push_back(facet_opposite(mesh, t, v));
  for (const Vec3& target : targets) {
    if (!std::isfinite(target.x) || !std::isfinite(target.y) || !std::isfinite(target.z)) continue;
    double w = 1.0;
    for (std::uint32_t k = 0; k < options.tries; ++k, w *= 0.5) {
      const SurfaceSupport3::Foot foot = support.project((1.0 - w) * p + w * target);
      if (foot.triangle == SurfaceSupport3::kNone) continue;
      const auto& ft = support.triangle(foot.triangle);
      if (feature[ft[0]] || feature[ft[1]] || feature[ft[2]]) continue;
      const std::optional<Vec3> on_face = in_face(foot.surface);
      if (!on_face) continue;
      const Vec3 moved = *on_face;
      if (moved == p || !std::isfinite(moved.x) || !std::isfinite(moved.y) || !std::isfinite(moved.z)) continue;
      if (std::fabs(dot(moved - p, s.normal)) > 0.25 * s.shortest) continue;  // another sheet's point
      const Metric3 metric = field ? field(moved) : mesh.metric(v);
      bool ok = true;
      for (std::size_t i = 0, j = 0; i < s.ball.size() && ok; ++i) {
        if (mesh.is_ghost(s.ball[i])) continue;
        const auto& f = opposite[j++];
        if (mesh.in_domain(s.ball[i]) &&
            !(positive_quality_in(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), moved, mesh.metric(f[0]),
                                  mesh.metric(f[1]), mesh.metric(f[2]), metric) < bound))
          ok = false;
      }
      for (std::size_t i = 0; i < opposite.size() && ok; ++i) {
        const auto& f = opposite[i];
        ok = orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), moved) == Sign::Positive;
      }
      ok = ok && hull_stays_convex(mesh, v, moved, s.ghosts);
      if (!ok) continue;
      // Shapes without losing lengths: no fewer of v's edges with metric length in the unit band.
      if (options.keep_unit_edges && unit_edges_at(mesh, s.neighbours, moved, metric) < unit_before) continue;
      mesh.set_point(v, moved);
      mesh.set_metric(v, metric);
      for (const std::uint32_t t : s.ball)
        for (const std::uint32_t u : mesh.tetrahedron(t))
          if (u != Mesh3::kInfinite) mesh.touch(u);
      return true;
    }
  }
  return false;
}

}  // namespace

bool try_relocate_boundary3(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const SurfaceSupport3& support,
                            const BoundaryRelocate3Options& options) {
  if (v >= mesh.vertex_capacity() || mesh.is_dead_vertex(v) || (mesh.flags(v) & Mesh3::kOnBoundary) == 0) return false;
  BoundaryStar s;
  return relocate_on_support(mesh, v, field, support, feature_vertices(support), options, s);
}

std::uint64_t boundary_relocate_sweep3(Mesh3& mesh, const MetricField3& field, const SurfaceSupport3& support,
                                       const BoundaryRelocate3Options& options) {
  // Worst domain ball first (ties by vertex id), as relocate_sweep3.
  std::vector<double> worst(mesh.vertex_capacity(), 0.0);
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    const double q = tetrahedron_quality(mesh, t);
    for (const std::uint32_t w : mesh.tetrahedron(t)) worst[w] = std::max(worst[w], q);
  }
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_dead_vertex(v) && (mesh.flags(v) & Mesh3::kOnBoundary) != 0 && worst[v] > 0.0) order.emplace_back(worst[v], v);
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  BoundaryStar s;
  const std::vector<std::uint8_t> feature = feature_vertices(support);
  std::uint64_t moved = 0;
  for (const auto& entry : order) moved += relocate_on_support(mesh, entry.second, field, support, feature, options, s) ? 1 : 0;
  return moved;
}

}  // namespace dtlab
