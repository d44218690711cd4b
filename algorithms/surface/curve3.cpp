#include "algorithms/surface/curve3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

// Gauss-Legendre, 8 points on [-1, 1] (Abramowitz and Stegun, Table 25.4).
constexpr std::array<double, 4> kNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

template <class F>
double gauss8(F&& f, double a, double b) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * (f(mid - half * kNodes[i]) + f(mid + half * kNodes[i]));
  return half * sum;
}

constexpr std::uint32_t kBSplineCells = 16;  // quadrature cells per knot span for the arc length

void check_finite(const std::vector<Vec3>& points, const std::string& what) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw InputError(what + ": point " + std::to_string(i + 1) + " is not finite", {i});
}

}  // namespace

Curve3 Curve3::segment(const Vec3& a, const Vec3& b) {
  check_finite({a, b}, "segment");
  Curve3 c;
  c.kind_ = Kind::Segment;
  c.points_ = {a, b};
  return c;
}

Curve3 Curve3::polyline(std::vector<Vec3> points) {
  if (points.size() < 2) throw InputError("polyline: needs at least two points");
  check_finite(points, "polyline");
  Curve3 c;
  c.kind_ = Kind::Polyline;
  c.lengths_.assign(1, 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double l = norm(points[i] - points[i - 1]);
    if (!(l > 0.0))
      throw InputError("polyline: points " + std::to_string(i) + " and " + std::to_string(i + 1) + " are the same",
                       {i - 1, i});
    c.lengths_.push_back(c.lengths_.back() + l);
  }
  for (std::size_t i = 1; i + 1 < points.size(); ++i) c.breaks_.push_back(c.lengths_[i] / c.lengths_.back());
  c.points_ = std::move(points);
  return c;
}

Curve3 Curve3::circle_arc(const Vec3& centre, const Vec3& start, const Vec3& axis, double angle) {
  check_finite({centre, start, axis}, "circle arc (centre, start, axis)");
  const Vec3 r = start - centre;
  if (!(norm(r) > 0.0)) throw InputError("circle arc: the start is the centre");
  if (std::abs(norm(axis) - 1.0) > 1e-12) throw InputError("circle arc: the axis is not a unit vector");
  if (std::abs(dot(r, axis)) > 1e-12 * norm(r)) throw InputError("circle arc: the start is not in the plane normal to the axis");
  if (!(std::abs(angle) > 0.0) || !std::isfinite(angle)) throw InputError("circle arc: the angle must be finite and not 0");
  Curve3 c;
  c.kind_ = Kind::Arc;
  c.points_ = {centre, start, axis};
  c.angle_ = angle;
  return c;
}

Curve3 Curve3::bspline(std::vector<Vec3> controls, std::vector<double> knots, std::uint32_t degree) {
  const std::size_t n = controls.size();
  if (degree < 1) throw InputError("B-spline: the degree must be at least 1");
  check_finite(controls, "B-spline control");
  if (n < degree + 1) throw InputError("B-spline: degree " + std::to_string(degree) + " needs at least " +
                                       std::to_string(degree + 1) + " control points");
  if (knots.size() != n + degree + 1)
    throw InputError("B-spline: " + std::to_string(knots.size()) + " knots for " + std::to_string(n) +
                     " control points of degree " + std::to_string(degree) + " (needs " + std::to_string(n + degree + 1) + ")");
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i]) || (i > 0 && knots[i] < knots[i - 1]))
      throw InputError("B-spline: knot " + std::to_string(i + 1) + " is not finite or decreases", {i});
  }
  for (std::uint32_t i = 0; i < degree; ++i)
    if (knots[i] != knots[degree] || knots[n + 1 + i] != knots[n])
      throw InputError("B-spline: not clamped (the first and last " + std::to_string(degree + 1) + " knots must be equal)");
  if (!(knots[n] > knots[degree])) throw InputError("B-spline: the knots span no interval");
  Curve3 c;
  c.kind_ = Kind::BSpline;
  c.points_ = std::move(controls);
  c.knots_ = std::move(knots);
  c.degree_ = degree;
  const double u0 = c.knots_[degree], u1 = c.knots_[n];
  // Arc length table: kBSplineCells cells per non-empty knot span.
  c.lengths_.assign(1, 0.0);
  std::vector<double>& cells = c.cells_;
  cells.assign(1, 0.0);
  for (std::size_t k = degree; k < n; ++k) {
    if (!(c.knots_[k + 1] > c.knots_[k])) continue;
    const double a = (c.knots_[k] - u0) / (u1 - u0), b = (c.knots_[k + 1] - u0) / (u1 - u0);
    if (k > degree) c.breaks_.push_back(a);
    for (std::uint32_t j = 1; j <= kBSplineCells; ++j) {
      const double x = j == kBSplineCells ? b : a + (b - a) * j / kBSplineCells;
      cells.push_back(x);
      c.lengths_.push_back(c.lengths_.back() + gauss8([&](double t) { return norm(c.derivative(t)); }, cells[cells.size() - 2], x));
    }
  }
  return c;
}

