// The geometric support of a volume mesh's boundary (book §10.5): the constrained facets of a
// Mesh3, turned out of the domain (an internal interface: out of its lower region), as a
// SurfaceSupport3 with each facet's reference, so that adaptation puts its new boundary vertices
// on the smooth surface through the input's facets. Interfaces meeting the boundary make edges of
// three or more facets: ridges (SurfaceSupportOptions::non_manifold_ridges).
#pragma once

#include <cstdint>
#include <vector>

#include "algorithms/surface/surface_support3.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

struct BoundarySupport3 {
  SurfaceSupport3 support;
  std::vector<std::uint32_t> mesh_vertex;  // per support point: its vertex in the mesh
};

// InputError when the mesh has no constrained facet beside its domain.
BoundarySupport3 boundary_support3(const Mesh3& mesh, SurfaceSupportOptions options = {});

}  // namespace dtlab
