#include "algorithms/mesh3d/spatial_renumber.hpp"

#include <vector>

#include "algorithms/spatial_sort.hpp"

namespace dtlab {

void renumber_spatially(Mesh3& mesh) {
  std::vector<std::uint32_t> vertex_order, free_vertices;
  vertex_order.reserve(mesh.live_vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_dead_vertex(v)) continue;
    ((mesh.flags(v) & Mesh3::kFixed) != 0 ? vertex_order : free_vertices).push_back(v);
  }
  hilbert_sort(mesh.points(), free_vertices);
  vertex_order.insert(vertex_order.end(), free_vertices.begin(), free_vertices.end());
  free_vertices = {};

  std::vector<Vec3> centroids;
  std::vector<std::uint32_t> tetrahedron_order, ghosts, slot_of;
  centroids.reserve(mesh.live_tetrahedron_count());
  slot_of.reserve(mesh.live_tetrahedron_count());
  for (std::uint32_t t = 0; t < mesh.tetrahedron_capacity(); ++t) {
    if (!mesh.is_alive(t)) continue;
    if (mesh.is_ghost(t)) {
      ghosts.push_back(t);
      continue;
    }
    const auto v = mesh.tetrahedron(t);
    centroids.push_back(0.25 * (mesh.point(v[0]) + mesh.point(v[1]) + mesh.point(v[2]) + mesh.point(v[3])));
    slot_of.push_back(t);
  }
  std::vector<std::uint32_t> ids(centroids.size());
  for (std::uint32_t k = 0; k < ids.size(); ++k) ids[k] = k;
  hilbert_sort(centroids, ids);
  centroids = {};
  tetrahedron_order.reserve(mesh.live_tetrahedron_count());
  for (const std::uint32_t k : ids) tetrahedron_order.push_back(slot_of[k]);
  tetrahedron_order.insert(tetrahedron_order.end(), ghosts.begin(), ghosts.end());
  mesh.renumber(vertex_order, tetrahedron_order);
}

}  // namespace dtlab
