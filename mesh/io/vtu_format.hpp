// VTK XML unstructured grids (.vtu), written for ParaView and meshio: ASCII data arrays, the
// doubles in their shortest exact form (mesh/io/text_output.hpp), so nothing is rounded.
//
//   Points       the vertices (x y z; z = 0 for a 2D mesh, mesh/io/planar_mesh.hpp)
//   Cells        the edges (VTK_LINE), then the triangles (VTK_TRIANGLE), then the tetrahedra
//                (VTK_TETRA): the boundary pieces are cells beside the elements
//   CellData     "ref": each cell's reference (Int32); "dimension": 1, 2 or 3 (UInt8), which tells
//                the boundary pieces from the elements; then the caller's cell fields
//   PointData    "vertex_ref" (Int32); then the caller's point fields (a metric, a size, ...)
//
// VTU has no place for the names of the references (Gmsh's physical names): a caller converting
// from a format that has them says so.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

struct VtuField {
  std::string name;
  int components = 1;          // 1 (a scalar), 3 or 6 (a symmetric tensor in Medit's order), ...
  std::vector<double> values;  // components per point, or per cell in the order of the cells above
};

struct VtuFields {
  std::vector<VtuField> point_data;
  std::vector<VtuField> cell_data;
};

// InputError naming the element for a vertex number out of range or refs of the wrong size, and
// naming the field for values that are not `components` per point (cell) or are not finite.
void write_vtu(std::ostream& out, const MeshData3& mesh, const VtuFields& fields = {});
void write_vtu(const std::string& path, const MeshData3& mesh, const VtuFields& fields = {});

}  // namespace dtlab
