// Local remeshing: the tetrahedra that optimization cannot cure, meshed again by the generator.
//
// A tetrahedron with a small dihedral angle whose four vertices lie on the boundary (two on each
// side of a sharp edge, none of its facets there) cannot be moved, and near a finely discretised
// sharp edge no swap, no single new vertex and no relocation improves it (issue 17, TetGen's mesh
// of a cube minus a ball: every such move was tried and none lifts the smallest angle above
// 16.7°): what is missing is a layer of interior vertices the size of the surface's triangles.
// So the region around it — the tetrahedra sharing a vertex with it, then those within two
// vertex rings — is cut out, its boundary surface handed to the generator (mesh3d.hpp: boundary
// recovery, field points, optimization; sizes: the vertex metrics on the old region, made finer
// where the region's surface triangles are smaller), and the result put
// in its place when it is better: the smallest dihedral angle of the region grows, its largest
// does not pass max(its old largest, max_dihedral_deg), its worst Q_K stays at most
// max(its old worst, quality_limit), and no new edge inside it is longer in the metric than
// max(the old longest inside it, sqrt 2) (the generator sizes a region from its own surface: a
// region whose surface is coarser than the metric asks, e.g. a whole small domain, would
// otherwise come back with too few tetrahedra). The region's boundary triangles come back unchanged (the
// generator keeps its surface, and a result with recovery Steiner points is refused), so the new
// tetrahedra fit the rest of the mesh exactly, and no constrained facet, constrained edge, fixed
// or boundary vertex or reference changes: a region holding any of those inside is not tried.
// Gmsh and MMG cure what their local operators leave behind the same way, by remeshing a cavity.
#pragma once

#include <cstdint>

#include "algorithms/optimize3d/operators.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

struct LocalRemesh3Options {
  double below_deg = 20.0;          // domain tetrahedra with a smaller dihedral angle are treated
  double quality_limit = 3.0;       // a region's new worst Q_K at most max(its old worst, this)
  double max_dihedral_deg = 150.0;  // its new largest angle at most max(its old largest, this)
  std::uint32_t max_rings = 2;      // regions of 1, then 2, ... vertex rings around the tetrahedron
  std::uint32_t max_region_tetrahedra = 500;  // a larger region is not tried
  std::uint32_t passes = 2;                    // over the tetrahedra still below, while some change
  // A region with a surface edge longer than this in the metric is not tried (the generator
  // keeps the surface: the region cannot be meshed well at the metric's sizes).
  double coarse_surface_length = 2.0;
  // The work bound: no region is tried once those handed to the generator hold work_factor
  // times the domain's tetrahedra plus work_floor in all (a surface with thousands of
  // degenerate spots — CGAL's cheese.off — would otherwise take hours; there 1,555 regions, 20
  // s). Deterministic, unlike a clock; reported in LocalRemesh3Stats::work_bound_reached.
  double work_factor = 0.5;
  double work_floor = 10000.0;
};

struct LocalRemesh3Stats {
  std::uint64_t tried = 0;     // regions handed to the generator
  std::uint64_t remeshed = 0;  // regions replaced
  std::uint64_t vertices_added = 0, vertices_removed = 0;
  std::uint64_t work = 0;       // tetrahedra of the regions handed to the generator
  bool work_bound_reached = false;
};

// Treats every domain tetrahedron of `mesh` with a dihedral angle below options.below_deg,
// smallest angle first. New vertices take their metric from `field` (empty: interpolated from the
// old region's vertex metrics). Deterministic. The mesh passes Mesh3::check() afterwards.
LocalRemesh3Stats remesh_small_angles(Mesh3& mesh, const MetricField3& field, const LocalRemesh3Options& options = {});

}  // namespace dtlab
