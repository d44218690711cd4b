// What the 3D optimization operators share (operators.hpp): the quality of a mesh tetrahedron in
// its vertex metrics, which facets, edges and vertices an operator may touch, and the
// replacement of a set of tetrahedra by another one with the same outer boundary (every
// operator: swaps, shell transformations, collapse, split).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/optimize3d/operators.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab::optimize3d_detail {

// Q_K (kernel/quality.hpp) of the tetrahedron (a, b, c, d) of points, in the four metrics (the
// worst). Q_K is invariant under scaling, so in isotropic metrics (h^-2 I, whatever h) it is the
// Euclidean Q_K: computed once instead of four times.
double quality_in(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma, const Metric3& mb,
                  const Metric3& mc, const Metric3& md) noexcept;
// quality_in of a tetrahedron known positive (the caller's exact orient3d): the same value
// without the flatness test.
double positive_quality_in(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                           const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept;
// Q_K (kernel/quality.hpp) of the tetrahedron (a, b, c, d) of vertex ids, in their metrics
// (the worst over the four); +infinity when it is not positive (exact orient3d).
double quality(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept;
// quality(), or +infinity as soon as one vertex metric's value reaches `bound` (a candidate that
// cannot be accepted costs one metric instead of four).
double quality_below(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                     double bound) noexcept;
// Q_K of the live finite tetrahedron t (positive: Mesh3's invariant, so no flatness test).
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
// `hint`: a live tetrahedron with edge ab (saves the search for one), or kNone.
bool is_free_edge(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& shell,
                  std::vector<std::uint32_t>& ring, std::uint32_t hint = Mesh3::kNone);
// Whether v may be moved or removed: live, neither kFixed nor kOnBoundary, every tetrahedron
// around it in the domain with one reference, no constrained facet at it (a constrained edge at
// v would make it kOnBoundary: mesh3.hpp). `ball` receives Mesh3::ball when true.
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

// Q_K of live tetrahedra by slot, for a pass in which no vertex moves, changes its metric or dies
// (swaps, shell transformations, splits): an entry keeps the vertices it was computed for, so a
// slot freed and reused by another tetrahedron is computed anew. The values are
// tetrahedron_quality's, bit for bit.
class QualityCache {
 public:
  double get(const Mesh3& mesh, std::uint32_t t) {
    if (t >= key_.size()) {
      key_.resize(std::max<std::size_t>(mesh.tetrahedron_capacity(), t + 1), kUnset);
      value_.resize(key_.size(), 0.0);
    }
    const auto v = mesh.tetrahedron(t);
    const auto& k = key_[t];
    // Element by element: std::array's == calls memcmp for 16 bytes, on the hottest path here.
    if (k[0] != v[0] || k[1] != v[1] || k[2] != v[2] || k[3] != v[3]) {
      key_[t] = v;
      value_[t] = tetrahedron_quality(mesh, t);
    }
    return value_[t];
  }
  double worst(const Mesh3& mesh, std::span<const std::uint32_t> tetrahedra) {
    double w = 0.0;
    for (const std::uint32_t t : tetrahedra) w = std::max(w, get(mesh, t));
    return w;
  }

 private:
  static constexpr std::array<std::uint32_t, 4> kUnset{Mesh3::kNone, Mesh3::kNone, Mesh3::kNone, Mesh3::kNone};
  std::vector<std::array<std::uint32_t, 4>> key_;
  std::vector<double> value_;
};

// Failed attempts remembered by slot (a vertex; a tetrahedron slot's edge, 6 t + k), each as the
// Mesh3 epoch opened when it failed (Mesh3::new_epoch): an attempt fails again, to the bit, while
// nothing it reads has changed since (Mesh3::changed_at below that epoch), so it is skipped. The
// epochs are kept as 32-bit offsets from the one the memo began at, all forgotten at once before
// they would overflow. A slot reused by a new tetrahedron needs no care: creating it touched its
// vertices.
class EpochMemo {
 public:
  explicit EpochMemo(const Mesh3& mesh) : base_(mesh.epoch()) {}
  // Whether slot i failed at an epoch after `changed` (the last change to what the attempt reads).
  bool failed_since(std::size_t i, std::uint64_t changed) const noexcept {
    return i < at_.size() && at_[i] != 0 && changed < base_ + at_[i];
  }
  void record(std::size_t i, std::uint64_t epoch) {
    if (epoch - base_ > 0xFFFFFFFFull) {
      std::fill(at_.begin(), at_.end(), 0u);
      base_ = epoch - 1;
    }
    if (i >= at_.size()) at_.resize(std::max(i + 1, at_.size() + at_.size() / 2), 0u);
    at_[i] = static_cast<std::uint32_t>(epoch - base_);
  }

 private:
  std::uint64_t base_;
  std::vector<std::uint32_t> at_;
};

// The memos of one optimize3d run: relocations by vertex, shell transformations by edge of a
// tetrahedron slot.
struct AttemptMemo {
  explicit AttemptMemo(const Mesh3& mesh) : relocation(mesh), shell(mesh) {}
  EpochMemo relocation, shell;
};

// The relaxation (8.13) of vertex relocation, shared by relocate.cpp and relocate_dihedral.cpp:
// P' = (1 - w) P + w T for each finite target T in turn and w = 1, 1/2, ... (`tries` values), each
// candidate with its metric from `field` (empty: v's own). The first that `accept(P', metric)`
// takes is applied: v moved there with that metric and every vertex of `ball` (v's) touched, its
// tetrahedra having changed shape (Mesh3's change epochs). True when v moved.
template <class Accept>
bool relax_vertex(Mesh3& mesh, std::uint32_t v, std::span<const Vec3> targets, std::uint32_t tries,
                  const MetricField3& field, std::span<const std::uint32_t> ball, Accept accept) {
  const Vec3 p = mesh.point(v);
  for (const Vec3& target : targets) {
    if (!std::isfinite(target.x) || !std::isfinite(target.y) || !std::isfinite(target.z)) continue;
    double w = 1.0;
    for (std::uint32_t k = 0; k < tries; ++k, w *= 0.5) {
      const Vec3 moved = (1.0 - w) * p + w * target;
      if (moved == p) break;
      const Metric3 metric = field ? field(moved) : mesh.metric(v);
      if (!accept(moved, metric)) continue;
      mesh.set_point(v, moved);
      mesh.set_metric(v, metric);
      for (const std::uint32_t t : ball)
        for (std::uint32_t i = 0; i < 4; ++i) mesh.touch(mesh.vertex(t, i));
      return true;
    }
  }
  return false;
}

// The local index (0..5, kEdges order: 01 02 03 12 13 23) of edge ab in tetrahedron t.
std::uint32_t local_edge(const Mesh3& mesh, std::uint32_t t, std::uint32_t a, std::uint32_t b) noexcept;

// The operators with their "before" Q_K read from `cache` (null: computed) and, for the shell
// transformation, failures remembered in `memo` (null: none; needs `hint`).
bool face_swap(Mesh3& mesh, std::uint32_t h, double margin, std::vector<std::uint32_t>* created, QualityCache* cache);
bool shell_transformation(Mesh3& mesh, std::uint32_t a, std::uint32_t b, double margin,
                          std::vector<std::uint32_t>* created, std::uint32_t hint, QualityCache* cache,
                          EpochMemo* memo = nullptr);
struct SwapPassResult {
  std::uint64_t face_swaps = 0;
  std::uint64_t shell_transformations = 0;
  bool limit_reached = false;
};
SwapPassResult swap_pass(Mesh3& mesh, double margin, std::span<const std::uint32_t> seeds, double threshold,
                         QualityCache& cache, AttemptMemo* memo = nullptr);
// The vertices a pass works on when a round is restricted to a region: empty, every vertex;
// else v when active[v] != 0, and every vertex made during the pass (v >= size).
using Region = std::span<const std::uint8_t>;
inline bool in_region(Region region, std::uint32_t v) noexcept {
  return region.empty() || v >= region.size() || region[v] != 0;
}
// relocate_sweep3 over the region's vertices, skipping those `memo` knows will fail (null: none).
std::uint64_t relocate_sweep(Mesh3& mesh, const MetricField3& field, const Relocate3Options& options, AttemptMemo* memo,
                             Region region = {});
// collapse_pass3 and split_pass3 over the edges with both ends in the region.
std::uint64_t collapse_pass(Mesh3& mesh, const Collapse3Options& options, Region region);
SplitPass3Result split_pass(Mesh3& mesh, const MetricField3& field, const Split3Options& options, Region region);

// The worst Q_K of a set of live tetrahedra / of candidates.
double worst_quality(const Mesh3& mesh, std::span<const std::uint32_t> tetrahedra) noexcept;
double worst_quality(const Mesh3& mesh, std::span<const NewTetrahedron> tetrahedra) noexcept;

}  // namespace dtlab::optimize3d_detail
