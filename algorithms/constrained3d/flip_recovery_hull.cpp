// The first hull edge that a segment along a flat part of the hull crosses (flip_recovery.hpp).
// On a flat face of the hull (the sides of a box, Chazelle's polyhedron) a missing edge is
// crossed by edges in its own plane, which the walks of flip_recovery.cpp cannot flip away
// (each is an edge of the hull) and which crossing_edge, looking for edges through a triangle's
// plane, does not see; recover_in_place.cpp then splits the missing edge where this one crosses.
#include "algorithms/constrained3d/flip_recovery.hpp"

#include "kernel/predicates.hpp"

namespace dtlab {

std::array<std::uint32_t, 2> FlipRecovery::hull_edge_crossing(std::uint32_t u, std::uint32_t v) {
  constexpr std::uint32_t kNone = Tetrahedralization3::kNone, kInf = Tetrahedralization3::kInfinite;
  ball_of(u, ball_);
  for (const std::uint32_t g : ball_) {
    const auto& x = records_[g].vertex;
    if (x[0] != kInf) continue;  // ghosts only: their facet 0 is a hull triangle
    std::uint32_t i = 1;
    while (i < 4 && x[i] != u) ++i;
    if (i == 4) continue;
    const std::uint32_t a = x[1 + (i % 3)], b = x[1 + ((i + 1) % 3)];
    if (a == v || b == v || orient3d(P(u), P(a), P(b), P(v)) != Sign::Zero) continue;
    // The apex of the finite tetrahedron under the hull triangle: off the plane, it tells the
    // sides of lines in it. uv leaves through the open edge ab where it lies strictly between
    // ua and ub.
    std::uint32_t d = kNone;
    for (const std::uint32_t w : records_[records_[g].neighbour[0] >> 2].vertex)
      if (w != u && w != a && w != b) d = w;
    if (d == kNone || d == kInf) continue;
    const Sign turn = orient3d(P(u), P(a), P(b), P(d));
    if (turn == Sign::Zero) continue;
    if (orient3d(P(u), P(a), P(v), P(d)) == turn && orient3d(P(u), P(v), P(b), P(d)) == turn &&
        orient3d(P(a), P(b), P(v), P(d)) == -turn)  // v beyond ab
      return {a, b};
  }
  return {kNone, kNone};
}

}  // namespace dtlab
