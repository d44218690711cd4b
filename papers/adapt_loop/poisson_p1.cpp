// P1 Poisson solver and error measures (poisson_p1.hpp).
#include "papers/adapt_loop/poisson_p1.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace dtlab::papers {

namespace {

// Dunavant's 7-point rule, exact for degree 5 (barycentric a, b, c; weights sum to 1).
struct QuadraturePoint {
  double a, b, c, w;
};
constexpr std::array<QuadraturePoint, 7> kRule{{
    {1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225},
    {0.059715871789770, 0.470142064105115, 0.470142064105115, 0.132394152788506},
    {0.470142064105115, 0.059715871789770, 0.470142064105115, 0.132394152788506},
    {0.470142064105115, 0.470142064105115, 0.059715871789770, 0.132394152788506},
    {0.797426985353087, 0.101286507323456, 0.101286507323456, 0.125939180544827},
    {0.101286507323456, 0.797426985353087, 0.101286507323456, 0.125939180544827},
    {0.101286507323456, 0.101286507323456, 0.797426985353087, 0.125939180544827},
}};

std::vector<char> boundary_vertices(const MeshData2& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) ++count[{std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])}];
  std::vector<char> on(mesh.vertices.size(), 0);
  for (const auto& [e, n] : count)
    if (n == 1) on[e.first] = on[e.second] = 1;
  return on;
}

}  // namespace

std::vector<double> solve_poisson_p1(const MeshData2& mesh, const ScalarField& f, const ScalarField& g) {
  const std::size_t n = mesh.vertices.size();
  const std::vector<char> fixed = boundary_vertices(mesh);
  std::vector<double> u(n, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    if (fixed[v]) u[v] = g(mesh.vertices[v]);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  for (const auto& t : mesh.triangles) {
    const Vec2 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    const double area2 = cross(p[1] - p[0], p[2] - p[0]);  // twice the area
    // Gradients of the barycentric functions: grad λ_i = perp(p_{i+2} - p_{i+1}) / (2 area).
    Vec2 grad[3];
    for (int i = 0; i < 3; ++i) {
      const Vec2 e = p[(i + 2) % 3] - p[(i + 1) % 3];
      grad[i] = (1.0 / area2) * Vec2{-e.y, e.x};
    }
    double load[3] = {0, 0, 0};
    for (const QuadraturePoint& q : kRule) {
      const Vec2 x = q.a * p[0] + q.b * p[1] + q.c * p[2];
      const double fx = f(x) * q.w * 0.5 * area2;
      load[0] += fx * q.a;
      load[1] += fx * q.b;
      load[2] += fx * q.c;
    }
    for (int i = 0; i < 3; ++i) {
      if (fixed[t[i]]) continue;
      rhs[t[i]] += load[i];
      for (int j = 0; j < 3; ++j) {
        const double k = 0.5 * area2 * dot(grad[i], grad[j]);
        if (fixed[t[j]])
          rhs[t[i]] -= k * u[t[j]];
        else
          entries.emplace_back(t[i], t[j], k);
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (fixed[v]) entries.emplace_back(v, v, 1.0), rhs[static_cast<Eigen::Index>(v)] = u[v];
  Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) throw std::runtime_error("poisson_p1: the stiffness matrix did not factorise");
  const Eigen::VectorXd x = solver.solve(rhs);
  for (std::size_t v = 0; v < n; ++v) u[v] = x[static_cast<Eigen::Index>(v)];
  return u;
}

FieldErrors p1_errors(const MeshData2& mesh, const std::vector<double>& values, const ScalarField& u) {
  FieldErrors e;
  double l2 = 0.0;
  constexpr int kLattice = 8;  // samples at barycentric coordinates (i, j, k) / 8
  for (const auto& t : mesh.triangles) {
    const Vec2 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    const double w[3] = {values[t[0]], values[t[1]], values[t[2]]};
    for (int i = 0; i <= kLattice; ++i)
      for (int j = 0; i + j <= kLattice; ++j) {
        const double a = static_cast<double>(i) / kLattice, b = static_cast<double>(j) / kLattice, c = 1.0 - a - b;
        const Vec2 x = a * p[0] + b * p[1] + c * p[2];
        e.linf = std::max(e.linf, std::fabs(u(x) - (a * w[0] + b * w[1] + c * w[2])));
      }
    const double area = 0.5 * cross(p[1] - p[0], p[2] - p[0]);
    for (const QuadraturePoint& q : kRule) {
      const Vec2 x = q.a * p[0] + q.b * p[1] + q.c * p[2];
      const double d = u(x) - (q.a * w[0] + q.b * w[1] + q.c * w[2]);
      l2 += q.w * area * d * d;
    }
  }
  e.l2 = std::sqrt(l2);
  return e;
}

}  // namespace dtlab::papers
