// Split of a constrained edge (book §9.3.1 with §8.3.6): the boundary part of 3D adaptation, and
// the boundary cut in the size by the 3D mesher (algorithms/mesh3d, Mesh3dOptions::keep_boundary).
#pragma once

#include <cstdint>

#include "algorithms/optimize3d/operators.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

class SurfaceSupport3;  // algorithms/surface/surface_support3.hpp

// Splits constrained edge ab at its metric midpoint m: on the segment (planar faces stay planar
// up to the rounding of m), or with a `support`, the point of the support over it (curved walls
// stay curved; refused where that point would make a tetrahedron not positive). Every tetrahedron of ab's closed shell, in the domain, exterior or
// ghost, becomes two, (.., m, ..) in place of b and of a; each constrained facet (a, b, c) becomes
// (a, m, c) and (m, b, c) with its reference; am, mb and every mc of such a facet become
// constrained edges. m is flagged kOnBoundary | kFixed (the interior operators leave it).
// Refused (kNone) when ab is no constrained edge, when a new finite tetrahedron is not positive
// (exact orient3d), when an edge from m to a domain ring vertex is shorter than short_length or
// the new domain tetrahedra's worst Q_K exceeds both the shell's and quality_limit.
std::uint32_t try_boundary_split3(Mesh3& mesh, std::uint32_t a, std::uint32_t b, const MetricField3& field,
                                  const Split3Options& options = {}, const SurfaceSupport3* support = nullptr);

// Splits every constrained edge longer than long_length, longest first; the halves and the new
// edges across the split facets, when too long, are queued in turn. At most max_vertices live vertices. Returns the number of splits.
std::uint64_t boundary_split_pass3(Mesh3& mesh, const MetricField3& field, const Split3Options& options = {},
                                   const SurfaceSupport3* support = nullptr);

// The constrained edges of the domain longer than long_length in the metric of their ends.
std::uint64_t long_constrained_edges(const Mesh3& mesh, double long_length);

}  // namespace dtlab
