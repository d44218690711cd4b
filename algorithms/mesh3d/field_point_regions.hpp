// The field points of one pass of the edge method (edge_points.cpp) inserted by the Delaunay
// kernel (delaunay_kernel.hpp), one after the other or by regions on several threads, with the
// same mesh for every thread count.
//
// One region (Mesh3dOptions::insertion_regions = 1, the default): the points in their order
// (Hilbert order of their edges), each filtered, located and inserted before the next.
//
// R regions (R from the option and the count of points, never from the threads): the filter
// grid's cells are ordered along a Hilbert curve and cut into R runs holding equal counts of the
// pass's points; a vertex belongs to the region of its cell, a tetrahedron to a region when its
// four vertices do. Each region inserts its points, in their order, on any thread, touching only
// its own tetrahedra: its walks and cavities stop at the first tetrahedron of another (the point
// is left for later), its filter looks only at its own cells (else left), its new vertices and
// tetrahedra go into slots taken for it beforehand in region order (Mesh3::take_vertex_slot,
// take_tetrahedron_slot). A tetrahedron next to one of region A's has three vertices in A, so it
// is no other region's and no other region links to it: the regions read and write disjoint
// words, and what each does depends only on the mesh as the round found it. A second round cuts
// halfway between the first's cuts for the points left; what is still left goes in one after the
// other. The first pass works on the empty mesh, whose tetrahedra span the domain and cross every
// cut: every sixteenth of its points goes in first, one after the other, to break them up. In the
// spirit of Marot, Pellerin, Remacle (2019) (algorithms/delaunay3d/parallel.cpp: points owned by
// slabs of space, the rest deferred to rounds with other cuts), with regions that do not depend on
// the thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/mesh3d/control_space.hpp"
#include "algorithms/mesh3d/delaunay_kernel.hpp"
#include "algorithms/mesh3d/mesh3d.hpp"
#include "algorithms/mesh3d/vertex_grid.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

struct FieldPoint {
  Vec3 p;
  std::uint32_t near;  // a vertex close to p, where the walk to p starts (the end of p's edge)
};

class FieldPointInserter {
 public:
  // Keeps references to all four; `options.threads` threads.
  FieldPointInserter(Mesh3& mesh, const ControlSpace3& control, VertexGrid& grid, const Mesh3dOptions& options);

  // Inserts what the filter keeps of one pass's `points`; marks the tetrahedra of each new
  // vertex's ball with `mark` in ball_marks (grown to the mesh's tetrahedron capacity). Adds to
  // stats (filtered, not_inserted, insertion_deferred; the cavity corrections: corrections()).
  // Returns the count inserted.
  std::uint64_t insert(std::span<const FieldPoint> points, Mesh3dStats& stats, std::vector<std::uint32_t>& ball_marks,
                       std::uint32_t mark);

  std::uint64_t corrections() const;

 private:
  enum class Outcome : std::uint8_t { Inserted, Filtered, NotInserted, Left };
  // A region's state within a round (a whole pass's for the sequential insertion).
  struct Region {
    std::vector<std::uint32_t> points;      // indices of the pass's points, in order
    std::vector<std::uint32_t> vertices;    // vertex slots taken for it, used from the front
    std::size_t used_vertices = 0;
    std::vector<std::uint32_t> tetrahedra;  // tetrahedron slots it may fill (a stack)
    std::vector<std::uint32_t> left;        // indices left for the next round
    std::vector<std::uint32_t> slots;
    std::uint64_t filtered = 0, not_inserted = 0, inserted = 0;
    std::uint32_t hint = ControlSpace3::kNoHint;
    std::uint32_t last = Mesh3::kNone;  // a tetrahedron of its last ball
  };

  Outcome insert_point(const FieldPoint& f, DelaunayKernel3& kernel, std::uint32_t& hint,
                       std::vector<std::uint32_t>& ball_marks, std::uint32_t mark);
  Outcome insert_point_in(std::uint16_t r, const FieldPoint& f, DelaunayKernel3& kernel,
                          std::vector<std::uint32_t>& ball_marks, std::uint32_t mark);
  std::uint64_t insert_sequentially(std::span<const FieldPoint> points, std::span<const std::uint32_t> indices,
                                    Mesh3dStats& stats, std::vector<std::uint32_t>& ball_marks, std::uint32_t mark);
  std::uint64_t region_round(std::span<const FieldPoint> points, std::span<const std::uint32_t> keys,
                             std::span<const std::uint32_t> cuts, std::vector<std::uint32_t>& todo,
                             std::vector<std::uint32_t>& ball_marks, std::uint32_t mark, Mesh3dStats& stats);

  Mesh3& mesh_;
  const ControlSpace3& control_;
  VertexGrid& grid_;
  const Mesh3dOptions& options_;
  WorkerTeam team_;
  std::vector<DelaunayKernel3> kernels_;  // one per thread; the first also for the sequential insertion
  std::uint32_t hint_ = ControlSpace3::kNoHint;  // the sequential insertion's, across passes
  bool first_pass_ = true;
  std::vector<std::uint32_t> cell_key_;        // per dense grid cell: its Hilbert index
  std::vector<std::uint16_t> region_of_cell_;  // per dense grid cell, this round
  std::vector<std::uint16_t> vertex_region_;   // per vertex slot, this round
  std::vector<Region> regions_;
};

}  // namespace dtlab
