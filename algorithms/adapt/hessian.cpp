// Hessian recovery (hessian.hpp), one template for 2D and 3D.
#include "algorithms/adapt/hessian.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

template <int D>
struct Space;
template <>
struct Space<2> {
  using Point = Vec2;
  static constexpr int kTensor = 3;
  static double at(const Vec2& p, int i) { return i == 0 ? p.x : p.y; }
};
template <>
struct Space<3> {
  using Point = Vec3;
  static constexpr int kTensor = 6;
  static double at(const Vec3& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }
};

// Medit's tensor order: the (i, j) entry's slot. 2D: 11 12 22; 3D: 11 12 22 13 23 33.
template <int D>
constexpr int slot(int i, int j) {
  if (i > j) std::swap(i, j);
  if constexpr (D == 2) return i + j;  // (0,0) 0, (0,1) 1, (1,1) 2
  return j == 0 ? 0 : j == 1 ? (i == 0 ? 1 : 2) : (i == 0 ? 3 : i == 1 ? 4 : 5);
}

template <int D>
void check_input(std::size_t points, std::span<const std::array<std::uint32_t, D + 1>> elements,
                 std::span<const double> values) {
  if (values.size() != points)
    throw InputError("Hessian recovery: " + std::to_string(values.size()) + " values for " + std::to_string(points) +
                     " vertices: give one value per vertex");
  for (std::size_t v = 0; v < values.size(); ++v)
    if (!std::isfinite(values[v]))
      throw InputError("Hessian recovery: the value at vertex " + std::to_string(v + 1) + " is not finite", {v});
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const std::uint32_t v : elements[e])
      if (v >= points)
        throw InputError("Hessian recovery: element " + std::to_string(e + 1) + " has vertex " + std::to_string(v + 1) +
                             ", beyond the " + std::to_string(points) + " vertices",
                         {e});
}

// The gradient of the P1 function with vertex values w on element e, and the element's measure.
template <int D>
double element_gradient(std::span<const typename Space<D>::Point> points, const std::array<std::uint32_t, D + 1>& e,
                        const double* w, Eigen::Matrix<double, D, 1>& gradient, std::size_t index) {
  Eigen::Matrix<double, D, D> j;
  Eigen::Matrix<double, D, 1> du;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) j(r, c) = Space<D>::at(points[e[r + 1]], c) - Space<D>::at(points[e[0]], c);
    du(r) = w[r + 1] - w[0];
  }
  const double det = j.determinant();
  if (!(std::fabs(det) > 0.0))
    throw InputError("Hessian recovery: element " + std::to_string(index + 1) + " has no volume (its vertices are " +
                         (D == 2 ? "collinear" : "coplanar") + " in doubles)",
                     {index});
  gradient = j.partialPivLu().solve(du);
  return std::fabs(det) / (D == 2 ? 2.0 : 6.0);
}

