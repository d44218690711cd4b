// The first half of Mesh2::domain and Mesh3::domain, written once: the vertices that the
// domain's elements use, numbered from 0 in slot order (the output's vertex order).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace dtlab {

// `element_vertices` holds kVertices slots per element (the mesh's flat vertex array); in_domain(t)
// says whether element t is kept. Returns number[v] (0xFFFFFFFF for a vertex no kept element
// uses) and appends the used vertices' points to `points`, a 0 reference each to `refs`, and
// their slots to `vertex_ids` when given (cleared first).
template <std::uint32_t kVertices, class Point, class InDomain>
std::vector<std::uint32_t> number_domain_vertices(std::span<const std::uint32_t> element_vertices,
                                                  std::span<const Point> mesh_points, InDomain in_domain,
                                                  std::vector<Point>& points, std::vector<int>& refs,
                                                  std::vector<std::uint32_t>* vertex_ids) {
  constexpr std::uint32_t kUnused = 0xFFFFFFFFu;
  std::vector<std::uint32_t> number(mesh_points.size(), kUnused);
  const auto elements = static_cast<std::uint32_t>(element_vertices.size() / kVertices);
  for (std::uint32_t t = 0; t < elements; ++t) {
    if (!in_domain(t)) continue;
    for (std::uint32_t i = 0; i < kVertices; ++i) number[element_vertices[kVertices * t + i]] = 0;
  }
  if (vertex_ids) vertex_ids->clear();
  for (std::uint32_t v = 0; v < number.size(); ++v) {
    if (number[v] == kUnused) continue;
    number[v] = static_cast<std::uint32_t>(points.size());
    points.push_back(mesh_points[v]);
    refs.push_back(0);
    if (vertex_ids) vertex_ids->push_back(v);
  }
  return number;
}

}  // namespace dtlab
