// The statistics of a parametric surface mesh (book §6.4's tables: np, ne; and the quality module's
// measures, mesh/mesh_quality.hpp): the charts' meshes measured in their parameter metrics, all
// charts in one report (a seam's edges counted once per chart that holds them).
#pragma once

#include "algorithms/parametric/mesh_patch.hpp"
#include "mesh/mesh_quality.hpp"

namespace dtlab {

QualityReport parameter_quality(const SurfaceMeshResult& result);

}  // namespace dtlab
