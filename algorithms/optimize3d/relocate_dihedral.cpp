// Vertex relocation judged by dihedral angles (the dihedral goal of optimize3d's efforts): the
// relocation of relocate.cpp moves a vertex only when the worst Q_K of its ball improves, so a
// tetrahedron with one small dihedral angle but a moderate Q_K, not the worst of its
// neighbourhood, is never its concern. Here the same candidates — P' = (1 - w) P + w T for T the
// optimal point P* of the ball (book (8.17)) and the centroid of the ball's link, w = 1, 1/2, ... —
// are accepted when every new tetrahedron is positive (exact orient3d), the ball's smallest
// dihedral angle grows, its largest does not pass max(its old largest, the goal's), and its worst
// Q_K stays at most max(the old worst, quality_limit).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab {

using namespace optimize3d_detail;

namespace {

struct BallAngles {
  double smallest_cos = -1.0;  // the cosine of the ball's smallest dihedral angle (the largest cosine)
  double largest_cos = 1.0;    // the cosine of its largest (the smallest cosine)
  double worst = 0.0;          // Q_K
};

}  // namespace

bool try_relocate_dihedral3(Mesh3& mesh, std::uint32_t v, const MetricField3& field,
                            const RelocateDihedral3Options& options) {
  thread_local std::vector<std::uint32_t> ball;
  thread_local std::vector<std::array<std::uint32_t, 3>> facets;
  if (!is_free_vertex(mesh, v, ball)) return false;
  facets.clear();
  BallAngles before;
  Vec3 link{0.0, 0.0, 0.0};
  for (const std::uint32_t t : ball) {
    for (std::uint32_t i = 0; i < 4; ++i) {
      if (mesh.vertex(t, i) != v) continue;
      facets.push_back(mesh.facet_vertices(Mesh3::facet(t, i)));
    }
    const auto w = mesh.tetrahedron(t);
    const auto c = dihedral_cosine_range(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]));
    before.smallest_cos = std::max(before.smallest_cos, c[1]);
    before.largest_cos = std::min(before.largest_cos, c[0]);
    before.worst = std::max(before.worst, tetrahedron_quality(mesh, t));
  }
  for (const auto& f : facets) link = link + (1.0 / 3.0) * (mesh.point(f[0]) + mesh.point(f[1]) + mesh.point(f[2]));
  link = (1.0 / static_cast<double>(facets.size())) * link;
  const double quality_bound = std::max(before.worst, options.quality_limit);
  const double largest_bound = std::min(before.largest_cos, options.max_dihedral_cos);
  const std::array<Vec3, 2> targets{optimal_point(mesh, v, ball), link};
  return relax_vertex(mesh, v, targets, options.tries, field, ball, [&](const Vec3& moved, const Metric3& metric) {
    double smallest_cos = -1.0;
    for (const auto& f : facets) {
      const Vec3 &a = mesh.point(f[0]), &b = mesh.point(f[1]), &c = mesh.point(f[2]);
      if (orient3d(a, b, c, moved) != Sign::Positive) return false;
      const auto range = dihedral_cosine_range(a, b, c, moved);
      smallest_cos = std::max(smallest_cos, range[1]);
      if (range[0] < largest_bound ||
          positive_quality_in(a, b, c, moved, mesh.metric(f[0]), mesh.metric(f[1]), mesh.metric(f[2]), metric) >
              quality_bound)
        return false;
    }
    // The smallest angle must grow: its cosine fall, by a margin against rounding.
    return smallest_cos < before.smallest_cos - options.margin;
  });
}

}  // namespace dtlab
