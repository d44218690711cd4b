// Points and vectors of doubles: the coordinates every predicate and structure works on.
#pragma once

#include <cmath>
#include <compare>

namespace dtlab {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
  // Lexicographic order (x, then y): the order the symbolic perturbation ranks points by.
  friend constexpr std::partial_ordering operator<=>(const Vec2& a, const Vec2& b) {
    if (auto c = a.x <=> b.x; c != 0) return c;
    return a.y <=> b.y;
  }
};

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
  friend constexpr std::partial_ordering operator<=>(const Vec3& a, const Vec3& b) {
    if (auto c = a.x <=> b.x; c != 0) return c;
    if (auto c = a.y <=> b.y; c != 0) return c;
    return a.z <=> b.z;
  }
};

constexpr Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator*(double s, const Vec2& a) { return {s * a.x, s * a.y}; }
constexpr double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
// z-component of the 3D cross product: twice the signed area of (0, a, b).
constexpr double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline double norm(const Vec2& a) { return std::hypot(a.x, a.y); }

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) { return std::hypot(a.x, a.y, a.z); }
// |a| as the square root of the rounded dot(a, a) where that square keeps its relative precision
// (a correctly rounded sqrt, several times cheaper than hypot's scaled sums; within an ulp or two
// of it), hypot's outside.
inline double norm_by_square(const Vec3& a) {
  const double q = dot(a, a);
  return q > 1e-280 && q < 1e280 ? std::sqrt(q) : norm(a);
}

}  // namespace dtlab
