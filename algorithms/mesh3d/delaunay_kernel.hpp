// Point insertion by the constrained Delaunay kernel in 3D (book §2.2, T_{i+1} = T_i - C_P + B_P;
// §7.9-§7.10) on the shared mesh, isotropic or anisotropic (§4.3). The cavity C_P is grown by
// adjacency from the tetrahedron holding P, never across a constrained facet nor into the
// exterior; a tetrahedron with a constrained facet whose other side is already in the cavity does
// not join (§7.10: a specified face must not end up inside a cavity without being crossed), so no
// constrained facet, and no edge of one, is ever removed. The empty-sphere test is taken in the
// metric at P (Borouchaki, George, Hecht, Laug, Saltel 1997, part I, §3): the exact insphere
// predicate on the images under M(P)^1/2 (rounded to double); where M(P) is isotropic it is the
// Euclidean exact insphere. A tie (P on a sphere) is no conflict.
// The cavity is then corrected (§2.6.3) until it is star-shaped with respect to P: every boundary
// facet sees P strictly on its inner side (exact orient3d) and every vertex of the cavity lies on
// its boundary; the tetrahedron behind an offending facet (or around an enclosed vertex) leaves
// the cavity. With positive cones over a closed boundary of degree one around P, the ball B_P
// tiles the cavity, so the new mesh is valid in doubles whatever the metric.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

class DelaunayKernel3 {
 public:
  explicit DelaunayKernel3(Mesh3& mesh) : mesh_(mesh) {}

  // Computes and corrects the cavity of p (metric mp) from `seed`, a domain tetrahedron holding p
  // (inside or on its boundary; Mesh3::locate). False when p cannot be inserted there: it lies on
  // a vertex, or on a constrained facet, or the corrected cavity loses the seed.
  bool find_cavity(const Vec3& p, const Metric3& mp, std::uint32_t seed);

  // Keeps the cavities in a part of the mesh (null: anywhere): find_cavity fails, with
  // left_region() set, when a tetrahedron outside it would join. The seed must be in it.
  void set_region(const Mesh3::Region* region) noexcept { region_ = region; }
  bool left_region() const noexcept { return left_region_; }

  // The smallest metric length (in mp) from p to a vertex of the cavity found last.
  double nearest_cavity_vertex(const Vec3& p, const Metric3& mp) const;

  // Replaces the cavity found last by the ball of a new vertex p (metric mp, flags); returns its id.
  std::uint32_t commit(const Vec3& p, const Metric3& mp, std::uint8_t flags = 0);
  // The write half of commit, for the cavity found last, given as cavity() and boundary() gave
  // them: the ball of v (added already, no tetrahedron yet) goes into the first boundary.size()
  // of `slots` (the cavity's tetrahedra and taken slots: plan_slots); the cavity's tetrahedra
  // are killed, those left in `slots` past the ball are the caller's to give back
  // (give_back_unused). Writes only those tetrahedra, the twins of the boundary facets and the
  // vertices of the ball, and takes nothing from the mesh's free lists: kernels on several
  // threads may commit at once in parts of the mesh that share none of these
  // (field_point_regions.hpp).
  void commit_into(std::span<const std::uint32_t> cavity, std::span<const std::uint32_t> boundary, std::uint32_t v,
                   std::span<const std::uint32_t> slots);
  // commit's choice of slots for commit_into, and its giving back of those past the ball once the
  // ball is in: from and to the mesh's free list (one thread), or a caller's stack of slots taken
  // beforehand (`pool`: a region of field_point_regions.hpp, on any thread).
  void plan_slots(std::span<const std::uint32_t> cavity, std::size_t ball_size, std::vector<std::uint32_t>& slots,
                  std::vector<std::uint32_t>* pool = nullptr);
  void give_back_unused(std::span<const std::uint32_t> slots, std::size_t ball_size,
                        std::vector<std::uint32_t>* pool = nullptr);

  // The cavity found last: its tetrahedra, and the facet handles of those whose twin is outside.
  const std::vector<std::uint32_t>& cavity() const noexcept { return cavity_; }
  const std::vector<std::uint32_t>& boundary() const noexcept { return boundary_; }
  std::size_t cavity_size() const noexcept { return cavity_.size(); }
  // Tetrahedra of the last committed ball.
  const std::vector<std::uint32_t>& ball() const noexcept { return ball_; }
  std::uint64_t corrections() const noexcept { return corrections_; }

 private:
  bool in_conflict(std::uint32_t t, const Vec3& p) const;
  void grow(std::uint32_t seed, const Vec3& p);
  bool faces_cavity_across_constraint(std::uint32_t t) const;
  std::uint32_t find_offender(std::uint32_t seed, const Vec3& p);

  Mesh3& mesh_;
  const Mesh3::Region* region_ = nullptr;
  bool left_region_ = false;
  Metric3 sqrt_m_;
  bool isotropic_ = true;
  std::vector<std::uint32_t> cavity_;    // tetrahedra
  std::vector<std::uint32_t> boundary_;  // facet handles of cavity tetrahedra whose twin is outside
  std::vector<std::uint32_t> ball_;
  std::vector<std::uint32_t> slots_;     // commit's: the cavity's tetrahedra, then taken slots
  std::vector<std::uint32_t> mark_;      // per tetrahedron: == stamp_ while in the cavity
  std::vector<std::uint32_t> excluded_;  // per tetrahedron: == exclusion_stamp_ once removed by a correction
  std::vector<std::uint32_t> vertex_mark_;
  struct Side {
    std::uint32_t a, b, c, outside;  // facet (a, b, c) seen from inside the cavity; the outside twin
    bool constrained;
    int ref;
  };
  std::vector<Side> sides_;
  struct Lateral {
    std::uint64_t edge;  // (min << 32 | max)
    std::uint32_t handle;
  };
  std::vector<Lateral> laterals_;
  std::vector<std::uint32_t> table_;  // commit's matching of the laterals (open addressing)
  static constexpr std::uint32_t kNone = Mesh3::kNone;
  std::uint32_t stamp_ = 0;
  std::uint32_t exclusion_stamp_ = 0;
  std::uint64_t corrections_ = 0;
};

}  // namespace dtlab
