#include "algorithms/mesh3d/registry.hpp"

namespace dtlab {

const Registry<FieldPointMethod3>& mesh3d_methods() {
  static const Registry<FieldPointMethod3> entries{
      "field point method",
      {FieldPointMethod3{"edge",
                         "the edge method (book §7.5-§7.7): points along the edges longer than sqrt 2 in the "
                         "metric, filtered by a grid, inserted by regions, in passes until saturation "
                         "(edge_points.cpp, field_point_regions.hpp)",
                         &insert_edge_points}}};
  return entries;
}

}  // namespace dtlab
