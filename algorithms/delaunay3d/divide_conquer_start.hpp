// The first facet of variant "divide-conquer": a hull facet of the perturbed Delaunay
// tetrahedralization, found by gift wrapping (Chand and Kapur 1970) with exact predicates only.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "kernel/vec.hpp"

namespace dtlab::dewall {

// Indices (a, b, c) into `points` (distinct, not all coplanar) of a triangle of the perturbed
// Delaunay tetrahedralization's hull, ordered so that every point q has orient3d(a, b, c, q) >= 0.
// O(n) predicates.
//
// How: a supporting plane through three non-collinear points (the plane x = min x, rotated about
// a line in it by up to two wrapping steps while it holds fewer); the set Q of points on it is a
// flat hull face. The lexicographically smallest point e0 is a corner of Q's hull; wrapping in
// the plane gives the next point e1 along Q's hull, the nearest on its ray, so that e0 e1 is a
// boundary edge of every triangulation. The triangle of the 2D perturbed Delaunay triangulation
// of Q on that edge is then found like make simplex one dimension down, by insphere_perturbed
// with a point d off the plane: for coplanar points its sign is d's side times the in-circle
// test of the plane under the same perturbation (d's cofactor vanishes), which is exactly how
// the hull of the perturbed Delaunay tetrahedralization is triangulated (the ghost rule of
// incremental.cpp).
std::array<std::uint32_t, 3> first_hull_facet(std::span<const Vec3> points);

}  // namespace dtlab::dewall
