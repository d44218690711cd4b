// Triangles per minute of every registered constrained method (algorithms/constrained2d) and of
// CGAL's Constrained_Delaunay_triangulation_2 (constrained2d_cgal.cpp, only when CGAL is found),
// on the same input:
//   random/<n>/<s>: n uniform points (verify/generators/points2d.hpp, seed 1) and s segments
//     that do not cross: a random choice of the Delaunay edges of the first 2s points;
//     (n, s) = (10^5, 10^4) and (10^6, 10^5);
//   star/<k>: a star-shaped polygon of k vertices at random radii (its boundary the segments),
//     k = 10^5 and 10^6.
// Each benchmark is named "constrained2d/<method or cgal>/<input>", e.g.
//   constrained2d_bench --benchmark_filter='random/1000000'
// Timed: one call from the input arrays to the triangulation (dtlab: Delaunay triangulation,
// segment insertion, the method, the domain; CGAL: point and constraint insertion), freed.
// triangles counts the finite triangles of the whole triangulation (the convex hull, as CGAL's).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/registry.hpp"
#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "mesh/element_sets2.hpp"
#include "verify/generators/points2d.hpp"

#if DTLAB_BENCH_WITH_CGAL
#include "bench/constrained2d_cgal.hpp"
#endif

namespace dtlab::bench {
namespace {

using Segment = std::array<std::uint32_t, 2>;

struct Input {
  std::vector<Vec2> points;
  std::vector<Segment> segments;
};

Input random_input(std::size_t n, std::size_t s) {
  Input in;
  in.points = generate_points2d("uniform", n, 1);
  const std::vector<Vec2> subset(in.points.begin(), in.points.begin() + static_cast<std::ptrdiff_t>(2 * s));
  std::vector<std::array<std::uint32_t, 2>> candidates = edges(delaunay2d(subset).triangulation);
  std::mt19937_64 rng(7);
  std::shuffle(candidates.begin(), candidates.end(), rng);
  candidates.resize(std::min(s, candidates.size()));
  in.segments.assign(candidates.begin(), candidates.end());
  return in;
}

Input star_input(std::size_t k) {
  Input in;
  std::mt19937_64 rng(k);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < k; ++i) {
    const double angle = (static_cast<double>(i) + 0.1 + 0.8 * u(rng)) * 6.283185307179586 / static_cast<double>(k);
    const double r = 0.5 + 0.5 * u(rng);
    in.points.push_back({r * std::cos(angle), r * std::sin(angle)});
    in.segments.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % k)});
  }
  return in;
}

// The input of the benchmark being run, cached by name (benchmarks are registered grouped by
// input).
const Input& input_named(const std::string& name) {
  static std::string cached_name;
  static Input cached;
  if (cached_name != name) {
    cached = {};
    if (name == "random/100000/10000") cached = random_input(100'000, 10'000);
    if (name == "random/1000000/100000") cached = random_input(1'000'000, 100'000);
    if (name == "star/100000") cached = star_input(100'000);
    if (name == "star/1000000") cached = star_input(1'000'000);
    cached_name = name;
  }
  return cached;
}

using Build = std::function<std::size_t(const Input&)>;

void run(benchmark::State& state, const std::string& input_name, const Build& build) {
  const Input& in = input_named(input_name);
  std::size_t triangles = 0;
  try {
    for (auto _ : state) {
      triangles = build(in);
      benchmark::DoNotOptimize(triangles);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["points"] = static_cast<double>(in.points.size());
  state.counters["segments"] = static_cast<double>(in.segments.size());
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["triangles_per_minute"] =
      benchmark::Counter(60.0 * static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}

std::size_t dtlab_triangles(const Input& in, const std::string& method, std::uint32_t* steiner) {
  const ConstrainedInput2 ci{.points = in.points, .segments = in.segments, .segment_markers = {}, .holes = {},
                             .regions = {}};
  const Constrained2dResult r = constrained2d(ci, {.method = method});
  if (steiner) *steiner = r.crossing_steiner_points + r.split_steiner_points;
  return r.triangulation.finite_triangle_count();
}

void register_all() {
  const char* const inputs[] = {"random/100000/10000", "star/100000", "random/1000000/100000", "star/1000000"};
  for (const std::string input : inputs) {
    for (const Constrained2dMethod& m : constrained2d_methods()) {
      const std::string method(m.name);
      benchmark::RegisterBenchmark(("constrained2d/" + method + "/" + input).c_str(),
                                   [input, method](benchmark::State& state) {
                                     run(state, input, [&](const Input& in) {
                                       std::uint32_t steiner = 0;
                                       const std::size_t t = dtlab_triangles(in, method, &steiner);
                                       state.counters["steiner_points"] = steiner;
                                       return t;
                                     });
                                   })
          ->Unit(benchmark::kMillisecond);
    }
#if DTLAB_BENCH_WITH_CGAL
    benchmark::RegisterBenchmark(("constrained2d/cgal/" + input).c_str(),
                                 [input](benchmark::State& state) {
                                   run(state, input, [](const Input& in) {
                                     return cgal_cdt_triangles(in.points, in.segments);
                                   });
                                 })
        ->Unit(benchmark::kMillisecond);
#endif
  }
}

}  // namespace
}  // namespace dtlab::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
#if DTLAB_BENCH_WITH_CGAL
  benchmark::AddCustomContext("cgal_version", dtlab::bench::cgal_cdt_version());
#endif
  dtlab::bench::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
