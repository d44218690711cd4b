// Output triangles that tile the pieces of a recovered surface: the 3D mesher cuts the surface in
// the size (Mesh3dOptions::keep_boundary off: constrained edges split at their metric midpoints,
// rounded), so an output boundary triangle is then a tile of one piece of the recovery rather than
// the piece itself. check_mesh3d (checks_mesh3d.hpp) places each such triangle in its piece here
// and then checks that the tiles of a piece cover its area.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

inline constexpr std::uint32_t kNoPiece = 0xFFFFFFFFu;

// A cut point is a point of the segment between its ends, rounded: a convex combination of their
// distances to the piece's plane plus a rounding of a few ulps. Its distance to the plane grows
// by at most those few ulps per level of cutting; kTileUlps ulps of the largest coordinate (a
// few hundred levels) is the tolerance, as the 2D check's 8 ulps for the cut points of a segment
// (checks_mesh2d.cpp), which are cut once.
inline constexpr double kTileUlps = 1024.0;

// For each triangle of `tiles` (indices into `tile_points`), the piece of `pieces` (indices into
// `piece_points`) that holds it: its three vertices within the tolerance of the piece's plane and
// its centroid inside the piece's triangle (closed, up to 1e-12 of its barycentric coordinates);
// kNoPiece where none does. The pieces are found by a uniform grid over their boxes.
std::vector<std::uint32_t> locate_tiles(std::span<const Vec3> piece_points,
                                        std::span<const std::array<std::uint32_t, 3>> pieces,
                                        std::span<const Vec3> tile_points,
                                        std::span<const std::array<std::uint32_t, 3>> tiles);

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace dtlab
