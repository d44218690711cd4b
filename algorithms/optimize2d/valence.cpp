// Valence relaxation of book §8.3.7 (after Frey and Field 1991): an edge swap lowers the degrees
// of the edge's ends and raises those of the opposite vertices by one; it is made when it brings
// the four degrees closer to their targets (sum of squared deviations strictly smaller) and the
// pair's worst Q_K does not get worse. Targets: 6 inside; at the boundary one more than the
// number of 60-degree sectors in the domain's angle there (4 on a straight boundary, 3 at a right
// corner), at least 3.
#include <algorithm>
#include <cmath>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using optimize2d_detail::is_locked;
using optimize2d_detail::quality;
using optimize2d_detail::triangle_quality;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Degree {
  int degree = 0;  // edges at v with a domain triangle beside them
  int target = 6;
};

Degree degree_of(const Mesh2& mesh, std::uint32_t v, std::vector<std::uint32_t>& ring) {
  mesh.ball(v, ring);
  Degree d;
  bool boundary = false;
  double angle = 0.0;
  for (const std::uint32_t h : ring) {
    const std::uint32_t t = Mesh2::triangle_of(h);
    const std::uint32_t spoke = Mesh2::prev(h);  // v -> origin(h)
    if (mesh.in_domain(t) || mesh.in_domain(Mesh2::triangle_of(mesh.twin(spoke)))) ++d.degree;
    if (!mesh.in_domain(t)) {
      boundary = true;
      continue;
    }
    const Vec2 e1 = mesh.point(mesh.origin(h)) - mesh.point(v);
    const Vec2 e2 = mesh.point(mesh.destination(h)) - mesh.point(v);
    angle += std::atan2(std::fabs(cross(e1, e2)), dot(e1, e2));
  }
  if (boundary) d.target = std::max(2, static_cast<int>(std::lround(angle / (kPi / 3.0)))) + 1;
  return d;
}

int deviation(int degree, int target) { return (degree - target) * (degree - target); }

}  // namespace

std::uint64_t valence_pass(Mesh2& mesh) {
  std::uint64_t swaps = 0;
  std::vector<std::uint32_t> ring;
  const std::uint32_t capacity = mesh.triangle_capacity();  // flips keep slots: no growth
  for (std::uint32_t t = 0; t < capacity; ++t) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = Mesh2::half_edge(t, i);
      if (!mesh.in_domain(t) || is_locked(mesh, h) || mesh.twin(h) < h) continue;
      const std::uint32_t g = mesh.twin(h);
      const std::uint32_t p = mesh.vertex_at(h), a = mesh.origin(h), b = mesh.destination(h), q = mesh.vertex_at(g);
      const Degree da = degree_of(mesh, a, ring), db = degree_of(mesh, b, ring);
      const Degree dp = degree_of(mesh, p, ring), dq = degree_of(mesh, q, ring);
      const int before = deviation(da.degree, da.target) + deviation(db.degree, db.target) +
                         deviation(dp.degree, dp.target) + deviation(dq.degree, dq.target);
      const int after = deviation(da.degree - 1, da.target) + deviation(db.degree - 1, db.target) +
                        deviation(dp.degree + 1, dp.target) + deviation(dq.degree + 1, dq.target);
      if (after >= before) continue;
      if (orient2d(mesh.point(p), mesh.point(a), mesh.point(q)) != Sign::Positive ||
          orient2d(mesh.point(q), mesh.point(b), mesh.point(p)) != Sign::Positive) {
        continue;
      }
      const double old_worst = std::max(triangle_quality(mesh, t), triangle_quality(mesh, Mesh2::triangle_of(g)));
      const double new_worst = std::max(quality(mesh, p, a, q), quality(mesh, q, b, p));
      if (!(new_worst <= old_worst)) continue;
      mesh.flip(h);
      ++swaps;
    }
  }
  return swaps;
}

}  // namespace dtlab
