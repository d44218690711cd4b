// check_coordinates: the supported range is 0 and magnitudes in [2^-142, 2^142]; everything else
// (NaN, infinities, too large, too small) is refused with an InputError naming point and
// coordinate.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"

namespace {

using dtlab::InputError;
using dtlab::Vec2;
using dtlab::Vec3;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
const double kMin = std::ldexp(1.0, -142);
const double kMax = std::ldexp(1.0, 142);

// The range from its definition, by binary exponent rather than by comparison with the bounds.
bool in_range_by_exponent(double v) {
  if (v == 0.0) return true;
  if (!std::isfinite(v)) return false;
  const int e = std::ilogb(v);
  if (e == 142) return std::fabs(v) == kMax;  // only 2^142 itself in the top binade
  return e >= -142 && e < 142;
}

// The InputError of check_coordinates on `points`, or a failure if none is thrown.
template <class P>
InputError error_of(const std::vector<P>& points) {
  try {
    dtlab::check_coordinates(std::span<const P>(points));
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("none");
}

struct BadValue {
  double value;
  const char* problem;  // a word the message must contain
};

const BadValue kBadValues[] = {
    {kNaN, "NaN"},
    {-kNaN, "NaN"},
    {kInf, "infinite"},
    {-kInf, "infinite"},
    {std::nextafter(kMax, kInf), "too large"},
    {-std::nextafter(kMax, kInf), "too large"},
    {std::numeric_limits<double>::max(), "too large"},
    {1e300, "too large"},
    {std::nextafter(kMin, 0.0), "too small"},
    {-std::nextafter(kMin, 0.0), "too small"},
    {std::numeric_limits<double>::denorm_min(), "too small"},
    {std::numeric_limits<double>::min(), "too small"},
    {1e-300, "too small"},
};

TEST(CoordinateRange, AcceptsZeroTheEndsAndBetween) {
  const double good[] = {0.0,  -0.0, kMin, -kMin, kMax, -kMax, std::nextafter(kMin, 1.0),
                         std::nextafter(kMax, 0.0), 1.0, -1.0, 0.5, 1e9, -1e-9, 3.14159, 1e42, 1e-42};
  for (double v : good) {
    EXPECT_TRUE(dtlab::coordinate_in_range(v)) << std::hexfloat << v;
    EXPECT_EQ(dtlab::coordinate_problem(v), "") << std::hexfloat << v;
    const std::vector<Vec2> p2 = {{v, v}, {0.0, v}, {v, -v}};
    const std::vector<Vec3> p3 = {{v, v, v}, {0.0, v, 1.0}};
    EXPECT_NO_THROW(dtlab::check_coordinates(std::span<const Vec2>(p2))) << std::hexfloat << v;
    EXPECT_NO_THROW(dtlab::check_coordinates(std::span<const Vec3>(p3))) << std::hexfloat << v;
  }
  EXPECT_NO_THROW(dtlab::check_coordinates(std::span<const Vec2>()));
}

TEST(CoordinateRange, RejectsEachBadValueInEachCoordinateOf2dPoints) {
  const char* const names[] = {"x", "y"};
  for (const BadValue& bad : kBadValues) {
    for (int k = 0; k < 2; ++k) {
      std::vector<Vec2> points = {{1, 2}, {3, 4}, {5, 6}, {7, 8}};
      (k == 0 ? points[2].x : points[2].y) = bad.value;
      const InputError e = error_of(points);
      const std::string msg = e.what();
      EXPECT_NE(msg.find("point 2"), std::string::npos) << msg;
      EXPECT_NE(msg.find(std::string("coordinate ") + names[k]), std::string::npos) << msg;
      EXPECT_NE(msg.find(bad.problem), std::string::npos) << msg;
      EXPECT_EQ(e.items(), std::vector<std::uint64_t>{2}) << msg;
    }
  }
}

TEST(CoordinateRange, RejectsEachBadValueInEachCoordinateOf3dPoints) {
  const char* const names[] = {"x", "y", "z"};
  for (const BadValue& bad : kBadValues) {
    for (int k = 0; k < 3; ++k) {
      std::vector<Vec3> points(12, Vec3{1, -1, 0});
      Vec3& p = points[11];
      (k == 0 ? p.x : (k == 1 ? p.y : p.z)) = bad.value;
      const InputError e = error_of(points);
      const std::string msg = e.what();
      EXPECT_NE(msg.find("point 11"), std::string::npos) << msg;
      EXPECT_NE(msg.find(std::string("coordinate ") + names[k]), std::string::npos) << msg;
      EXPECT_NE(msg.find(bad.problem), std::string::npos) << msg;
      EXPECT_EQ(e.items(), std::vector<std::uint64_t>{11}) << msg;
    }
  }
}

TEST(CoordinateRange, NamesTheFirstOffendingPointAndTheInput) {
  const std::vector<Vec2> points = {{0, 0}, {1, kInf}, {kNaN, 0}};
  try {
    dtlab::check_coordinates(std::span<const Vec2>(points), "mesh.node");
    FAIL() << "no InputError thrown";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("mesh.node 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("coordinate y"), std::string::npos) << msg;
    EXPECT_EQ(e.items(), std::vector<std::uint64_t>{1});
  }
}

// Any bit pattern: check_coordinates refuses a point exactly when a coordinate is out of range
// by the exponent definition, and then names the first such point.
RC_GTEST_PROP(CoordinateRange, AgreesWithTheExponentDefinition, (std::vector<std::uint64_t> bits)) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i + 2 < bits.size(); i += 3)
    points.push_back({std::bit_cast<double>(bits[i]), std::bit_cast<double>(bits[i + 1]),
                      std::bit_cast<double>(bits[i + 2])});
  std::size_t first_bad = points.size();
  for (std::size_t i = 0; i < points.size() && first_bad == points.size(); ++i)
    if (!in_range_by_exponent(points[i].x) || !in_range_by_exponent(points[i].y) ||
        !in_range_by_exponent(points[i].z))
      first_bad = i;
  // On one thread and in shares on a team (every share may hold bad points): the same point.
  static dtlab::WorkerTeam team(2);
  for (dtlab::WorkerTeam* on : {static_cast<dtlab::WorkerTeam*>(nullptr), &team}) {
    try {
      dtlab::check_coordinates(std::span<const Vec3>(points), "point", on);
      RC_ASSERT(first_bad == points.size());
    } catch (const InputError& e) {
      RC_ASSERT(first_bad < points.size());
      RC_ASSERT(e.items() == std::vector<std::uint64_t>{first_bad});
      RC_ASSERT(std::string(e.what()).find("point " + std::to_string(first_bad) + ":") != std::string::npos);
    }
  }
}

// Values near the ends, where an off-by-one in the bounds would show.
RC_GTEST_PROP(CoordinateRange, EndsAreSharp, (int steps, bool top, bool negative)) {
  const int k = steps % 64;
  double v = top ? kMax : kMin;
  for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, k > 0 ? kInf : 0.0);
  if (negative) v = -v;
  const bool expected = top ? k <= 0 : k >= 0;
  RC_ASSERT(dtlab::coordinate_in_range(v) == expected);
  RC_ASSERT(in_range_by_exponent(v) == expected);
}

}  // namespace
