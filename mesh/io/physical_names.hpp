// Names of references, as Gmsh's $PhysicalNames give them: a (dimension, tag) pair and a name.
// A physical group of dimension d is the set of elements of dimension d whose reference (MeshData's
// *_refs) is the tag: 0 vertices, 1 edges, 2 triangles, 3 tetrahedra.
#pragma once

#include <string>

namespace dtlab {

struct PhysicalName {
  int dimension = 0;
  int tag = 0;
  std::string name;

  friend bool operator==(const PhysicalName&, const PhysicalName&) = default;
};

}  // namespace dtlab
