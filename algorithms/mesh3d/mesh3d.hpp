// Mesh generation in 3D governed by a control space (book §7, the scheme of §7.12):
//   1. the empty mesh: the constrained tetrahedralization of the input surface by boundary
//      recovery (algorithms/constrained3d, method "recover": fewest Steiner points), regions
//      coloured, exterior kept as kExterior tetrahedra (empty_mesh.cpp);
//   2. the control space: classical (h at a surface vertex = mean length of its surface edges,
//      P1 on the empty mesh: classical_sizes.cpp), or a size or metric map on a background mesh
//      (control_space.hpp): one code path;
//   3. field points by the edge method (§7.5-§7.7), filtered in the metric by a grid, iterated to
//      saturation (edge_points.cpp);
//   4. insertion by the constrained, possibly anisotropic Delaunay kernel (§7.9-§7.10,
//      delaunay_kernel.hpp);
//   5. optimization (algorithms/optimize3d), the regions it cannot cure meshed again
//      (local_remesh.hpp), then the exterior removed, regions written with their references
//      (Mesh3::domain).
//
//   dtlab::Mesh3dResult r = dtlab::mesh3d({.points = pts, .triangles = tris}, {});
//   write_mesh3("out.mesh", r.output);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/common/element_estimate.hpp"
#include "algorithms/common/mesh_pipeline.hpp"
#include "algorithms/common/registry.hpp"
#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/mesh3d/control_space.hpp"
#include "algorithms/optimize3d/optimize3d.hpp"
#include "kernel/interrupt.hpp"
#include "kernel/metric.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

// The input: a closed surface (several shells allowed), as constrained3d takes it.
using Mesh3dInput = ConstrainedInput3;

using element_estimate::kNoElementLimit;

struct Mesh3dOptions;
struct Mesh3dStats;
// A field point method (registry.hpp).
using FieldPointMethod3 = NamedEntry<void(Mesh3&, const ControlSpace3&, const Mesh3dOptions&, Mesh3dStats&)>;

// The 3D mesher's types and defaults (algorithms/common/mesh_pipeline.hpp).
struct Mesh3dTraits {
  using Method = FieldPointMethod3;
  using ControlSpace = ControlSpace3;
  // Step 5: the 3D optimization (algorithms/optimize3d, book §8.6's strategy), governed by the
  // control space (moved and new points take their metric from it).
  using Optimization = Optimize3dOptions;
  static constexpr std::uint64_t kMaxVertices = 50'000'000;
  static Optimization optimization() { return optimize3d_effort("standard"); }
};

// The meshers' options (mesh_pipeline.hpp; "front" is refused by name: §7.8 is not implemented
// in 3D yet; the surface cut optimize3d/boundary_split.hpp, longest first; the element bound at
// element_estimate::kBytesPerTetrahedron, the vertex bound lowered to a third of it,
// kNoElementLimit: no estimate, for local_remesh.hpp's regions) and 3D's own.
struct Mesh3dOptions : MesherOptions<Mesh3dTraits> {
  // After step 5, the regions around the tetrahedra still below the optimization's goal for the
  // smallest dihedral angle meshed again (local_remesh.hpp); none without such a goal.
  bool local_remesh = true;
  // Drop the cavities: regions bounded only by shells nested inside another (a cube minus a
  // ball: the ball's inside), as Constrained3dOptions::remove_cavities.
  bool remove_cavities = false;
  // The filter's grid keeps its cells over the empty mesh's box in an array up to this many
  // cells, in a hash table beyond (or for all of them at 0): the same mesh either way.
  std::uint64_t filter_dense_cells = std::uint64_t{1} << 22;
  // Threads for the field point insertion (field_point_regions.hpp): they share its regions; the
  // mesh is the same for every count (capped at the cores).
  unsigned threads = 1;
  // A pass's field points go in by up to this many regions (field_point_regions.hpp), each
  // holding at least insertion_region_points of them. Part of the algorithm, not of the
  // parallelism: another count gives another (equally valid) mesh; 1 (the default) inserts the
  // points one after the other in Hilbert order.
  std::uint32_t insertion_regions = 1;
  std::uint32_t insertion_region_points = 4096;
  // Boundary recovery's Steiner bound (Constrained3dOptions::steiner_limit_factor).
  std::uint32_t steiner_limit_factor = 200;
};

struct Mesh3dStats : MesherStats {
  // Within field points: their insertion (field_point_regions.hpp: metric, filter, location,
  // cavity, correction, ball), wall clock; the rest is finding the candidates.
  double seconds_insertion = 0;
  std::uint64_t insertion_deferred = 0;  // points the regions left to the sequential insertion
  std::uint64_t input_triangles = 0;
  std::uint64_t steiner_points = 0;  // added by the boundary recovery
  std::uint64_t empty_mesh_tetrahedra = 0;
  std::uint64_t long_boundary_edges = 0;   // surface edges left longer than sqrt 2 in the metric
  double estimated_tetrahedra = 0;         // the up-front estimate (0 in the classical case)
  // Optimization counts (algorithms/optimize3d).
  std::uint64_t face_swaps = 0, shell_transformations = 0;
  std::string optimization_stopped_by;
  std::uint64_t remeshed_regions = 0;  // local_remesh.hpp
  bool remesh_work_bound_reached = false;
};

using Mesh3dResult = MesherResult<Mesh3, MeshData3, Metric3, Mesh3dStats>;

// Throws InputError for bad input (as constrained3d: open, self-intersecting, degenerate surfaces
// by name), a domain with no tetrahedron, an unknown method, or a bound reached (named).
Mesh3dResult mesh3d(const Mesh3dInput& input, const Mesh3dOptions& options = {});

// Step 1's boundary recovery: constrained3d with method "recover" (fewest Steiner points), the
// exterior not kept; the reference that check_mesh3d (verify/checks_mesh3d.hpp) checks an output
// against.
Constrained3dResult recover_domain(const Mesh3dInput& input, bool remove_cavities = false,
                                   std::uint32_t steiner_limit_factor = 200);

// The pieces, for tests and for other meshers.
// 1. The empty mesh: every tetrahedron of the recovered tetrahedralization, the domain's with
//    their region, the others kExterior; the input triangles' pieces as constrained facets with
//    their references, their edges as constrained edges.
Mesh3 empty_mesh(const Constrained3dResult& recovered);
// 2. Classical sizes: at each vertex the mean length of its constrained edges (of all its edges
//    for a vertex on none); the control space is the empty mesh's finite tetrahedra with these sizes.
ControlSpace3 classical_control_space(const Mesh3& empty);
// 3.+4. The edge method: field points inserted until saturation. Adds to `stats`.
void insert_edge_points(Mesh3& mesh, const ControlSpace3& control, const Mesh3dOptions& options, Mesh3dStats& stats);

}  // namespace dtlab
