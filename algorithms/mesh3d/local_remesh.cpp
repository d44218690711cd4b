#include "algorithms/mesh3d/local_remesh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "algorithms/mesh3d/control_space.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "algorithms/optimize3d/local.hpp"
#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "mesh/edge_key.hpp"

namespace dtlab {

namespace {

using optimize3d_detail::NewTetrahedron;

constexpr double kRadians = 0.017453292519943295769;  // pi / 180
constexpr std::array<std::array<std::uint32_t, 2>, 6> kEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// The smallest and largest dihedral angles (as cosines), the worst Q_K and the longest edge
// inside the region (not on its surface), in the metric, of a set of tetrahedra.
struct Measure {
  double smallest_cos = -1.0, largest_cos = 1.0, worst = 0.0, longest = 0.0;
  // `ids`: the vertices (Mesh3::kNone for one not in the mesh yet); `surface_edges` the keys of
  // the region's surface edges.
  void add(const std::array<std::uint32_t, 4>& ids, const std::array<const Vec3*, 4>& p,
           const std::array<const Metric3*, 4>& m, double q, const std::map<std::uint64_t, std::uint32_t>& surface_edges) {
    const auto r = dihedral_cosine_range(*p[0], *p[1], *p[2], *p[3]);
    smallest_cos = std::max(smallest_cos, r[1]);
    largest_cos = std::min(largest_cos, r[0]);
    worst = std::max(worst, q);
    for (const auto& e : kEdges) {
      const std::uint32_t a = ids[e[0]], b = ids[e[1]];
      if (a != Mesh3::kNone && b != Mesh3::kNone && surface_edges.count(edge_key(a, b))) continue;
      longest = std::max(longest, edge_length(*p[e[0]], *m[e[0]], *p[e[1]], *m[e[1]]));
    }
  }
};

// A region cut out of the mesh: its tetrahedra (sorted slots), its boundary surface (mesh vertex
// ids in local order, triangles in local ids, each oriented with the region on its positive
// side) and the vertices inside it.
struct Region {
  std::vector<std::uint32_t> tetrahedra;
  std::vector<std::uint32_t> surface_vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> interior_vertices;
  std::map<std::uint64_t, std::uint32_t> surface_edges;  // key (edge_key of mesh ids) -> triangles on it
};

bool holds(const std::vector<std::uint32_t>& sorted, std::uint32_t x) {
  return std::binary_search(sorted.begin(), sorted.end(), x);
}

// The domain tetrahedra of t's reference within `rings` vertex rings of t. False when the region
// is too large or may not be replaced: a constrained facet or edge inside it, a fixed or boundary
// vertex inside it, or a boundary surface that is not one closed sphere-like sheet (every edge on
// two triangles, connected, V - E + F = 2).
bool cut_region(const Mesh3& mesh, std::uint32_t t, std::uint32_t rings, std::uint32_t max_tetrahedra, Region& r) {
  const int ref = mesh.ref(t);
  const auto tv = mesh.tetrahedron(t);
  std::vector<std::uint32_t> vertices(tv.begin(), tv.end()), ball;
  r = Region{};
  for (std::uint32_t ring = 0; ring < rings; ++ring) {
    r.tetrahedra.clear();
    for (const std::uint32_t v : vertices) {
      mesh.ball(v, ball);
      for (const std::uint32_t u : ball)
        if (mesh.in_domain(u) && mesh.ref(u) == ref) r.tetrahedra.push_back(u);
    }
    std::sort(r.tetrahedra.begin(), r.tetrahedra.end());
    r.tetrahedra.erase(std::unique(r.tetrahedra.begin(), r.tetrahedra.end()), r.tetrahedra.end());
    if (r.tetrahedra.size() > max_tetrahedra) return false;
    vertices.clear();
    for (const std::uint32_t u : r.tetrahedra)
      for (const std::uint32_t w : mesh.tetrahedron(u)) vertices.push_back(w);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  }
  // The boundary surface, local ids in order of first appearance.
  std::map<std::uint32_t, std::uint32_t> local;
  std::map<std::uint64_t, std::uint32_t>& edge_uses = r.surface_edges;
  for (const std::uint32_t u : r.tetrahedra) {
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(u, i);
      if (holds(r.tetrahedra, Mesh3::tetrahedron_of(mesh.twin(h)))) {
        if (mesh.is_constrained(h)) return false;
        continue;
      }
      // (f0, f1, f2, apex) is positive: the region lies on the facet's positive side.
      const auto f = mesh.facet_vertices(h);
      std::array<std::uint32_t, 3> tri;
      for (std::uint32_t k = 0; k < 3; ++k) {
        const auto [it, fresh] = local.emplace(f[k], static_cast<std::uint32_t>(r.surface_vertices.size()));
        if (fresh) r.surface_vertices.push_back(f[k]);
        tri[k] = it->second;
      }
      r.triangles.push_back(tri);
      for (std::uint32_t k = 0; k < 3; ++k) ++edge_uses[edge_key(f[k], f[(k + 1) % 3])];
    }
  }
  for (const auto& [key, uses] : edge_uses)
    if (uses != 2) return false;
  const auto euler = static_cast<long long>(r.surface_vertices.size()) - static_cast<long long>(edge_uses.size()) +
                     static_cast<long long>(r.triangles.size());
  if (euler != 2) return false;
  // Connected: the triangles reached from the first one across edges.
  {
    std::map<std::uint64_t, std::vector<std::uint32_t>> by_edge;
    for (std::uint32_t k = 0; k < r.triangles.size(); ++k)
      for (std::uint32_t e = 0; e < 3; ++e) by_edge[edge_key(r.triangles[k][e], r.triangles[k][(e + 1) % 3])].push_back(k);
    std::vector<std::uint8_t> seen(r.triangles.size(), 0);
    std::vector<std::uint32_t> stack{0};
    seen[0] = 1;
    std::size_t reached = 1;
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      for (std::uint32_t e = 0; e < 3; ++e)
        for (const std::uint32_t m : by_edge[edge_key(r.triangles[k][e], r.triangles[k][(e + 1) % 3])])
          if (!seen[m]) seen[m] = 1, ++reached, stack.push_back(m);
    }
    if (reached != r.triangles.size()) return false;
  }
  for (const std::uint32_t v : vertices) {
    if (local.count(v)) continue;
    if ((mesh.flags(v) & (Mesh3::kFixed | Mesh3::kOnBoundary)) != 0) return false;
    r.interior_vertices.push_back(v);
  }
  // An edge through the region's inside (not on its surface) must not be constrained.
  for (const std::uint32_t u : r.tetrahedra) {
    const auto w = mesh.tetrahedron(u);
    for (const auto& e : kEdges)
      if (!edge_uses.count(edge_key(w[e[0]], w[e[1]])) && mesh.is_constrained_edge(w[e[0]], w[e[1]])) return false;
  }
  return true;
}

