// The 3D path of `dtlab constrain` (apps/constrain.cpp hands over surface inputs: OFF, OBJ, STL,
// TetGen .poly/.smesh with dimension 3, Medit .mesh with Dimension 3).
#pragma once

#include <cstdint>
#include <string>

namespace dtlab::cli {

struct Constrain3dCliArgs {
  std::string input;
  std::string output;  // empty, or OUT.mesh (Medit: Vertices, Triangles with references, Tetrahedra with regions)
  std::string method = "conforming";
  bool keep_exterior = false;
  bool remove_cavities = false;
  bool stats = false;
  bool verify = false;
  std::uint32_t steiner_limit = 200;  // Constrained3dOptions::steiner_limit_factor
  bool merge_coplanar = false;        // FacetTriangulationOptions::merge_coplanar
};

// Returns the exit status: 0 success, 3 a check failed. Throws InputError for bad input, naming
// the items (plc_checks.hpp).
int run_constrain3d(const Constrain3dCliArgs& args);

// --list-methods for 3D: name, tab, description per line.
int list_constrained3d_methods();

}  // namespace dtlab::cli
