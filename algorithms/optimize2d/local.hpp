// What the 2D optimization operators share (operators.hpp): the quality of a mesh triangle in
// its vertex metrics, which edges and vertices an operator may touch, and the replacement of a
// set of triangles by another one with the same outer boundary (collapse, split).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab::optimize2d_detail {

// Q_K (kernel/quality.hpp) of the triangle (a, b, c) of vertex ids, in their metrics.
double quality(const Mesh2& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept;
// Q_K of the live finite triangle t.
double triangle_quality(const Mesh2& mesh, std::uint32_t t) noexcept;
// Metric length of the edge uv (kernel/metric.hpp edge_length).
double edge_length(const Mesh2& mesh, std::uint32_t u, std::uint32_t v) noexcept;

// An edge no operator may change: constrained, or beside a triangle outside the domain (ghost,
// exterior, dead), or between two regions (triangles of different references).
bool is_locked(const Mesh2& mesh, std::uint32_t h) noexcept;

// Whether v may be moved or removed: live, neither kFixed nor kOnBoundary, every triangle around
// it in the domain with one reference, no constrained edge at it. `ring` receives its ball
// (Mesh2::ball: the half-edges opposite v, counter-clockwise) when true.
bool is_free(const Mesh2& mesh, std::uint32_t v, std::vector<std::uint32_t>& ring);

// A triangle to create: vertices counter-clockwise (kInfinite only first), reference.
struct NewTriangle {
  std::uint32_t a, b, c;
  int ref;
};

// Replaces the live triangles `old_triangles` by `new_triangles`. Every edge of a new triangle
// must be either an edge of the old set's outer boundary, in the same direction (it is linked to
// the triangle outside and takes that edge's constraint), or shared, reversed, with another new
// triangle (then it is constrained only if listed in `constrained`, with that reference). Dead
// vertices are the caller's to remove. `slots` receives the new triangles' slots.
void replace_triangles(Mesh2& mesh, std::span<const std::uint32_t> old_triangles,
                       std::span<const NewTriangle> new_triangles, std::span<const MeshEdge2> constrained,
                       std::vector<std::uint32_t>& slots);

}  // namespace dtlab::optimize2d_detail
