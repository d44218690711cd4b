// The arguments of `dtlab mesh`, one set for both dimensions: apps/mesh.cpp parses them and
// meshes a planar graph, or hands a closed surface to apps/mesh3.cpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/metric.hpp"

namespace dtlab::cli {

struct MeshCliArgs {
  std::string input, output, output_metric;
  std::string size;  // kept as text: refused with our own message (parse_size, cli_util.hpp)
  bool size_given = false;
  std::string size_map, metric, background;
  std::string method = "edge";
  std::string interpolation = "sizes";
  bool no_optimize = false, stats = false, verify = false;
  bool keep_boundary = false;      // Mesh2dOptions / Mesh3dOptions::keep_boundary
  bool resample_boundary = false;  // the former option, now the default: refused with a hint
  std::uint64_t max_elements = 0;  // Mesh2dOptions / Mesh3dOptions::max_elements (0: from the memory)
  bool no_remesh = false;               // surfaces: Mesh3dOptions::local_remesh off
  bool remove_cavities = false;         // surfaces: Mesh3dOptions::remove_cavities
  std::string optimize = "standard";    // surfaces: the effort, optimize3d_effort (optimize3d.hpp)
  bool triangulate_nonplanar = false;   // surfaces: FacetTriangulationOptions::triangulate_nonplanar
  unsigned threads = 1;                 // surfaces: Mesh3dOptions::threads
  std::uint32_t insertion_regions = 1;  // surfaces: Mesh3dOptions::insertion_regions
  bool optimize_given = false;          // --optimize was given (surfaces only)
  // Parametric patches (a .json description, apps/mesh_patch.cpp).
  bool surface_only = false;
  double hausdorff = 0.0, relative_gap = 0.0, hmin = 0.0, hmax = 0.0;
  std::string geometric;                // "", "isotropic" or "anisotropic"
  std::uint32_t background_cells = 64;  // SurfaceMeshOptions::background_cells

  // How many of --size, --size-map, --metric were given.
  int sizes_given() const { return size_given + !size_map.empty() + !metric.empty(); }
};

// The --size-map (scalars) or --metric (tensors) file at `vertex_count` vertices of `against`,
// checked to be of that kind and dimension. Metric2 or Metric3.
template <class Metric>
std::vector<Metric> read_size_file(const MeshCliArgs& args, std::size_t vertex_count, const std::string& against);

// --resample-boundary, given: the InputError that says it is the default now.
[[noreturn]] void throw_resample_boundary_refused();

// A parametric patch (PATCH.json, --surface-only): returns 0; InputError for bad input.
int run_mesh_patch(const MeshCliArgs& args);
bool is_patch_description(const std::string& path);  // ends in .json

// The 3D path: returns the exit status (0 success, 3 --verify failed); InputError for bad input.
int run_mesh3(const MeshCliArgs& args);

}  // namespace dtlab::cli
