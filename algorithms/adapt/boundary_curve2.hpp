// The boundary of a 2D mesh under adaptation (book §9.3.1 with §10.5's geometric support, in
// 2D): its corners, kept, and a smooth curve through its other vertices on which boundary splits
// put their points, so that a curved boundary given as a polygon stays curved as it is refined
// instead of keeping the polygon's chords.
//
// Corners (book §10.5, §11.3.3 detect ridges and corners by angle): a boundary vertex where the
// boundary turns by more than the ridge angle, where other than two constrained edges meet, or
// where two boundary pieces of different references meet. Corners get Mesh2::kFixed (never moved
// or removed); the other boundary vertices lose it and keep kOnBoundary, so that boundary
// collapses (optimize2d boundary_collapse.cpp) may coarsen them.
//
// The support of a boundary edge ab: the cubic Hermite curve from a to b whose tangent at each
// end is the tangent at that end of the circle through the end and its two boundary neighbours
// (exact on circles, whatever the spacing; a straight run gives the straight line), one-sided at
// a corner (the circle through the corner, the other end and its next neighbour), the tangents'
// lengths those of the cubic Bezier that best fits a circular arc of the angle they make
// (4 tan(theta/4) R; de Casteljau's and Dokken's classical fit). Placement only: every decision
// on the points stays exact (try_split checks each new triangle by orient2d and falls back to
// the chord point).
#pragma once

#include <cstdint>

#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

// Sets kFixed on the corners of the boundary and clears it on its other vertices (interior
// vertices are left as they are). `ridge_angle_degrees` in [0, 180]. Returns the number of corners.
std::uint32_t mark_boundary_corners(Mesh2& mesh, double ridge_angle_degrees);

// The support point at parameter s in [0, 1] of the constrained half-edge h (origin a at s = 0,
// destination b at s = 1).
Vec2 boundary_support_point(const Mesh2& mesh, std::uint32_t h, double s);

}  // namespace dtlab
