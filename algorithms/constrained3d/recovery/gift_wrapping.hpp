// Gift-wrapping of a polyhedral cavity into its constrained Delaunay tetrahedralization
// (Shewchuk 2002, "Constrained Delaunay tetrahedralizations and provably good boundary
// recovery", §4; book §3.7). The cavity is given by its front: oriented triangles, the region
// to fill on the positive side of each (orient3d(a, b, c, p) > 0 for p inside), constraint
// triangles inside the cavity listed once per side. Each step takes a front triangle abc and
// the vertex p on its positive side whose tetrahedron abcp is free (it crosses no front
// triangle and holds no other vertex) and whose sphere holds no other free candidate
// (perturbed insphere: the candidates are totally ordered by the pencil of spheres through a,
// b, c). If the cavity has a constrained Delaunay tetrahedralization, that tetrahedron is one
// of it, so the wrapping rebuilds it tetrahedron by tetrahedron; if no vertex is free for
// some triangle, it has none (or the front was not a closed surface) and the wrapping fails.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

// The tetrahedra filling the cavity (positive), or empty with `why` set when it fails. Every
// vertex in `vertices` (the cavity's, those strictly inside it included) must be used, or it
// fails. Bounded: at most |vertices|^2 + |front| tetrahedra are tried before InternalError.
std::vector<std::array<std::uint32_t, 4>> gift_wrap_cavity(std::span<const Vec3> points,
                                                           std::span<const std::array<std::uint32_t, 3>> front,
                                                           std::span<const std::uint32_t> vertices, std::string& why);

}  // namespace dtlab
