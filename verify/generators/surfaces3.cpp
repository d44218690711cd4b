#include "verify/generators/surfaces3.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace dtlab::gen {

Surface3 cube_surface() {
  Surface3 s;
  for (int k = 0; k < 8; ++k) s.points.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  // Faces as quads (outward counter-clockwise), split along a diagonal.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
    s.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  return s;
}

Surface3 octahedron_sphere(int levels) {
  Surface3 s;
  s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::pair{std::min(a, b), std::max(a, b)};
      if (const auto it = mid.find(key); it != mid.end()) return it->second;
      const Vec3 m = 0.5 * (s.points[a] + s.points[b]);
      s.points.push_back((1.0 / norm(m)) * m);
      return mid[key] = std::uint32_t(s.points.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : s.triangles) {
      const std::uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    s.triangles = std::move(next);
  }
  return s;
}

Surface3 capped_cylinder(double r, std::uint32_t around, std::uint32_t rows) {
  Surface3 s;
  for (std::uint32_t k = 0; k <= rows; ++k)
    for (std::uint32_t i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around;
      s.points.push_back({r * std::cos(a), r * std::sin(a), double(k) / rows});
    }
  auto at = [&](std::uint32_t k, std::uint32_t i) { return k * around + i % around; };
  for (std::uint32_t k = 0; k < rows; ++k)
    for (std::uint32_t i = 0; i < around; ++i) {
      s.triangles.push_back({at(k, i), at(k, i + 1), at(k + 1, i + 1)});
      s.triangles.push_back({at(k, i), at(k + 1, i + 1), at(k + 1, i)});
    }
  const auto bottom = std::uint32_t(s.points.size());
  s.points.push_back({0, 0, 0});
  const auto top = std::uint32_t(s.points.size());
  s.points.push_back({0, 0, 1});
  for (std::uint32_t i = 0; i < around; ++i) {
    s.triangles.push_back({bottom, at(0, i + 1), at(0, i)});
    s.triangles.push_back({top, at(rows, i), at(rows, i + 1)});
  }
  return s;
}

}  // namespace dtlab::gen