template <int D>
std::vector<std::array<double, Space<D>::kTensor>> l2_projection(std::span<const typename Space<D>::Point> points,
                                                                 std::span<const std::array<std::uint32_t, D + 1>> elements,
                                                                 std::span<const double> values) {
  const std::size_t n = points.size();
  std::vector<double> weight(n, 0.0);
  std::vector<Eigen::Matrix<double, D, 1>> gradient(n, Eigen::Matrix<double, D, 1>::Zero());
  Eigen::Matrix<double, D, 1> g;
  double w[D + 1];
  for (std::size_t k = 0; k < elements.size(); ++k) {
    for (int i = 0; i <= D; ++i) w[i] = values[elements[k][i]];
    const double measure = element_gradient<D>(points, elements[k], w, g, k);
    for (const std::uint32_t v : elements[k]) {
      gradient[v] += measure * g;
      weight[v] += measure;
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (weight[v] > 0.0) gradient[v] /= weight[v];
  // The second projection: the gradient of each component of the P1 gradient field.
  std::vector<Eigen::Matrix<double, D, D>> hessian(n, Eigen::Matrix<double, D, D>::Zero());
  for (std::size_t k = 0; k < elements.size(); ++k) {
    Eigen::Matrix<double, D, D> h;
    double measure = 0.0;
    for (int c = 0; c < D; ++c) {
      for (int i = 0; i <= D; ++i) w[i] = gradient[elements[k][i]](c);
      measure = element_gradient<D>(points, elements[k], w, g, k);
      h.row(c) = g.transpose();
    }
    for (const std::uint32_t v : elements[k]) hessian[v] += measure * h;
  }
  std::vector<std::array<double, Space<D>::kTensor>> out(n);
  for (std::size_t v = 0; v < n; ++v) {
    if (!(weight[v] > 0.0)) continue;
    const Eigen::Matrix<double, D, D> h = hessian[v] / weight[v];
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j) out[v][slot<D>(i, j)] = 0.5 * (h(i, j) + h(j, i));
  }
  return out;
}

template <int D>
std::vector<std::array<double, Space<D>::kTensor>> least_squares(std::span<const typename Space<D>::Point> points,
                                                                 std::span<const std::array<std::uint32_t, D + 1>> elements,
                                                                 std::span<const double> values) {
  constexpr int kUnknowns = D + Space<D>::kTensor;  // gradient and Hessian; the vertex's value is kept
  const std::size_t n = points.size();
  // Vertex neighbours (sorted, unique) from the elements.
  std::vector<std::vector<std::uint32_t>> ring(n);
  for (const auto& e : elements)
    for (const std::uint32_t a : e)
      for (const std::uint32_t b : e)
        if (a != b) ring[a].push_back(b);
  for (auto& r : ring) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  std::vector<std::array<double, Space<D>::kTensor>> out(n);
  std::vector<std::uint32_t> patch;
  for (std::size_t v = 0; v < n; ++v) {
    if (ring[v].empty()) continue;  // unused
    bool solved = false;
    // Rings 1, 2, ... up to kMaxRings (a corner with one triangle has its first rings on two
    // lines): the first with at least twice the unknowns and a fit of full rank.
    constexpr int kMaxRings = 4;
    patch = ring[v];
    for (int level = 1; level <= kMaxRings && !solved; ++level) {
      if (level > 1) {
        const std::size_t before = patch.size();
        for (std::size_t k = 0; k < before; ++k) patch.insert(patch.end(), ring[patch[k]].begin(), ring[patch[k]].end());
        std::sort(patch.begin(), patch.end());
        patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
        patch.erase(std::remove(patch.begin(), patch.end(), static_cast<std::uint32_t>(v)), patch.end());
      }
      if (patch.size() < 2 * static_cast<std::size_t>(kUnknowns) && level < kMaxRings) continue;
      // Coordinates relative to v, scaled by the patch's radius (conditioning).
      double scale = 0.0;
      for (const std::uint32_t w : patch)
        for (int c = 0; c < D; ++c)
          scale = std::max(scale, std::fabs(Space<D>::at(points[w], c) - Space<D>::at(points[v], c)));
      if (!(scale > 0.0)) break;
      Eigen::MatrixXd a(static_cast<Eigen::Index>(patch.size()), kUnknowns);
      Eigen::VectorXd b(static_cast<Eigen::Index>(patch.size()));
      for (std::size_t r = 0; r < patch.size(); ++r) {
        double d[D];
        for (int c = 0; c < D; ++c) d[c] = (Space<D>::at(points[patch[r]], c) - Space<D>::at(points[v], c)) / scale;
        const auto row = static_cast<Eigen::Index>(r);
        for (int c = 0; c < D; ++c) a(row, c) = d[c];
        // u(v + d) = u(v) + g.d + 1/2 d^T H d: the coefficient of H_ij is d_i d_j (i < j), d_i^2 / 2.
        for (int i = 0; i < D; ++i)
          for (int j = i; j < D; ++j) a(row, D + slot<D>(i, j)) = i == j ? 0.5 * d[i] * d[i] : d[i] * d[j];
        b(row) = values[patch[r]] - values[v];
      }
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
      if (qr.rank() < kUnknowns) continue;
      const Eigen::VectorXd x = qr.solve(b);
      for (int k = 0; k < Space<D>::kTensor; ++k) out[v][k] = x(D + k) / (scale * scale);
      solved = true;
    }
    if (!solved)
      throw InputError("Hessian recovery (least squares): vertex " + std::to_string(v + 1) +
                           " has too few neighbours in general position, even in its 4-ring, to fit a quadratic",
                       {v});
  }
  return out;
}

template <int D>
std::vector<std::array<double, Space<D>::kTensor>> recover(std::span<const typename Space<D>::Point> points,
                                                           std::span<const std::array<std::uint32_t, D + 1>> elements,
                                                           std::span<const double> values, HessianRecovery method) {
  check_input<D>(points.size(), elements, values);
  return method == HessianRecovery::L2Projection ? l2_projection<D>(points, elements, values)
                                                 : least_squares<D>(points, elements, values);
}

}  // namespace

std::vector<std::array<double, 3>> recover_hessian(std::span<const Vec2> points,
                                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                                    std::span<const double> values, HessianRecovery method) {
  return recover<2>(points, triangles, values, method);
}

std::vector<std::array<double, 6>> recover_hessian(std::span<const Vec3> points,
                                                    std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                                                    std::span<const double> values, HessianRecovery method) {
  return recover<3>(points, tetrahedra, values, method);
}

}  // namespace dtlab
