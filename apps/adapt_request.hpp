// What `dtlab adapt` was asked, parsed and validated by apps/adapt.cpp and handed to the part
// for the mesh's dimension (the 2D adaptation in apps/adapt.cpp, run_adapt3 in apps/adapt3.hpp).
//   dtlab adapt MESH.mesh --metric M.sol -o OUT.mesh [--method local|reconstruct] [--hgrad G]
//               [--rounds R] [--stats]
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace dtlab::cli {

struct AdaptRequest {
  std::string mesh;    // Medit .mesh / .meshb (the dimension decides 2D or 3D)
  std::string metric;  // Medit .sol / .solb at the mesh's vertices: a size or a symmetric tensor
  std::string output;  // Medit .mesh / .meshb
  std::string method = "local";  // "local" (§9.3.1) or "reconstruct" (§9.3.2, §9.7)
  // Gradation of the given metric over the input mesh's edges before adapting (kernel/metric.hpp
  // apply_gradation, beta = hgrad > 1); none when absent.
  std::optional<double> hgrad;
  std::uint32_t max_rounds = 12;  // rounds of the local modification
  bool stats = false;             // one JSON line with the counts and both quality reports last
  // The boundary: corners where it turns by more than ridge_angle degrees (kept; in 3D the
  // ridges and corners of the surface support); a removed boundary vertex within
  // boundary_deviation of the new boundary (absent: 1e-3 of the bounding box's diagonal; 2D only,
  // refused in 3D); keep_boundary: no boundary vertex added or removed.
  double ridge_angle = 45.0;
  std::optional<double> boundary_deviation;
  bool keep_boundary = false;
  std::string output_metric;  // write the metric at the output's vertices (Medit .sol) when given
  std::uint64_t max_elements = 0;  // Adapt2d/3dOptions::max_elements (0: from the memory)
};

}  // namespace dtlab::cli
