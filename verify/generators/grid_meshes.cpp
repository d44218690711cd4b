// Jittered grid meshes of the unit square (grid_meshes.hpp).
#include "verify/generators/grid_meshes.hpp"

#include <cmath>
#include <cstdint>

namespace dtlab::gen {

MeshData2 jittered_grid(int n, double jitter) {
  MeshData2 m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      double x = double(i) / n, y = double(j) / n;
      if (i > 0 && i < n && j > 0 && j < n) {
        x += jitter / n * std::sin(12.9898 * i + 78.233 * j);
        y += jitter / n * std::cos(39.3468 * i + 11.135 * j);
      }
      m.vertices.push_back({x, y});
      m.vertex_refs.push_back(0);
    }
  }
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      m.triangle_refs.push_back(1);
      m.triangle_refs.push_back(1);
    }
  }
  return m;
}

}  // namespace dtlab::gen
