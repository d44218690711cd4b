#include "algorithms/surface/boundary_support3.hpp"

#include <array>
#include <utility>

#include "kernel/error.hpp"

namespace dtlab {

BoundarySupport3 boundary_support3(const Mesh3& mesh, SurfaceSupportOptions options) {
  options.non_manifold_ridges = true;
  std::vector<std::uint32_t> point_of(mesh.vertex_capacity(), SurfaceSupport3::kNone);
  std::vector<std::uint32_t> mesh_vertex;
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> refs;
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.in_domain(t)) continue;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = Mesh3::facet(t, i);
      if (!mesh.is_constrained(h)) continue;
      // Once per facet: from the domain's side, or from the lower region's on an interface.
      const std::uint32_t g = mesh.twin(h), u = Mesh3::tetrahedron_of(g);
      if (mesh.in_domain(u) && (mesh.ref(u) < mesh.ref(t) || (mesh.ref(u) == mesh.ref(t) && g < h))) continue;
      const auto f = mesh.facet_vertices(h);  // counter-clockwise seen from inside t
      std::array<std::uint32_t, 3> out{};
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t v = f[k == 0 ? 0 : 3 - k];  // reversed: out of t
        if (point_of[v] == SurfaceSupport3::kNone) {
          point_of[v] = static_cast<std::uint32_t>(points.size());
          points.push_back(mesh.point(v));
          mesh_vertex.push_back(v);
        }
        out[k] = point_of[v];
      }
      triangles.push_back(out);
      refs.push_back(mesh.facet_ref(h));
    }
  }
  if (triangles.empty()) throw InputError("the mesh has no boundary facet to build a surface support on");
  return {SurfaceSupport3(points, triangles, refs, options), std::move(mesh_vertex)};
}

}  // namespace dtlab
