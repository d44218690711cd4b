// Removing a list of input points from a dynamic Delaunay triangulation (DynamicDelaunay2/3), the
// one call that `dtlab delaunay --remove` and the benchmarks make: build, remove in the given
// order, and report the elements of the survivors in input ids with the two phases' times.
// Written once over the dimension; delaunay2d_remove / delaunay3d_remove instantiate it.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

namespace dtlab {

template <std::size_t kCorners, class Stats>
struct PointRemoval {
  std::vector<std::array<std::uint32_t, kCorners>> elements;  // the survivors' finite elements, input ids
  std::vector<std::uint8_t> removed;                          // one per input point: 1 if removed
  double build_seconds = 0.0;                                 // the Delaunay call of the construction
  double remove_seconds = 0.0;                                // the removals
  Stats stats;
};

// Dynamic: DynamicDelaunay2/3; Points a span of Vec2/Vec3. Throws what Dynamic's constructor and
// remove() throw (UnknownVertexError names an index out of range or given twice).
template <class Dynamic, std::size_t kCorners, class Stats, class Points, class Options>
PointRemoval<kCorners, Stats> remove_points(Points points, std::span<const std::uint32_t> indices,
                                            const Options& options) {
  using Clock = std::chrono::steady_clock;
  PointRemoval<kCorners, Stats> out;
  const auto t0 = Clock::now();
  Dynamic dynamic(points, options);
  const auto t1 = Clock::now();
  for (const std::uint32_t v : indices) dynamic.remove(v);
  const auto t2 = Clock::now();
  out.build_seconds = std::chrono::duration<double>(t1 - t0).count();
  out.remove_seconds = std::chrono::duration<double>(t2 - t1).count();
  out.removed.assign(points.size(), 0);
  for (const std::uint32_t v : indices) out.removed[v] = 1;
  out.stats = dynamic.stats();
  out.elements = dynamic.finite_elements();
  return out;
}

}  // namespace dtlab
