#include "kernel/coordinate_range.hpp"

#include <cstdio>

#include "kernel/error.hpp"

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

template <class P, std::size_t N>
void check(std::span<const P> points, const std::string& what, const char* const (&names)[N]) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t k = 0; k < N; ++k) {
      const double c = coordinate(points[i], k);
      if (coordinate_in_range(c)) continue;
      throw InputError(what + " " + std::to_string(i) + ": coordinate " + names[k] + " is " +
                           coordinate_problem(c),
                       {i});
    }
  }
}
}  // namespace

void check_coordinates(std::span<const Vec2> points, const std::string& what) {
  static const char* const names[] = {"x", "y"};
  check(points, what, names);
}

void check_coordinates(std::span<const Vec3> points, const std::string& what) {
  static const char* const names[] = {"x", "y", "z"};
  check(points, what, names);
}

void throw_internal_error(const char* condition, const char* file, int line) {
  throw InternalError(std::string("internal error: ") + condition + " failed at " + file + ":" +
                      std::to_string(line));
}

}  // namespace dtlab
