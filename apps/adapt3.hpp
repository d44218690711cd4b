// The 3D path of `dtlab adapt` (apps/adapt.cpp parses the command and hands over a tetrahedral
// Medit mesh with its metric here; apps/adapt3.cpp).
#pragma once

#include <cstdint>
#include <string>

namespace dtlab::cli {

struct Adapt3CliArgs {
  std::string input, metric, output;  // MESH.mesh (Tetrahedra + Triangles), M.sol at its vertices, OUT.mesh
  std::string output_metric;          // optional: the metric at the output's vertices (.sol)
  std::string method = "local";       // local (book §9.3.1) | reconstruct (§9.3.2)
  double hgrad = 0.0;                 // 0: no gradation; else the size gradation (> 1)
  std::uint32_t max_cycles = 0;       // 0: the method's default bound
  bool stats = false, verify = false;
};

// Returns the exit status: 0 success, 3 --verify failed. Throws InputError for bad input.
int run_adapt3(const Adapt3CliArgs& args);

}  // namespace dtlab::cli
