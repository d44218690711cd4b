// Mesh2::domain and Mesh3::domain, written once: the vertices that the domain's elements use,
// numbered from 0 in slot order (the output's vertex order), then the domain's elements and its
// constrained sides (edges in 2D, facets in 3D), each side once.
#pragma once

#include <array>
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

// The second half: every kept element, its vertices renumbered by `number`, with its reference;
// after each, those of its kVertices sides h (h = kVertices t + i, the flat arrays' handles, twin
// neighbours[h]) that is_constrained(h) marks, each side once: from the kept element beside it
// with the smaller id (emit_side(h) writes it).
template <std::uint32_t kVertices, class InDomain, class IsConstrained, class EmitSide>
void append_domain_elements(std::span<const std::uint32_t> element_vertices, std::span<const std::uint32_t> neighbours,
                            std::span<const int> element_refs, std::span<const std::uint32_t> number,
                            InDomain in_domain, IsConstrained is_constrained, EmitSide emit_side,
                            std::vector<std::array<std::uint32_t, kVertices>>& elements, std::vector<int>& refs) {
  const auto count = static_cast<std::uint32_t>(element_vertices.size() / kVertices);
  for (std::uint32_t t = 0; t < count; ++t) {
    if (!in_domain(t)) continue;
    std::array<std::uint32_t, kVertices> e;
    for (std::uint32_t i = 0; i < kVertices; ++i) e[i] = number[element_vertices[kVertices * t + i]];
    elements.push_back(e);
    refs.push_back(element_refs[t]);
    for (std::uint32_t i = 0; i < kVertices; ++i) {
      const std::uint32_t h = kVertices * t + i;
      if (!is_constrained(h)) continue;
      const std::uint32_t u = neighbours[h] / kVertices;
      if (in_domain(u) && u < t) continue;
      emit_side(h);
    }
  }
}

// The whole of Mesh2::domain / Mesh3::domain: `Data` (MeshData2, MeshData3) with the numbered
// vertices, the kept elements into its member `elements` with their references into
// `element_refs`, and each constrained side once through emit_side(out, number, h).
template <std::uint32_t kVertices, class Data, class Mesh, class IsConstrained, class EmitSide>
Data mesh_domain(const Mesh& mesh, std::span<const std::uint32_t> element_vertices,
                 std::span<const std::uint32_t> neighbours, std::span<const int> element_refs,
                 std::vector<std::array<std::uint32_t, kVertices>> Data::*elements, std::vector<int> Data::*refs,
                 std::vector<std::uint32_t>* vertex_ids, IsConstrained is_constrained, EmitSide emit_side) {
  Data out;
  const auto in_domain = [&mesh](std::uint32_t t) { return mesh.in_domain(t); };
  const std::vector<std::uint32_t> number = number_domain_vertices<kVertices>(
      element_vertices, mesh.points(), in_domain, out.vertices, out.vertex_refs, vertex_ids);
  append_domain_elements<kVertices>(
      element_vertices, neighbours, element_refs, number, in_domain, is_constrained,
      [&](std::uint32_t h) { emit_side(out, number, h); }, out.*elements, out.*refs);
  return out;
}

}  // namespace dtlab