// Meshes the region again and puts the result in its place when the criterion holds.
bool remesh_region(Mesh3& mesh, const Region& r, const MetricField3& field, const LocalRemesh3Options& options,
                   LocalRemesh3Stats& stats) {
  // A surface much coarser than the metric (the generator keeps it as it is) is left alone: its
  // region cannot come back well shaped at the metric's sizes, and trying costs the most there.
  for (const auto& [key, uses] : r.surface_edges) {
    const std::uint32_t a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    if (edge_length(mesh.point(a), mesh.metric(a), mesh.point(b), mesh.metric(b)) > options.coarse_surface_length)
      return false;
  }
  std::vector<Vec3> points;
  points.reserve(r.surface_vertices.size());
  for (const std::uint32_t v : r.surface_vertices) points.push_back(mesh.point(v));
  Mesh3dInput input;
  input.points = points;
  input.triangles = r.triangles;
  // The control space inside: the old region as background, each vertex with its metric
  // intersected with the classical size (§7.4) — at a surface vertex the mean length of its
  // surface edges, inside the mean of those — so that a region never comes back coarser than
  // the metric asks, nor, where the surface's triangles are smaller, coarser than they are.
  MeshData3 background;
  std::map<std::uint32_t, std::uint32_t> background_id;
  std::vector<Metric3> outer_metrics, inner_metrics;
  const auto add_background_vertex = [&](std::uint32_t v) {
    background_id.emplace(v, static_cast<std::uint32_t>(background.vertices.size()));
    background.vertices.push_back(mesh.point(v));
    background.vertex_refs.push_back(0);
    outer_metrics.push_back(mesh.metric(v));
  };
  for (const std::uint32_t v : r.surface_vertices) add_background_vertex(v);
  for (const std::uint32_t v : r.interior_vertices) add_background_vertex(v);
  {
    std::vector<double> size(r.surface_vertices.size(), 0.0);
    std::vector<std::uint32_t> count(r.surface_vertices.size(), 0);
    for (const auto& t : r.triangles)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3];
        const double l = norm(points[b] - points[a]);
        size[a] += l, size[b] += l;  // (each edge on two triangles: counted twice, evenly)
        ++count[a], ++count[b];
      }
    double mean = 0.0;
    for (std::uint32_t k = 0; k < size.size(); ++k) mean += (size[k] /= count[k]) / static_cast<double>(size.size());
    for (std::uint32_t k = 0; k < outer_metrics.size(); ++k)
      inner_metrics.push_back(intersect(outer_metrics[k], Metric3::isotropic(k < size.size() ? size[k] : mean)));
  }
  for (const std::uint32_t u : r.tetrahedra) {
    const auto w = mesh.tetrahedron(u);
    background.tetrahedra.push_back({background_id[w[0]], background_id[w[1]], background_id[w[2]], background_id[w[3]]});
    background.tetrahedron_refs.push_back(0);
  }
  const ControlSpace3 inner(background, inner_metrics);
  // The old metrics interpolated, for new vertices when there is no field.
  std::optional<ControlSpace3> outer;
  if (!field) outer.emplace(background, std::move(outer_metrics));
  Mesh3dOptions mesher;
  mesher.control = &inner;
  mesher.max_vertices = 1000 + 100 * points.size();
  mesher.local_remesh = false;  // (one level: a region's own small angles stay)
  mesher.keep_boundary = true;  // the region's surface is the mesh around it
  mesher.max_elements = kNoElementLimit;  // bounded by max_vertices above
  // A region whose surface needs a Steiner point is left as it is (checked below): the recovery
  // stops at the first one instead of spending up to 200 per point on a result that is refused
  // (a surface cut in the size is coplanar only to within its cut points' rounding, and its
  // recovery can need thousands).
  mesher.steiner_limit_factor = 0;
  ++stats.tried;
  stats.work += r.tetrahedra.size();
  Mesh3dResult result;
  try {
    result = mesh3d(input, mesher);
  } catch (const InputError&) {
    return false;  // (a surface the generator refuses: the region stays as it is)
  }
  if (result.stats.steiner_points != 0 || result.output.triangles.size() != r.triangles.size()) return false;
  // Output vertices: the surface's (by their exact coordinates), then new ones, which take their
  // metric from `field`, or else interpolated from the old region's.
  using Key = std::array<std::uint64_t, 3>;
  std::map<Key, std::uint32_t> surface;
  for (std::uint32_t k = 0; k < points.size(); ++k)
    surface.emplace(Key{std::bit_cast<std::uint64_t>(points[k].x), std::bit_cast<std::uint64_t>(points[k].y),
                        std::bit_cast<std::uint64_t>(points[k].z)},
                    r.surface_vertices[k]);
  const MeshData3& out = result.output;
  constexpr std::uint32_t kNew = Mesh3::kNone;
  std::vector<std::uint32_t> id(out.vertices.size(), kNew);
  std::size_t matched = 0;
  std::vector<Metric3> metric(out.vertices.size());
  std::uint32_t hint = ControlSpace3::kNoHint;
  for (std::uint32_t k = 0; k < out.vertices.size(); ++k) {
    const Vec3& p = out.vertices[k];
    const auto it = surface.find(Key{std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y),
                                     std::bit_cast<std::uint64_t>(p.z)});
    if (it != surface.end()) {
      id[k] = it->second, ++matched;
      metric[k] = mesh.metric(it->second);
    } else {
      metric[k] = field ? field(p) : outer->metric_at(p, hint);
    }
  }
  if (matched != points.size()) return false;
  // The boundary triangles must come back unchanged.
  auto sorted3 = [](std::array<std::uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<std::array<std::uint32_t, 3>> before, after;
  for (const auto& t : r.triangles)
    before.push_back(sorted3({r.surface_vertices[t[0]], r.surface_vertices[t[1]], r.surface_vertices[t[2]]}));
  for (const auto& t : out.triangles) {
    if (id[t[0]] == kNew || id[t[1]] == kNew || id[t[2]] == kNew) return false;
    after.push_back(sorted3({id[t[0]], id[t[1]], id[t[2]]}));
  }
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  if (before != after) return false;
  // The criterion, on the old region and on the new tetrahedra (each positive, exactly).
  Measure old_measure, new_measure;
  for (const std::uint32_t u : r.tetrahedra) {
    const auto w = mesh.tetrahedron(u);
    old_measure.add(w, {&mesh.point(w[0]), &mesh.point(w[1]), &mesh.point(w[2]), &mesh.point(w[3])},
                    {&mesh.metric(w[0]), &mesh.metric(w[1]), &mesh.metric(w[2]), &mesh.metric(w[3])},
                    optimize3d_detail::tetrahedron_quality(mesh, u), r.surface_edges);
  }
  for (const auto& t : out.tetrahedra) {
    const Vec3 &a = out.vertices[t[0]], &b = out.vertices[t[1]], &c = out.vertices[t[2]], &d = out.vertices[t[3]];
    if (orient3d(a, b, c, d) != Sign::Positive) return false;
    new_measure.add({id[t[0]], id[t[1]], id[t[2]], id[t[3]]}, {&a, &b, &c, &d},
                    {&metric[t[0]], &metric[t[1]], &metric[t[2]], &metric[t[3]]},
                    optimize3d_detail::positive_quality_in(a, b, c, d, metric[t[0]], metric[t[1]], metric[t[2]],
                                                           metric[t[3]]),
                    r.surface_edges);
  }
  constexpr double kMargin = 1e-9;
  if (!(new_measure.smallest_cos < old_measure.smallest_cos - kMargin &&
        new_measure.worst <= std::max(old_measure.worst, options.quality_limit) &&
        new_measure.largest_cos >= std::min(old_measure.largest_cos, std::cos(options.max_dihedral_deg * kRadians)) &&
        new_measure.longest <= std::max(old_measure.longest, kLongEdgeLength)))
    return false;
  // In its place: the new vertices, the new tetrahedra, the old inside vertices removed.
  for (std::uint32_t k = 0; k < out.vertices.size(); ++k) {
    if (id[k] != kNew) continue;
    id[k] = mesh.add_vertex(out.vertices[k], metric[k], 0);
    ++stats.vertices_added;
  }
  const int ref = mesh.ref(r.tetrahedra.front());
  std::vector<NewTetrahedron> fresh;
  fresh.reserve(out.tetrahedra.size());
  for (const auto& t : out.tetrahedra) fresh.push_back({{id[t[0]], id[t[1]], id[t[2]], id[t[3]]}, ref});
  std::vector<std::uint32_t> slots;
  optimize3d_detail::replace_tetrahedra(mesh, r.tetrahedra, fresh, slots);
  for (const std::uint32_t v : r.interior_vertices) mesh.remove_vertex(v);
  stats.vertices_removed += r.interior_vertices.size();
  for (const NewTetrahedron& n : fresh)
    for (const std::uint32_t v : n.v) mesh.touch(v);
  ++stats.remeshed;
  return true;
}

}  // namespace

