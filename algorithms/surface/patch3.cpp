// Patch3: the charts' maps and their exact derivatives (patch3.hpp).
#include "algorithms/surface/patch3.hpp"

#include <cmath>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {
namespace {

Vec3 axis(std::uint32_t k) {
  return k == 0 ? Vec3{1, 0, 0} : k == 1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
}

// A knot vector's basis: the span s (knots[s] <= t < knots[s + 1], the last non-empty span at the
// end) and the p + 1 non-zero values N_{s-p..s, p}(t) (Cox-de Boor, The NURBS Book A2.2).
struct Basis {
  std::size_t span = 0;
  std::vector<double> values;
};

Basis basis(const std::vector<double>& knots, std::uint32_t p, std::size_t count, double t) {
  Basis b;
  std::size_t s = p;
  while (s + 1 < count && knots[s + 1] <= t) ++s;  // bounded by count
  b.span = s;
  b.values.assign(p + 1, 0.0);
  b.values[0] = 1.0;
  std::vector<double> left(p + 1), right(p + 1);
  for (std::uint32_t j = 1; j <= p; ++j) {
    left[j] = t - knots[s + 1 - j];
    right[j] = knots[s + j] - t;
    double saved = 0.0;
    for (std::uint32_t r = 0; r < j; ++r) {
      const double denominator = right[r + 1] + left[j - r];
      const double temp = denominator != 0.0 ? b.values[r] / denominator : 0.0;
      b.values[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    b.values[j] = saved;
  }
  return b;
}

// The derivative control net along u (rows) of a net of rows x cols: p (P_{i+1} - P_i) /
// (u_{i+p+1} - u_{i+1}), rows - 1 rows, on the knots without their ends (The NURBS Book (3.8)).
std::vector<Vec3> derivative_net_u(const std::vector<Vec3>& net, std::size_t rows, std::size_t cols,
                                   const std::vector<double>& knots, std::uint32_t p) {
  std::vector<Vec3> d;
  if (p == 0 || rows < 2) return d;
  d.resize((rows - 1) * cols);
  for (std::size_t i = 0; i + 1 < rows; ++i) {
    const double span = knots[i + p + 1] - knots[i + 1];
    const double factor = span > 0.0 ? p / span : 0.0;
    for (std::size_t j = 0; j < cols; ++j) d[i * cols + j] = factor * (net[(i + 1) * cols + j] - net[i * cols + j]);
  }
  return d;
}

std::vector<Vec3> transpose(const std::vector<Vec3>& net, std::size_t rows, std::size_t cols) {
  std::vector<Vec3> t(net.size());
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) t[j * rows + i] = net[i * cols + j];
  return t;
}

std::vector<double> inner(const std::vector<double>& knots) {
  return knots.size() < 2 ? std::vector<double>{} : std::vector<double>(knots.begin() + 1, knots.end() - 1);
}

// sum N_i(u) N_j(v) P_ij over a net of rows x cols with degrees (p, q); zero for an empty net.
Vec3 tensor_sum(const std::vector<Vec3>& net, std::size_t rows, std::size_t cols, const std::vector<double>& ku,
                const std::vector<double>& kv, std::uint32_t p, std::uint32_t q, const Vec2& uv) {
  if (net.empty()) return {};
  const Basis bu = basis(ku, p, rows, uv.x), bv = basis(kv, q, cols, uv.y);
  Vec3 s{};
  for (std::uint32_t a = 0; a <= p; ++a)
    for (std::uint32_t b = 0; b <= q; ++b)
      s = s + (bu.values[a] * bv.values[b]) * net[(bu.span - p + a) * cols + (bv.span - q + b)];
  return s;
}

void check_knots(const std::vector<double>& knots, std::size_t count, std::uint32_t degree, const char* dir) {
  const std::string d(dir);
  if (count < degree + 1)
    throw InputError("B-spline patch: " + std::to_string(count) + " control points along " + d + " for degree " +
                     std::to_string(degree) + " (at least degree + 1)");
  if (knots.size() != count + degree + 1)
    throw InputError("B-spline patch: " + std::to_string(knots.size()) + " knots along " + d + "; want controls + degree + 1 = " +
                     std::to_string(count + degree + 1));
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) throw InputError("B-spline patch: knot " + std::to_string(i) + " along " + d + " is not finite");
    if (i > 0 && knots[i] < knots[i - 1])
      throw InputError("B-spline patch: knots along " + d + " decrease at " + std::to_string(i));
  }
  for (std::uint32_t k = 1; k <= degree; ++k) {
    if (knots[k] != knots[0] || knots[knots.size() - 1 - k] != knots.back())
      throw InputError("B-spline patch: knots along " + d + " are not clamped (degree + 1 equal at each end)");
  }
  if (!(knots.back() > knots.front())) throw InputError("B-spline patch: the knots along " + d + " span no interval");
}

}  // namespace

