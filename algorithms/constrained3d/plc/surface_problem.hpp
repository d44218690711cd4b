// A closed surface file made ready for the 3D constrained methods and the 3D mesher, the same way
// for `dtlab constrain`, `dtlab mesh` and any other caller: the file read (mesh/io/surface_input),
// each facet triangulated in its plane (facet_triangulation.hpp), region attributes taken as
// integer references (a fractional one is said, not silently cut), each input triangle named by
// its facet for the input check's messages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/constrained3d/constrained3d.hpp"
#include "algorithms/constrained3d/plc/facet_triangulation.hpp"
#include "mesh/io/surface_input.hpp"

namespace dtlab {

struct SurfaceProblem {
  std::string path;
  SurfaceInput surface;
  FacetTriangulation facets;
  std::vector<RegionSeed3> regions;
  std::vector<std::string> messages;  // the facet triangulation's, then the regions'

  // The constrained input, viewing this object's arrays (keep it alive and in place while used).
  ConstrainedInput3 input() const;
  // Input triangle t as the input check names it: its facet, and which of the facet's triangles
  // it is where the facet has several.
  std::string triangle_name(std::uint32_t t) const;
};

// Throws InputError naming the file for a file that cannot be read or a facet that cannot be
// triangulated (options.facet_name and first_vertex_number are set from the file).
SurfaceProblem read_surface_problem(const std::string& path, FacetTriangulationOptions options = {});

}  // namespace dtlab
