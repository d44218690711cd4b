// The shared mutable mesh (mesh2.hpp) built from a neutral 2D mesh (mesh/io/mesh_data.hpp: a
// file's Vertices, Edges with references, Triangles with references).
//
// Adjacency from the triangles' edges; every edge with a triangle on one side only is on the
// boundary: the outside is closed across it by a ghost (kInfinite, b, a) with reference
// kExterior, the ghosts linked to each other around kInfinite (the input need not be convex:
// ghosts close holes and concavities directly). Constrained: every Edges entry (with its
// reference) and every boundary edge not listed (reference 0). Vertices on a constrained edge
// are kFixed | kOnBoundary, the others free (flags 0); vertices no triangle uses are dead slots.
#pragma once

#include "kernel/metric.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

// Vertex v of `data` is vertex v of the mesh, triangle t slot t; every vertex gets `metric`. Throws
// InputError (numbered from 1) for a mesh without triangles, a vertex number out of range, a
// triangle that is not strictly counter-clockwise (exact orient2d), an edge in two triangles with
// the same orientation or in more than two, a boundary passing twice through a vertex, an Edges
// entry that is not an edge of the triangles.
Mesh2 mesh2_from_data(const MeshData2& data, const Metric2& metric = {});

}  // namespace dtlab
