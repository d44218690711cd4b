// A 2D mesh as a 3D one in the plane z = 0 and back, for formats that store three coordinates
// (Gmsh .msh, VTK .vtu) and for tools that take either dimension.
#pragma once

#include <string>

#include "kernel/error.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

inline MeshData3 planar_to_mesh3(const MeshData2& m) {
  MeshData3 out;
  out.vertices.reserve(m.vertices.size());
  for (const Vec2& p : m.vertices) out.vertices.push_back(Vec3{p.x, p.y, 0.0});
  out.vertex_refs = m.vertex_refs;
  out.edges = m.edges;
  out.edge_refs = m.edge_refs;
  out.triangles = m.triangles;
  out.triangle_refs = m.triangle_refs;
  return out;
}

// True iff the mesh has no tetrahedra and every z is 0 (or -0): a 2D mesh.
inline bool is_planar(const MeshData3& m) {
  if (!m.tetrahedra.empty()) return false;
  for (const Vec3& p : m.vertices) {
    if (p.z != 0.0) return false;
  }
  return true;
}

// InputError naming the first vertex off the plane, or the tetrahedra, unless is_planar(m).
inline MeshData2 planar_to_mesh2(const MeshData3& m, const std::string& what) {
  if (!m.tetrahedra.empty()) {
    throw InputError(what + " has " + std::to_string(m.tetrahedra.size()) + " tetrahedra: a 3D mesh, not a 2D one");
  }
  MeshData2 out;
  out.vertices.reserve(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    if (m.vertices[i].z != 0.0) {
      throw InputError(what + ": vertex " + std::to_string(i) + " has z = " + std::to_string(m.vertices[i].z) +
                           ", not 0: a surface in 3D, not a 2D mesh",
                       {i});
    }
    out.vertices.push_back(Vec2{m.vertices[i].x, m.vertices[i].y});
  }
  out.vertex_refs = m.vertex_refs;
  out.edges = m.edges;
  out.edge_refs = m.edge_refs;
  out.triangles = m.triangles;
  out.triangle_refs = m.triangle_refs;
  return out;
}

}  // namespace dtlab
