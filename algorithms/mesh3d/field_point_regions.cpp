// The field point insertion, one after the other or by regions (field_point_regions.hpp).
#include "algorithms/mesh3d/field_point_regions.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"

namespace dtlab {

namespace {

constexpr std::uint16_t kNoRegion = 0xFFFF;
constexpr std::uint32_t kNoKey = 0xFFFFFFFFu;
// The first pass's sample inserted before its regions: one point in kSeedStride (at h = 0.02 the
// sample of 1 in 8 and of 1 in 16 took the same 0.25 - 0.3 s: the empty mesh's large cavities;
// 1 in 16 leaves more to the regions).
constexpr std::size_t kSeedStride = 16;
// Slots taken for a region of m points: vertices for a share of them (the filter drops most of a
// pass's candidates: 65 - 85 % measured), tetrahedra for about 6.5 each (a ball outgrows its
// cavity by that much); a region that runs out leaves its points to the next round.
constexpr double kVertexShare = 0.4, kTetrahedraPerPoint = 2.5;

double largest_size(const Metric3& m) { return m.is_scalar() ? 1.0 / std::sqrt(m.m[0]) : sizes(m)[0]; }

}  // namespace

FieldPointInserter::FieldPointInserter(Mesh3& mesh, const ControlSpace3& control, VertexGrid& grid,
                                       const Mesh3dOptions& options)
    : mesh_(mesh), control_(control), grid_(grid), options_(options), team_(options.threads) {
  kernels_.reserve(team_.threads());
  for (unsigned k = 0; k < team_.threads(); ++k) kernels_.emplace_back(mesh);
}

std::uint64_t FieldPointInserter::corrections() const {
  std::uint64_t total = 0;
  for (const DelaunayKernel3& k : kernels_) total += k.corrections();
  return total;
}

// The sequential insertion of one point: the whole mesh is this thread's.
FieldPointInserter::Outcome FieldPointInserter::insert_point(const FieldPoint& f, DelaunayKernel3& kernel,
                                                             std::uint32_t& hint, std::vector<std::uint32_t>& ball_marks,
                                                             std::uint32_t mark) {
  const Metric3 mp = control_.metric_at(f.p, hint);
  if (grid_.any_closer(f.p, mp, largest_size(mp), options_.filter_distance, mesh_.points())) return Outcome::Filtered;
  // p lies on an edge that was internal when the pass began, so in the domain; the walk may pass
  // through the exterior.
  std::uint32_t start = mesh_.vertex_tetrahedron(f.near);
  if (mesh_.is_ghost(start)) start = mesh_.adjacent(start, 0);
  const Mesh3::Location loc = mesh_.locate(f.p, start);
  if (loc.where == Mesh3::Where::Outside || loc.where == Mesh3::Where::Vertex || !mesh_.in_domain(loc.tetrahedron))
    return Outcome::NotInserted;
  if (!kernel.find_cavity(f.p, mp, loc.tetrahedron)) return Outcome::NotInserted;
  if (mesh_.live_vertex_count() >= options_.max_vertices) {
    throw InputError("mesh3d: the mesh reached the vertex bound of " + std::to_string(options_.max_vertices) +
                     " (max_vertices; is the size far smaller than the domain?)");
  }
  const std::uint32_t v = kernel.commit(f.p, mp);
  if (ball_marks.size() < mesh_.tetrahedron_capacity()) ball_marks.resize(mesh_.tetrahedron_capacity(), 0);
  for (const std::uint32_t t : kernel.ball()) ball_marks[t] = mark;
  grid_.insert(v, f.p);
  return Outcome::Inserted;
}

// The insertion of one point within region r, on any thread: reads and writes only what is r's
// (field_point_regions.hpp), or leaves the point.
FieldPointInserter::Outcome FieldPointInserter::insert_point_in(std::uint16_t r, const FieldPoint& f,
                                                                DelaunayKernel3& kernel,
                                                                std::vector<std::uint32_t>& ball_marks,
                                                                std::uint32_t mark) {
  Region& w = regions_[r];
  const Mesh3::Region region{vertex_region_.data(), r};
  const Metric3 mp = control_.metric_at(f.p, w.hint);
  const double h_max = largest_size(mp);
  if (!grid_.all_cells(f.p, h_max, options_.filter_distance,
                       [&](std::size_t cell) { return region_of_cell_[cell] == r; }))
    return Outcome::Left;
  if (grid_.any_closer(f.p, mp, h_max, options_.filter_distance, mesh_.points())) return Outcome::Filtered;
  // The walk starts from the edge's end when that is r's, else from r's last ball.
  std::uint32_t start = Mesh3::kNone;
  if (vertex_region_[f.near] == r) {
    start = mesh_.vertex_tetrahedron(f.near);
    if (mesh_.is_ghost(start)) start = mesh_.adjacent(start, 0);
  }
  if ((start == Mesh3::kNone || !mesh_.in_region(start, region)) && w.last != Mesh3::kNone && mesh_.is_alive(w.last))
    start = w.last;
  if (start == Mesh3::kNone || !mesh_.in_region(start, region)) return Outcome::Left;
  const Mesh3::Location loc = mesh_.locate(f.p, start, false, &region);
  if (loc.blocked) return Outcome::Left;
  if (loc.where == Mesh3::Where::Outside || loc.where == Mesh3::Where::Vertex || !mesh_.in_domain(loc.tetrahedron))
    return Outcome::NotInserted;
  kernel.set_region(&region);
  const bool found = kernel.find_cavity(f.p, mp, loc.tetrahedron);
  kernel.set_region(nullptr);
  if (!found) return kernel.left_region() ? Outcome::Left : Outcome::NotInserted;
  const std::size_t nc = kernel.cavity().size(), nb = kernel.boundary().size();
  if (w.used_vertices == w.vertices.size() || (nb > nc && w.tetrahedra.size() < nb - nc)) return Outcome::Left;
  const std::uint32_t v = w.vertices[w.used_vertices++];
  mesh_.fill_vertex(v, f.p, mp);
  vertex_region_[v] = r;
  kernel.plan_slots(kernel.cavity(), nb, w.slots, &w.tetrahedra);
  kernel.commit_into(kernel.cavity(), kernel.boundary(), v, w.slots);
  kernel.give_back_unused(w.slots, nb, &w.tetrahedra);
  grid_.insert(v, f.p);
  for (const std::uint32_t t : kernel.ball()) ball_marks[t] = mark;
  w.last = kernel.ball().front();
  return Outcome::Inserted;
}

std::uint64_t FieldPointInserter::insert_sequentially(std::span<const FieldPoint> points,
                                                      std::span<const std::uint32_t> indices, Mesh3dStats& stats,
                                                      std::vector<std::uint32_t>& ball_marks, std::uint32_t mark) {
  std::uint64_t inserted = 0;
  for (std::size_t k = 0; k < indices.size(); ++k) {
    if ((k & 4095) == 0) poll_interrupt(options_.interrupt, "mesh3d: during the field point insertion");
    switch (insert_point(points[indices[k]], kernels_[0], hint_, ball_marks, mark)) {
      case Outcome::Inserted: ++inserted; break;
      case Outcome::Filtered: ++stats.filtered; break;
      case Outcome::NotInserted:
      case Outcome::Left: ++stats.not_inserted; break;
    }
  }
  return inserted;
}

std::uint64_t FieldPointInserter::insert(std::span<const FieldPoint> points, Mesh3dStats& stats,
                                         std::vector<std::uint32_t>& ball_marks, std::uint32_t mark) {
  const std::size_t n = points.size();
  const bool first_pass = first_pass_;
  first_pass_ = false;
  const std::size_t count =
      std::clamp<std::size_t>(n / std::max<std::uint32_t>(options_.insertion_region_points, 1), 1,
                              std::min<std::uint32_t>(std::max<std::uint32_t>(options_.insertion_regions, 1), 4096));
  std::vector<std::uint32_t> all;
  if (count < 2 || !grid_.dense() || mesh_.live_vertex_count() + n > options_.max_vertices) {
    all.resize(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = static_cast<std::uint32_t>(i);
    return insert_sequentially(points, all, stats, ball_marks, mark);
  }
  std::uint64_t inserted = 0;
  std::vector<std::uint32_t> todo, left;
  if (first_pass) {
    for (std::size_t i = 0; i < n; i += kSeedStride) all.push_back(static_cast<std::uint32_t>(i));
    inserted += insert_sequentially(points, all, stats, ball_marks, mark);
  }
  // Each cell's Hilbert index on a 1024^3 lattice over the grid (once: the grid is the run's).
  if (cell_key_.empty()) {
    const auto dims = grid_.dense_dims();
    const std::int64_t most = std::max({dims[0], dims[1], dims[2]});
    cell_key_.resize(grid_.dense_cell_count());
    const auto q = [&](std::int64_t x) { return static_cast<std::uint32_t>(std::min<std::int64_t>(1023, x * 1024 / most)); };
    for (std::size_t c = 0; c < cell_key_.size(); ++c) {
      const auto xyz = grid_.dense_cell(c);
      cell_key_[c] = hilbert_index3(q(xyz[0]), q(xyz[1]), q(xyz[2]));
    }
  }
  std::vector<std::uint32_t> keys(n, kNoKey), sorted;
  for (std::size_t i = 0; i < n; ++i) {
    if (first_pass && i % kSeedStride == 0) continue;
    const std::int64_t c = grid_.cell_of(points[i].p);
    if (c < 0) {
      left.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    keys[i] = cell_key_[static_cast<std::size_t>(c)];
    todo.push_back(static_cast<std::uint32_t>(i));
    sorted.push_back(keys[i]);
  }
  std::sort(sorted.begin(), sorted.end());
  // Two rounds, the second's cuts halfway between the first's.
  for (int round = 0; round < 2 && !todo.empty(); ++round) {
    std::vector<std::uint32_t> cuts;
    const std::size_t m = sorted.size();
    if (round == 0)
      for (std::size_t k = 1; k < count; ++k) cuts.push_back(sorted[k * m / count]);
    else
      for (std::size_t k = 0; k < count; ++k) cuts.push_back(sorted[(2 * k + 1) * m / (2 * count)]);
    inserted += region_round(points, keys, cuts, todo, ball_marks, mark, stats);
  }
  left.insert(left.end(), todo.begin(), todo.end());
  std::sort(left.begin(), left.end());
  stats.insertion_deferred += left.size();
  return inserted + insert_sequentially(points, left, stats, ball_marks, mark);
}

// One round of regions over the points `todo` (indices, in order), which then holds those left.
std::uint64_t FieldPointInserter::region_round(std::span<const FieldPoint> points, std::span<const std::uint32_t> keys,
                                               std::span<const std::uint32_t> cuts, std::vector<std::uint32_t>& todo,
                                               std::vector<std::uint32_t>& ball_marks, std::uint32_t mark,
                                               Mesh3dStats& stats) {
  poll_interrupt(options_.interrupt, "mesh3d: during the field point insertion");
  const auto region_of_key = [&](std::uint32_t key) {
    return static_cast<std::uint16_t>(std::upper_bound(cuts.begin(), cuts.end(), key) - cuts.begin());
  };
  region_of_cell_.resize(cell_key_.size());
  for (std::size_t c = 0; c < cell_key_.size(); ++c) region_of_cell_[c] = region_of_key(cell_key_[c]);
  const std::size_t count = cuts.size() + 1;
  regions_.assign(count, {});
  for (const std::uint32_t i : todo) regions_[region_of_key(keys[i])].points.push_back(i);
  // The slots, taken in region order (the same ids for every thread count).
  for (Region& w : regions_) {
    const double m = static_cast<double>(w.points.size());
    w.vertices.resize(static_cast<std::size_t>(kVertexShare * m) + 16);
    for (std::uint32_t& v : w.vertices) v = mesh_.take_vertex_slot();
    mesh_.take_tetrahedron_slots(static_cast<std::size_t>(kTetrahedraPerPoint * m) + 64, w.tetrahedra);
    std::reverse(w.tetrahedra.begin(), w.tetrahedra.end());
  }
  vertex_region_.assign(mesh_.vertex_capacity(), kNoRegion);
  for (std::uint32_t v = 0; v < mesh_.vertex_capacity(); ++v) {
    if (mesh_.is_dead_vertex(v)) continue;
    const std::int64_t c = grid_.cell_of(mesh_.point(v));
    if (c >= 0) vertex_region_[v] = region_of_cell_[static_cast<std::size_t>(c)];
  }
  // Nothing below may reallocate while the regions run.
  grid_.reserve_vertices(mesh_.vertex_capacity());
  if (ball_marks.size() < mesh_.tetrahedron_capacity()) ball_marks.resize(mesh_.tetrahedron_capacity(), 0);
  team_.run(count, [&](std::size_t r, unsigned worker) {
    Region& w = regions_[r];
    for (const std::uint32_t i : w.points) {
      switch (insert_point_in(static_cast<std::uint16_t>(r), points[i], kernels_[worker], ball_marks, mark)) {
        case Outcome::Inserted: ++w.inserted; break;
        case Outcome::Filtered: ++w.filtered; break;
        case Outcome::NotInserted: ++w.not_inserted; break;
        case Outcome::Left: w.left.push_back(i); break;
      }
    }
  });
  // Back on one thread: the new vertices' bookkeeping, the unused slots given back, in region order.
  std::uint64_t inserted = 0;
  todo.clear();
  for (Region& w : regions_) {
    for (std::size_t k = 0; k < w.vertices.size(); ++k) {
      if (k < w.used_vertices)
        mesh_.settle_vertex(w.vertices[k]);
      else
        mesh_.give_back_vertex_slot(w.vertices[k]);
    }
    for (auto it = w.tetrahedra.rbegin(); it != w.tetrahedra.rend(); ++it) mesh_.give_back_tetrahedron_slot(*it);
    stats.filtered += w.filtered;
    stats.not_inserted += w.not_inserted;
    inserted += w.inserted;
    todo.insert(todo.end(), w.left.begin(), w.left.end());
  }
  regions_.clear();
  std::sort(todo.begin(), todo.end());
  DTLAB_ASSERT(mesh_.live_vertex_count() <= options_.max_vertices);  // insert() checked live + points
  return inserted;
}

}  // namespace dtlab
