// Triangles per minute of every registered 2D Delaunay variant (registry.hpp) and of CGAL's
// Delaunay_triangulation_2 (delaunay2d_cgal.cpp, only when CGAL is found), on the same points:
// n = 10^3 .. 10^6 (10^7 with --large), distributions uniform, normal, grid, circle, clustered
// (verify/generators/points2d.hpp, fixed seed). Each benchmark is named
// "delaunay2d/<variant or cgal>/<distribution>/<n>"; e.g.
//   delaunay2d_bench --benchmark_filter='/uniform/1000000$'
//
// Timed: one call that builds the triangulation from the points (input copy included) and
// frees it. Not timed: point generation, and one extra call that measures the call's peak heap
// (the operator new/delete below), reported as peak_heap_mb and heap_bytes_per_triangle.
// Peak resident memory of a whole run needs a process per run: scripts/bench_delaunay2d.py.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/error.hpp"
#include "verify/generators/points2d.hpp"

#if DTLAB_BENCH_WITH_CGAL
#include "bench/delaunay2d_cgal.hpp"
#endif

// --- Heap accounting ------------------------------------------------------------------------
// Every operator new/delete of this executable (dtlab's vectors, CGAL's containers) adds or
// removes the block's usable size, so the peak over one call is that call's working memory on
// the heap. A relaxed atomic add per allocation: both dtlab and CGAL allocate in large blocks.
// noinline: inlined into a caller, the free() below would meet the caller's `new` and trip
// -Wmismatched-new-delete.
namespace {
std::atomic<std::size_t> g_heap_bytes{0};
std::atomic<std::size_t> g_heap_peak{0};
}  // namespace

[[gnu::noinline]] void* operator new(std::size_t size) {
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
  g_heap_bytes.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
  std::free(p);
}
void operator delete[](void* p) noexcept { ::operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { ::operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { ::operator delete(p); }

namespace dtlab::bench {
namespace {

constexpr std::uint64_t kSeed = 1;  // the seed `dtlab delaunay` uses by default
const char* const kDistributions[] = {"uniform", "normal", "grid", "circle", "clustered"};

// Builds a triangulation of the points, frees it, returns its triangle count: all stored ones
// when `finite` is false (O(1), for the timed loop), else the finite ones.
using Build = std::function<std::size_t(std::span<const Vec2>, bool finite)>;

// The points of the benchmark being run. Benchmarks are registered grouped by (distribution,
// n), so one cached set is enough, and a 10^7 set does not outlive its group.
const std::vector<Vec2>& points_for(const std::string& distribution, std::size_t n) {
  static std::string cached_distribution;
  static std::vector<Vec2> cached;
  if (cached_distribution != distribution || cached.size() != n) {
    cached = {};
    cached = generate_points2d(distribution, n, kSeed);
    cached_distribution = distribution;
  }
  return cached;
}

// Measured once per benchmark, outside the timed loop.
struct Untimed {
  bool done = false;
  std::size_t finite_triangles = 0;
  std::size_t peak_heap_bytes = 0;
};

void run(benchmark::State& state, const std::string& distribution, std::size_t n, const Build& build,
         Untimed& untimed) {
  const std::vector<Vec2>& points = points_for(distribution, n);
  try {
    if (!untimed.done) {
      const std::size_t before = g_heap_bytes.load();
      g_heap_peak.store(before);
      untimed.finite_triangles = build(points, true);
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
  const double triangles = static_cast<double>(untimed.finite_triangles);
  state.counters["triangles"] = triangles;
  state.counters["triangles_per_minute"] =
      benchmark::Counter(60.0 * triangles, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_heap_mb"] = static_cast<double>(untimed.peak_heap_bytes) / (1024.0 * 1024.0);
  state.counters["heap_bytes_per_triangle"] =
      triangles > 0 ? static_cast<double>(untimed.peak_heap_bytes) / triangles : 0.0;
}

std::size_t dtlab_triangles(std::span<const Vec2> points, const std::string& algorithm, bool finite) {
  Delaunay2dOptions options;
  options.algorithm = algorithm;
  const Delaunay2dResult result = delaunay2d(points, options);
  if (!result.degenerate_message.empty()) throw InputError("no triangles: " + result.degenerate_message);
  return finite ? result.triangulation.finite_triangle_count() : result.triangulation.triangle_count();
}

void add(const std::string& implementation, const std::string& distribution, std::size_t n, Build build) {
  const std::string name = "delaunay2d/" + implementation + "/" + distribution + "/" + std::to_string(n);
  auto untimed = std::make_shared<Untimed>();
  benchmark::RegisterBenchmark(name.c_str(),
                               [distribution, n, build, untimed](benchmark::State& state) {
                                 run(state, distribution, n, build, *untimed);
                               })
      ->Unit(benchmark::kMillisecond);
}

void register_all(bool large) {
  std::vector<std::size_t> sizes = {1'000, 10'000, 100'000, 1'000'000};
  if (large) sizes.push_back(10'000'000);
  for (const std::size_t n : sizes) {
    for (const std::string distribution : kDistributions) {
      for (const Delaunay2dVariant& variant : delaunay2d_variants()) {
        const std::string algorithm(variant.name);
        add(algorithm, distribution, n, [algorithm](std::span<const Vec2> points, bool finite) {
          return dtlab_triangles(points, algorithm, finite);
        });
      }
#if DTLAB_BENCH_WITH_CGAL
      add("cgal", distribution, n, [](std::span<const Vec2> points, bool finite) {
        return cgal_delaunay2d_triangles(points, finite ? FaceCount::finite : FaceCount::stored);
      });
#endif
    }
  }
}

}  // namespace
}  // namespace dtlab::bench

int main(int argc, char** argv) {
  // Our one flag, taken out before Google Benchmark parses the rest.
  bool large = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--large") == 0) {
      large = true;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("dtlab_commit", dtlab::build_info::kCommit);
  benchmark::AddCustomContext("compiler", dtlab::build_info::kCompiler);
  benchmark::AddCustomContext("build_type", dtlab::build_info::kBuildType);
  benchmark::AddCustomContext("flags", dtlab::build_info::kFlags);
  benchmark::AddCustomContext("seed", std::to_string(dtlab::bench::kSeed));
#if DTLAB_BENCH_WITH_CGAL
  benchmark::AddCustomContext("cgal", dtlab::bench::cgal_version());
#endif
  dtlab::bench::register_all(large);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
