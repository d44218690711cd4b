// Edge swap of book §8.3.1: the diagonal of the quadrilateral of two triangles is replaced by the
// other one when the worst shape quality Q_K of the pair (in the vertex metrics, §8.2) strictly
// improves. Validity is exact (orient2d of both new triangles: a strictly convex quadrilateral).
// The pass is the queue-driven one of §8.6.2: worst pairs first, the neighbours of each swap
// queued again; each swap lowers the pair's worst Q_K, so the pass ends (the bound is a net).
#include <algorithm>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

using optimize2d_detail::is_locked;
using optimize2d_detail::quality;
using optimize2d_detail::triangle_quality;

namespace {

// Q_K by triangle slot for one swap pass (triangle_quality's values), measured when first asked;
// a flip forgets its two slots. Only flips change the mesh during the pass.
class SlotQualities {
 public:
  explicit SlotQualities(const Mesh2& mesh)
      : mesh_(mesh), q_(mesh.triangle_capacity()), known_(mesh.triangle_capacity(), 0) {}
  double operator()(std::uint32_t t) {
    if (!known_[t]) {
      q_[t] = triangle_quality(mesh_, t);
      known_[t] = 1;
    }
    return q_[t];
  }
  void forget(std::uint32_t t) noexcept { known_[t] = 0; }

 private:
  const Mesh2& mesh_;
  std::vector<double> q_;
  std::vector<std::uint8_t> known_;
};

// try_swap with the pair's present qualities from `slot_quality(t)`.
template <class SlotQuality>
bool swap_if_better(Mesh2& mesh, std::uint32_t h, double margin, SlotQuality&& slot_quality) {
  if (is_locked(mesh, h)) return false;
  const std::uint32_t g = mesh.twin(h);
  // t1 = (p, a, b) with h = a -> b; t2 = (q, b, a). New pair (p, a, q), (q, b, p).
  const std::uint32_t p = mesh.vertex_at(h), a = mesh.origin(h), b = mesh.destination(h), q = mesh.vertex_at(g);
  if (orient2d(mesh.point(p), mesh.point(a), mesh.point(q)) != Sign::Positive ||
      orient2d(mesh.point(q), mesh.point(b), mesh.point(p)) != Sign::Positive) {
    return false;
  }
  const double before = std::max(slot_quality(Mesh2::triangle_of(h)), slot_quality(Mesh2::triangle_of(g)));
  const double after = std::max(quality(mesh, p, a, q), quality(mesh, q, b, p));
  if (!(after < before * (1.0 - margin))) return false;
  mesh.flip(h);
  return true;
}

}  // namespace

bool try_swap(Mesh2& mesh, std::uint32_t h, double margin) {
  return swap_if_better(mesh, h, margin, [&](std::uint32_t t) { return triangle_quality(mesh, t); });
}

SwapPassResult swap_pass(Mesh2& mesh, double margin, std::span<const std::uint32_t> seeds) {
  SwapPassResult result;
  // One queue entry per edge: the smaller of its two half-edges, marked while queued. The marks
  // live across calls (one buffer per thread, grown with the mesh, every mark cleared before
  // returning): split_pass calls this after every split with a handful of seeds, and a fresh
  // buffer per call would cost the size of the mesh each time.
  thread_local std::vector<std::uint8_t> queued;
  if (queued.size() < 3ull * mesh.triangle_capacity()) queued.resize(3ull * mesh.triangle_capacity(), 0);
  std::deque<std::uint32_t> queue;
  // Every mark still set is cleared on the way out (the bound, or an exception).
  struct ClearMarks {
    std::vector<std::uint8_t>& marks;
    std::deque<std::uint32_t>& left;
    ~ClearMarks() {
      for (const std::uint32_t h : left) marks[h] = 0;
    }
  } clear_marks{queued, queue};
  auto canonical = [&](std::uint32_t h) { return std::min(h, mesh.twin(h)); };
  auto push = [&](std::uint32_t h) {
    if (is_locked(mesh, h)) return;
    const std::uint32_t e = canonical(h);
    if (queued[e]) return;
    queued[e] = 1;
    queue.push_back(e);
  };
  // The whole-mesh pass measures each triangle once (for the order, then until it is flipped);
  // a seeded one, a handful of edges after a split, measures as it goes.
  std::optional<SlotQualities> cache;
  if (seeds.empty()) {
    cache.emplace(mesh);
    // Every unlocked edge, the worst pair first (ties by half-edge: deterministic).
    std::vector<std::pair<double, std::uint32_t>> order;
    for (std::uint32_t t = 0; t < mesh.triangle_capacity(); ++t) {
      if (!mesh.in_domain(t)) continue;
      const double qt = (*cache)(t);
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = Mesh2::half_edge(t, i);
        if (is_locked(mesh, h) || mesh.twin(h) < h) continue;
        order.emplace_back(std::max(qt, (*cache)(Mesh2::triangle_of(mesh.twin(h)))), h);
      }
    }
    std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    for (const auto& entry : order) push(entry.second);
  } else {
    for (const std::uint32_t h : seeds) push(h);
  }
  const std::uint64_t bound = 20ull * mesh.live_triangle_count() + 1000;
  while (!queue.empty()) {
    const std::uint32_t h = queue.front();
    queue.pop_front();
    queued[h] = 0;
    if (!mesh.is_alive(Mesh2::triangle_of(h))) continue;
    // flip keeps both slots (with other vertices): the quadrilateral's outer edges are edges of
    // these two triangles.
    const std::uint32_t t1 = Mesh2::triangle_of(h), t2 = Mesh2::triangle_of(mesh.twin(h));
    const bool swapped = cache ? swap_if_better(mesh, h, margin, *cache) : try_swap(mesh, h, margin);
    if (!swapped) continue;
    if (cache) {
      cache->forget(t1);
      cache->forget(t2);
    }
    if (++result.swaps >= bound) {
      result.limit_reached = true;
      break;
    }
    for (std::uint32_t i = 0; i < 3; ++i) {
      push(Mesh2::half_edge(t1, i));
      push(Mesh2::half_edge(t2, i));
    }
  }
  return result;
}

}  // namespace dtlab
