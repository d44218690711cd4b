// Planar domains for the 2D mesher's tests (domains2d.hpp).
#include "verify/generators/domains2d.hpp"

#include <cmath>
#include <numbers>

namespace dtlab::gen {

void add_loop(Domain2& d, const std::vector<Vec2>& loop, int marker) {
  const auto first = static_cast<std::uint32_t>(d.points.size());
  const auto n = static_cast<std::uint32_t>(loop.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    d.points.push_back(loop[i]);
    d.segments.push_back({first + i, first + (i + 1) % n});
    d.markers.push_back(marker);
  }
}

std::vector<Vec2> circle_polygon(const Vec2& c, double r, int n) {
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

std::vector<Vec2> unit_square_loop(int n) {
  std::vector<Vec2> square;
  for (int s = 0; s < 4; ++s) {
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      square.push_back(s == 0 ? Vec2{t, 0} : s == 1 ? Vec2{1, t} : s == 2 ? Vec2{1 - t, 1} : Vec2{0, 1 - t});
    }
  }
  return square;
}

Domain2 unit_square(int n, int marker) {
  Domain2 d;
  add_loop(d, unit_square_loop(n), marker);
  return d;
}

Domain2 square_minus_disc(int n) {
  Domain2 d = unit_square(n, 1);
  add_loop(d, circle_polygon({0.5, 0.5}, 0.2, static_cast<int>(std::ceil(2 * std::numbers::pi * 0.2 * n))), 2);
  d.holes.push_back({0.5, 0.5});
  return d;
}

}  // namespace dtlab::gen
