// Tetrahedra per minute of every registered 3D Delaunay variant (registry.hpp) and of CGAL's
// Delaunay_triangulation_3 (delaunay3d_cgal.cpp, only when CGAL is found), on the same points:
// n = 10^3 .. 10^6 (10^7 with --large), distributions uniform, normal, grid, sphere, clustered
// (verify/generators/points3d.hpp, fixed seed: the points of `dtlab delaunay --dim 3 --random N
// --distribution D`). Each benchmark is named
// "delaunay3d/<variant or cgal>/<distribution>/<n>"; a parallel variant appears once per thread
// count, as "<variant>-t1" and "<variant>-t2". E.g.
//   delaunay3d_bench --benchmark_filter='/uniform/1000000$'
//
// Timed: one call that builds the tetrahedralization from the points (input copy included) and
// frees it. Not timed: point generation, and one extra call that measures the call's peak heap
// (the operator new/delete below), reported as peak_heap_mb and heap_bytes_per_tetrahedron.
// A variant that is registered but not written yet (its run throws InternalError "... not built
// yet") is left out. Peak resident memory needs a process per run: scripts/bench_delaunay3d.py.
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
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "bench/element_bench.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/error.hpp"
#include "verify/generators/points3d.hpp"

#if DTLAB_BENCH_WITH_CGAL
#include "bench/delaunay3d_cgal.hpp"
#endif

namespace dtlab::bench {
namespace {

constexpr std::uint64_t kSeed = 1;  // the seed `dtlab delaunay` uses by default
const char* const kDistributions[] = {"uniform", "normal", "grid", "sphere", "clustered"};
constexpr unsigned kParallelThreads[] = {1, 2};

using Build = ElementBuild<Vec3>;

void run(benchmark::State& state, const std::string& distribution, std::size_t n, const Build& build,
         Untimed& untimed) {
  const auto& points = cached_points<Vec3>(distribution, n, [](const std::string& d, std::size_t size) {
    return generate_points3d(d, size, kSeed);
  });
  run_element_bench<Vec3>(state, points, build, untimed, "tetrahedra", "tetrahedron");
}

std::size_t dtlab_tetrahedra(std::span<const Vec3> points, const Delaunay3dOptions& options, bool finite) {
  const Delaunay3dResult result = delaunay3d(points, options);
  if (!result.degenerate_message.empty()) throw InputError("no tetrahedra: " + result.degenerate_message);
  return finite ? result.tetrahedralization.finite_tetrahedron_count() : result.tetrahedralization.tetrahedron_count();
}

// False for a variant that is registered but refuses to run because it is not written yet; any
// other failure on this small input is the benchmark's to report, so the variant stays in.
bool is_built(const Delaunay3dOptions& options) {
  try {
    dtlab_tetrahedra(generate_points3d("uniform", 64, kSeed), options, false);
  } catch (const InternalError& e) {
    if (std::strstr(e.what(), "not built yet") != nullptr) return false;
  } catch (const std::exception&) {
  }
  return true;
}

bool is_parallel(std::string_view variant) { return variant.find("parallel") != std::string_view::npos; }

// (benchmark name, options) of every variant to run: one entry per thread count for a parallel one.
std::vector<std::pair<std::string, Delaunay3dOptions>> built_variants() {
  std::vector<std::pair<std::string, Delaunay3dOptions>> out;
  for (const Delaunay3dVariant& variant : delaunay3d_variants()) {
    Delaunay3dOptions options;
    options.algorithm = std::string(variant.name);
    if (!is_built(options)) continue;
    if (!is_parallel(variant.name)) {
      out.emplace_back(options.algorithm, options);
      continue;
    }
    for (const unsigned threads : kParallelThreads) {
      options.threads = threads;
      out.emplace_back(options.algorithm + "-t" + std::to_string(threads), options);
    }
  }
  return out;
}

void add(const std::string& implementation, const std::string& distribution, std::size_t n, Build build) {
  const std::string name = "delaunay3d/" + implementation + "/" + distribution + "/" + std::to_string(n);
  auto untimed = std::make_shared<Untimed>();
  benchmark::RegisterBenchmark(name.c_str(),
                               [distribution, n, build, untimed](benchmark::State& state) {
                                 run(state, distribution, n, build, *untimed);
                               })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

void register_all(bool large) {
  std::vector<std::size_t> sizes = {1'000, 10'000, 100'000, 1'000'000};
  if (large) sizes.push_back(10'000'000);
  const auto variants = built_variants();
  for (const std::size_t n : sizes) {
    for (const std::string distribution : kDistributions) {
      for (const auto& [name, options] : variants) {
        add(name, distribution, n, [options](std::span<const Vec3> points, bool finite) {
          return dtlab_tetrahedra(points, options, finite);
        });
      }
#if DTLAB_BENCH_WITH_CGAL
      add("cgal", distribution, n, [](std::span<const Vec3> points, bool finite) {
        return cgal_delaunay3d_tetrahedra(points, finite ? CellCount::finite : CellCount::stored);
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
