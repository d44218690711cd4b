// Transfer of vertex fields between tetrahedral meshes (transfer.hpp, 3D part; book §9.8,
// §12.2.6): the same scheme as the 2D transfer (transfer.cpp), with Mesh3's walk, the bucket
// grid for walks lost through a concavity, and the nearest point on the old boundary triangles
// for vertices outside (a curved surface discretised differently).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>

#include "algorithms/adapt/transfer.hpp"
#include "algorithms/adapt/transfer_apply.hpp"
#include "algorithms/common/transfer_walk.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/mesh3.hpp"
#include "mesh/mesh3_from_data.hpp"

namespace dtlab {
namespace {

double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

P1Weights3 weights_in(const MeshData3& mesh, std::uint32_t t, const Vec3& p) {
  const auto& ids = mesh.tetrahedra[t];
  const std::array<Vec3, 4> v{mesh.vertices[ids[0]], mesh.vertices[ids[1]], mesh.vertices[ids[2]], mesh.vertices[ids[3]]};
  const double whole = det3(v[1] - v[0], v[2] - v[0], v[3] - v[0]);
  P1Weights3 w{ids, {1.0, 0.0, 0.0, 0.0}};
  if (!(whole > 0.0)) return w;  // flat in doubles though positive exactly: the first vertex
  w.weights[1] = det3(p - v[0], v[2] - v[0], v[3] - v[0]) / whole;
  w.weights[2] = det3(v[1] - v[0], p - v[0], v[3] - v[0]) / whole;
  w.weights[3] = det3(v[1] - v[0], v[2] - v[0], p - v[0]) / whole;
  for (int i = 1; i < 4; ++i) w.weights[i] = std::clamp(w.weights[i], 0.0, 1.0);
  w.weights[0] = std::max(0.0, 1.0 - w.weights[1] - w.weights[2] - w.weights[3]);
  const double sum = w.weights[0] + w.weights[1] + w.weights[2] + w.weights[3];
  for (double& x : w.weights) x /= sum;
  return w;
}

// The point of triangle abc nearest to p, as barycentric weights (by the Voronoi regions of the
// vertices, edges and face: the classical closest-point construction).
std::array<double, 3> nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double s = d1 / (d1 - d3);
    return {1.0 - s, s, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double s = d2 / (d2 - d6);
    return {1.0 - s, 0.0, s};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - s, s};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return {1.0, 0.0, 0.0};  // a degenerate triangle
  return {va / sum, vb / sum, vc / sum};
}

// The old boundary: the facets of one tetrahedron only.
std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const MeshData3& mesh) {
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<std::uint32_t, 3>>> facets;
  for (const auto& t : mesh.tetrahedra) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) f[k++] = t[i];
      std::array<std::uint32_t, 3> sorted = f;
      std::sort(sorted.begin(), sorted.end());
      auto& entry = facets[sorted];
      ++entry.first;
      entry.second = f;
    }
  }
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& [key, entry] : facets)
    if (entry.first == 1) out.push_back(entry.second);
  return out;
}

// The 3D placement of a new vertex for the walk of algorithms/common/transfer_walk.hpp.
struct Walk3 {
  static constexpr const char* kSize = "the longest edge of the nearest old boundary triangle";
  const MeshData3& old_mesh;
  const Mesh3 mesh = mesh3_from_data(old_mesh);  // names an invalid old mesh (numbered from 1)
  const ElementGrid<Vec3> grid{std::span<const Vec3>(old_mesh.vertices),
                               std::span<const std::array<std::uint32_t, 4>>(old_mesh.tetrahedra)};
  const std::vector<std::array<std::uint32_t, 3>> boundary = boundary_triangles(old_mesh);
  const ElementGrid<Vec3> boundary_grid{std::span<const Vec3>(old_mesh.vertices),
                                        std::span<const std::array<std::uint32_t, 3>>(boundary)};
  std::uint32_t hint = 0;  // tetrahedron t of the data is slot t of the mesh

  transfer_detail::Placement<P1Weights3> place(const Vec3& p) {
    const Mesh3::Location loc = mesh.locate(p, hint);
    if (loc.where != Mesh3::Where::Outside) {
      hint = loc.tetrahedron;
      return {weights_in(old_mesh, hint, p)};
    }
    for (const std::uint32_t c : grid.candidates(p)) {
      const auto& ids = old_mesh.tetrahedra[c];
      if (closed_tetrahedron_holds(old_mesh.vertices[ids[0]], old_mesh.vertices[ids[1]], old_mesh.vertices[ids[2]],
                                   old_mesh.vertices[ids[3]], p)) {
        hint = c;
        return {weights_in(old_mesh, c, p), transfer_detail::Placed::Rescanned};
      }
    }
    // Outside: the nearest point of the boundary triangles of p's bucket (all of them if none).
    std::span<const std::uint32_t> near = boundary_grid.candidates(p);
    std::vector<std::uint32_t> all;
    if (near.empty()) {
      all.resize(boundary.size());
      std::iota(all.begin(), all.end(), 0u);
      near = all;
    }
    transfer_detail::Placement<P1Weights3> at{{}, transfer_detail::Placed::Outside,
                                              std::numeric_limits<double>::infinity(), 0.0};
    for (const std::uint32_t f : near) {
      const auto& ids = boundary[f];
      const Vec3 &a = old_mesh.vertices[ids[0]], &b = old_mesh.vertices[ids[1]], &c = old_mesh.vertices[ids[2]];
      const std::array<double, 3> w = nearest_on_triangle(p, a, b, c);
      const Vec3 q = w[0] * a + w[1] * b + w[2] * c;
      const double d = norm(p - q);
      if (d < at.distance) {
        at.distance = d;
        at.size = std::max({norm(b - a), norm(c - b), norm(a - c)});
        at.weights = P1Weights3{{ids[0], ids[1], ids[2], ids[2]}, {w[0], w[1], w[2], 0.0}};
      }
    }
    return at;
  }
};

}  // namespace

double integrate_p1(const MeshData3& mesh, std::span<const double> field, std::size_t components,
                    std::size_t component) {
  return transfer_detail::integrate_elements(mesh, field, components, component, [&](const auto& t) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]], &d = mesh.vertices[t[3]];
    return det3(b - a, c - a, d - a) / 6.0;
  });
}

std::vector<P1Weights3> transfer_weights3(const MeshData3& old_mesh, const MeshData3& new_mesh,
                                          const TransferOptions& options, TransferStats* stats) {
  if (old_mesh.tetrahedra.empty()) throw InputError("the old mesh has no tetrahedron");
  transfer_detail::check_elements(new_mesh, "new");
  Walk3 walk{old_mesh};
  std::vector<std::uint32_t> order(new_mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  hilbert_sort(new_mesh.vertices, order);
  return transfer_detail::transfer_walk(walk, std::span<const Vec3>(new_mesh.vertices), order, options.outside_limit,
                                        stats);
}

std::vector<double> transfer_field3(const MeshData3& old_mesh, std::span<const double> field, std::size_t components,
                                    const MeshData3& new_mesh, const TransferOptions& options, TransferStats* stats) {
  return transfer_detail::apply_field(old_mesh, field, components, new_mesh, options, stats, transfer_weights3);
}

std::vector<Metric3> transfer_metrics3(const MeshData3& old_mesh, std::span<const Metric3> metrics,
                                       const MeshData3& new_mesh, const TransferOptions& options,
                                       TransferStats* stats, MetricInterpolation mode) {
  return transfer_detail::apply_metrics(old_mesh, metrics, new_mesh, options, stats, mode, transfer_weights3);
}

}  // namespace dtlab