Patch3 Patch3::plane(const Vec3& origin, const Vec3& e1, const Vec3& e2) {
  return framed(Kind::Plane, origin, e1, e2, 0.0, 0.0, 0.0);
}

Patch3 Patch3::sphere_face(const Vec3& centre, double radius, std::uint32_t face) {
  if (face > 5) throw InputError("sphere face " + std::to_string(face) + ": faces are 0..5");
  Patch3 p;
  p.kind_ = Kind::SphereFace;
  p.centre_ = centre;
  p.a_ = radius;
  const std::uint32_t k = face / 2;
  const double sign = face % 2 == 0 ? 1.0 : -1.0;
  p.e3_ = sign * axis(k);  // n
  // a, b: the next two axes in cyclic order, b flipped on a negative face so that a x b = n.
  p.e1_ = axis((k + 1) % 3);
  p.e2_ = sign * axis((k + 2) % 3);
  return p;
}

Patch3 Patch3::framed(Kind kind, const Vec3& centre, const Vec3& e1, const Vec3& e2, double a, double b, double c) {
  Patch3 p;
  p.kind_ = kind;
  p.centre_ = centre;
  p.e1_ = e1;
  p.e2_ = e2;
  p.e3_ = cross(e1, e2);
  p.a_ = a;
  p.b_ = b;
  p.c_ = c;
  return p;
}

Patch3 Patch3::cone(const Vec3& centre, const Vec3& e1, const Vec3& e2, double r0, double r1, double height) {
  return framed(Kind::Cone, centre, e1, e2, r0, r1, height);
}

Patch3 Patch3::torus(const Vec3& centre, const Vec3& e1, const Vec3& e2, double major, double minor) {
  return framed(Kind::Torus, centre, e1, e2, major, minor, 0.0);
}

Patch3 Patch3::sine_graph(double amplitude, double frequency_u, double frequency_v) {
  return framed(Kind::SineGraph, {}, {1, 0, 0}, {0, 1, 0}, amplitude, frequency_u, frequency_v);
}

