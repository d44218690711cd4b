// What a 3D mesh reader does with a tetrahedron that is not positive (orient3d <= 0, against
// MeshData3's convention, mesh_data3.hpp): refuse it by name, as every command that works on the
// mesh needs, or keep it as written, for `dtlab quality` to count the inverted and flat ones.
#pragma once

namespace dtlab {

enum class NonPositiveTetrahedra : unsigned char { Refuse, Keep };

}  // namespace dtlab
