// 3D local mesh adaptation (book §9.3.1): the mesh is modified in place toward a unit mesh in a
// metric given on a background (the input mesh and its vertex metrics, algorithms/mesh3d/
// control_space.hpp): collapses of edges shorter than 1/sqrt2, splits of edges longer than sqrt2
// (new vertices take the metric interpolated in the background), face swaps, shell
// transformations and relocations, all with the operators of algorithms/optimize3d, repeated in
// rounds until the metric edge lengths stop changing.
//
// Scope of this version: the interior, and the split of boundary edges (algorithms/optimize3d/
// boundary_split.hpp, references kept) at the point of the input surface's geometric support
// (algorithms/surface/boundary_support3.hpp: a curved wall stays curved) over the metric
// midpoint; on request (Adapt3dOptions::boundary_relocation) the relocation of the boundary
// vertices off ridges and corners on that support (algorithms/optimize3d/relocate_boundary.hpp).
// Boundary collapse and swaps are not written yet (issue 44): boundary vertices are never removed.
#pragma once

#include <cstdint>
#include <string>

#include "algorithms/mesh3d/control_space.hpp"
#include "algorithms/optimize3d/optimize3d.hpp"
#include "mesh/mesh3.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab {

struct Adapt3dOptions {
  std::uint32_t max_rounds = 12;  // rounds of (collapse, split, swap, relocation)
  // Stop when a round changes the share of unit edges by less than this (absolute) and
  // collapses + splits by fewer than one per thousand live vertices.
  double share_tolerance = 1e-3;
  std::uint32_t relocation_sweeps = 2;  // per round
  std::uint64_t max_vertices = 20'000'000;
  // The tetrahedra the metric may ask for, estimated before any change from its complexity
  // (algorithms/common/element_estimate.hpp): past it, InputError with the estimate, and the
  // vertex bound is lowered to a third of it. 0: half this machine's memory.
  std::uint64_t max_elements = 0;
  bool boundary = true;  // split constrained edges longer than sqrt2 (algorithms/optimize3d/boundary_split.hpp)
  // New boundary vertices on the smooth support of the input's boundary facets (false: on the
  // facets), with ridges and corners where the facets turn by more than ridge_angle_degrees.
  bool surface_support = true;
  double ridge_angle_degrees = 45.0;
  // With the support: boundary vertices off ridges and corners moved on it after each round's
  // volume operators (algorithms/optimize3d/relocate_boundary.hpp), relocation_sweeps sweeps.
  // Off by default: on the UGAWG cases (4 cycles, 2026-12-08) it gains 1.5 points in band on
  // polar-1 but loses 1 on polar-2 and 10 on cube linear (docs/adaptation.md).
  bool boundary_relocation = false;
};

struct Adapt3dStats {
  QualityReport before, after;  // measure_quality in the vertex metrics (UGAWG figures, book's Q)
  std::uint64_t collapses = 0, splits = 0, boundary_splits = 0, boundary_relocations = 0, face_swaps = 0, shell_transformations = 0, relocations = 0;
  std::uint32_t rounds = 0;
  // "converged" (lengths stopped changing), "max_rounds", or optimize3d's "vertex_limit" /
  // "swap_limit".
  std::string stopped_by;
  double seconds = 0.0;
  double tetrahedra_per_second = 0.0;  // tetrahedra after / seconds
};

// The metrics of the mesh's live vertices are set from `metric` at their positions first.
// Throws InputError when the mesh has no tetrahedron in its domain. The mesh passes
// Mesh3::check() afterwards; constrained facets, edges and their references are unchanged.
// Deterministic. New boundary vertices stay kOnBoundary | kFixed.
Adapt3dStats adapt3d(Mesh3& mesh, const ControlSpace3& metric, const Adapt3dOptions& options = {});

}  // namespace dtlab