Vec3 Curve3::point(double t) const {
  switch (kind_) {
    case Kind::Segment: return points_[0] + t * (points_[1] - points_[0]);
    case Kind::Polyline: {
      const double s = std::clamp(t, 0.0, 1.0) * lengths_.back();
      const std::size_t i = std::clamp<std::size_t>(
          std::upper_bound(lengths_.begin(), lengths_.end(), s) - lengths_.begin(), 1, lengths_.size() - 1);
      const double u = (s - lengths_[i - 1]) / (lengths_[i] - lengths_[i - 1]);
      return points_[i - 1] + u * (points_[i] - points_[i - 1]);
    }
    case Kind::Arc: {
      const Vec3 r = points_[1] - points_[0], q = cross(points_[2], r);
      const double a = t * angle_;
      return points_[0] + std::cos(a) * r + std::sin(a) * q;
    }
    case Kind::BSpline: break;
  }
  // de Boor's algorithm on the span holding u.
  const std::size_t n = points_.size(), p = degree_;
  const double u = knots_[p] + t * (knots_[n] - knots_[p]);
  std::size_t k = std::upper_bound(knots_.begin() + p, knots_.begin() + n, u) - knots_.begin() - 1;
  k = std::clamp(k, p, n - 1);
  std::vector<Vec3> d(points_.begin() + (k - p), points_.begin() + (k + 1));
  for (std::size_t r = 1; r <= p; ++r)
    for (std::size_t j = p; j >= r; --j) {
      const double lo = knots_[j + k - p], hi = knots_[j + 1 + k - r];
      const double alpha = hi > lo ? (u - lo) / (hi - lo) : 0.0;
      d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
    }
  return d[p];
}

Vec3 Curve3::derivative(double t) const {
  switch (kind_) {
    case Kind::Segment: return points_[1] - points_[0];
    case Kind::Polyline: {
      const double s = std::clamp(t, 0.0, 1.0) * lengths_.back();
      const std::size_t i = std::clamp<std::size_t>(
          std::upper_bound(lengths_.begin(), lengths_.end(), s) - lengths_.begin(), 1, lengths_.size() - 1);
      return (lengths_.back() / (lengths_[i] - lengths_[i - 1])) * (points_[i] - points_[i - 1]);
    }
    case Kind::Arc: {
      const Vec3 r = points_[1] - points_[0], q = cross(points_[2], r);
      const double a = t * angle_;
      return angle_ * (std::cos(a) * q - std::sin(a) * r);
    }
    case Kind::BSpline: break;
  }
  // The derivative is the B-spline of degree p - 1 on the differences p (P_i+1 - P_i) / (u_i+p+1 -
  // u_i+1), on the knots less their first and last, times du/dt.
  const std::size_t n = points_.size(), p = degree_;
  const double span = knots_[n] - knots_[p];
  const double u = knots_[p] + t * span;
  std::size_t k = std::upper_bound(knots_.begin() + p, knots_.begin() + n, u) - knots_.begin() - 1;
  k = std::clamp(k, p, n - 1);
  std::vector<Vec3> d;
  for (std::size_t i = k - p; i < k; ++i) {
    const double w = knots_[i + p + 1] - knots_[i + 1];
    d.push_back(w > 0.0 ? (double(p) / w) * (points_[i + 1] - points_[i]) : Vec3{});
  }
  for (std::size_t r = 1; r + 1 <= p; ++r)
    for (std::size_t j = p - 1; j >= r; --j) {
      // Knots of the derivative: knots_[i + 1]; control d[j] is Q_{j + k - p}.
      const double lo = knots_[j + k - p + 1], hi = knots_[j + 1 + k - r];
      const double alpha = hi > lo ? (u - lo) / (hi - lo) : 0.0;
      d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
    }
  return span * d[p - 1];
}

