// Metrics from the fundamental forms (surface_metric.hpp, book §6.2-§6.3).
#include "algorithms/surface/surface_metric.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

void SurfaceMetricSpec::check() const {
  if (size == 0.0 && !user_metric && geometric == GeometricMetric::None)
    throw InputError("surface metric: give a size, a user metric or a geometric metric");
  if (size != 0.0) check_size(size, "size");
  if (geometric != GeometricMetric::None) {
    if (hausdorff != 0.0) check_size(hausdorff, "hausdorff");
    if (hausdorff == 0.0 && !(relative_gap > 0.0 && relative_gap < 1.0))
      throw InputError("surface metric: relative gap " + std::to_string(relative_gap) + " outside (0, 1)");
    if (h_min != 0.0) check_size(h_min, "h_min");
    if (h_max != 0.0) check_size(h_max, "h_max");
    if (h_min != 0.0 && h_max != 0.0 && h_min > h_max)
      throw InputError("surface metric: h_min " + std::to_string(h_min) + " above h_max " + std::to_string(h_max));
  }
}

PrincipalCurvatures principal_curvatures(const PatchDerivatives& d) {
  // An orthonormal tangent basis (e1, e2), A = the chart's Jacobian in it, and the shape operator
  // in that basis W = A^-T II A^-1, symmetric: its eigenpairs are the curvatures and directions.
  const Vec3 n0 = cross(d.du, d.dv);
  const Vec3 n = (1.0 / norm(n0)) * n0;
  const Vec3 e1 = (1.0 / norm(d.du)) * d.du;
  const Vec3 e2 = cross(n, e1);
  const double a11 = dot(e1, d.du), a12 = dot(e1, d.dv), a22 = dot(e2, d.dv);  // dot(e2, du) = 0
  const double l = dot(n, d.duu), m = dot(n, d.duv), nn = dot(n, d.dvv);
  // A^-1 = [1/a11, -a12/(a11 a22); 0, 1/a22]; W = A^-T II A^-1.
  const double i11 = 1.0 / a11, i12 = -a12 / (a11 * a22), i22 = 1.0 / a22;
  // B = II A^-1 (its (2, 1) entry is not needed: W is symmetric)
  const double b11 = l * i11, b12 = l * i12 + m * i22, b22 = m * i12 + nn * i22;
  // W = A^-T B, A^-T = [i11, 0; i12, i22]
  const double w11 = i11 * b11, w12 = i11 * b12, w22 = i12 * b12 + i22 * b22;
  const MetricEigen2 e = eigen(Metric2{{w11, w12, w22}});
  const int big = std::abs(e.values[0]) >= std::abs(e.values[1]) ? 0 : 1;
  PrincipalCurvatures c;
  c.k1 = e.values[big];
  c.k2 = e.values[1 - big];
  const Vec2 v1 = e.vectors[big], v2 = e.vectors[1 - big];
  c.t1 = v1.x * e1 + v1.y * e2;
  c.t2 = v2.x * e1 + v2.y * e2;
  c.normal = n;
  return c;
}

Metric2 pull_back(const PatchDerivatives& d, const Metric3& m) {
  auto mv = [&](const Vec3& v) {
    return Vec3{m.m[0] * v.x + m.m[1] * v.y + m.m[3] * v.z, m.m[1] * v.x + m.m[2] * v.y + m.m[4] * v.z,
                m.m[3] * v.x + m.m[4] * v.y + m.m[5] * v.z};
  };
  const Vec3 mu = mv(d.du), mvv = mv(d.dv);
  return Metric2{{dot(d.du, mu), dot(d.du, mvv), dot(d.dv, mvv)}};
}

Metric2 induced_metric(const PatchDerivatives& d, double h) {
  const double w = 1.0 / (h * h);
  return Metric2{{w * dot(d.du, d.du), w * dot(d.du, d.dv), w * dot(d.dv, d.dv)}};
}

Metric2 geometric_metric(const PatchDerivatives& d, const SurfaceMetricSpec& spec) {
  const double alpha = 2.0 * std::sqrt(spec.relative_gap * (2.0 - spec.relative_gap));
  const double lo = spec.h_min > 0.0 ? spec.h_min : kMinMetricSize;
  const double hi = spec.h_max > 0.0 ? spec.h_max : kMaxMetricSize;
  auto size_of = [&](double k) {
    if (k == 0.0) return hi;
    const double rho = 1.0 / std::abs(k);
    const double e = 0.375 * spec.hausdorff;  // 3 E / 8 (surface_metric.hpp)
    const double h = e > 0.0 ? (e >= rho ? 2.0 * rho : 2.0 * std::sqrt(e * (2.0 * rho - e))) : alpha * rho;
    return std::clamp(h, lo, hi);
  };
  const PrincipalCurvatures c = principal_curvatures(d);
  if (spec.geometric == GeometricMetric::Isotropic) return induced_metric(d, size_of(c.k1));
  // Anisotropic: sum over the principal directions of t_i t_i^T / h_i^2, pulled back.
  const double w1 = 1.0 / (size_of(c.k1) * size_of(c.k1)), w2 = 1.0 / (size_of(c.k2) * size_of(c.k2));
  const double p1u = dot(c.t1, d.du), p1v = dot(c.t1, d.dv), p2u = dot(c.t2, d.du), p2v = dot(c.t2, d.dv);
  return Metric2{{w1 * p1u * p1u + w2 * p2u * p2u, w1 * p1u * p1v + w2 * p2u * p2v, w1 * p1v * p1v + w2 * p2v * p2v}};
}

Metric2 parameter_metric(const PatchDerivatives& d, const SurfaceMetricSpec& spec) {
  std::optional<Metric2> m;
  auto meet = [&](const Metric2& x) { m = m ? intersect(*m, x) : x; };
  if (spec.size != 0.0) meet(induced_metric(d, spec.size));
  if (spec.user_metric) meet(pull_back(d, spec.user_metric(d.point)));
  if (spec.geometric != GeometricMetric::None) meet(geometric_metric(d, spec));
  if (!m) throw InputError("surface metric: give a size, a user metric or a geometric metric");
  return *m;
}

}  // namespace dtlab
