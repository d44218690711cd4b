// The first mesh edge in a segment's plane that the segment crosses (flip_recovery.hpp). On a flat
// face of the hull (the sides of a box, Chazelle's polyhedron) or a flat part of the surface where
// the tetrahedralization has a face in that plane (anchor.off), a missing edge can be crossed by
// an edge in its own plane, which the walks of flip_recovery.cpp cannot flip away (on the hull
// no flip can) and which crossing_edge, looking for edges through a triangle's plane, does not
// see; recover_in_place.cpp then places the triangle's point where this edge crosses.
#include "algorithms/constrained3d/recovery/flip_recovery.hpp"

#include "kernel/predicates.hpp"

namespace dtlab {

std::array<std::uint32_t, 2> FlipRecovery::coplanar_edge_crossing(std::uint32_t u, std::uint32_t v) {
  constexpr std::uint32_t kNone = Tetrahedralization3::kNone, kInf = Tetrahedralization3::kInfinite;
  ball_of(u, ball_);
  for (const std::uint32_t t : ball_) {
    const auto& x = records_[t].vertex;
    if (x[0] == kInf) continue;
    // The three faces (u, a, b) of t, d the fourth vertex: off their plane (t is positive), it
    // tells the sides of lines in it. uv leaves through the open edge ab where it lies in the
    // face's plane, strictly between ua and ub, with v beyond ab.
    for (std::uint32_t j = 0; j < 4; ++j) {
      const std::uint32_t d = x[j];
      if (d == u) continue;
      std::uint32_t a = kNone, b = kNone;
      for (std::uint32_t k = 0; k < 4; ++k)
        if (x[k] != u && x[k] != d) (a == kNone ? a : b) = x[k];
      if (a == v || b == v || orient3d(P(u), P(a), P(b), P(v)) != Sign::Zero) continue;
      const Sign turn = orient3d(P(u), P(a), P(b), P(d));
      if (turn == Sign::Zero) continue;
      if (orient3d(P(u), P(a), P(v), P(d)) == turn && orient3d(P(u), P(v), P(b), P(d)) == turn &&
          orient3d(P(a), P(b), P(v), P(d)) == -turn)
        return {a, b};
    }
  }
  return {kNone, kNone};
}

}  // namespace dtlab
