// What the Delaunay benchmarks (delaunay2d_bench, delaunay3d_bench) share: heap accounting and
// the body of one benchmark (elements per minute, peak heap per element).
//
// Heap accounting: every operator new/delete of the executable (dtlab's vectors, CGAL's
// containers, a parallel variant's workers) adds or removes the block's usable size, so the
// peak over one call is that call's working memory on the heap. A relaxed atomic add per
// allocation: dtlab and CGAL allocate in large blocks. The replacement operators are defined
// here, so include this header in exactly one translation unit of an executable (its
// *_bench.cpp, never its CGAL companion). noinline: inlined into a caller, the free() below
// would meet the caller's `new` and trip -Wmismatched-new-delete.
#pragma once

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <functional>
#include <new>
#include <span>
#include <string>
#include <vector>

namespace dtlab::bench {
inline std::atomic<std::size_t> g_heap_bytes{0};
inline std::atomic<std::size_t> g_heap_peak{0};
}  // namespace dtlab::bench

[[gnu::noinline]] void* operator new(std::size_t size) {
  using dtlab::bench::g_heap_bytes, dtlab::bench::g_heap_peak;
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  const std::size_t now = g_heap_bytes.fetch_add(malloc_usable_size(p), std::memory_order_relaxed) +
                          malloc_usable_size(p);
  std::size_t peak = g_heap_peak.load(std::memory_order_relaxed);
  while (now > peak && !g_heap_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
  return p;
}
void* operator new[](std::size_t size) { return ::operator new(size); }
[[gnu::noinline]] void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  dtlab::bench::g_heap_bytes.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
  std::free(p);
}
void operator delete[](void* p) noexcept { ::operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { ::operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { ::operator delete(p); }

namespace dtlab::bench {

// Builds the mesh of the points, frees it, returns its element count: all stored ones when
// `finite` is false (O(1), for the timed loop), else the finite ones.
template <class Point>
using ElementBuild = std::function<std::size_t(std::span<const Point>, bool finite)>;

// Measured once per benchmark, outside the timed loop.
struct Untimed {
  bool done = false;
  std::size_t finite_elements = 0;
  std::size_t peak_heap_bytes = 0;
};

// The points of the benchmark being run, from generate(distribution, n). Benchmarks are
// registered grouped by (distribution, n), so one cached set is enough, and a 10^7 set does not
// outlive its group.
template <class Point, class Generate>
const std::vector<Point>& cached_points(const std::string& distribution, std::size_t n, Generate generate) {
  static std::string cached_distribution;
  static std::vector<Point> cached;
  if (cached_distribution != distribution || cached.size() != n) {
    cached = {};
    cached = generate(distribution, n);
    cached_distribution = distribution;
  }
  return cached;
}

// One benchmark: the untimed heap measurement once, then the timed builds; counters named after
// the element ("triangles", "triangles_per_minute", "heap_bytes_per_triangle").
template <class Point>
void run_element_bench(benchmark::State& state, const std::vector<Point>& points, const ElementBuild<Point>& build,
                       Untimed& untimed, const std::string& elements, const std::string& element) {
  try {
    if (!untimed.done) {
      const std::size_t before = g_heap_bytes.load();
      g_heap_peak.store(before);
      untimed.finite_elements = build(points, true);
      untimed.peak_heap_bytes = g_heap_peak.load() - before;
      untimed.done = true;
    }
    for (auto _ : state) {
      benchmark::DoNotOptimize(build(points, false));
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const double count = static_cast<double>(untimed.finite_elements);
  state.counters[elements] = count;
  state.counters[elements + "_per_minute"] =
      benchmark::Counter(60.0 * count, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_heap_mb"] = static_cast<double>(untimed.peak_heap_bytes) / (1024.0 * 1024.0);
  state.counters["heap_bytes_per_" + element] = count > 0 ? static_cast<double>(untimed.peak_heap_bytes) / count : 0.0;
}

}  // namespace dtlab::bench
