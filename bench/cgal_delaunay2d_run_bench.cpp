// One CGAL Delaunay_triangulation_2 run in a process of its own, so that the process's peak
// resident memory is that run's: the CGAL column of scripts/bench_delaunay2d.py, beside
// `dtlab delaunay --random N --distribution D --seed S --stats` for dtlab's variants.
//
//   cgal_delaunay2d_run_bench --random 1000000 --distribution uniform --seed 1
//   cgal_delaunay2d_run_bench --random 1000000 --distribution uniform --seed 1 --write-node points.node
//
// The first prints one JSON line with the fields of `dtlab delaunay --stats` that the script reads
// (points, elements, seconds, elements_per_minute, peak_rss_mb). The points are dtlab's
// (verify/generators/points2d.hpp), bit for bit; seconds cover the conversion of the input and
// the insertion, as dtlab's cover its input copy and triangulation. The second triangulates
// nothing: it writes the same points as a Triangle .node file (17 significant digits, which read
// back to the same doubles), so that Shewchuk's Triangle runs on them too. Not a Google Benchmark: the
// "_bench" suffix puts it in bench/CMakeLists.txt's glob, and "cgal" in its name builds it only
// when CGAL is found.
#include <sys/resource.h>

#include <CGAL/version.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bench/delaunay2d_cgal_impl.hpp"
#include "verify/generators/points2d.hpp"

namespace {

struct Args {
  std::size_t n = 0;
  std::string distribution = "uniform";
  std::uint64_t seed = 1;  // `dtlab delaunay`'s default
  std::string node_file;   // non-empty: write the points there instead of triangulating
};

const char* const kUsage =
    "usage: cgal_delaunay2d_run_bench --random N [--distribution NAME] [--seed S] [--write-node FILE.node]\n";

Args parse(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + std::string(flag));
    const std::string value = argv[++i];
    if (flag == "--random") {
      args.n = std::stoull(value);
    } else if (flag == "--distribution") {
      args.distribution = value;
    } else if (flag == "--seed") {
      args.seed = std::stoull(value);
    } else if (flag == "--write-node") {
      args.node_file = value;
    } else {
      throw std::invalid_argument("unknown option " + std::string(flag));
    }
  }
  if (args.n == 0) throw std::invalid_argument("--random N (N > 0) is required");
  return args;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

// Triangle's .node format: "<count> 2 0 0", then "<index> x y" per point, numbered from 1.
void write_node(const std::string& path, const std::vector<dtlab::Vec2>& points) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) throw std::runtime_error("cannot open '" + path + "' for writing");
  std::fprintf(out, "%zu 2 0 0\n", points.size());
  for (std::size_t i = 0; i < points.size(); ++i) std::fprintf(out, "%zu %.17g %.17g\n", i + 1, points[i].x, points[i].y);
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed) throw std::runtime_error("writing '" + path + "' failed");
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  try {
    args = parse(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "cgal_delaunay2d_run_bench: " << e.what() << "\n" << kUsage;
    return 2;
  }
  try {
    const std::vector<dtlab::Vec2> points = dtlab::generate_points2d(args.distribution, args.n, args.seed);
    if (!args.node_file.empty()) {
      write_node(args.node_file, points);
      return 0;
    }
    const auto start = std::chrono::steady_clock::now();
    dtlab::bench::cgal2d::Delaunay dt;
    dtlab::bench::cgal2d::build(points, dt);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t elements = dt.number_of_faces();
    const double per_minute = seconds > 0 ? static_cast<double>(elements) * 60.0 / seconds : 0.0;
    std::printf(
        "{\"input\":\"random %s n=%zu seed=%llu\",\"dim\":2,\"algo\":\"cgal\",\"cgal_version\":\"%s\","
        "\"points\":%zu,\"distinct_points\":%zu,\"elements\":%zu,\"seconds\":%.6g,"
        "\"elements_per_minute\":%.6g,\"peak_rss_mb\":%.6g}\n",
        args.distribution.c_str(), args.n, static_cast<unsigned long long>(args.seed), CGAL_VERSION_STR,
        points.size(), static_cast<std::size_t>(dt.number_of_vertices()), elements, seconds, per_minute,
        peak_rss_mb());
  } catch (const std::exception& e) {
    // An unknown distribution name (dtlab::InputError lists the known ones), an unwritable .node
    // file, or no memory.
    std::cerr << "cgal_delaunay2d_run_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
