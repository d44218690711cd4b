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
#include "bench/element_bench.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/error.hpp"
#include "verify/generators/points2d.hpp"

#if DTLAB_BENCH_WITH_CGAL
#include "bench/delaunay2d_cgal.hpp"
#endif

namespace dtlab::bench {
namespace {

constexpr std::uint64_t kSeed = 1;  // the seed `dtlab delaunay` uses by default
const char* const kDistributions[] = {"uniform", "normal", "grid", "circle", "clustered"};

using Build = ElementBuild<Vec2>;

void run(benchmark::State& state, const std::string& distribution, std::size_t n, const Build& build,
         Untimed& untimed) {
  const auto& points = cached_points<Vec2>(distribution, n, [](const std::string& d, std::size_t size) {
    return generate_points2d(d, size, kSeed);
  });
  run_element_bench<Vec2>(state, points, build, untimed, "triangles", "triangle");
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
