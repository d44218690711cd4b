// The 3D path of `dtlab delaunay` (apps/delaunay.cpp hands over 3D inputs and --dim 3).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace dtlab::cli {

struct Delaunay3dCliArgs {
  std::string input;      // a plain "x y z" point file or a Medit .mesh, or empty with random > 0
  std::string output;     // empty, or OUT.mesh (Medit, Vertices and Tetrahedra)
  std::string algorithm = "incremental";
  bool stats = false;     // last line: one JSON object, as in 2D
  bool verify = false;    // the exact checks of verify/checks3d.hpp
  std::size_t random = 0;
  std::string distribution = "uniform";  // verify/generators/points3d.hpp
  std::uint64_t seed = 1;
  unsigned threads = 1;   // Delaunay3dOptions::threads
};

// --list-algos --dim 3: one line per registered 3D variant (name, tab, description).
int list_delaunay3d_variants();

// Returns the exit status: 0 success, 3 a check failed. Throws InputError for bad arguments.
int run_delaunay3d(const Delaunay3dCliArgs& args);

}  // namespace dtlab::cli
