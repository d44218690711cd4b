// The shared mutable 3D mesh (mesh3.hpp) built from a neutral 3D mesh (mesh/io/mesh_data3.hpp:
// a file's Vertices, Triangles and Edges with references, Tetrahedra with references), any
// tool's tetrahedral mesh with its boundary triangles (TetGen's, Gmsh's, dtlab's).
//
// Adjacency from the tetrahedra's facets; every facet with a tetrahedron on one side only is on
// the boundary: the outside is closed across it by a ghost (kInfinite, f0, f1, f2) with
// reference kExterior, the ghosts linked to each other around kInfinite across the boundary
// edges (the input need not be convex: ghosts close holes, cavities and concavities directly).
// Constrained facets: every Triangles entry (with its reference), every boundary facet not
// listed and every facet between tetrahedra of different references not listed (reference 0).
// Triangles entries that are interior faces with one region on both sides are internal
// constraints, unless every interior face is listed (TetGen's -g output): then none of them is;
// `messages` (when given) says which, with the count.
// Constrained edges: the edges of the constrained facets and every Edges entry. Vertices on a
// constrained facet or edge are kFixed | kOnBoundary, the others free (flags 0); vertices no
// tetrahedron uses are dead slots.
#pragma once

#include <string>
#include <vector>

#include "kernel/metric.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

// Vertex v of `data` is vertex v of the mesh, tetrahedron t slot t; every vertex gets `metric`.
// Throws InputError naming the item (numbered from 1) for a mesh without tetrahedra, a vertex
// number out of range, a tetrahedron that is not positive (exact orient3d: flat or negative), a
// facet in more than two tetrahedra or in two on the same side, a boundary that is not a closed
// 2-manifold (an edge on other than two boundary facets, a vertex where the boundary pinches: its
// tetrahedra not connected across facets), a Triangles entry that is not a facet of the tetrahedra,
// an Edges entry that is not an edge of them.
Mesh3 mesh3_from_data(const MeshData3& data, const Metric3& metric = {}, std::vector<std::string>* messages = nullptr);

}  // namespace dtlab
