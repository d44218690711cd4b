// Complete reconstruction in 2D (reconstruct2d.hpp): the previous mesh's boundary as segments,
// its regions and holes as seeds, then mesh2d with the boundary cut anew in the metric.
#include "algorithms/adapt/reconstruct2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <utility>

#include "algorithms/adapt/boundary_curve2.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/mesh2_from_data.hpp"

namespace dtlab {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
Edge key(std::uint32_t a, std::uint32_t b) { return std::minmax(a, b); }

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// The previous mesh as a Mesh2 whose constrained edges are the boundary, its listed edges and the
// interfaces between references, corners marked; then its domain renumbered.
MeshData2 constrained_domain(const MeshData2& previous, double ridge_angle, std::vector<bool>& corner) {
  Mesh2 mesh = mesh2_from_data(previous);
  for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i), u = Mesh2::triangle_of(mesh.twin(h));
      if (!mesh.is_constrained(h) && mesh.in_domain(u) && mesh.ref(u) != mesh.ref(t)) mesh.set_constraint_both(h, true, 0);
    }
  }
  mark_boundary_corners(mesh, ridge_angle);
  std::vector<std::uint32_t> ids;
  MeshData2 d = mesh.domain(&ids);
  corner.assign(d.vertices.size(), false);
  for (std::size_t v = 0; v < d.vertices.size(); ++v) corner[v] = (mesh.flags(ids[v]) & Mesh2::kFixed) != 0;
  return d;
}

struct Segments {
  std::vector<std::array<std::uint32_t, 2>> ends;  // in the domain's numbering
  std::vector<int> refs;
  std::uint64_t merged = 0;
};

// The constrained edges as chains between corners; an exactly collinear chain of more than one
// edge becomes one segment.
Segments chains(const MeshData2& d, std::vector<bool> corner) {
  std::vector<std::vector<std::uint32_t>> incident(d.vertices.size());
  for (std::uint32_t e = 0; e < d.edges.size(); ++e) {
    incident[d.edges[e][0]].push_back(e);
    incident[d.edges[e][1]].push_back(e);
  }
  for (std::size_t v = 0; v < incident.size(); ++v)
    if (!incident[v].empty() && incident[v].size() != 2) corner[v] = true;
  Segments out;
  std::vector<bool> done(d.edges.size(), false);
  auto walk = [&](std::uint32_t start, std::uint32_t first_edge) {
    std::vector<std::uint32_t> vertices{start}, edges;
    std::uint32_t v = start, e = first_edge;
    for (std::size_t step = 0; step <= d.edges.size(); ++step) {
      done[e] = true;
      edges.push_back(e);
      v = d.edges[e][0] == v ? d.edges[e][1] : d.edges[e][0];
      vertices.push_back(v);
      if (corner[v] || v == start) break;
      const std::uint32_t next = incident[v][0] == e ? incident[v][1] : incident[v][0];
      if (done[next] || d.edge_refs[next] != d.edge_refs[first_edge]) break;
      e = next;
    }
    bool straight = edges.size() > 1 && vertices.front() != vertices.back();
    for (std::size_t k = 1; straight && k + 1 < vertices.size(); ++k) {
      straight = orient2d(d.vertices[vertices.front()], d.vertices[vertices.back()], d.vertices[vertices[k]]) == Sign::Zero;
    }
    if (straight) {
      out.ends.push_back({vertices.front(), vertices.back()});
      out.refs.push_back(d.edge_refs[first_edge]);
      ++out.merged;
      return;
    }
    for (const std::uint32_t x : edges) {
      out.ends.push_back(d.edges[x]);
      out.refs.push_back(d.edge_refs[x]);
    }
  };
  for (std::uint32_t v = 0; v < incident.size(); ++v) {
    if (!corner[v]) continue;
    for (const std::uint32_t e : incident[v])
      if (!done[e]) walk(v, e);
  }
  for (std::uint32_t e = 0; e < d.edges.size(); ++e)  // closed loops without a corner
    if (!done[e]) walk(d.edges[e][0], e);
  return out;
}

// One seed per connected set of triangles (across edges that are not constrained): the centroid
// of its largest triangle, with its reference.
std::vector<RegionSeed2> region_seeds(const MeshData2& d) {
  std::map<Edge, std::uint32_t> constrained;
  for (const auto& e : d.edges) constrained.emplace(key(e[0], e[1]), 0);
  std::vector<std::uint32_t> parent(d.triangles.size());
  std::iota(parent.begin(), parent.end(), 0u);
  std::map<Edge, std::uint32_t> first_triangle;
  for (std::uint32_t t = 0; t < d.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const Edge k = key(d.triangles[t][i], d.triangles[t][(i + 1) % 3]);
      if (constrained.count(k)) continue;
      const auto [it, fresh] = first_triangle.emplace(k, t);
      if (!fresh) parent[find(parent, t)] = find(parent, it->second);
    }
  }
  std::map<std::uint32_t, std::pair<double, std::uint32_t>> largest;  // root -> (area, triangle)
  for (std::uint32_t t = 0; t < d.triangles.size(); ++t) {
    const auto& v = d.triangles[t];
    const double area = cross(d.vertices[v[1]] - d.vertices[v[0]], d.vertices[v[2]] - d.vertices[v[0]]);
    auto& best = largest.try_emplace(find(parent, t), area, t).first->second;
    if (area > best.first) best = {area, t};
  }
  std::vector<RegionSeed2> seeds;
  for (const auto& [root, best] : largest) {
    const auto& v = d.triangles[best.second];
    const Vec2 c = (1.0 / 3.0) * (d.vertices[v[0]] + d.vertices[v[1]] + d.vertices[v[2]]);
    seeds.push_back({c, d.triangle_refs[best.second]});
  }
  return seeds;
}

