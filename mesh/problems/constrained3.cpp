#include "mesh/problems/constrained3.hpp"

namespace dtlab {

ExactPoint3 exact_facet_point(std::span<const Vec3> p, const std::array<std::uint32_t, 3>& corners, double s,
                              double t) {
  const ExactPoint3 A = to_exact(p[corners[0]]), B = to_exact(p[corners[1]]), C = to_exact(p[corners[2]]);
  const Rational S(s), T(t);
  return {A.x + S * (B.x - A.x) + T * (C.x - A.x), A.y + S * (B.y - A.y) + T * (C.y - A.y),
          A.z + S * (B.z - A.z) + T * (C.z - A.z)};
}

bool steiner_point_within_rounding_bound(std::span<const Vec3> input_points, const SteinerPoint3& s,
                                         const Vec3& vertex) {
  const ExactPoint3 exact =
      s.kind == SteinerPoint3::Kind::OnEdge
          ? point_on_segment_exact(input_points[s.support[0]], input_points[s.support[1]], Rational(s.parameters[0]))
          : exact_facet_point(input_points, s.support, s.parameters[0], s.parameters[1]);
  return within_rounding_bound(exact, vertex);
}

}  // namespace dtlab
