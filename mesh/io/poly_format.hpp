// Triangle's .poly files: a planar straight line graph (PSLG) with holes and regions, as the
// documentation of Shewchuk's Triangle describes it (no code of Triangle is used).
//
//   <#vertices> [<dimension = 2> [<#attributes> [<#boundary markers: 0 or 1>]]]
//   <vertex #> <x> <y> [attributes...] [marker]          (the .node format, vertex after vertex)
//   <#segments> [<#boundary markers: 0 or 1>]
//   <segment #> <endpoint> <endpoint> [marker]
//   <#holes>
//   <hole #> <x> <y>
//   [<#regions>                                           (optional section)
//    <region #> <x> <y> <attribute> <maximum area>]
//
// A vertex count of 0 means the vertices are in a separate .node file (Triangle writes .poly
// files so): the path overload reads <path without .poly>.node, the stream overload takes them
// as an argument. Every list is numbered from 0 or 1, as its first entry says, and then
// consecutively; endpoints use the vertices' numbering. Omitted header fields take Triangle's
// defaults (2, 0, 0; 0 segment markers). Blank lines and '#' comments may appear anywhere.
//
// ParseError (file and line) for: a count that does not match the entries, a missing section,
// a field count other than the header announces, an endpoint out of range, a coordinate of a
// vertex, hole or region point outside kernel/coordinate_range.hpp, a non-finite attribute or
// area, text after the last section. Geometry is not the reader's business: crossing or
// repeated segments, segments through vertices, duplicate points and holes outside the domain
// go to the constrained triangulation, which reports them.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/io/triangle_format.hpp"

namespace dtlab {

struct PolyRegion {
  Vec2 point;
  double attribute = 0.0;
  double max_area = -1.0;  // Triangle's convention: negative = no area constraint

  friend bool operator==(const PolyRegion&, const PolyRegion&) = default;
};

struct PolyData2 {
  std::vector<Vec2> points;
  std::size_t attribute_count = 0;
  std::vector<double> attributes;  // attribute_count per point, point after point
  bool has_point_markers = false;
  std::vector<int> point_markers;  // one per point if has_point_markers, else empty
  int first_index = 1;             // 0 or 1: the number of the first vertex in the file

  std::vector<std::array<std::uint32_t, 2>> segments;  // endpoints, 0-based
  bool has_segment_markers = false;
  std::vector<int> segment_markers;  // one per segment if has_segment_markers, else empty

  std::vector<Vec2> holes;
  std::vector<PolyRegion> regions;

  friend bool operator==(const PolyData2&, const PolyData2&) = default;
};

// `file_name` names the input in error messages. `separate_nodes` supplies the vertices when the
// .poly's vertex count is 0 (without it, such a file has no vertices, and any segment is out of
// range).
PolyData2 read_triangle_poly(std::istream& in, const std::string& file_name,
                             const TriangleNodes* separate_nodes = nullptr);
PolyData2 read_triangle_poly(const std::string& path);

// Writes the vertices in the .poly itself, numbered from first_index (as every list is), and
// the region section even when empty. Malformed data (sizes, endpoints out of range, first_index
// not 0 or 1) is an InputError.
void write_triangle_poly(std::ostream& out, const PolyData2& poly);
void write_triangle_poly(const std::string& path, const PolyData2& poly);

}  // namespace dtlab
