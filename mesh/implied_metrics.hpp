// The metric a mesh implies at its vertices when none is given (dtlab optimize, dtlab.optimize):
// the isotropic metric of size h_v = the mean Euclidean length of the element edges at v, each
// edge counted once per element beside it (a mean weighted toward interior edges, which is what
// sizes are). A vertex no element uses keeps the identity metric.
#pragma once

#include <vector>

#include "kernel/metric.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

// Out-of-range vertex ids are skipped (mesh2_from_data / mesh3_from_data name them).
std::vector<Metric2> implied_metrics(const MeshData2& data);
std::vector<Metric3> implied_metrics(const MeshData3& data);

}  // namespace dtlab
