#include "algorithms/mesh2d/registry.hpp"

namespace dtlab {

const Registry<FieldPointMethod2>& mesh2d_methods() {
  static const Registry<FieldPointMethod2> entries{
      "field point method",
      {FieldPointMethod2{"edge",
                         "the edge method (book §5, §7.5-§7.7): points along the edges longer than sqrt 2 in the "
                         "metric, filtered, inserted, in passes until saturation (edge_points.cpp)",
                         &insert_edge_points},
       FieldPointMethod2{"front",
                         "advancing-front placement (§5.8, §7.8): points placed from the front of accepted "
                         "triangles at unit distance in the metric, inserted at once (front_points.cpp)",
                         &insert_front_points}}};
  return entries;
}

}  // namespace dtlab
