// A swap followed by the relocation of the quadrilateral's free vertices, judged as one move
// (book §8.6.3: operators are combined when no single one improves a bad element). A bad
// triangle whose defect is topological — typically a boundary vertex with two triangles where
// a straight boundary wants three — cannot be cured by a swap (the pair gets worse) nor by a
// relocation (its ball keeps the defect); the swap followed by relocations can. The move is
// simulated: the worst Q_K over the balls of the four vertices before, then after the swap and
// the relocations; undone exactly (points, metrics, the diagonal flipped back) unless it
// improves.
#include <algorithm>
#include <array>
#include <utility>

#include "algorithms/optimize2d/local.hpp"
#include "algorithms/optimize2d/operators.hpp"
#include "kernel/predicates.hpp"

namespace dtlab {

using optimize2d_detail::is_free;
using optimize2d_detail::is_locked;
using optimize2d_detail::triangle_quality;

namespace {

// The worst Q_K of the domain triangles around any of `vertices`.
double worst_around(const Mesh2& mesh, std::span<const std::uint32_t> vertices, std::vector<std::uint32_t>& ring) {
  double worst = 0.0;
  for (const std::uint32_t v : vertices) {
    mesh.ball(v, ring);
    for (const std::uint32_t h : ring) {
      const std::uint32_t t = Mesh2::triangle_of(h);
      if (mesh.in_domain(t)) worst = std::max(worst, triangle_quality(mesh, t));
    }
  }
  return worst;
}

}  // namespace

bool try_swap_relocate(Mesh2& mesh, std::uint32_t h, const MetricField2& field, const RelocateOptions& options,
                       double margin) {
  if (is_locked(mesh, h)) return false;
  const std::uint32_t g = mesh.twin(h);
  const std::uint32_t p = mesh.vertex_at(h), a = mesh.origin(h), b = mesh.destination(h), q = mesh.vertex_at(g);
  if (orient2d(mesh.point(p), mesh.point(a), mesh.point(q)) != Sign::Positive ||
      orient2d(mesh.point(q), mesh.point(b), mesh.point(p)) != Sign::Positive) {
    return false;
  }
  const std::array<std::uint32_t, 4> quad{p, a, b, q};
  std::vector<std::uint32_t> ring;
  // Only worth trying when some vertex of the quadrilateral can move.
  bool movable = false;
  for (const std::uint32_t v : quad) movable = movable || is_free(mesh, v, ring);
  if (!movable) return false;
  const double before = worst_around(mesh, quad, ring);
  std::array<std::pair<Vec2, Metric2>, 4> saved;
  for (std::size_t k = 0; k < 4; ++k) saved[k] = {mesh.point(quad[k]), mesh.metric(quad[k])};
  const std::uint32_t diagonal = mesh.flip(h);
  // The worst balls first, as the sweep does; try_relocate keeps only moves that improve a ball.
  for (const std::uint32_t v : quad) try_relocate(mesh, v, field, options);
  const double after = worst_around(mesh, quad, ring);
  if (after < before * (1.0 - margin)) return true;
  for (std::size_t k = 0; k < 4; ++k) {
    mesh.set_point(quad[k], saved[k].first);
    mesh.set_metric(quad[k], saved[k].second);
  }
  // The points are back, so the quadrilateral is the strictly convex one it was.
  mesh.flip(diagonal);
  return false;
}

}  // namespace dtlab
