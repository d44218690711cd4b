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

template <class Entry>
class Registry;  // algorithms/common/registry.hpp
struct FieldPointMethod3;  // registry.hpp

using element_estimate::kNoElementLimit;

struct Mesh3dOptions {
  // Field point placement: "edge" (the edge method, §7.5-§7.7). The advancing-front placement
  // of §7.8 is not implemented in 3D yet: "front" is refused by name. A name from
  // mesh3d_methods() (registry.hpp), looked up in `methods` when given.
  std::string method = "edge";
  const Registry<FieldPointMethod3>* methods = nullptr;
  // The size specification; null: the classical case (sizes from the surface discretisation).
  const ControlSpace3* control = nullptr;
  // Step 5: the 3D optimization (algorithms/optimize3d, book §8.6's strategy), governed by the
  // control space (moved and new points take their metric from it).
  bool optimize = true;
  Optimize3dOptions optimization = optimize3d_effort("standard");
  // After it, the regions around the tetrahedra still below the optimization's goal for the
  // smallest dihedral angle meshed again (local_remesh.hpp); none without such a goal.
  bool local_remesh = true;
  // Drop the cavities: regions bounded only by shells nested inside another (a cube minus a
  // ball: the ball's inside), as Constrained3dOptions::remove_cavities.
  bool remove_cavities = false;
  // A field point closer than this (metric length, in the metric at the point) to a vertex is
  // filtered out.
  double filter_distance = 0.7;
  // The filter's grid keeps its cells over the empty mesh's box in an array up to this many
  // cells, in a hash table beyond (or for all of them at 0): the same mesh either way.
  std::uint64_t filter_dense_cells = std::uint64_t{1} << 22;
  // Internal edges longer than this in the metric get field points.
  double split_length = 1.4142135623730951;
  // Threads for the field point insertion (field_point_regions.hpp): they share its regions; the
  // mesh is the same for every count (capped at the cores).
  unsigned threads = 1;
  // A pass's field points go in by up to this many regions (field_point_regions.hpp), each
  // holding at least insertion_region_points of them. Part of the algorithm, not of the
  // parallelism: another count gives another (equally valid) mesh; 1 (the default) inserts the
  // points one after the other in Hilbert order.
  std::uint32_t insertion_regions = 1;
  std::uint32_t insertion_region_points = 4096;
  // With a size or metric given, the constrained edges of the surface longer than sqrt 2 in it are
  // split first (optimize3d/boundary_split.hpp, longest first: the surface triangles are cut by
  // their edge midpoints), so that the size holds on the boundary too and a domain with no
  // interior edge is still refined; keep_boundary keeps the surface as given (`messages` counts
  // its long edges). Not in the classical case, whose sizes come from the surface itself.
  bool keep_boundary = false;
  // Bounds, each with a named error when reached.
  std::uint32_t max_passes = 200;
  std::uint64_t max_vertices = 50'000'000;
  // The tetrahedra the size or metric may ask for, estimated before any point is made from the
  // metric's complexity (algorithms/common/element_estimate.hpp): past it, InputError with the
  // estimate, and the vertex bound is lowered to a third of it. 0: half this machine's memory at
  // element_estimate::kBytesPerTetrahedron; kNoElementLimit: no estimate (local_remesh.hpp's
  // regions, bounded by max_vertices alone). Not checked in the classical case.
  std::uint64_t max_elements = 0;
  // Boundary recovery's Steiner bound (Constrained3dOptions::steiner_limit_factor).
  std::uint32_t steiner_limit_factor = 200;
  // Asked between the phases and at each pass of the field point loop (kernel/interrupt.hpp);
  // yes: Interrupted. The optimization asks its own check, or this one when it has none.
  InterruptCheck interrupt{};
};

struct Mesh3dStats {
  double seconds_empty_mesh = 0, seconds_control_space = 0, seconds_field_points = 0, seconds_optimization = 0;
  // Within field points: their insertion (field_point_regions.hpp: metric, filter, location,
  // cavity, correction, ball), wall clock; the rest is finding the candidates.
  double seconds_insertion = 0;
  double seconds = 0;            // the whole call
  std::uint32_t passes = 0;
  std::uint64_t field_points = 0;        // inserted
  std::uint64_t filtered = 0;            // candidates rejected as too close (grid)
  std::uint64_t not_inserted = 0;        // candidates outside the domain, on a vertex, or with an empty cavity
  std::uint64_t cavity_corrections = 0;  // tetrahedra taken out of cavities (star-shapedness)
  std::uint64_t insertion_deferred = 0;  // points the regions left to the sequential insertion
  std::uint64_t input_points = 0, input_triangles = 0;
  std::uint64_t steiner_points = 0;  // added by the boundary recovery
  std::uint64_t empty_mesh_tetrahedra = 0;
  std::uint64_t boundary_points = 0;       // surface edges split in the size (keep_boundary off)
  std::uint64_t long_boundary_edges = 0;   // surface edges left longer than sqrt 2 in the metric
  double estimated_tetrahedra = 0;         // the up-front estimate (0 in the classical case)
  // Optimization counts (algorithms/optimize3d), filled when it ran.
  std::uint64_t face_swaps = 0, shell_transformations = 0, relocations = 0, collapses = 0, splits = 0;
  std::uint32_t optimization_rounds = 0;
  std::string optimization_stopped_by;
  std::uint64_t remeshed_regions = 0;  // local_remesh.hpp
  bool remesh_work_bound_reached = false;
};

struct Mesh3dResult {
  Mesh3 mesh;        // the whole structure, exterior included
  MeshData3 output;  // the domain: vertices, boundary triangles with their references, tetrahedra with regions
  std::vector<std::uint32_t> output_vertex_ids;  // the slot in `mesh` of each output vertex
  std::vector<Metric3> output_metrics;           // the metric at each output vertex
  Mesh3dStats stats;
  std::vector<std::string> messages;  // from the boundary recovery
};

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