// One point per boundary loop just outside it: beside its longest edge, on the exterior side,
// in no triangle (a hole's seed; the outer loop's lies in the exterior, which goes anyway).
std::vector<Vec2> hole_seeds(const MeshData2& d) {
  std::map<Edge, int> uses;
  for (const auto& t : d.triangles)
    for (int i = 0; i < 3; ++i) ++uses[key(t[i], t[(i + 1) % 3])];
  std::vector<std::array<std::uint32_t, 2>> boundary;  // oriented with the domain on the left
  for (const auto& t : d.triangles)
    for (int i = 0; i < 3; ++i)
      if (uses[key(t[i], t[(i + 1) % 3])] == 1) boundary.push_back({t[i], t[(i + 1) % 3]});
  std::vector<std::uint32_t> parent(d.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& e : boundary) parent[find(parent, e[0])] = find(parent, e[1]);
  std::map<std::uint32_t, std::pair<double, std::size_t>> longest;  // loop root -> (length, edge)
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const double l = norm(d.vertices[boundary[k][1]] - d.vertices[boundary[k][0]]);
    auto& best = longest.try_emplace(find(parent, boundary[k][0]), l, k).first->second;
    if (l > best.first) best = {l, k};
  }
  const ElementGrid<Vec2> grid(std::span<const Vec2>(d.vertices), std::span<const std::array<std::uint32_t, 3>>(d.triangles));
  auto inside_some_triangle = [&](const Vec2& p) {
    for (const std::uint32_t t : grid.candidates(p)) {
      const auto& v = d.triangles[t];
      if (closed_triangle_holds(d.vertices[v[0]], d.vertices[v[1]], d.vertices[v[2]], p)) return true;
    }
    return false;
  };
  std::vector<Vec2> seeds;
  for (const auto& [root, best] : longest) {
    const Vec2 &a = d.vertices[boundary[best.second][0]], &b = d.vertices[boundary[best.second][1]];
    const Vec2 mid = 0.5 * (a + b), along = b - a;
    const Vec2 right{along.y, -along.x};  // the exterior side, |right| = |ab|
    bool placed = false;
    for (double f = 1e-3; f > 1e-9 && !placed; f *= 0.125) {
      const Vec2 p = mid + f * right;
      if (orient2d(a, b, p) == Sign::Negative && !inside_some_triangle(p)) {
        seeds.push_back(p);
        placed = true;
      }
    }
    if (!placed) {
      throw InputError("reconstruct2d: no point outside the mesh found beside boundary edge (" +
                       std::to_string(boundary[best.second][0] + 1) + ", " + std::to_string(boundary[best.second][1] + 1) +
                       "): the boundary loop's exterior cannot be seeded");
    }
  }
  return seeds;
}

}  // namespace

Reconstruct2dResult reconstruct2d(const MeshData2& previous, const ControlSpace2& control,
                                  const Reconstruct2dOptions& options) {
  Reconstruct2dResult result;
  std::vector<bool> corner;
  const MeshData2 d = constrained_domain(previous, options.ridge_angle, corner);
  const Segments s = chains(d, corner);
  // Only the segments' vertices go to the mesher (the interior ones are the old mesh's).
  std::vector<std::uint32_t> number(d.vertices.size(), UINT32_MAX);
  std::vector<Vec2> points;
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (const auto& e : s.ends) {
    std::array<std::uint32_t, 2> n{};
    for (int k = 0; k < 2; ++k) {
      if (number[e[k]] == UINT32_MAX) {
        number[e[k]] = static_cast<std::uint32_t>(points.size());
        points.push_back(d.vertices[e[k]]);
      }
      n[k] = number[e[k]];
    }
    segments.push_back(n);
  }
  const std::vector<RegionSeed2> regions = region_seeds(d);
  const std::vector<Vec2> holes = hole_seeds(d);
  Mesh2dInput input{.points = points, .segments = segments, .segment_markers = s.refs, .holes = holes, .regions = regions};
  Mesh2dOptions o;
  o.method = options.method;
  o.control = &control;
  o.interpolation = options.interpolation;
  o.interrupt = options.interrupt;
  o.max_elements = options.max_elements;
  result.generated = mesh2d(input, o);
  result.segments = segments.size();
  result.merged_chains = s.merged;
  result.region_seeds = regions.size();
  result.hole_seeds = holes.size();
  return result;
}

}  // namespace dtlab
