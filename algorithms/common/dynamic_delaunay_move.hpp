// move = remove + insert for DynamicDelaunay2/3, written once: refused before any change when
// the vertex is not live (UnknownVertexError), the new position is out of range (InputError) or
// another live vertex is there (DuplicatePointError naming it).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "algorithms/common/dynamic_delaunay_errors.hpp"
#include "kernel/coordinate_range.hpp"

namespace dtlab {

template <class Dynamic, class Mesh, class Point>
std::uint32_t move_vertex(Dynamic& dynamic, const Mesh& mesh, std::uint32_t hint, std::uint32_t v, const Point& p) {
  if (!dynamic.contains(v)) throw UnknownVertexError(v);
  if (mesh.point(v) == p) return v;
  check_coordinates(std::span<const Point>(&p, 1), "moved point");
  const auto loc = mesh.locate(p, hint);
  if (loc.where == Mesh::Where::Vertex)
    throw DuplicatePointError("vertex " + std::to_string(v) + " cannot move onto vertex " + std::to_string(loc.handle),
                              {loc.handle});
  dynamic.remove(v);
  return dynamic.insert(p);
}

}  // namespace dtlab