double Curve3::arc_length(double t) const {
  switch (kind_) {
    case Kind::Segment: return t * norm(points_[1] - points_[0]);
    case Kind::Polyline: return t * lengths_.back();
    case Kind::Arc: return t * std::abs(angle_) * norm(points_[1] - points_[0]);
    case Kind::BSpline: break;
  }
  const std::size_t i =
      std::clamp<std::size_t>(std::upper_bound(cells_.begin(), cells_.end(), t) - cells_.begin(), 1, cells_.size() - 1);
  return lengths_[i - 1] + gauss8([&](double x) { return norm(derivative(x)); }, cells_[i - 1], t);
}

void CurveMap::check() const {
  if (abscissas.empty()) throw InputError("curve map: no abscissa");
  for (std::size_t i = 0; i < abscissas.size(); ++i)
    if (!std::isfinite(abscissas[i]) || (i > 0 && !(abscissas[i] > abscissas[i - 1])))
      throw InputError("curve map: abscissa " + std::to_string(i + 1) + " is not finite or does not increase", {i});
  if (sizes.empty() == metrics.empty()) throw InputError("curve map: give sizes or metrics, one per abscissa");
  if (!sizes.empty() && sizes.size() != abscissas.size())
    throw InputError("curve map: " + std::to_string(sizes.size()) + " sizes for " + std::to_string(abscissas.size()) + " abscissas");
  if (!metrics.empty() && metrics.size() != abscissas.size())
    throw InputError("curve map: " + std::to_string(metrics.size()) + " metrics for " + std::to_string(abscissas.size()) +
                     " abscissas");
  for (std::size_t i = 0; i < sizes.size(); ++i) check_size(sizes[i], "curve map: size " + std::to_string(i + 1));
  for (std::size_t i = 0; i < metrics.size(); ++i)
    if (!metrics[i].is_positive_definite())
      throw InputError("curve map: metric " + std::to_string(i + 1) + " is not positive definite", {i});
}

double CurveMap::length(double s, const Vec3& d) const {
  const std::size_t last = abscissas.size() - 1;
  std::size_t i = 0;
  double u = 0.0;
  if (s >= abscissas[last]) {
    i = last;
  } else if (s > abscissas[0]) {
    i = std::upper_bound(abscissas.begin(), abscissas.end(), s) - abscissas.begin() - 1;
    u = (s - abscissas[i]) / (abscissas[i + 1] - abscissas[i]);
  }
  if (!metrics.empty()) return (u > 0.0 ? interpolate(metrics[i], metrics[i + 1], u) : metrics[i]).length(d);
  double h = sizes[i];
  if (u > 0.0) {
    const double a = sizes[i], b = sizes[i + 1];
    switch (interpolation) {
      case SizeInterpolation::Linear: h = a + (b - a) * u; break;
      case SizeInterpolation::Geometric: h = a * std::pow(b / a, u); break;
      case SizeInterpolation::Sinusoidal: h = a + (b - a) * 0.5 * (1.0 - std::cos(std::numbers::pi * u)); break;
    }
  }
  return norm(d) / h;
}

