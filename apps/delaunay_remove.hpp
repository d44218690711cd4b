// `dtlab delaunay POINTS --remove FILE | --remove-random F`: the Delaunay triangulation (2D) or
// tetrahedralization (3D) of the points, then the given points removed one by one
// (DynamicDelaunay2/3); writes the survivors' mesh and reports the removal's statistics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace dtlab::cli {

struct DelaunayRemoveCliArgs {
  std::string input;       // a point file, or empty with random > 0
  std::string output;      // empty, or a mesh of the survivors (renumbered in input order)
  std::string algorithm = "incremental";
  bool stats = false;      // last line: one JSON object
  bool verify = false;     // the result equals the survivors' triangulation built from scratch
  std::size_t random = 0;
  std::string distribution = "uniform";
  std::uint64_t seed = 1;  // the generated points and the random choice of removed points
  int dim = 2;             // of generated points; a file's own dimension wins
  std::string remove_file;       // whitespace-separated point numbers, from 1
  std::optional<double> remove_fraction;  // or this fraction of the points, drawn with `seed`
};

// Returns the exit status: 0 success, 3 --verify failed. Throws InputError for bad arguments or
// input (an index out of range or repeated, a removal leaving no element), ParseError for a
// malformed index file.
int run_delaunay_remove(const DelaunayRemoveCliArgs& args);

}  // namespace dtlab::cli
