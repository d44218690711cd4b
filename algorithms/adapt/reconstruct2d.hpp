// Complete reconstruction in 2D (book §9.3.2, §9.7: "global remeshing"): the adapted mesh is
// generated anew by the mesher (algorithms/mesh2d) governed by the control space (the previous
// mesh with its metric), its boundary cut anew in the metric, instead of being modified in place
// (adapt2d.hpp, §9.3.1). What is taken from the previous mesh:
//   - the boundary and the interfaces between regions: its constrained edges, the boundary edges
//     and the edges between triangles of different references, as segments with their
//     references. Between corners (boundary_curve2.hpp's, at the ridge angle) a chain of
//     exactly collinear edges becomes one segment, so that the new cut may coarsen it; any other
//     chain keeps its vertices (a curved boundary keeps its resolution: the cut points lie on its
//     chords);
//   - the regions: one seed per connected set of triangles of the same reference, and one hole
//     seed per boundary loop just outside it (on the exterior side of a boundary edge, outside
//     every triangle), so holes stay holes.
// Deterministic: the same mesh and metric give the same mesh, bit for bit.
#pragma once

#include <string>
#include <vector>

#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/mesh2d/mesh2d.hpp"
#include "kernel/interrupt.hpp"
#include "mesh/io/mesh_data.hpp"

namespace dtlab {

struct Reconstruct2dOptions {
  std::string method = "edge";  // mesh2d's field points: "edge" or "front"
  double ridge_angle = 45.0;    // degrees: boundary vertices turning more are corners
  MetricInterpolation interpolation = MetricInterpolation::Sizes;
  std::uint64_t max_elements = 0;  // Mesh2dOptions::max_elements
  InterruptCheck interrupt{};
};

struct Reconstruct2dResult {
  Mesh2dResult generated;  // mesh2d's result: output (the new mesh), output_metrics, stats
  std::uint64_t segments = 0, merged_chains = 0, region_seeds = 0, hole_seeds = 0;
};

// Throws InputError for an invalid previous mesh (as mesh2_from_data, numbered from 1) and as
// mesh2d for a bound reached.
Reconstruct2dResult reconstruct2d(const MeshData2& previous, const ControlSpace2& control,
                                  const Reconstruct2dOptions& options = {});

}  // namespace dtlab