LocalRemesh3Stats remesh_small_angles(Mesh3& mesh, const MetricField3& field, const LocalRemesh3Options& options) {
  LocalRemesh3Stats stats;
  const double cos_below = std::cos(options.below_deg * kRadians);
  auto smallest_cos = [&](std::uint32_t t) {
    const auto v = mesh.tetrahedron(t);
    return dihedral_cosine_range(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]))[1];
  };
  std::vector<std::pair<double, std::uint32_t>> small;
  Region region;
  std::uint64_t domain = 0;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) domain += mesh.in_domain(t);
  const double bound = options.work_factor * static_cast<double>(domain) + options.work_floor;
  for (std::uint32_t pass = 0; pass < options.passes && !stats.work_bound_reached; ++pass) {
    small.clear();
    for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const double c = smallest_cos(t);
      if (c > cos_below) small.emplace_back(-c, t);  // smallest angle first
    }
    std::sort(small.begin(), small.end());
    std::uint64_t changed = 0;
    for (const auto& [key, t] : small) {
      if (stats.work_bound_reached) break;
      // Changed by an earlier region (its slot reused, or it is gone): judged again if still small.
      if (!mesh.in_domain(t) || !(smallest_cos(t) > cos_below)) continue;
      for (std::uint32_t rings = 1; rings <= options.max_rings && !stats.work_bound_reached; ++rings) {
        if (static_cast<double>(stats.work) >= bound) {
          stats.work_bound_reached = true;
          break;
        }
        if (!cut_region(mesh, t, rings, options.max_region_tetrahedra, region)) continue;
        if (remesh_region(mesh, region, field, options, stats)) {
          ++changed;
          break;
        }
      }
    }
    if (changed == 0) break;
  }
  return stats;
}

}  // namespace dtlab
