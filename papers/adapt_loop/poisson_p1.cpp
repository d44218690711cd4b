// P1 Poisson solver and the loop's error measures (poisson_p1.hpp).
#include "papers/adapt_loop/poisson_p1.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "kernel/error.hpp"

namespace dtlab::paper {
namespace {

// Dunavant 1985, degree 5, 7 points: barycentric coordinates and weights (summing to 1).
struct QuadraturePoint {
  double l0, l1, l2, w;
};
constexpr double kA1 = 0.059715871789770, kB1 = 0.470142064105115;
constexpr double kA2 = 0.797426985353087, kB2 = 0.101286507323456;
constexpr double kW0 = 0.225, kW1 = 0.132394152788506, kW2 = 0.125939180544827;
constexpr std::array<QuadraturePoint, 7> kRule{{{1.0 / 3, 1.0 / 3, 1.0 / 3, kW0},
                                                 {kA1, kB1, kB1, kW1},
                                                 {kB1, kA1, kB1, kW1},
                                                 {kB1, kB1, kA1, kW1},
                                                 {kA2, kB2, kB2, kW2},
                                                 {kB2, kA2, kB2, kW2},
                                                 {kB2, kB2, kA2, kW2}}};

Vec2 at(const std::array<Vec2, 3>& p, double l0, double l1, double l2) {
  return {l0 * p[0].x + l1 * p[1].x + l2 * p[2].x, l0 * p[0].y + l1 * p[1].y + l2 * p[2].y};
}

std::array<Vec2, 3> corners(const MeshData2& mesh, std::size_t t) {
  const auto& tri = mesh.triangles[t];
  return {mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
}

// Vertices of edges that one triangle only has.
std::vector<bool> boundary_vertices(const MeshData2& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) ++uses[std::minmax(t[i], t[(i + 1) % 3])];
  std::vector<bool> on(mesh.vertices.size(), false);
  for (const auto& [edge, count] : uses)
    if (count == 1) on[edge.first] = on[edge.second] = true;
  return on;
}

}  // namespace

std::vector<double> solve_poisson(const MeshData2& mesh, const ScalarField& f, const ScalarField& g) {
  const std::size_t n = mesh.vertices.size();
  const std::vector<bool> on_boundary = boundary_vertices(mesh);
  std::vector<double> u(n, 0.0);
  std::vector<std::int64_t> unknown(n, -1);
  std::int64_t unknowns = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (on_boundary[v]) u[v] = g(mesh.vertices[v]);
    else unknown[v] = unknowns++;
  }
  if (unknowns == 0) throw InputError("solve_poisson: the mesh has no interior vertex");

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(mesh.triangles.size() * 9);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<Vec2, 3> p = corners(mesh, t);
    const double twice_area = cross(p[1] - p[0], p[2] - p[0]);
    // Gradient of the hat function of corner i: the rotated opposite edge over twice the area.
    std::array<Vec2, 3> grad;
    for (int i = 0; i < 3; ++i) {
      const Vec2 e = p[(i + 2) % 3] - p[(i + 1) % 3];
      grad[i] = {-e.y / twice_area, e.x / twice_area};
    }
    std::array<double, 3> load{0.0, 0.0, 0.0};
    for (const QuadraturePoint& q : kRule) {
      const double fq = f(at(p, q.l0, q.l1, q.l2)) * q.w * 0.5 * twice_area;
      load[0] += fq * q.l0;
      load[1] += fq * q.l1;
      load[2] += fq * q.l2;
    }
    for (int i = 0; i < 3; ++i) {
      const std::int64_t row = unknown[tri[i]];
      if (row < 0) continue;
      rhs[row] += load[i];
      for (int j = 0; j < 3; ++j) {
        const double k = 0.5 * twice_area * dot(grad[i], grad[j]);
        const std::int64_t col = unknown[tri[j]];
        if (col >= 0) entries.emplace_back(row, col, k);
        else rhs[row] -= k * u[tri[j]];
      }
    }
  }
  Eigen::SparseMatrix<double> stiffness(unknowns, unknowns);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(stiffness);
  if (solver.info() != Eigen::Success)
    throw InputError("solve_poisson: the factorization of the stiffness matrix failed (" + std::to_string(unknowns) +
                     " unknowns): is the mesh degenerate?");
  const Eigen::VectorXd x = solver.solve(rhs);
  for (std::size_t v = 0; v < n; ++v)
    if (unknown[v] >= 0) u[v] = x[unknown[v]];
  return u;
}

FieldErrors field_errors(const MeshData2& mesh, const std::vector<double>& uh, const ScalarField& u, int lattice) {
  std::vector<double> exact(mesh.vertices.size());
  for (std::size_t v = 0; v < exact.size(); ++v) exact[v] = u(mesh.vertices[v]);
  FieldErrors e;
  double l2 = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<Vec2, 3> p = corners(mesh, t);
    const auto value = [&](const std::vector<double>& at_vertices, double l0, double l1, double l2_) {
      return l0 * at_vertices[tri[0]] + l1 * at_vertices[tri[1]] + l2_ * at_vertices[tri[2]];
    };
    for (int i = 0; i <= lattice; ++i)
      for (int j = 0; i + j <= lattice; ++j) {
        const double l1 = static_cast<double>(i) / lattice, l2_ = static_cast<double>(j) / lattice;
        const double l0 = 1.0 - l1 - l2_;
        const double ux = u(at(p, l0, l1, l2_));
        e.fe_max = std::max(e.fe_max, std::fabs(ux - value(uh, l0, l1, l2_)));
        e.interp_max = std::max(e.interp_max, std::fabs(ux - value(exact, l0, l1, l2_)));
      }
    const double area = 0.5 * cross(p[1] - p[0], p[2] - p[0]);
    for (const QuadraturePoint& q : kRule) {
      const double d = u(at(p, q.l0, q.l1, q.l2)) - value(uh, q.l0, q.l1, q.l2);
      l2 += q.w * area * d * d;
    }
  }
  e.fe_l2 = std::sqrt(l2);
  return e;
}

}  // namespace dtlab::paper
