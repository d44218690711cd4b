// Wavefront OBJ files, the polygonal subset that surface meshes use, read as a PLC of polygon
// facets (mesh/io/tetgen_poly.hpp):
//
//   v x y z [w]      a vertex (w, if given, must be 1: no rational vertices); or v x y z r g b
//                    (a vertex colour, read and not kept)
//   f c1 c2 c3 ...   a face of 3 or more corners, each "v", "v/vt", "v//vn" or "v/vt/vn"
//   l c1 c2 ...      a polyline: each of its pieces a facet of one 2-corner polygon
//   p c1 ...         points: read and not kept (each vertex is in the PLC already)
//
// Vertex numbers count from 1 in file order; a negative one counts back from the last vertex
// read so far (-1 is the last), as the format says. Texture and normal indices are read as
// integers and not kept; vt, vn, vp, g, o, s, usemtl and mtllib lines are skipped. Each face or
// polyline piece is a facet in file order, marker 0 (OBJ has no references); vertex_markers are
// 0. '#' comments and blank lines may appear anywhere.
//
// ParseError at the line for: an unknown keyword, free-form geometry (cstype, curv, surf, ...),
// a line continued with '\', a vertex number 0 or out of range (positive ones are checked once
// the file is read: a face may name a vertex given after it), a face of fewer than 3 corners, a
// coordinate outside kernel/coordinate_range.hpp, a w other than 1. Planarity and simplicity of
// a face are decided later, exactly (algorithms/constrained3d/plc/facet_triangulation.hpp).
#pragma once

#include <istream>
#include <string>

#include "mesh/io/tetgen_poly.hpp"

namespace dtlab {

// `file_name` names the input in error messages.
Plc3 read_obj_surface(std::istream& in, const std::string& file_name);
Plc3 read_obj_surface(const std::string& path);

}  // namespace dtlab
