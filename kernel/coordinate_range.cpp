#include "kernel/coordinate_range.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {

std::string coordinate_problem(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return "infinite";
  if (coordinate_in_range(v)) return "";
  char buf[160];
  if (std::fabs(v) > kMaxCoordinateMagnitude) {
    std::snprintf(buf, sizeof buf, "too large (%.17g; supported magnitudes are 0 or 2^%d..2^%d)", v,
                  kMinCoordinateExponent, kMaxCoordinateExponent);
  } else {
    std::snprintf(buf, sizeof buf, "too small (%.17g; supported magnitudes are 0 or 2^%d..2^%d)", v,
                  kMinCoordinateExponent, kMaxCoordinateExponent);
  }
  return buf;
}

namespace {
double coordinate(const Vec2& p, std::size_t k) { return k == 0 ? p.x : p.y; }
double coordinate(const Vec3& p, std::size_t k) { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

// Throws for the first point (lowest index) with a coordinate out of range. With `team`, each
// share of the points is scanned on its own thread for its first such point; the lowest is
// reported, so the error is the same for every team.
template <class P, std::size_t N>
void check(std::span<const P> points, const std::string& what, const char* const (&names)[N], WorkerTeam* team) {
  const auto in_range = [&](std::size_t i) {
    bool ok = true;
    for (std::size_t k = 0; k < N; ++k) ok &= coordinate_in_range(coordinate(points[i], k));
    return ok;
  };
  std::vector<std::size_t> first_bad(shares(team), points.size());
  for_each_share(team, points.size(), [&](std::size_t s, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (!in_range(i)) {
        first_bad[s] = i;
        return;
      }
  });
  const std::size_t i = *std::min_element(first_bad.begin(), first_bad.end());
  if (i == points.size()) return;
  for (std::size_t k = 0; k < N; ++k) {
    const double c = coordinate(points[i], k);
    if (!coordinate_in_range(c))
      throw InputError(what + " " + std::to_string(i) + ": coordinate " + names[k] + " is " + coordinate_problem(c), {i});
  }
}
}  // namespace

void check_coordinates(std::span<const Vec2> points, const std::string& what, WorkerTeam* team) {
  static const char* const names[] = {"x", "y"};
  check(points, what, names, team);
}

void check_coordinates(std::span<const Vec3> points, const std::string& what, WorkerTeam* team) {
  static const char* const names[] = {"x", "y", "z"};
  check(points, what, names, team);
}

void throw_internal_error(const char* condition, const char* file, int line) {
  throw InternalError(std::string("internal error: ") + condition + " failed at " + file + ":" +
                      std::to_string(line));
}

}  // namespace dtlab
