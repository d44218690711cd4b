// What the 3D optimization operators share (operators.hpp): the quality of a mesh tetrahedron in
// its vertex metrics, which facets, edges and vertices an operator may touch, and the
// replacement of a set of tetrahedra by another one with the same outer boundary (every
// operator: swaps, shell transformations, collapse, split).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh3.hpp"

namespace dtlab::optimize3d_detail {

// Q_K (kernel/quality.hpp) of the tetrahedron (a, b, c, d) of vertex ids, in their metrics
// (the worst over the four); +infinity when it is not positive (exact orient3d).
double quality(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept;
// Q_K of the live finite tetrahedron t.
double tetrahedron_quality(const Mesh3& mesh, std::uint32_t t) noexcept;
// Metric length of the edge uv (kernel/metric.hpp edge_length).
double edge_length(const Mesh3& mesh, std::uint32_t u, std::uint32_t v) noexcept;
// Whether (a, b, c, d) is positive, exactly.
bool positive(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept;

// A facet no operator may remove: constrained, or beside a tetrahedron outside the domain
// (ghost, exterior), or between two regions (tetrahedra of different references).
bool is_locked_facet(const Mesh3& mesh, std::uint32_t h) noexcept;
// Whether edge ab may be removed (its shell retriangulated, split or collapsed): not a
// constrained edge, every tetrahedron of its shell in the domain with one reference, no facet
// of the shell (those holding ab) constrained. `shell` and `ring` receive Mesh3::shell's output.
bool is_free_edge(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& shell,
                  std::vector<std::uint32_t>& ring);
// Whether v may be moved or removed: live, neither kFixed nor kOnBoundary, every tetrahedron
// around it in the domain with one reference, no constrained facet or edge at it. `ball`
// receives Mesh3::ball when true.
bool is_free_vertex(const Mesh3& mesh, std::uint32_t v, std::vector<std::uint32_t>& ball);

// A tetrahedron to create: positive, finite, with its reference.
struct NewTetrahedron {
  std::array<std::uint32_t, 4> v;
  int ref;
};

// Replaces the live tetrahedra `old_tetrahedra` by `new_tetrahedra`. Every facet of a new
// tetrahedron must be either a facet of the old set's outer boundary (it is linked to the
// tetrahedron outside and takes that facet's constraint) or shared with another new
// tetrahedron (unconstrained). Dead vertices are the caller's to remove. `slots` receives the
// new tetrahedra's slots.
void replace_tetrahedra(Mesh3& mesh, std::span<const std::uint32_t> old_tetrahedra,
                        std::span<const NewTetrahedron> new_tetrahedra, std::vector<std::uint32_t>& slots);

// The worst Q_K of a set of live tetrahedra / of candidates.
double worst_quality(const Mesh3& mesh, std::span<const std::uint32_t> tetrahedra) noexcept;
double worst_quality(const Mesh3& mesh, std::span<const NewTetrahedron> tetrahedra) noexcept;

}  // namespace dtlab::optimize3d_detail
