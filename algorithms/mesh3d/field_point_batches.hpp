// The field points of one pass of the edge method (edge_points.cpp) inserted by the Delaunay
// kernel (delaunay_kernel.hpp), on one thread or several, with the same mesh for every count.
//
// The pass's points, in their order (Hilbert order of their edges), are cut into S runs of
// consecutive points ("streams"; S from Mesh3dOptions::insertion_streams and the count of points,
// never from the threads). Each batch takes the next point of every stream, in three steps:
//   A. (threads) each point on its own, on the mesh as the batch found it, which nobody changes
//      meanwhile: its metric (the control space, a hint per stream), the grid filter, the
//      location, its corrected cavity — a pure function of the mesh and the point;
//   B. (one thread, stream order) which go in: not a point whose cavity holds a tetrahedron, a
//      twin of a boundary facet or a boundary vertex that an earlier point of the batch claimed
//      (a cavity found on parts that have not changed is the one that would be found now; such a
//      point is tried again in the next batch, on the new mesh), nor one that the grid, looked at
//      again where the batch put vertices (VertexGrid stamps), finds too close to one of them; the
//      others claim their parts, get their vertex and their slots (DelaunayKernel3::plan_slots);
//   C. (threads) the accepted balls written (DelaunayKernel3::commit_into), each thread in parts
//      no other thread reads or writes, on the streams it looked at in A; then, on one thread,
//      the unused slots given back in stream order.
// Each batch settles at least its first stream's point, so the loop ends within the count of
// points (a named error otherwise). With one stream every batch is one point: the sequential
// kernel, point after point in Hilbert order, the mesh of `commit` to the byte.
//
// Measured on the 2-core machine of the project (docs/performance_mesh3d.md): more streams
// cost cache locality (16 streams: about 1.5x the insertion time of one, on one thread), which
// two threads do not win back; so the default is one stream, and several streams with several
// threads are for machines with more cores. In the spirit of the speculative parallel
// Bowyer-Watson kernels (Kohout, Kolingerova, Zara 2005; Batista, Millman, Pion, Singler 2010),
// made deterministic by deciding in a fixed order.
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

  // Inserts what the filter keeps of `points`; marks the tetrahedra of each new vertex's ball
  // with `mark` in ball_marks (grown to the mesh's tetrahedron capacity). Adds to stats
  // (filtered, not_inserted, insertion_retries; the cavity corrections: corrections()). Returns
  // the count inserted.
  std::uint64_t insert(std::span<const FieldPoint> points, Mesh3dStats& stats, std::vector<std::uint32_t>& ball_marks,
                       std::uint32_t mark);

  std::uint64_t corrections() const;

 private:
  enum class State : std::uint8_t { Filtered, NotInserted, Ready, Lost, Accepted };
  struct Stream {
    std::size_t next = 0, end = 0;
    std::uint32_t hint = ControlSpace3::kNoHint;
    std::size_t metric_of = SIZE_MAX;  // the point whose metric `mp` is
    Metric3 mp;
    double h_max = 0;
    State state = State::NotInserted;
    std::vector<std::uint32_t> cavity, boundary;
    std::uint32_t vertex = 0;            // accepted: the new vertex
    std::vector<std::uint32_t> slots;    // accepted: where its ball goes (DelaunayKernel3::commit_into)
  };

  void look_at(Stream& s, std::span<const FieldPoint> points, DelaunayKernel3& kernel);
  bool lost(const Stream& s) const;
  void claim(const Stream& s);
  void next_stamp();

  Mesh3& mesh_;
  const ControlSpace3& control_;
  VertexGrid& grid_;
  const Mesh3dOptions& options_;
  WorkerTeam team_;
  std::vector<DelaunayKernel3> kernels_;  // one per thread; the first also commits
  std::vector<Stream> streams_;
  std::vector<std::uint32_t> active_;   // streams with points left, in order
  std::vector<std::uint32_t> touched_;         // per tetrahedron slot: the stamp of the batch that claimed it
  std::vector<std::uint32_t> vertex_touched_;  // per vertex: the same
  std::uint32_t stamp_ = 0;
};

}  // namespace dtlab
