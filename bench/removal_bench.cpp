// Point removal against CGAL's remove() in the same process (issue 46): n uniform points (fixed
// seed), a fraction of them removed in a fixed random order, 2D (DynamicDelaunay2 against
// Delaunay_triangulation_2) and 3D (DynamicDelaunay3 against Delaunay_triangulation_3). Only the
// removals are timed; the runs of dtlab and CGAL alternate, and each case prints the median and
// the range (min..max) of each, and the ratio of medians dtlab / CGAL. The element counts of the
// two are compared (they triangulate the same survivors).
//
//   removal_bench [--n N] [--runs R] [--dim 2|3|0] [--fractions 0.1,0.5]
//
// Without CGAL (DTLAB_BENCH_WITH_CGAL unset) only dtlab runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/dynamic_delaunay2.hpp"
#include "algorithms/delaunay3d/dynamic_delaunay3.hpp"
#include "verify/generators/points2d.hpp"
#include "verify/generators/points3d.hpp"
#include "verify/generators/portable_random.hpp"
#if DTLAB_BENCH_WITH_CGAL
#include "bench/removal_cgal.hpp"
#endif

namespace dtlab::bench {
namespace {

struct Series {
  std::vector<double> seconds;
  double median() const {
    std::vector<double> s = seconds;
    std::sort(s.begin(), s.end());
    const std::size_t k = s.size();
    return k % 2 ? s[k / 2] : 0.5 * (s[k / 2 - 1] + s[k / 2]);
  }
  double min() const { return *std::min_element(seconds.begin(), seconds.end()); }
  double max() const { return *std::max_element(seconds.begin(), seconds.end()); }
};

std::vector<std::uint32_t> removal_order(std::size_t n, double fraction, std::uint64_t seed) {
  std::vector<std::uint32_t> all(n);
  std::iota(all.begin(), all.end(), 0u);
  portable::Rng rng(seed);
  portable::shuffle(all, rng);
  all.resize(static_cast<std::size_t>(fraction * static_cast<double>(n) + 0.5));
  return all;
}

template <class Dynamic, class Point>
double dtlab_remove(const std::vector<Point>& points, const std::vector<std::uint32_t>& order, std::size_t* elements) {
  Dynamic d(points);
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::uint32_t v : order) d.remove(v);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  *elements = d.finite_elements().size();
  return s;
}

template <int kDim, class Point>
void run_case(const std::vector<Point>& points, double fraction, int runs) {
  const std::vector<std::uint32_t> order = removal_order(points.size(), fraction, 7);
  Series mine, cgal;
  std::size_t my_elements = 0, cgal_elements = 0;
  for (int r = 0; r < runs; ++r) {
    if constexpr (kDim == 2) mine.seconds.push_back(dtlab_remove<DynamicDelaunay2>(points, order, &my_elements));
    else mine.seconds.push_back(dtlab_remove<DynamicDelaunay3>(points, order, &my_elements));
#if DTLAB_BENCH_WITH_CGAL
    CgalRemoval c;
    if constexpr (kDim == 2) c = cgal_remove2d(points, order);
    else c = cgal_remove3d(points, order);
    cgal.seconds.push_back(c.remove_seconds);
    cgal_elements = c.finite_elements;
#endif
  }
  std::printf("%dD n=%zu remove %4.0f%% (%zu points): dtlab median %.3f s [%.3f..%.3f]", kDim, points.size(),
              100.0 * fraction, order.size(), mine.median(), mine.min(), mine.max());
  if (!cgal.seconds.empty()) {
    std::printf("  CGAL median %.3f s [%.3f..%.3f]  dtlab/CGAL %.2f [%.2f..%.2f]%s", cgal.median(), cgal.min(),
                cgal.max(), mine.median() / cgal.median(), mine.min() / cgal.max(), mine.max() / cgal.min(),
                my_elements == cgal_elements ? "" : "  ELEMENT COUNTS DIFFER");
  }
  std::printf("  (%d interleaved runs, %zu elements left)\n", runs, my_elements);
  std::fflush(stdout);
}

}  // namespace
}  // namespace dtlab::bench

int main(int argc, char** argv) {
  using namespace dtlab;
  std::size_t n = 1'000'000;
  int runs = 5, dim = 0;
  std::vector<double> fractions{0.1, 0.5};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--n") n = std::stoull(value);
    else if (key == "--runs") runs = std::stoi(value);
    else if (key == "--dim") dim = std::stoi(value);
    else if (key == "--fractions") {
      fractions.clear();
      std::stringstream s(value);
      for (std::string f; std::getline(s, f, ',');) fractions.push_back(std::stod(f));
    } else {
      std::fprintf(stderr, "removal_bench: unknown option %s\n", key.c_str());
      return 1;
    }
  }
#if DTLAB_BENCH_WITH_CGAL
  std::printf("CGAL %s\n", bench::cgal_removal_version());
#endif
  if (dim == 0 || dim == 2) {
    const std::vector<Vec2> points = generate_points2d("uniform", n, 1);
    for (const double f : fractions) bench::run_case<2>(points, f, runs);
  }
  if (dim == 0 || dim == 3) {
    const std::vector<Vec3> points = generate_points3d("uniform", n, 1);
    for (const double f : fractions) bench::run_case<3>(points, f, runs);
  }
  return 0;
}
