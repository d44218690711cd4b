// The problem types of constrained tetrahedralization (book §3.5-§3.7): what a piecewise linear
// complex is as input, what a constrained tetrahedralization is as a result, where its Steiner
// points come from, and the exact check of their rounding. They sit below algorithms/ so that
// verify/ checks results without depending on the algorithms that make them;
// algorithms/constrained3d/constrained3d.hpp makes them, algorithms/mesh3d reads them.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "kernel/rounding.hpp"
#include "kernel/stats.hpp"
#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

struct RegionSeed3 {
  Vec3 point;
  int attribute = 0;
};

struct ConstrainedInput3 {
  std::span<const Vec3> points;
  std::span<const std::array<std::uint32_t, 3>> triangles;  // indices into points
  std::span<const int> triangle_refs;                        // empty, or one per triangle
  std::span<const Vec3> holes;                               // each removes the region holding it
  std::span<const RegionSeed3> regions;                      // each gives its region an attribute
  // Empty, or what input triangle t (0-based) is part of, for the input check's messages (the
  // facet it was cut from: facet_triangulation.hpp), e.g. "quadrilateral 2".
  std::function<std::string(std::uint32_t)> triangle_name = {};
};

// Where a Steiner point comes from: exact = a + t (b - a) for an edge (support {a, b}, with
// parameters {t, 0}), a + s (b - a) + t (c - a) for a triangle (support {a, b, c}, {s, t}).
struct SteinerPoint3 {
  enum class Kind : std::uint8_t { OnEdge, OnFace, Interior };
  Kind kind = Kind::OnEdge;
  std::uint32_t owner = 0;                   // the input triangle; for OnEdge, one triangle of the edge
  std::array<std::uint32_t, 3> support{};    // input vertex ids (OnEdge: the third unused)
  std::array<double, 2> parameters{};
};

struct SteinerCounts {
  std::uint32_t on_edges = 0, on_faces = 0, interior = 0;
  std::uint32_t total() const noexcept { return on_edges + on_faces + interior; }
};

struct Constrained3dPhaseTimes {
  double checks = 0, delaunay = 0, edge_recovery = 0, face_recovery = 0, regions = 0, total = 0;  // seconds
};

struct Constrained3dResult {
  // Input points in input order, then the Steiner points (steiner[i] is vertex
  // input_point_count + i).
  std::vector<Vec3> vertices;
  std::uint32_t input_point_count = 0;
  std::vector<SteinerPoint3> steiner;
  SteinerCounts steiner_points;
  // The pieces of the input triangles, each turned like its input triangle, with the input
  // triangle's index and reference (0 when no references were given).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> triangle_face;
  std::vector<int> triangle_refs;
  std::vector<std::uint32_t> triangle_facets;  // one facet handle of each in `tetrahedralization`
  // The kept tetrahedra, positive, and each one's region: with region seeds, the attribute of
  // the seed in it (0 where none); without, 1, 2, ... by first appearance; 0 for the exterior
  // when kept.
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<int> tetrahedron_regions;
  // The same per stored tetrahedron of `tetrahedralization`, as Mesh3 takes it: the region, or
  // Mesh3::kExterior for ghosts and tetrahedra outside the domain.
  std::vector<int> slot_regions;
  std::uint32_t region_count = 0;  // bounded regions kept
  // The whole tetrahedralization of the convex hull (closed by ghosts), exterior included.
  Tetrahedralization3 tetrahedralization;
  // Steiner points not within their rounding bound of the exact point (must be 0).
  std::uint32_t rounding_checks_failed = 0;
  std::uint32_t rounds = 0;  // insertion rounds of the recovery
  // Method "cdt" made a constrained Delaunay tetrahedralization (false where it handed over to
  // "recover", which messages then say; always false for the other methods).
  bool constrained_delaunay = false;
  std::vector<std::string> messages;
  PredicateStats predicate_stats;
  Constrained3dPhaseTimes seconds;
};

// Whether `vertex` lies within its rounding bound (kernel/rounding.hpp, decided exactly) of the
// exact point that Steiner record s stands for, on the input points.
bool steiner_point_within_rounding_bound(std::span<const Vec3> input_points, const SteinerPoint3& s,
                                         const Vec3& vertex);

// The exact point a + s (b - a) + t (c - a) of the triangle with corners `corners` of p.
ExactPoint3 exact_facet_point(std::span<const Vec3> p, const std::array<std::uint32_t, 3>& corners, double s, double t);

}  // namespace dtlab
