// Reading a planar straight line graph (graph_input.hpp).
#include "apps/graph_input.hpp"

#include <cmath>
#include <iostream>

#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"

namespace dtlab::cli {

GraphInput read_graph(const std::string& path, bool ignored_triangles_note) {
  const std::string ext = extension_of(path);
  GraphInput in;
  if (ext == "poly") {
    in.poly = read_triangle_poly(path);
    in.first_number = static_cast<std::uint32_t>(in.poly.first_index);
  } else if (ext == "mesh") {
    in.medit = read_medit2(path);
    if (!in.medit.triangles.empty() && ignored_triangles_note)
      std::cerr << "dtlab: " << path << ": its " << in.medit.triangles.size()
                << " Triangles are ignored; the graph is its Vertices and Edges\n";
    in.poly.points = in.medit.vertices;
    in.poly.segments = in.medit.edges;
    in.poly.has_segment_markers = true;
    in.poly.segment_markers = in.medit.edge_refs;
  } else {
    throw InputError(path + ": give a Triangle .poly or a Medit .mesh (with Edges) file");
  }
  for (const PolyRegion& r : in.poly.regions) {
    const double rounded = std::nearbyint(r.attribute);
    if (rounded != r.attribute || std::fabs(rounded) > 2e9)
      std::cerr << "dtlab: region attribute " << r.attribute << " written as the integer reference "
                << (std::fabs(rounded) > 2e9 ? 0 : rounded) << "\n";
    in.regions.push_back({r.point, static_cast<int>(std::fabs(rounded) > 2e9 ? 0 : rounded)});
  }
  return in;
}

}  // namespace dtlab::cli
