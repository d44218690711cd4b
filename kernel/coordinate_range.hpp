// The coordinates the predicates are exact on, and the check that enforces them.
//
// Supported: every coordinate is 0 or has magnitude in [2^-142, 2^142] (about 1.8e-43 to
// 5.6e42). Then every coordinate difference is 0 or at least 2^-194 and at most 2^143, every
// product of up to five of them is a normal double well below overflow, and so the semi-static
// bounds (no underflow assumed), the expansion arithmetic (error-free transformations need no
// underflow) and the GMP conversion are all exact. NaN, infinity and anything outside the range
// are refused with an InputError naming the point and coordinate, never misjudged.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>

#include "kernel/vec.hpp"

namespace dtlab {

inline constexpr int kMinCoordinateExponent = -142;
inline constexpr int kMaxCoordinateExponent = 142;
inline const double kMinCoordinateMagnitude = std::ldexp(1.0, kMinCoordinateExponent);
inline const double kMaxCoordinateMagnitude = std::ldexp(1.0, kMaxCoordinateExponent);

// True iff v is 0 or finite with magnitude in [2^-142, 2^142].
inline bool coordinate_in_range(double v) noexcept {
  const double m = std::fabs(v);
  return m == 0.0 || (m >= kMinCoordinateMagnitude && m <= kMaxCoordinateMagnitude);
}

// Why v is refused ("NaN", "infinite", "too large (...)", "too small (...)"), or "" if in range.
std::string coordinate_problem(double v);

class WorkerTeam;

// Throw InputError naming the first point (0-based index) with a coordinate out of range.
// `what` names the input in the message, e.g. "input point" or a file name. With `team`, the
// points are scanned in shares on its threads (the same point is named).
void check_coordinates(std::span<const Vec2> points, const std::string& what = "point", WorkerTeam* team = nullptr);
void check_coordinates(std::span<const Vec3> points, const std::string& what = "point", WorkerTeam* team = nullptr);

}  // namespace dtlab
