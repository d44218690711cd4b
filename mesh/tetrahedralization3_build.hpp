// A Tetrahedralization3 from a bare list of tetrahedra (a mesh file written by any tool): twins
// matched by their three vertices, the hull closed by ghost tetrahedra as
// tetrahedralization3.hpp requires. This is how `dtlab verify` checks a 3D mesh it did not make.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

// Throws InputError naming the offending item when the tetrahedra cannot form a closed structure:
// a vertex id out of range, a tetrahedron with a repeated vertex, a facet shared by more than two
// tetrahedra, or two tetrahedra on the same side of a shared facet (inconsistent orientation),
// or a boundary that is not a closed 2-manifold (an edge on a number of boundary facets other than
// two). Orientation itself (orient3d > 0) is geometry: checkers test it, this does not.
Tetrahedralization3 tetrahedralization_from_tetrahedra(std::vector<Vec3> points,
                                                       std::span<const std::array<std::uint32_t, 4>> tetrahedra);

}  // namespace dtlab
