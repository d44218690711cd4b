// The facets of a piecewise linear complex (mesh/io/tetgen_poly.hpp: planar polygons, several per
// facet, with segments, isolated vertices and facet holes; book §3.5, TetGen 1.5 manual §5.2) as
// the triangles that constrained3d recovers: each facet checked exactly for planarity and
// simplicity, then triangulated in its own plane by the constrained Delaunay triangulation of
// algorithms/constrained2d (method "cdt", book §3.4), holes honoured. No point is added: a facet
// whose polygons would need one (they cross) is refused.
//
// Exact decisions only (kernel/predicates.hpp):
//  - planarity: every vertex of the facet has orient3d = 0 against its first three non-collinear
//    vertices (in order of appearance); a non-planar facet is refused naming the facet and the
//    vertex farthest from that plane (the distance, in doubles, only picks which one to name);
//  - the plane: the facet is projected by dropping the coordinate of the largest component of
//    its normal. The projection copies coordinates, so orient2d of projected points is exactly
//    the sign of that component of the 3D normal of the points, never zero for a non-degenerate
//    triangle of the facet: every orientation and incircle decision of the 2D triangulation is
//    exact in the facet's own (projected) coordinates, and the triangles lifted back are exactly
//    in the facet's plane. (Dropping the largest component also keeps the projection's
//    distortion smallest, so its Delaunay triangulation is close to the one in the plane.)
//  - simplicity: a polygon of 3 or more corners whose corners are all collinear, that repeats a
//    vertex, whose edges meet other than consecutive ones at their shared corner (touching or
//    crossing itself), or two polygons of a facet that cross, are refused naming the facet.
// A facet that is one triangle is passed on as it is (degenerate triangles are check_plc's to
// name). Each facet's triangles keep its turn (the orientation of its first polygon of 3 or more
// corners), its marker as reference and its index, so the output's boundary triangles carry the
// facet's reference.
//
// Merging coplanar facets (TetGen merges them unless told -M): with merge_coplanar, triangles of
// different facets across an edge that only they share, in one plane (orient3d = 0), turned
// consistently, on either side of the edge and with the same reference, are joined, and each
// group of more than one facet is triangulated again as one: the constrained Delaunay
// triangulation of its vertices with its boundary edges as constraints, the inside found from
// the side of each boundary edge its triangle lay on. The vertex set is kept, so a valid group
// keeps its triangle count (Euler); a group whose new triangulation does not (overlapping input,
// which check_plc then names) is left as it was, and said so.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

struct FacetTriangulationOptions {
  bool merge_coplanar = false;
  // A facet whose vertices are not in one plane (quadrilaterals of a scanned or smoothed
  // surface, off their plane by 1e-7): triangulated in its projection along the largest
  // component of its first polygon's Newell normal instead of refused, each triangle a boundary
  // face of its own with the facet's marker. Asked for, never silent: the count is in
  // FacetTriangulation::nonplanar_facets and a message. The projection must be simple, as a
  // planar facet's must (else refused by name).
  bool triangulate_nonplanar = false;
  // How messages name facet f (0-based): empty, "facet <f + 1>".
  std::function<std::string(std::size_t)> facet_name;
  std::uint32_t first_vertex_number = 1;  // how messages number vertices (0 for OFF)
};

struct FacetTriangulation {
  std::vector<std::array<std::uint32_t, 3>> triangles;  // vertex ids into the PLC's vertices
  std::vector<int> triangle_refs;                       // the facet's marker
  std::vector<std::uint32_t> triangle_facet;            // the facet it comes from (merged: the group's first)
  std::size_t polygon_facets = 0;      // facets triangulated in their plane (not one triangle)
  std::size_t segments_alone = 0;      // facets of segments and isolated vertices only (no area)
  std::size_t nonplanar_facets = 0;    // triangulate_nonplanar: facets triangulated in their projection
  std::vector<std::vector<std::uint32_t>> merged;  // merge_coplanar: each group of facets merged, sorted
  std::size_t merged_facets = 0;       // facets in those groups
  std::vector<std::string> messages;   // what the user should know (facets with no area left, ...)
};

// Throws InputError naming the facet (items: the facet, 0-based) for a corner out of range, a
// non-planar facet (and its farthest vertex), a degenerate or non-simple polygon, a segment from
// a vertex to itself, crossing polygons, or two vertices of a facet at the same point; and
// naming the vertex or hole point for a coordinate outside kernel/coordinate_range.hpp.
FacetTriangulation triangulate_facets(const Plc3& plc, const FacetTriangulationOptions& options = {});

}  // namespace dtlab
