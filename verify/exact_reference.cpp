// The exact reference signs (exact_reference.hpp): homogeneous determinants over GMP rationals,
// signed by Gaussian elimination (the sign of the product of the pivots, flipped once per row
// exchange).
#include "verify/exact_reference.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "kernel/error.hpp"

namespace dtlab::reference {

namespace {

double coord(const Vec2& p, int k) { return k == 0 ? p.x : p.y; }
double coord(const Vec3& p, int k) { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

// The sign of the homogeneous determinant of `points`: rows (p, 1), or (p, |p|^2, 1) if lifted.
template <class P>
Sign homogeneous_sign(std::span<const P> points, int dim, bool lifted) {
  const int n = dim + (lifted ? 2 : 1);
  DTLAB_ASSERT(static_cast<int>(points.size()) == n);
  std::vector<std::vector<Rational>> m(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    std::vector<Rational>& row = m[static_cast<std::size_t>(i)];
    Rational lift;
    for (int k = 0; k < dim; ++k) {
      const double v = coord(points[static_cast<std::size_t>(i)], k);
      if (!std::isfinite(v)) {
        throw InputError("exact reference: coordinate " + std::to_string(v) + " of point " + std::to_string(i) +
                             " is not finite",
                         {static_cast<std::uint64_t>(i)});
      }
      row.emplace_back(v);  // exact: a finite double is a dyadic rational
      lift += row.back() * row.back();
    }
    if (lifted) row.push_back(lift);
    row.emplace_back(1);
  }
  return determinant_sign(std::move(m));
}

template <class P, std::size_t N>
Sign homogeneous_sign(const std::array<P, N>& points, int dim, bool lifted) {
  return homogeneous_sign(std::span<const P>(points), dim, lifted);
}

Sign times(int s, Sign v) { return s > 0 ? v : -v; }

// Indices of `points` in decreasing lexicographic order; throws on duplicates.
template <class P, std::size_t N>
std::array<int, N> rank_order(const std::array<P, N>& points) {
  std::array<int, N> order;
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) { return points[j] < points[i]; });
  for (std::size_t k = 1; k < N; ++k)
    if (points[order[k - 1]] == points[order[k]])
      throw InputError("exact reference: the perturbation needs distinct points, points " +
                           std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) + " coincide",
                       {static_cast<std::uint64_t>(std::min(order[k - 1], order[k])),
                        static_cast<std::uint64_t>(std::max(order[k - 1], order[k]))});
  return order;
}

// det of the lifted matrix with column `dim` (the lift) perturbed by eps^rank, times `sign`.
template <class P, std::size_t N>
Sign perturbed_sign(const std::array<P, N>& points, int dim, int sign) {
  const std::array<int, N> order = rank_order(points);
  if (const Sign s = homogeneous_sign(points, dim, true); s != Sign::Zero) return times(sign, s);
  for (const int row : order) {
    // Cofactor (row, dim) = (-1)^(row + dim) * minor(row, dim); without the lifted column and
    // the row, the minor is the (p, 1) determinant of the other points.
    std::array<P, N - 1> others;
    for (int i = 0, k = 0; i < static_cast<int>(N); ++i)
      if (i != row) others[static_cast<std::size_t>(k++)] = points[static_cast<std::size_t>(i)];
    const Sign minor = homogeneous_sign(others, dim, false);
    if (minor != Sign::Zero) return times(sign * ((row + dim) % 2 == 0 ? 1 : -1), minor);
  }
  return Sign::Zero;
}

}  // namespace

Sign determinant_sign(std::vector<std::vector<Rational>> m) {
  const std::size_t n = m.size();
  int sign = 1;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    while (pivot < n && m[pivot][k].sign() == Sign::Zero) ++pivot;
    if (pivot == n) return Sign::Zero;
    if (pivot != k) {
      std::swap(m[pivot], m[k]);
      sign = -sign;
    }
    if (m[k][k].sign() == Sign::Negative) sign = -sign;
    for (std::size_t i = k + 1; i < n; ++i) {
      if (m[i][k].sign() == Sign::Zero) continue;
      const Rational factor = m[i][k] / m[k][k];
      for (std::size_t j = k + 1; j < n; ++j) m[i][j] -= factor * m[k][j];
    }
  }
  return sign > 0 ? Sign::Positive : Sign::Negative;
}

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return homogeneous_sign(std::array<Vec2, 3>{a, b, c}, 2, false);
}

Sign incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return homogeneous_sign(std::array<Vec2, 4>{a, b, c, d}, 2, true);
}

Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return -homogeneous_sign(std::array<Vec3, 4>{a, b, c, d}, 3, false);
}

Sign insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  return -homogeneous_sign(std::array<Vec3, 5>{a, b, c, d, e}, 3, true);
}

Sign incircle_perturbed(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return perturbed_sign(std::array<Vec2, 4>{a, b, c, d}, 2, +1);
}

Sign insphere_perturbed(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  return perturbed_sign(std::array<Vec3, 5>{a, b, c, d, e}, 3, -1);
}

bool all_collinear(std::span<const Vec2> points) {
  if (points.empty()) return true;
  const Vec2& p = points[0];
  const auto q = std::find_if(points.begin(), points.end(), [&](const Vec2& x) { return x != p; });
  if (q == points.end()) return true;
  return std::all_of(points.begin(), points.end(),
                     [&](const Vec2& r) { return orient2d(p, *q, r) == Sign::Zero; });
}

bool all_coplanar(std::span<const Vec3> points) {
  if (points.empty()) return true;
  const Vec3& p = points[0];
  const auto q = std::find_if(points.begin(), points.end(), [&](const Vec3& x) { return x != p; });
  if (q == points.end()) return true;
  // Three points are collinear in space iff their three axis projections are collinear.
  const auto collinear3 = [](const Vec3& a, const Vec3& b, const Vec3& c) {
    return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::Zero &&
           orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::Zero &&
           orient2d({a.x, a.z}, {b.x, b.z}, {c.x, c.z}) == Sign::Zero;
  };
  const auto r = std::find_if(points.begin(), points.end(), [&](const Vec3& x) { return !collinear3(p, *q, x); });
  if (r == points.end()) return true;
  return std::all_of(points.begin(), points.end(),
                     [&](const Vec3& s) { return orient3d(p, *q, *r, s) == Sign::Zero; });
}

}  // namespace dtlab::reference
