// Closed test surfaces made of boxes, shared by the 3D mesher's tests (mesh3d_test,
// mesh3d_property_test, local_remesh3_test).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "algorithms/mesh3d/mesh3d.hpp"
#include "kernel/vec.hpp"

namespace dtlab::test {

struct SurfaceData {
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> refs;
  std::vector<Vec3> holes;

  Mesh3dInput input() const {
    return {.points = points, .triangles = triangles, .triangle_refs = refs, .holes = holes, .regions = {}};
  }
};

// The surface of the box [lo, lo + size]: the face normal to an axis is an n[u] x n[w] grid of
// rectangles (u, w the next two axes), each cut in two; face reference ref_base + face (face =
// 2 axis + side, 0..5). A point at the place of an earlier box's is shared; `skip_face` is left
// out (a face shared with an earlier box).
inline void add_box(SurfaceData& s, const Vec3& lo, const Vec3& size, const std::array<int, 3>& n, int ref_base,
                    int skip_face = -1) {
  std::map<std::array<int, 3>, std::uint32_t> index;
  const auto vertex = [&](std::array<int, 3> g) {
    const auto [it, fresh] = index.try_emplace(g, static_cast<std::uint32_t>(s.points.size()));
    if (fresh) {
      const Vec3 p{lo.x + size.x * g[0] / n[0], lo.y + size.y * g[1] / n[1], lo.z + size.z * g[2] / n[2]};
      for (std::uint32_t k = 0; k < s.points.size(); ++k)
        if (s.points[k] == p) return it->second = k;
      s.points.push_back(p);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int face = 2 * axis + side;
      if (face == skip_face) continue;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int i = 0; i < n[u]; ++i)
        for (int j = 0; j < n[w]; ++j) {
          std::array<std::uint32_t, 4> c{};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> g{};
            g[axis] = side * n[axis];
            g[u] = i + (k == 1 || k == 2);
            g[w] = j + (k >= 2);
            c[k] = vertex(g);
          }
          s.triangles.push_back({c[0], c[1], c[2]});
          s.triangles.push_back({c[0], c[2], c[3]});
          s.refs.push_back(ref_base + face);
          s.refs.push_back(ref_base + face);
        }
    }
}

// A cube of side `size` with every face an n x n grid.
inline void add_box(SurfaceData& s, const Vec3& lo, double size, int n, int ref_base, int skip_face = -1) {
  add_box(s, lo, {size, size, size}, {n, n, n}, ref_base, skip_face);
}

}  // namespace dtlab::test
