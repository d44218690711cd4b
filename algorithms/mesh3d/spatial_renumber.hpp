// Renumbering a Mesh3 for locality: after the field points are in, the tetrahedra lie in slots in
// the order the kernel freed and reused them, so the optimization's shells and balls jump across
// memory (at 10^6 tetrahedra a step around a shell is a cache miss). Mesh3::renumber with the
// fixed vertices (the input's, recovery's Steiner points) first in their order, so that the output
// still lists the input's vertices first, then the others in Hilbert order, and the tetrahedra in
// Hilbert order of their centroids (algorithms/spatial_sort), ghosts last.
#pragma once

#include "mesh/mesh3.hpp"

namespace dtlab {

void renumber_spatially(Mesh3& mesh);

}  // namespace dtlab
