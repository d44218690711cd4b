// The 3D points of delaunay3d_bench and cgal_delaunay3d_run_bench: the same doubles, bit for
// bit, as `dtlab delaunay --dim 3 --random N --seed S` (apps/delaunay3d.cpp): std::mt19937_64
// seeded with S, three uniform_real_distribution(0, 1) draws per point, x then y then z. Kept
// beside the benchmarks until verify/generators/ has a 3D generator the CLI uses; the scripts
// compare the programs' tetrahedron counts, which differ if the points ever drift apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/vec.hpp"

namespace dtlab::bench {

inline std::vector<Vec3> generate_points3(const std::string& distribution, std::size_t n, std::uint64_t seed) {
  if (distribution != "uniform")
    throw InputError("3D point distribution '" + distribution + "' is not available (only: uniform)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> out(n);
  // Separate statements: the order of the three draws must not be left to the compiler.
  for (Vec3& p : out) {
    p.x = unit(rng);
    p.y = unit(rng);
    p.z = unit(rng);
  }
  return out;
}

}  // namespace dtlab::bench
