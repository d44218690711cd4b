// The 3D path of `dtlab adapt` (apps/adapt.cpp parses the command and, when the mesh is 3D,
// calls this; apps/adapt3.cpp): reads the tetrahedral Medit mesh and its metric .sol, adapts
// (algorithms/adapt/adapt3d.hpp, book §9.3.1), writes the Medit .mesh, prints the quality
// tables before and after (one JSON line with request.stats).
#pragma once

#include "apps/adapt_request.hpp"

namespace dtlab::cli {

// Returns the exit status (0). Throws InputError for bad input (file and item named), and for
// method "reconstruct" (2D only).
int run_adapt3(const AdaptRequest& request);

}  // namespace dtlab::cli
