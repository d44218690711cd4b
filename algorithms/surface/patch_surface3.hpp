// A surface made of charts (patch3.hpp) glued along seams (book §6.3.4, §6.5.1: a closed or
// periodic surface is meshed through parameter domains whose shared boundaries are meshed once).
// Each chart's parameter domain is bounded by sides, counter-clockwise: a rectangle's four (v = v0,
// u = u1, v = v1, u = u0), or a disc's one closed circle. Side k runs from corner k to corner k + 1
// (mod the side count) as s goes from 0 to 1, linearly in its parameters (the circle: in angle).
// A seam glues side a of chart A to side b of chart B with s_B = 1 - s_A: both charts map the
// two to the same 3D curve, and the mesher puts one set of points on it.
//
// How the periodic surfaces are cut (no parameter domain with identified edges, no pole):
//   - cylinder and cone: three charts, u in thirds of [0, 2 pi], each glued to the next;
//   - torus: nine charts, u and v each in thirds, glued across both;
// three a period, not two: two charts then share one seam at most, so no two edges of the surface
// join the same two vertices (two halves of a coarse torus join the same corners in both);
//   - sphere: the six faces of the gnomonic cubed sphere, glued along the cube's twelve edges.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/surface/patch3.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

struct PatchChart3 {
  Patch3 patch;
  bool disc = false;
  Vec2 lo{}, hi{};     // the rectangle [lo, hi], or the disc's bounding box (centre (lo + hi) / 2)
  std::uint32_t side_count() const noexcept { return disc ? 1u : 4u; }
  // The parameters of side k at s in [0, 1], and their derivative in s.
  Vec2 side_point(std::uint32_t k, double s) const;
  Vec2 side_derivative(std::uint32_t k, double s) const;
};

struct PatchSeam3 {
  std::uint32_t chart_a = 0, side_a = 0, chart_b = 0, side_b = 0;
};

class PatchSurface3 {
 public:
  // InputError, naming the patch, for a zero or negative radius (size), a non-finite parameter, a
  // minor radius not below the major one (a self-intersecting torus), a cone through its apex, or
  // axes that are not orthonormal.
  static PatchSurface3 plane(const Vec3& origin, const Vec3& e1, const Vec3& e2, const Vec2& lo, const Vec2& hi);
  static PatchSurface3 sphere(const Vec3& centre, double radius);
  static PatchSurface3 cylinder(const Vec3& centre, const Vec3& axis, double radius, double height);
  static PatchSurface3 cone(const Vec3& centre, const Vec3& axis, double r0, double r1, double height);
  static PatchSurface3 torus(const Vec3& centre, const Vec3& axis, double major, double minor);
  // The book's sigma(x, y) = (x, y, amplitude sin(fx x) cos(fy y)) over the disc of `radius`
  // about the origin (§6.4: 3, 2, 2, radius 3).
  static PatchSurface3 sine_graph(double amplitude, double frequency_x, double frequency_y, double radius);
  // One chart over the knot rectangle (Patch3::bspline's checks).
  static PatchSurface3 bspline(Patch3 patch, const Vec2& lo, const Vec2& hi);

  const std::vector<PatchChart3>& charts() const noexcept { return charts_; }
  const std::vector<PatchSeam3>& seams() const noexcept { return seams_; }
  const std::string& name() const noexcept { return name_; }

  // InputError "degenerate patch: ... singular parametrization at (u, v) of chart c" when
  // |sigma_u x sigma_v| <= 1e-12 |sigma_u| |sigma_v| at a point of a 17 x 17 sample of a chart
  // (a measure, never a combinatorial decision); every constructor calls it.
  void check_regular() const;
  // The diagonal of the box of a 17 x 17 sample of every chart: a length scale for defaults.
  double extent() const;

 private:
  std::string name_;
  std::vector<PatchChart3> charts_;
  std::vector<PatchSeam3> seams_;
};

}  // namespace dtlab
