// A planar straight line graph read from a file, whichever the format: a Triangle .poly as it is,
// a Medit .mesh as its Vertices and Edges (references as markers; its Triangles are kept aside,
// for the commands that use the file as a background mesh too). Shared by `dtlab constrain` and
// `dtlab mesh`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/poly_format.hpp"

namespace dtlab::cli {

struct GraphInput {
  PolyData2 poly;
  std::uint32_t first_number = 1;  // the file's numbering of points and segments
  MeshData2 medit;                 // a Medit input as read (triangles included); empty for .poly
  std::vector<RegionSeed2> regions;  // poly.regions with integer attributes
};

// Throws InputError naming the file for another extension. `ignored_triangles_note`: print on
// stderr that a Medit file's Triangles are not part of the graph.
GraphInput read_graph(const std::string& path, bool ignored_triangles_note);

}  // namespace dtlab::cli
