// The regions of a constrained tetrahedralization (book §5.2): tetrahedra coloured by adjacency
// across every facet that is not a piece of an input triangle, ghosts included, so that the
// component holding the ghosts is the exterior.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct TetrahedronComponents {
  std::vector<std::uint32_t> component;  // per stored tetrahedron
  std::uint32_t count = 0;
  std::uint32_t exterior = 0;            // the component of the ghosts
  std::vector<std::uint32_t> wall_facet;  // per wall, one facet handle of it (kNone if it is none)
};

// Components of mesh's tetrahedra separated by the given faces (vertex ids, any order).
TetrahedronComponents tetrahedron_components(const Tetrahedralization3& mesh,
                                             std::span<const std::array<std::uint32_t, 3>> walls);

// The shells of a triangulated surface: triangles joined across shared edges; per triangle its
// shell, 0, 1, ... in order of first triangle.
std::vector<std::uint32_t> surface_shells(std::span<const std::array<std::uint32_t, 3>> triangles);

// Per component: true for a cavity, a bounded component whose walls all belong to shells that
// touch no exterior tetrahedron (shells nested inside another). Wall k is a piece of input
// triangle wall_triangle[k]; shell[t] is input triangle t's shell (surface_shells).
std::vector<bool> cavity_components(const Tetrahedralization3& mesh, const TetrahedronComponents& components,
                                    std::span<const std::uint32_t> wall_triangle, std::span<const std::uint32_t> shell);

// A finite tetrahedron whose closed region holds p (exact orient3d), or kNone if p is outside
// the hull. Linear scan: for the few hole and region points of an input.
std::uint32_t tetrahedron_containing(const Tetrahedralization3& mesh, const Vec3& p);

}  // namespace dtlab