CurveMesh mesh_curve(const Curve3& curve, const CurveMap& map) {
  map.check();
  const double total = curve.length();
  if (!(total > 0.0)) throw InputError("curve mesh: the curve has zero length");
  // Breakpoints: the curve's, and the map's abscissas (where the density's derivative jumps).
  std::vector<double> cuts{0.0, 1.0};
  for (const double b : curve.breaks()) cuts.push_back(b);
  for (const double s : map.abscissas) {
    if (!(s > 0.0 && s < total)) continue;
    double lo = 0.0, hi = 1.0;  // t with arc_length(t) = s, by bisection
    for (int k = 0; k < 80 && hi - lo > 0.0; ++k) {
      const double mid = 0.5 * (lo + hi);
      (curve.arc_length(mid) < s ? lo : hi) = mid;
    }
    cuts.push_back(0.5 * (lo + hi));
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const auto density = [&](double t) { return map.length(curve.arc_length(t), curve.derivative(t)); };
  // Adaptive Gauss-Legendre: an interval is kept when its two halves agree with it to 1e-13.
  struct Cell {
    double a, b, value;
  };
  std::vector<Cell> cells;
  constexpr std::size_t kMaxCells = 1u << 20;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    std::vector<std::pair<Cell, int>> stack{{{cuts[k], cuts[k + 1], gauss8(density, cuts[k], cuts[k + 1])}, 0}};
    std::vector<Cell> done;
    while (!stack.empty()) {
      const auto [c, depth] = stack.back();
      stack.pop_back();
      const double m = 0.5 * (c.a + c.b);
      const double left = gauss8(density, c.a, m), right = gauss8(density, m, c.b);
      if (depth >= 40 || std::abs(left + right - c.value) <= 1e-13 * std::max(std::abs(c.value), 1e-300)) {
        done.push_back({c.a, m, left});
        done.push_back({m, c.b, right});
      } else {
        stack.push_back({{m, c.b, right}, depth + 1});
        stack.push_back({{c.a, m, left}, depth + 1});
      }
      if (done.size() + cells.size() > kMaxCells)
        throw InternalError("curve mesh: the quadrature of the map length exceeded its bound of " + std::to_string(kMaxCells) + " cells");
    }
    std::sort(done.begin(), done.end(), [](const Cell& x, const Cell& y) { return x.a < y.a; });
    cells.insert(cells.end(), done.begin(), done.end());
  }
  std::vector<double> cumulative{0.0};
  for (const Cell& c : cells) cumulative.push_back(cumulative.back() + c.value);
  const double length = cumulative.back();
  const auto lambda = [&](double t, std::size_t cell) { return cumulative[cell] + gauss8(density, cells[cell].a, t); };
  CurveMesh mesh;
  mesh.map_length = length;
  const auto n = static_cast<std::uint64_t>(std::max(1.0, std::round(length)));
  if (n > (1u << 26)) throw InputError("curve mesh: " + std::to_string(n) + " sub-segments asked (the map is too fine)");
  mesh.parameters.push_back(0.0);
  std::vector<std::size_t> where{0};
  for (std::uint64_t k = 1; k < n; ++k) {
    const double target = length * static_cast<double>(k) / static_cast<double>(n);
    const std::size_t c = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin() - 1, cells.size() - 1);
    double lo = cells[c].a, hi = cells[c].b;
    for (int it = 0; it < 80 && hi - lo > 0.0; ++it) {
      const double mid = 0.5 * (lo + hi);
      (lambda(mid, c) < target ? lo : hi) = mid;
    }
    mesh.parameters.push_back(0.5 * (lo + hi));
    where.push_back(c);
  }
  mesh.parameters.push_back(1.0);
  where.push_back(cells.size() - 1);
  double previous = 0.0;
  for (std::size_t k = 0; k < mesh.parameters.size(); ++k) {
    mesh.points.push_back(curve.point(mesh.parameters[k]));
    if (k == 0) continue;
    const double at = k + 1 == mesh.parameters.size() ? length : lambda(mesh.parameters[k], where[k]);
    mesh.lengths.push_back(at - previous);
    previous = at;
  }
  return mesh;
}

}  // namespace dtlab
