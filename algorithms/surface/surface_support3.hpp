// The geometric support of a triangulated surface (book §10.5, §11.3.3: "the support mesh which
// serves as geometric support"): a smooth surface through the input's vertices on which new
// boundary vertices are placed, so that refining a curved wall given by flat facets (a cylinder's
// chords) brings the wall closer to the curve instead of keeping the facets. Shared by surface
// remeshing and 3D adaptation; placement only: every decision on the mesh stays exact.
//
// Features (§10.5, §11.3.3, ridges first): an edge is a ridge where the normals of its two
// triangles turn by more than the ridge angle, where their references differ, or where it has one
// triangle (an open boundary). A vertex is a corner where other than two ridges meet, or where its
// two ridges turn by more than the ridge angle. The triangles around a vertex fall into sectors
// between its ridges; each sector has its own normal, so a ridge stays sharp: the sum of its
// corners' e1 x e2 / (|e1|^2 |e2|^2) (Max, "Weights for computing vertex normals from facet
// normals", 1999: exact when the vertex and its neighbours lie on a sphere; on the sphere test
// 8.9e-5 off where angle-weighted normals leave the support 1.2e-3 off). One-sided at a ridge, so
// biased there by about half a facet's turn (the UGAWG cube-cylinder's wall: 1.6e-3 at the
// midpoints of the edges from its ridge vertices; a quadric fit would remove it).
//
// The surface: over each triangle a cubic Bézier triangle (Vlachos, Peters, Boyd, Mitchell, "Curved
// PN triangles", 2001; MMGS builds its support the same way, Dapogny, Dobrzynski and Frey 2014),
// whose boundary curves depend only on their edge, so the surface is closed where the input is:
//   - a smooth edge ab leaves a along the projection of b - a on a's sector plane, and arrives at
//     b likewise;
//   - a ridge leaves a along the tangent at a of the circle through a's ridge neighbours and a
//     (the one-sided circle at a corner), as the 2D boundary curve does (adapt/boundary_curve2);
//   - the control points lie at |b - a| / (3 cos^2(theta / 4)) along those tangents, theta the
//     angle they make: the length of the cubic that best fits a circular arc (4 tan(theta/4) R),
//     so a circle is followed to O(theta^6) and a straight edge stays straight.
// The centre control point is PN's (E + (E - V) / 2). Points on an edge are computed from the
// edge alone, in the order of its lower vertex, so two triangles give the same bits there.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec.hpp"
#include "mesh/element_grid.hpp"

namespace dtlab {

struct SurfaceSupportOptions {
  // Adjacent normals turning by more than this make a ridge; ridges turning by more, a corner.
  double ridge_angle_degrees = 45.0;
  // An edge in more than two triangles, or across which two triangles are oriented differently
  // (internal interfaces of a volume mesh meeting the boundary): a ridge joining nothing, instead
  // of an InputError.
  bool non_manifold_ridges = false;
};

class SurfaceSupport3 {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  // A surface of triangles over `points` (orientation consistent across every edge; each edge in
  // one or two triangles), one reference per triangle (empty: all 0). InputError, naming the
  // triangle or edge (numbered from 1), for a vertex number out of range, a triangle of zero area,
  // an edge in more than two triangles, or two triangles oriented differently across an edge.
  SurfaceSupport3(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                  std::span<const int> triangle_refs = {}, const SurfaceSupportOptions& options = {});

  std::uint32_t triangle_count() const noexcept { return static_cast<std::uint32_t>(triangles_.size()); }
  const std::array<std::uint32_t, 3>& triangle(std::uint32_t t) const noexcept { return triangles_[t]; }
  const Vec3& point(std::uint32_t v) const noexcept { return points_[v]; }

  // Features. Edge i of triangle t joins its vertices i and i + 1 (mod 3).
  bool is_ridge(std::uint32_t t, std::uint32_t i) const noexcept { return ridge_[3 * t + i] != 0; }
  bool is_corner(std::uint32_t v) const noexcept { return corner_[v] != 0; }
  std::uint32_t ridge_count() const noexcept { return ridge_edges_; }
  std::uint32_t corner_count() const noexcept { return corners_; }
  // The triangle across edge i of t, or kNone on an open boundary.
  std::uint32_t neighbour(std::uint32_t t, std::uint32_t i) const noexcept { return neighbours_[3 * t + i]; }
  // The unit normal at vertex i of triangle t (its sector's).
  const Vec3& vertex_normal(std::uint32_t t, std::uint32_t i) const noexcept { return sector_normals_[sector_[3 * t + i]]; }

  // The support point of triangle t at barycentric coordinates w (w[i] >= 0 weighs vertex i; they
  // are normalised). On an edge (one weight 0) the edge's curve; at a vertex the vertex.
  Vec3 surface_point(std::uint32_t t, std::array<double, 3> w) const;
  // The point at parameter s in [0, 1] of the curve of edge i of triangle t, from its vertex i.
  Vec3 edge_point(std::uint32_t t, std::uint32_t i, double s) const;

  // The point of the flat triangles nearest to p (its triangle and barycentric coordinates) and
  // the support point there: a point near the surface (a chord's midpoint, a relocated vertex)
  // put on it.
  struct Foot {
    std::uint32_t triangle = kNone;
    std::array<double, 3> weights{};
    Vec3 flat;     // on the flat triangle
    Vec3 surface;  // on the support
  };
  Foot project(const Vec3& p) const;

 private:
  std::uint32_t edge_of(std::uint32_t t, std::uint32_t i) const noexcept { return edge_[3 * t + i]; }
  void build_features(double ridge_angle_degrees);
  void build_sectors();
  void build_edge_curves();
  Vec3 ridge_tangent(std::uint32_t v, std::uint32_t towards) const;
  // The curve of edge e at parameter r from its lower vertex.
  Vec3 edge_curve(std::uint32_t e, double r) const;

  std::vector<Vec3> points_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<int> refs_;
  std::vector<Vec3> face_normals_;
  std::vector<std::uint32_t> neighbours_;  // 3 per triangle, across edge i (vertices i, i + 1)
  std::vector<std::uint32_t> edge_;        // 3 per triangle: the undirected edge's number
  std::vector<std::uint8_t> ridge_;        // 3 per triangle
  std::vector<std::uint8_t> corner_;       // per vertex
  std::vector<std::array<std::uint32_t, 2>> ridge_neighbours_;  // per vertex: its ridge neighbours (kNone)
  std::vector<std::uint32_t> sector_;      // 3 per triangle: the sector of each corner
  std::vector<Vec3> sector_normals_;
  // Per undirected edge: its vertices, lower first, and the two inner control points of its cubic
  // from the lower vertex.
  std::vector<std::array<std::uint32_t, 2>> edge_vertices_;
  std::vector<std::uint32_t> edge_halves_;  // per undirected edge: one of its half-edges
  std::vector<std::array<Vec3, 2>> edge_controls_;
  std::vector<Vec3> centres_;  // per triangle: the control point b111
  std::uint32_t ridge_edges_ = 0, corners_ = 0;
  ElementGrid<Vec3> grid_;
};

// The point of triangle abc nearest to p, with its barycentric coordinates (Ericson, "Real-Time
// Collision Detection", §5.1.5: by the Voronoi regions of the vertices, edges and face).
struct TrianglePoint {
  Vec3 point;
  std::array<double, 3> weights{};
};
TrianglePoint nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace dtlab
