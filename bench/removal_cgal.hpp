// The CGAL side of removal_bench (removal_cgal.cpp, built only when CGAL is found): CGAL's
// Delaunay_triangulation_2 / _3 (set up as delaunay2d_cgal_impl.hpp / delaunay3d_cgal_impl.hpp
// say) built on the points, then remove() of the given points in the given order. No CGAL header
// here, so that removal_bench.cpp compiles as a dtlab user's code does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kernel/vec.hpp"

namespace dtlab::bench {

struct CgalRemoval {
  double remove_seconds = 0.0;  // the removals only
  std::size_t finite_elements = 0;
};

const char* cgal_removal_version();
CgalRemoval cgal_remove2d(std::span<const Vec2> points, std::span<const std::uint32_t> order);
CgalRemoval cgal_remove3d(std::span<const Vec3> points, std::span<const std::uint32_t> order);

}  // namespace dtlab::bench
