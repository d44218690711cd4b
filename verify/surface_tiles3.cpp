// Placing output triangles in the pieces of a recovered surface (surface_tiles3.hpp).
#include "verify/surface_tiles3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dtlab {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * norm(cross(b - a, c - a)); }

namespace {

double max_abs(const Vec3& p) { return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}); }

struct Grid {
  Vec3 lo, step;
  std::uint32_t n = 1;  // cells per axis
  std::vector<std::vector<std::uint32_t>> cells;

  std::uint32_t index(double x, double lo_x, double step_x) const {
    const double c = step_x > 0 ? std::floor((x - lo_x) / step_x) : 0.0;
    return static_cast<std::uint32_t>(std::clamp(c, 0.0, static_cast<double>(n - 1)));
  }
  std::array<std::uint32_t, 3> cell_of(const Vec3& p) const {
    return {index(p.x, lo.x, step.x), index(p.y, lo.y, step.y), index(p.z, lo.z, step.z)};
  }
  std::vector<std::uint32_t>& at(const std::array<std::uint32_t, 3>& c) { return cells[(c[0] * n + c[1]) * n + c[2]]; }
};

}  // namespace

std::vector<std::uint32_t> locate_tiles(std::span<const Vec3> piece_points,
                                        std::span<const std::array<std::uint32_t, 3>> pieces,
                                        std::span<const Vec3> tile_points,
                                        std::span<const std::array<std::uint32_t, 3>> tiles) {
  std::vector<std::uint32_t> found(tiles.size(), kNoPiece);
  if (pieces.empty() || tiles.empty()) return found;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double scale = 1e-300;
  Vec3 lo = piece_points[pieces[0][0]], hi = lo;
  for (const auto& f : pieces)
    for (const std::uint32_t v : f) {
      const Vec3& p = piece_points[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      scale = std::max(scale, max_abs(p));
    }
  for (const auto& f : tiles)
    for (const std::uint32_t v : f) scale = std::max(scale, max_abs(tile_points[v]));
  const double tolerance = kTileUlps * kEps * scale;
  // About one piece a cell, at most 64^3 cells.
  Grid grid;
  grid.n = static_cast<std::uint32_t>(std::clamp(std::cbrt(static_cast<double>(pieces.size())), 1.0, 64.0));
  grid.lo = lo;
  grid.step = (1.0 / grid.n) * (hi - lo);
  grid.cells.resize(std::size_t{grid.n} * grid.n * grid.n);
  const Vec3 pad{tolerance, tolerance, tolerance};
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    const Vec3 &a = piece_points[pieces[k][0]], &b = piece_points[pieces[k][1]], &c = piece_points[pieces[k][2]];
    const Vec3 plo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
    const Vec3 phi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
    const auto c0 = grid.cell_of(plo - pad), c1 = grid.cell_of(phi + pad);
    for (std::uint32_t i = c0[0]; i <= c1[0]; ++i)
      for (std::uint32_t j = c0[1]; j <= c1[1]; ++j)
        for (std::uint32_t l = c0[2]; l <= c1[2]; ++l) grid.at({i, j, l}).push_back(k);
  }
  for (std::uint32_t t = 0; t < tiles.size(); ++t) {
    const Vec3 &p = tile_points[tiles[t][0]], &q = tile_points[tiles[t][1]], &r = tile_points[tiles[t][2]];
    const Vec3 centroid = (1.0 / 3.0) * (p + q + r);
    for (const std::uint32_t k : grid.at(grid.cell_of(centroid))) {
      const Vec3 &a = piece_points[pieces[k][0]], &b = piece_points[pieces[k][1]], &c = piece_points[pieces[k][2]];
      const Vec3 normal = cross(b - a, c - a);
      const double twice_area = norm(normal);
      if (!(twice_area > 0)) continue;
      const Vec3 n = (1.0 / twice_area) * normal;
      if (std::fabs(dot(n, p - a)) > tolerance || std::fabs(dot(n, q - a)) > tolerance ||
          std::fabs(dot(n, r - a)) > tolerance)
        continue;
      // Barycentric coordinates of the centroid in the piece, in its plane.
      const double u = dot(n, cross(b - centroid, c - centroid)) / twice_area;
      const double v = dot(n, cross(c - centroid, a - centroid)) / twice_area;
      const double w = dot(n, cross(a - centroid, b - centroid)) / twice_area;
      if (u >= -1e-12 && v >= -1e-12 && w >= -1e-12) {
        found[t] = k;
        break;
      }
    }
  }
  return found;
}

}  // namespace dtlab
