// Metrics in a chart's parameter space (book §6.2, §6.3.2-§6.3.3). A metric M3 of R^3 restricted to
// the tangent plane and read in the parameters is J^T M3 J, J = [sigma_u sigma_v]; so
//   - the induced metric of a 3D size h is the first fundamental form over h^2: [E F; F G] / h^2;
//   - the geometric metrics come from the second fundamental form: principal curvatures k1, k2
//     and directions from the shape operator, radii rho_i = 1 / |k_i|. The edge of a chord of a
//     circle of radius rho whose gap (sagitta) is eps rho is alpha rho, alpha = 2 sqrt(eps (2 -
//     eps)); the isotropic map takes the size alpha rho_min in every direction, the anisotropic
//     one alpha rho_i along direction i (book (6.23) and the anisotropic map after it; the OCR lost
//     the constant, this is the chord's), each size clipped to [h_min, h_max];
//   - a user's 3D metric is pulled back the same way and intersected (kernel/metric.hpp, §9.5)
//     with the geometric one (§6.3.3's physico-geometric cases).
// Everything is computed from the exact derivatives (patch3.hpp), intrinsic to the surface: two
// charts that share a seam give the same lengths along it.
#pragma once

#include <functional>
#include <optional>

#include "algorithms/surface/patch3.hpp"
#include "kernel/metric.hpp"

namespace dtlab {

enum class GeometricMetric : std::uint8_t { None, Isotropic, Anisotropic };

struct SurfaceMetricSpec {
  // A uniform 3D size (the induced metric); 0: none.
  double size = 0.0;
  // A 3D size or metric map given by the user (as book (6.30)); empty: none.
  std::function<Metric3(const Vec3&)> user_metric;
  GeometricMetric geometric = GeometricMetric::None;
  double relative_gap = 0.01;  // eps of alpha = 2 sqrt(eps (2 - eps))
  // An absolute bound E on the gap between the triangles and the surface instead (when > 0). The
  // chord whose sagitta on a circle of radius rho is s has length 2 sqrt(s (2 rho - s)); a unit
  // mesh has edges up to sqrt 2 (sagitta x 2) and a triangle's centre lies 4/3 as far from the
  // surface as its edges' midpoints (equilateral), so the sizes take s = 3 E / 8 (2 rho when s >= rho).
  double hausdorff = 0.0;
  double h_min = 0.0, h_max = 0.0;  // the geometric sizes' clip; h_max = 0: no upper bound but kMaxMetricSize

  // InputError naming the field: no metric at all, a size, gap or bound out of range.
  void check() const;
};

struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;  // |k1| >= |k2|
  Vec3 t1{}, t2{};        // unit principal directions in R^3
  Vec3 normal{};
};
PrincipalCurvatures principal_curvatures(const PatchDerivatives& d);

// J^T M3 J.
Metric2 pull_back(const PatchDerivatives& d, const Metric3& m);
// [E F; F G] / h^2.
Metric2 induced_metric(const PatchDerivatives& d, double h);
// The geometric metric (isotropic or anisotropic, spec's gap and clip).
Metric2 geometric_metric(const PatchDerivatives& d, const SurfaceMetricSpec& spec);
// The metric the spec asks for at a point: the intersection of those it names.
Metric2 parameter_metric(const PatchDerivatives& d, const SurfaceMetricSpec& spec);

}  // namespace dtlab
