// TetGen's .poly and .smesh files: a 3D piecewise linear complex (PLC) with volume holes and
// regions, as TetGen's documentation (TetGen 1.5 manual §5.2) describes them; no code of
// TetGen is used.
//
//   Part 1  <#points> [<dimension = 3> [<#attributes> [<#boundary markers: 0 or 1>]]]
//           <point #> <x> <y> <z> [attributes...] [marker]     (the .node format)
//   Part 2  <#facets> [<#boundary markers: 0 or 1>]
//     .poly:  per facet  <#polygons> [<#holes> [<marker>]]
//                        <#corners> <corner 1> ... <corner n>   (one line per polygon)
//                        <hole #> <x> <y> <z>                   (one line per facet hole)
//     .smesh: per facet  <#corners> <corner 1> ... <corner n> [<marker>]
//   Part 3  <#holes>   then  <hole #> <x> <y> <z>
//   Part 4  (optional) <#regions>  then  <region #> <x> <y> <z> <attribute> [<maximum volume>]
//
// As TetGen's documentation says: a point count of 0 means the points are in a separate .node
// file (the path overload reads <path without extension>.node); a polygon of 1 or 2 corners is an
// isolated vertex or a segment inside its facet; a facet hole is a point whose projection onto
// the facet lies in the hole; a corner list may continue over several lines (the reader takes
// the tokens it needs from the following lines). The facet marker is present iff the facet list
// header's marker flag is 1 (.poly then needs the <#holes> field too); in a .smesh it must sit on
// the line of the last corner, so that a missing marker is reported there rather than taken from
// the next facet's line. Every list is numbered
// from 0 or 1, as its first entry says, and then consecutively; corners use the points'
// numbering. Point attributes are read as numbers and not kept (dtlab's constrained meshes do
// not carry them); a region without a maximum volume gets -1 (none), TetGen's convention.
//
// ParseError (file and line) for: a count that does not match the entries, a missing part, a
// field count other than the header announces, a corner out of range, a polygon with no corner,
// a coordinate of a point or hole outside kernel/coordinate_range.hpp, text after the last part.
// Geometry is not the reader's business: non-planar facets, crossing facets and duplicate
// points go to the PLC check, which names them.
#pragma once

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/tetgen_format.hpp"

namespace dtlab {

struct PlcFacet3 {
  std::vector<std::vector<std::uint32_t>> polygons;  // corners, 0-based; 1 or 2 corners: a vertex or segment
  std::vector<Vec3> holes;                           // facet holes (.poly only)
  int marker = 0;                                    // 0 without markers

  friend bool operator==(const PlcFacet3&, const PlcFacet3&) = default;
};

struct PlcRegion3 {
  Vec3 point;
  double attribute = 0.0;
  double max_volume = -1.0;  // TetGen's convention: negative = no volume constraint

  friend bool operator==(const PlcRegion3&, const PlcRegion3&) = default;
};

struct Plc3 {
  std::vector<Vec3> vertices;
  std::vector<int> vertex_markers;  // one per vertex (0 without markers); empty = all 0 (API input)
  std::vector<PlcFacet3> facets;
  std::vector<Vec3> holes;          // volume holes
  std::vector<PlcRegion3> regions;

  friend bool operator==(const Plc3&, const Plc3&) = default;
};

// `file_name` names the input in error messages; `separate_nodes` supplies the points when the
// point count is 0 (without it, such a file has no points and any corner is out of range).
Plc3 read_tetgen_poly(std::istream& in, const std::string& file_name, const TetGenNodes* separate_nodes = nullptr);
Plc3 read_tetgen_poly(const std::string& path);
Plc3 read_tetgen_smesh(std::istream& in, const std::string& file_name, const TetGenNodes* separate_nodes = nullptr);
Plc3 read_tetgen_smesh(const std::string& path);

// Writers number every list from 1 and write the points, markers and the region part. A .smesh
// holds one polygon per facet and no facet holes: anything else is an InputError naming the facet,
// as are corners out of range and vertex_markers of the wrong size.
void write_tetgen_poly(std::ostream& out, const Plc3& plc);
void write_tetgen_poly(const std::string& path, const Plc3& plc);
void write_tetgen_smesh(std::ostream& out, const Plc3& plc);
void write_tetgen_smesh(const std::string& path, const Plc3& plc);

// mesh/io's own split of the facets, kept for writers and the reader fuzz target: `dtlab
// constrain` triangulates facets with algorithms/constrained3d/plc/facet_triangulation.hpp instead
// (any simple planar polygon, holes, exact checks, the constrained Delaunay triangulation).
// The PLC's facets as a triangle surface: vertices and vertex_refs = vertex_markers; each
// triangle polygon becomes a triangle, each 2-corner polygon an edge, both with their facet's
// marker as reference; a 1-corner polygon adds nothing (its vertex is among the vertices). A
// polygon of more than 3 corners is split into a fan from its first corner when it is planar
// and strictly convex, both decided exactly (orient3d against its first three non-collinear
// corners; orient2d of its projection onto the coordinate plane where that triangle is not
// flat), keeping its corner order, so its orientation. Refused with an InputError naming the
// facet and polygon (items: the facet, 0-based): a non-planar polygon, a non-convex or
// self-intersecting one, one with three consecutive collinear corners or all corners collinear,
// a facet with holes ("facet holes are not supported yet").
MeshData3 triangulate_plc_facets(const Plc3& plc);

}  // namespace dtlab
