// Analytic and B-spline surface patches with exact first and second derivatives (book §6.2: the
// fundamental forms need sigma_u, sigma_v, sigma_uu, sigma_uv, sigma_vv). One Patch3 is one chart:
// a map sigma from a parameter region of R^2 to R^3; a closed or periodic surface is several charts
// glued along seams (patch_surface3.hpp). Derivatives are written out by hand for every kind (the
// B-spline by its derivative control nets, Piegl and Tiller, "The NURBS Book", §3.3), never by
// finite differences: the metrics read them directly.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

struct PatchDerivatives {
  Vec3 point, du, dv, duu, duv, dvv;
};

class Patch3 {
 public:
  // origin + u e1 + v e2.
  static Patch3 plane(const Vec3& origin, const Vec3& e1, const Vec3& e2);
  // One face of the cube [-1, 1]^3 projected from its centre onto the sphere (gnomonic cubed
  // sphere): centre + radius q / |q|, q = n + u a + v b with (u, v) in [-1, 1]^2, where n, a, b are
  // the unit axes of `face` (0..5: +x, -x, +y, -y, +z, -z) with a x b = n, so that sigma_u x
  // sigma_v points outwards. No pole: every face is regular.
  static Patch3 sphere_face(const Vec3& centre, double radius, std::uint32_t face);
  // centre + radius(v) (cos u e1 + sin u e2) + v axis, radius(v) = r0 + (r1 - r0) v / height (a
  // cylinder when r0 == r1, a cone otherwise); e1, e2, axis orthonormal.
  static Patch3 cone(const Vec3& centre, const Vec3& e1, const Vec3& e2, double r0, double r1, double height);
  // centre + (R + r cos v)(cos u e1 + sin u e2) + r sin v (e1 x e2).
  static Patch3 torus(const Vec3& centre, const Vec3& e1, const Vec3& e2, double major, double minor);
  // The book's example (§6.4, (6.29)): (u, v, amplitude sin(fu u) cos(fv v)); the book's
  // amplitude 3, frequencies 2 and 2.
  static Patch3 sine_graph(double amplitude, double frequency_u, double frequency_v);
  // Tensor-product clamped B-spline: controls row-major (count_u rows of count_v), degrees and
  // knot vectors as Curve3::bspline (p + 1 equal knots at each end, count + p + 1 knots). The
  // parameters are the knots' (u in [knots_u.front, knots_u.back]). InputError otherwise.
  static Patch3 bspline(std::vector<Vec3> controls, std::uint32_t count_u, std::uint32_t count_v,
                        std::vector<double> knots_u, std::vector<double> knots_v, std::uint32_t degree_u,
                        std::uint32_t degree_v);

  PatchDerivatives evaluate(const Vec2& uv) const;
  Vec3 point(const Vec2& uv) const { return evaluate(uv).point; }

 private:
  enum class Kind : std::uint8_t { Plane, SphereFace, Cone, Torus, SineGraph, BSpline };
  PatchDerivatives bspline_derivatives(const Vec2& uv) const;
  void build_derivative_nets();
  // centre, the frame e1, e2, e3 = e1 x e2 and the three shape numbers.
  static Patch3 framed(Kind kind, const Vec3& centre, const Vec3& e1, const Vec3& e2, double a, double b, double c);

  Kind kind_ = Kind::Plane;
  Vec3 centre_{}, e1_{}, e2_{}, e3_{};
  double a_ = 0, b_ = 0, c_ = 0;  // radius / (r0, r1, height) / (R, r) / (amplitude, fu, fv)
  std::vector<Vec3> controls_;
  std::vector<Vec3> du_net_, duu_net_, dv_net_, dvv_net_, duv_net_;  // the derivative control nets
  std::vector<double> knots_u_, knots_v_;
  std::uint32_t count_u_ = 0, count_v_ = 0, degree_u_ = 0, degree_v_ = 0;
};

}  // namespace dtlab