Patch3 Patch3::bspline(std::vector<Vec3> controls, std::uint32_t count_u, std::uint32_t count_v,
                       std::vector<double> knots_u, std::vector<double> knots_v, std::uint32_t degree_u,
                       std::uint32_t degree_v) {
  if (static_cast<std::uint64_t>(count_u) * count_v != controls.size())
    throw InputError("B-spline patch: " + std::to_string(controls.size()) + " control points for a net of " +
                     std::to_string(count_u) + " x " + std::to_string(count_v));
  for (std::size_t i = 0; i < controls.size(); ++i) {
    const Vec3& c = controls[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      throw InputError("B-spline patch: control point " + std::to_string(i) + " is not finite", {i});
  }
  check_knots(knots_u, count_u, degree_u, "u");
  check_knots(knots_v, count_v, degree_v, "v");
  Patch3 p;
  p.kind_ = Kind::BSpline;
  p.controls_ = std::move(controls);
  p.knots_u_ = std::move(knots_u);
  p.knots_v_ = std::move(knots_v);
  p.count_u_ = count_u;
  p.count_v_ = count_v;
  p.degree_u_ = degree_u;
  p.degree_v_ = degree_v;
  p.build_derivative_nets();
  return p;
}

void Patch3::build_derivative_nets() {
  const std::size_t nu = count_u_, nv = count_v_;
  const std::uint32_t p = degree_u_, q = degree_v_;
  // Along u on the rows; along v on the transpose, turned back.
  du_net_ = derivative_net_u(controls_, nu, nv, knots_u_, p);
  duu_net_ = derivative_net_u(du_net_, nu - 1, nv, inner(knots_u_), p - (p > 0));
  const std::vector<Vec3> dv_t = derivative_net_u(transpose(controls_, nu, nv), nv, nu, knots_v_, q);
  dv_net_ = dv_t.empty() ? dv_t : transpose(dv_t, nv - 1, nu);
  const std::vector<Vec3> dvv_t = derivative_net_u(dv_t, nv - 1, nu, inner(knots_v_), q - (q > 0));
  dvv_net_ = dvv_t.empty() ? dvv_t : transpose(dvv_t, nv - 2, nu);
  duv_net_ = dv_net_.empty() ? dv_net_ : derivative_net_u(dv_net_, nu, nv - 1, knots_u_, p);
}

PatchDerivatives Patch3::bspline_derivatives(const Vec2& uv) const {
  const std::size_t nu = count_u_, nv = count_v_;
  const std::uint32_t p = degree_u_, q = degree_v_;
  const std::vector<double> ku1 = inner(knots_u_), kv1 = inner(knots_v_);
  PatchDerivatives d;
  d.point = tensor_sum(controls_, nu, nv, knots_u_, knots_v_, p, q, uv);
  if (p >= 1) d.du = tensor_sum(du_net_, nu - 1, nv, ku1, knots_v_, p - 1, q, uv);
  if (p >= 2) d.duu = tensor_sum(duu_net_, nu - 2, nv, inner(ku1), knots_v_, p - 2, q, uv);
  if (q >= 1) d.dv = tensor_sum(dv_net_, nu, nv - 1, knots_u_, kv1, p, q - 1, uv);
  if (q >= 2) d.dvv = tensor_sum(dvv_net_, nu, nv - 2, knots_u_, inner(kv1), p, q - 2, uv);
  if (p >= 1 && q >= 1) d.duv = tensor_sum(duv_net_, nu - 1, nv - 1, ku1, kv1, p - 1, q - 1, uv);
  return d;
}

PatchDerivatives Patch3::evaluate(const Vec2& uv) const {
  const double u = uv.x, v = uv.y;
  PatchDerivatives d;
  switch (kind_) {
    case Kind::Plane:
      d.point = centre_ + u * e1_ + v * e2_;
      d.du = e1_;
      d.dv = e2_;
      return d;
    case Kind::SphereFace: {
      // g(q) = q / |q| with q linear in (u, v): g_i = q_i / r - q (q.q_i) / r^3 and
      // g_ij = -(q_i (q.q_j) + q_j (q.q_i) + q (q_i.q_j)) / r^3 + 3 q (q.q_i)(q.q_j) / r^5.
      const Vec3 q = e3_ + u * e1_ + v * e2_;
      const double r2 = dot(q, q), r = std::sqrt(r2), r3 = r2 * r, r5 = r3 * r2;
      const double qa = dot(q, e1_), qb = dot(q, e2_);
      const double s = a_;
      d.point = centre_ + (s / r) * q;
      d.du = s * ((1.0 / r) * e1_ - (qa / r3) * q);
      d.dv = s * ((1.0 / r) * e2_ - (qb / r3) * q);
      d.duu = s * ((-2.0 * qa / r3) * e1_ + (3.0 * qa * qa / r5 - 1.0 / r3) * q);
      d.dvv = s * ((-2.0 * qb / r3) * e2_ + (3.0 * qb * qb / r5 - 1.0 / r3) * q);
      d.duv = s * ((-qb / r3) * e1_ + (-qa / r3) * e2_ + (3.0 * qa * qb / r5 - dot(e1_, e2_) / r3) * q);
      return d;
    }
    case Kind::Cone: {
      const double slope = (b_ - a_) / c_;
      const double radius = a_ + slope * v;
      const Vec3 radial = std::cos(u) * e1_ + std::sin(u) * e2_;
      const Vec3 turn = -std::sin(u) * e1_ + std::cos(u) * e2_;  // d radial / du
      d.point = centre_ + radius * radial + v * e3_;
      d.du = radius * turn;
      d.dv = slope * radial + e3_;
      d.duu = -radius * radial;
      d.duv = slope * turn;
      return d;
    }
    case Kind::Torus: {
      const Vec3 radial = std::cos(u) * e1_ + std::sin(u) * e2_;
      const Vec3 turn = -std::sin(u) * e1_ + std::cos(u) * e2_;
      const double ring = a_ + b_ * std::cos(v);
      d.point = centre_ + ring * radial + (b_ * std::sin(v)) * e3_;
      d.du = ring * turn;
      d.dv = (-b_ * std::sin(v)) * radial + (b_ * std::cos(v)) * e3_;
      d.duu = -ring * radial;
      d.duv = (-b_ * std::sin(v)) * turn;
      d.dvv = (-b_ * std::cos(v)) * radial + (-b_ * std::sin(v)) * e3_;
      return d;
    }
    case Kind::SineGraph: {
      const double su = std::sin(b_ * u), cu = std::cos(b_ * u), sv = std::sin(c_ * v), cv = std::cos(c_ * v);
      d.point = {u, v, a_ * su * cv};
      d.du = {1, 0, a_ * b_ * cu * cv};
      d.dv = {0, 1, -a_ * c_ * su * sv};
      d.duu = {0, 0, -a_ * b_ * b_ * su * cv};
      d.duv = {0, 0, -a_ * b_ * c_ * cu * sv};
      d.dvv = {0, 0, -a_ * c_ * c_ * su * cv};
      return d;
    }
    case Kind::BSpline:
      return bspline_derivatives(uv);
  }
  return d;
}

}  // namespace dtlab
