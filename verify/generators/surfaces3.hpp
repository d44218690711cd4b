// Closed triangulated surfaces whose exact shape is known, for the surface support and the
// meshers' tests: a cube, a sphere from a subdivided octahedron, a capped cylinder. Outward
// orientation, vertices on the exact surface.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab::gen {

struct Surface3 {
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// The unit cube [0, 1]^3, each face two triangles.
Surface3 cube_surface();
// The unit sphere: an octahedron subdivided `levels` times (8 * 4^levels triangles).
Surface3 octahedron_sphere(int levels);
// Radius r about the z axis, z in [0, 1]: `around` vertices a circle, `rows` rows of side quads
// (two triangles each), each cap a fan around its centre.
Surface3 capped_cylinder(double r, std::uint32_t around, std::uint32_t rows);

}  // namespace dtlab::gen
