// Batched, thread-count-independent insertion of the field points (field_point_batches.hpp).
#include "algorithms/mesh3d/field_point_batches.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

double largest_size(const Metric3& m) {
  const bool iso = m.m[1] == 0.0 && m.m[3] == 0.0 && m.m[4] == 0.0 && m.m[0] == m.m[2] && m.m[2] == m.m[5];
  return iso ? 1.0 / std::sqrt(m.m[0]) : sizes(m)[0];
}

}  // namespace

FieldPointInserter::FieldPointInserter(Mesh3& mesh, const ControlSpace3& control, VertexGrid& grid,
                                       const Mesh3dOptions& options)
    : mesh_(mesh), control_(control), grid_(grid), options_(options), team_(options.threads) {
  kernels_.reserve(options.threads);
  for (unsigned k = 0; k < options.threads; ++k) kernels_.emplace_back(mesh);
}

std::uint64_t FieldPointInserter::corrections() const {
  std::uint64_t total = 0;
  for (const DelaunayKernel3& k : kernels_) total += k.corrections();
  return total;
}

// On the mesh as the batch found it: only reads it (and the grid and the control space), and
// writes only s and this thread's kernel.
void FieldPointInserter::look_at(Stream& s, std::span<const FieldPoint> points, DelaunayKernel3& kernel) {
  const FieldPoint& f = points[s.next];
  if (s.metric_of != s.next) {  // a point tried again keeps its metric
    s.mp = control_.metric_at(f.p, s.hint);
    s.h_max = largest_size(s.mp);
    s.metric_of = s.next;
  }
  s.state = State::NotInserted;
  if (grid_.any_closer(f.p, s.mp, s.h_max, options_.filter_distance, mesh_.points())) {
    s.state = State::Filtered;
    return;
  }
  // p lies on an edge that was internal when the pass began, so in the domain; the walk may pass
  // through the exterior.
  std::uint32_t start = mesh_.vertex_tetrahedron(f.near);
  if (mesh_.is_ghost(start)) start = mesh_.adjacent(start, 0);
  const Mesh3::Location loc = mesh_.locate(f.p, start);
  if (loc.where == Mesh3::Where::Outside || loc.where == Mesh3::Where::Vertex || !mesh_.in_domain(loc.tetrahedron))
    return;
  if (!kernel.find_cavity(f.p, s.mp, loc.tetrahedron)) return;
  s.cavity.assign(kernel.cavity().begin(), kernel.cavity().end());
  s.boundary.assign(kernel.boundary().begin(), kernel.boundary().end());
  s.state = State::Ready;
}

// Whether an earlier insertion of this batch took a tetrahedron the cavity removes or links to,
// or a vertex of its boundary. The cavity's tetrahedra are checked first: while none changed,
// neither did their facets' twins nor their vertices.
bool FieldPointInserter::lost(const Stream& s) const {
  for (const std::uint32_t t : s.cavity)
    if (touched_[t] == stamp_) return true;
  for (const std::uint32_t h : s.boundary) {
    if (touched_[Mesh3::tetrahedron_of(mesh_.twin(h))] == stamp_) return true;
    for (const std::uint32_t v : mesh_.facet_vertices(h))
      if (vertex_touched_[v] == stamp_) return true;
  }
  return false;
}

// Claims what the stream's insertion will write (lost() for the later points of the batch).
void FieldPointInserter::claim(const Stream& s) {
  for (const std::uint32_t t : s.cavity) touched_[t] = stamp_;
  for (const std::uint32_t h : s.boundary) {
    touched_[Mesh3::tetrahedron_of(mesh_.twin(h))] = stamp_;
    for (const std::uint32_t v : mesh_.facet_vertices(h)) vertex_touched_[v] = stamp_;
  }
}

void FieldPointInserter::next_stamp() {
  if (stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(touched_.begin(), touched_.end(), 0);
    std::fill(vertex_touched_.begin(), vertex_touched_.end(), 0);
    grid_.clear_stamps();
    stamp_ = 0;
  }
  ++stamp_;
}

