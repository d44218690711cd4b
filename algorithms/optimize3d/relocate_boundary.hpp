// Relocation of boundary vertices on the surface's geometric support (book §9.3.1 with §8.4 and
// §10.5: the boundary mesh is optimized on its support, as the volume's vertices are in the
// volume; Klingner and Shewchuk, "Aggressive tetrahedral mesh improvement", 2007, §3: boundary
// vertices smoothed within their surface). The boundary part of 3D adaptation's relocation.
#pragma once

#include <cstdint>

#include "algorithms/optimize3d/operators.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

class SurfaceSupport3;  // algorithms/surface/surface_support3.hpp

struct BoundaryRelocate3Options {
  double margin = kImprovementMargin;  // the ball's worst Q_K must improve by this, relative
  std::uint32_t tries = 4;             // relaxation w = 1, 1/2, ..., 2^-(tries-1)
  // Adjacent boundary facets at v turning by more than this make v a ridge or corner vertex: kept.
  // The support's ridge angle (SurfaceSupportOptions::ridge_angle_degrees).
  double ridge_angle_degrees = 45.0;
  // Refuse a move that leaves fewer of v's edges with metric length in [1/sqrt2, sqrt2]
  // (adaptation: the shapes improve without undoing the lengths the splits and collapses made).
  bool keep_unit_edges = true;
};

// Moves boundary vertex v along the surface when that improves its ball. v must be smooth: its
// constrained facets of one reference, one closed fan around it, adjacent ones turning by less
// than the ridge angle. The candidate is P' = (1 - w) P + w T (w = 1, 1/2, ...) projected on
// `support` (SurfaceSupport3::project: the smooth surface through the input's facets), T first
// the optimal point of the ball (book (8.17)) in v's tangent plane, then the centroid of its
// boundary neighbours. Kept when
//   - every finite tetrahedron of its ball (domain or exterior) stays positive (exact orient3d),
//     and at a hull vertex no vertex of the hull facets at it or beside them lies strictly
//     beyond one of them (the hull stays convex);
//   - a planar fan stays exactly planar (orient3d = 0 with each facet);
//   - it lies within a quarter of the fan's shortest edge of the tangent plane (a projection onto
//     another sheet of the surface is refused);
//   - its support triangle has no ridge or corner vertex (the support is one-sided there, off a
//     curved wall by up to half a facet's turn);
//   - the worst Q_K of its domain tetrahedra improves by the margin, and (keep_unit_edges) no
//     fewer of its edges have unit length.
// No topology changes: references, constrained facets and edges stay. v's metric becomes `field`
// at P' (kept when the field is empty). True when v moved. Each call reads the support's
// features (O(support)); the sweep reads them once.
bool try_relocate_boundary3(Mesh3& mesh, std::uint32_t v, const MetricField3& field, const SurfaceSupport3& support,
                            const BoundaryRelocate3Options& options = {});

// One sweep: every live kOnBoundary vertex once, worst domain ball first. Returns how many moved.
std::uint64_t boundary_relocate_sweep3(Mesh3& mesh, const MetricField3& field, const SurfaceSupport3& support,
                                       const BoundaryRelocate3Options& options = {});

}  // namespace dtlab
