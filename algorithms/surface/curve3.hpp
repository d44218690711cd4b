// Curves and their meshes under a size or metric map (book §11.2, §11.3.1; Tables 11.1, 11.2):
// the curve is cut into sub-segments of length 1 in the map, their number the rounding of the
// curve's length in the map, L = ∫ sqrt(γ'(t)^T M(γ(t)) γ'(t)) dt, so that each has length L / n.
//
// Curves: a segment, a polyline, a circle arc and a clamped B-spline, each with exact derivatives.
// Maps are given at abscissas s_i (arc length from the curve's start):
//   - isotropic sizes h_i, between two abscissas, at u = (s - s_i) / (s_i+1 - s_i): linear
//     h_i + (h_i+1 - h_i) u, geometric h_i (h_i+1 / h_i)^u, or sinusoidal h_i + (h_i+1 - h_i)
//     (1 - cos(pi u)) / 2 (the book's three, §11.4.1 Figs. 11.16-11.18; its formulas were lost
//     with the OCR, these are the classical ones of the names);
//   - metrics M_i, interpolated on the sizes (kernel/metric.hpp), Table 11.2's case.
// Before the first abscissa and after the last, the end value holds.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

class Curve3 {
 public:
  static Curve3 segment(const Vec3& a, const Vec3& b);
  // Parametrised by arc length; consecutive points distinct (InputError naming the first pair).
  static Curve3 polyline(std::vector<Vec3> points);
  // From `start`, turning by `angle` radians (positive: counter-clockwise about `axis`, a unit
  // vector) around `centre`.
  static Curve3 circle_arc(const Vec3& centre, const Vec3& start, const Vec3& axis, double angle);
  // Clamped B-spline of degree p: control points, and knots (non-decreasing, p + 1 equal at each
  // end, control points + p + 1 of them); InputError otherwise.
  static Curve3 bspline(std::vector<Vec3> controls, std::vector<double> knots, std::uint32_t degree);

  // At t in [0, 1] (a B-spline: its knot range mapped to [0, 1]).
  Vec3 point(double t) const;
  Vec3 derivative(double t) const;
  // Arc length from t = 0 to t (exact for segments, polylines and arcs; B-splines by Gauss-Legendre
  // quadrature on each knot span, to round-off).
  double arc_length(double t) const;
  double length() const { return arc_length(1.0); }
  // Where the derivative may jump (polyline vertices, knots): kept as quadrature breakpoints.
  const std::vector<double>& breaks() const noexcept { return breaks_; }

 private:
  enum class Kind { Segment, Polyline, Arc, BSpline };
  Kind kind_ = Kind::Segment;
  std::vector<Vec3> points_;    // segment: a, b; polyline: its points; arc: centre, start, axis; B-spline: controls
  std::vector<double> lengths_;  // polyline: cumulative; B-spline: cumulative per quadrature cell
  std::vector<double> knots_;
  std::vector<double> breaks_;
  std::vector<double> cells_;    // B-spline: the arc length table's cell bounds in t
  std::uint32_t degree_ = 0;
  double angle_ = 0.0;
};

enum class SizeInterpolation { Linear, Geometric, Sinusoidal };

// A map along a curve by abscissa: sizes (isotropic) or metrics.
struct CurveMap {
  std::vector<double> abscissas;  // increasing
  std::vector<double> sizes;      // one per abscissa, or empty
  std::vector<Metric3> metrics;   // one per abscissa, or empty
  SizeInterpolation interpolation = SizeInterpolation::Linear;

  // InputError unless the abscissas increase and exactly one of sizes / metrics matches them
  // (positive finite sizes in kernel/metric.hpp's range, positive definite metrics).
  void check() const;
  // The length of the tangent vector d at abscissa s in the map.
  double length(double s, const Vec3& d) const;
};

struct CurveMesh {
  std::vector<double> parameters;  // t of each point, 0 first and 1 last
  std::vector<Vec3> points;
  std::vector<double> lengths;     // of each sub-segment in the map
  double map_length = 0.0;         // L
};

// InputError for a bad map (CurveMap::check) or a curve of zero length.
CurveMesh mesh_curve(const Curve3& curve, const CurveMap& map);

}  // namespace dtlab
