// Point insertion by the constrained Delaunay kernel (book §2.2, T_{i+1} = T_i - C_P + B_P) on the
// shared mesh, isotropic or anisotropic (§4.3): the cavity C_P is grown by adjacency from the
// triangle holding P, never across a constrained edge or into the exterior, with the empty-circle
// criterion taken in the metric at P (the simplest of the book's discrete approximations; Borouchaki,
// George, Hecht, Laug, Saltel 1997, part I, §3). Where M(P) is isotropic the test is the Euclidean
// one. Either way the test is the exact, perturbed incircle predicate on the points' images under
// M(P)^1/2 (rounded to double): decisions are reproducible and every variant agrees.
// The cavity is then corrected (§2.6.3) until it is star-shaped with respect to P: every boundary
// edge sees P strictly on its left (exact orient2d), and no vertex is enclosed; the triangle behind
// an offending edge (or around an enclosed vertex) leaves the cavity. The ball B_P reuses the
// cavity's slots, so the new mesh is valid in doubles whatever the metric.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

class DelaunayKernel2 {
 public:
  explicit DelaunayKernel2(Mesh2& mesh) : mesh_(mesh) {}

  // Computes and corrects the cavity of p (metric mp) from `seed`, a domain triangle holding p
  // (inside or on an edge; Mesh2::locate). False when p cannot be inserted there: it lies on a
  // vertex, or on a constrained edge, or the corrected cavity is empty.
  bool find_cavity(const Vec2& p, const Metric2& mp, std::uint32_t seed);

  // The smallest metric length (in mp, the metric at p) from p to a vertex of the cavity found
  // last: the vertices that become p's neighbours, among them its nearest one in a Delaunay
  // mesh. Used to filter field points without a search structure.
  double nearest_cavity_vertex(const Vec2& p, const Metric2& mp) const;

  // Replaces the cavity found last by the ball of a new vertex p (metric mp, flags); returns its id.
  std::uint32_t commit(const Vec2& p, const Metric2& mp, std::uint8_t flags = 0);

  std::size_t cavity_size() const noexcept { return cavity_.size(); }
  // Triangles of the last committed ball (new slots), for callers that queue work on them.
  const std::vector<std::uint32_t>& ball() const noexcept { return ball_; }
  std::uint64_t corrections() const noexcept { return corrections_; }

 private:
  bool in_conflict(std::uint32_t t, const Vec2& p_image) const;
  void grow(std::uint32_t seed, const Vec2& p_image);
  bool faces_cavity_across_constraint(std::uint32_t t) const;
  void stamp_grow();

  Mesh2& mesh_;
  Metric2 sqrt_m_;
  bool isotropic_ = true;
  std::vector<std::uint32_t> cavity_;    // triangles
  std::vector<std::uint32_t> boundary_;  // half-edges of cavity triangles whose twin is outside
  std::vector<std::uint32_t> ball_;
  std::vector<std::uint32_t> mark_;      // per triangle: == stamp_ while in the cavity
  std::vector<std::uint32_t> excluded_;  // per triangle: == stamp_ once removed by a correction
  std::vector<std::uint32_t> vertex_mark_;
  std::vector<std::uint32_t> vertex_slot_;
  struct Side {
    std::uint32_t a, b, outside;
    bool constrained;
    int ref;
  };
  std::vector<Side> sides_;
  std::uint32_t stamp_ = 0;
  std::uint32_t exclusion_stamp_ = 0;
  std::uint64_t corrections_ = 0;
};

}  // namespace dtlab
