// The 3D path of `dtlab mesh` (apps/mesh.cpp hands over surface inputs: OFF, OBJ, STL, TetGen
// .poly/.smesh with dimension 3, Medit .mesh with Dimension 3 and triangles only).
#pragma once

#include <cstdint>
#include <string>

namespace dtlab::cli {

struct Mesh3CliArgs {
  std::string input, output, output_metric;
  double size = 0.0;  // 0: not given
  std::string size_map, metric, background;
  std::string method = "edge";
  std::string interpolation = "sizes";
  bool no_optimize = false, stats = false, verify = false, resample_boundary = false;
  bool remove_cavities = false;  // Mesh3dOptions::remove_cavities
  std::string optimize = "standard";  // the effort: optimize3d_effort (optimize3d.hpp)
  bool triangulate_nonplanar = false;  // FacetTriangulationOptions::triangulate_nonplanar
  bool no_remesh = false;              // Mesh3dOptions::local_remesh off
  unsigned threads = 1;                // Mesh3dOptions::threads
  std::uint32_t insertion_regions = 1;  // Mesh3dOptions::insertion_regions
};

// Returns the exit status: 0 success, 3 --verify failed. Throws InputError for bad input.
int run_mesh3(const Mesh3CliArgs& args);

}  // namespace dtlab::cli
