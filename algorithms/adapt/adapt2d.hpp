// Local mesh adaptation in 2D (book §9.3.1, "local modification"): the mesh is modified in place
// until its edges are unit in the given metric, [1/sqrt2, sqrt2], and its triangles good in it:
// edges too long are split, too short collapsed, diagonals swapped and vertices relocated in the
// metric, with the optimization operators and strategy of algorithms/optimize2d (one structure
// and one set of operators for optimization and adaptation, as in MMG: Dapogny, Dobrzynski, Frey
// 2014). What adaptation adds to optimization is the boundary:
//   - its vertices other than corners may be removed (boundary_collapse.cpp), within a distance
//     `boundary_deviation` of the boundary (0 for the straight pieces, exactly);
//   - its edges are split, the new point put on a smooth support of the boundary
//     (boundary_curve2.hpp), so that a curved boundary stays curved.
// Corners (boundary_curve2.hpp: a turn above the ridge angle, a change of reference, more than
// two boundary pieces) and references are kept. The metric is the control space: the input mesh
// with its metric (ControlSpace2), interpolated at every new or moved vertex.
//
//   ControlSpace2 control(input, metrics);
//   Mesh2 mesh = mesh2_from_data(input);
//   Adapt2dStats s = adapt2d(mesh, control, {});
//
// Deterministic: the same mesh, metric and options give the same mesh, bit for bit.
#pragma once

#include <cstdint>

#include "algorithms/mesh2d/control_space.hpp"
#include "algorithms/optimize2d/optimize2d.hpp"
#include "kernel/interrupt.hpp"
#include "mesh/mesh2.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab {

struct Adapt2dOptions {
  std::uint32_t max_rounds = 12;
  // A boundary vertex where the boundary turns by more than this (degrees) is a corner.
  double ridge_angle = 45.0;
  // How far (absolute) a removed boundary vertex may lie from the edge that replaces its two; a
  // negative value means 1e-3 of the bounding box's diagonal.
  double boundary_deviation = -1.0;
  bool smooth_boundary = true;  // boundary splits on the support; false: on the chord
  bool boundary_changes = true;  // false: the boundary is kept as it is (no split, no collapse)
  // The triangles the metric may ask for (Optimize2dOptions::max_elements, checked before any
  // change; 0: half this machine's memory).
  std::uint64_t max_elements = 0;
  // Asked before each round and each pass (kernel/interrupt.hpp).
  InterruptCheck interrupt{};
};

struct Adapt2dStats {
  Optimize2dStats operations;
  std::uint32_t corners = 0;
  double boundary_deviation = 0.0;  // the one used
  // mesh/mesh_quality.hpp in the metric of the control space: before, after.
  QualityReport before, after;
  double seconds = 0.0;
};

// Adapts `mesh` (its domain triangles; vertex metrics are taken anew from `metric`). Throws
// InputError when the mesh has no domain triangle.
Adapt2dStats adapt2d(Mesh2& mesh, const ControlSpace2& metric, const Adapt2dOptions& options = {});

}  // namespace dtlab