std::uint64_t FieldPointInserter::insert(std::span<const FieldPoint> points, Mesh3dStats& stats,
                                         std::vector<std::uint32_t>& ball_marks, std::uint32_t mark) {
  const std::size_t n = points.size();
  if (n == 0) return 0;
  const std::size_t count =
      std::clamp<std::size_t>(n / std::max<std::uint32_t>(options_.insertion_stream_length, 1), 1, std::max<std::uint32_t>(options_.insertion_streams, 1));
  streams_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    Stream& s = streams_[i];
    s.next = n * i / count;
    s.end = n * (i + 1) / count;
    s.metric_of = SIZE_MAX;
    s.hint = ControlSpace3::kNoHint;
  }
  // A. Each point on its own, on the mesh as the batch found it.
  const WorkerTeam::Body look = [&](std::size_t i, unsigned worker) {
    look_at(streams_[active_[i]], points, kernels_[worker]);
  };
  // C. The accepted insertions, each in its own part of the mesh; the same thread as in A for
  //    the same stream (the same count of active streams: the same shares), so its cavity is in
  //    that thread's cache.
  const WorkerTeam::Body write = [&](std::size_t i, unsigned worker) {
    Stream& s = streams_[active_[i]];
    if (s.state != State::Accepted) return;
    DelaunayKernel3& kernel = kernels_[worker];
    kernel.commit_into(s.cavity, s.boundary, s.vertex, s.slots);
    for (const std::uint32_t t : kernel.ball()) ball_marks[t] = mark;
  };
  const auto step = [&](const WorkerTeam::Body& body) {
    if (active_.size() == 1)
      body(0, 0);  // one stream: no hand-over
    else
      team_.run(active_.size(), body);
  };
  std::uint64_t inserted = 0;
  // Each batch settles at least its first stream's point (nothing has changed before it).
  for (std::size_t batch = 0;; ++batch) {
    if (batch > n) throw InternalError("mesh3d: the batched insertion did not end within one batch a point");
    active_.clear();
    for (std::uint32_t i = 0; i < count; ++i)
      if (streams_[i].next < streams_[i].end) active_.push_back(i);
    if (active_.empty()) break;
    poll_interrupt(options_.interrupt, "mesh3d: during the field point insertion");
    step(look);
    // B. In stream order, on this thread: which insertions go in, their vertex and slots.
    next_stamp();
    if (touched_.size() < mesh_.tetrahedron_capacity()) touched_.resize(mesh_.tetrahedron_capacity(), 0);
    if (vertex_touched_.size() < mesh_.vertex_capacity()) vertex_touched_.resize(mesh_.vertex_capacity(), 0);
    bool any = false;
    for (const std::uint32_t i : active_) {
      Stream& s = streams_[i];
      const FieldPoint& f = points[s.next];
      if (s.state == State::Filtered) {
        ++stats.filtered;
      } else if (s.state == State::NotInserted) {
        ++stats.not_inserted;
      } else if (lost(s)) {
        ++stats.insertion_retries;
        s.state = State::Lost;
        continue;  // the same point in the next batch
      } else if (grid_.stamped_near(f.p, s.h_max, options_.filter_distance, stamp_) &&
                 grid_.any_closer(f.p, s.mp, s.h_max, options_.filter_distance, mesh_.points())) {
        ++stats.filtered;
        s.state = State::Filtered;
      } else {
        if (mesh_.live_vertex_count() >= options_.max_vertices) {
          throw InputError("mesh3d: the mesh reached the vertex bound of " + std::to_string(options_.max_vertices) +
                           " (max_vertices; is the size far smaller than the domain?)");
        }
        claim(s);
        s.vertex = mesh_.add_vertex(f.p, s.mp);
        grid_.insert(s.vertex, f.p, stamp_);
        kernels_[0].plan_slots(s.cavity, s.boundary.size(), s.slots);
        s.state = State::Accepted;
        any = true;
        ++inserted;
      }
      ++s.next;
    }
    if (!any) continue;
    if (ball_marks.size() < mesh_.tetrahedron_capacity()) ball_marks.resize(mesh_.tetrahedron_capacity(), 0);
    step(write);
    // The cavities' tetrahedra their balls did not need, killed in C: given back only now, or a
    // later insertion of the batch could have taken one still in use.
    for (const std::uint32_t i : active_) {
      const Stream& s = streams_[i];
      if (s.state != State::Accepted) continue;
      kernels_[0].give_back_unused(s.slots, s.boundary.size());
    }
  }
  return inserted;
}

}  // namespace dtlab
