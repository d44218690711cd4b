// Face swap 2 -> 3 (book §8.3.2): the two tetrahedra (p, q, r, d) and (r, q, p, e) beside a facet
// become the three around the new edge de, (p, q, e, d), (q, r, e, d), (r, p, e, d). Valid
// exactly when de crosses the facet's interior, i.e. when the three are positive (exact
// orient3d); kept when their worst Q_K is below the pair's.
#include <algorithm>
#include <array>

#include "algorithms/optimize3d/local.hpp"
#include "algorithms/optimize3d/operators.hpp"

namespace dtlab {

using namespace optimize3d_detail;

bool optimize3d_detail::face_swap(Mesh3& mesh, std::uint32_t h, double margin, std::vector<std::uint32_t>* created,
                                  QualityCache* cache) {
  const std::uint32_t t = Mesh3::tetrahedron_of(h);
  if (t >= mesh.tetrahedron_capacity() || !mesh.is_alive(t) || is_locked_facet(mesh, h)) return false;
  const std::uint32_t g = mesh.twin(h);
  const std::uint32_t u = Mesh3::tetrahedron_of(g);
  const std::uint32_t d = mesh.apex(h), e = mesh.apex(g);
  const auto f = mesh.facet_vertices(h);  // (f0, f1, f2, d) positive
  // (f0, f1, e, d): e replaces f2 on f2's side of the plane (f0, f1, d) when de crosses the facet.
  const std::array<NewTetrahedron, 3> fresh{{{{f[0], f[1], e, d}, mesh.ref(t)},
                                              {{f[1], f[2], e, d}, mesh.ref(t)},
                                              {{f[2], f[0], e, d}, mesh.ref(t)}}};
  const double before = cache ? std::max(cache->get(mesh, t), cache->get(mesh, u))
                              : std::max(tetrahedron_quality(mesh, t), tetrahedron_quality(mesh, u));
  // Each new tetrahedron must be below the bound: stop at the first that is not (or is not
  // positive: +inf).
  const double bound = before * (1.0 - margin);
  for (const NewTetrahedron& n : fresh)
    if (!(quality_below(mesh, n.v[0], n.v[1], n.v[2], n.v[3], bound) < bound)) return false;
  const std::array<std::uint32_t, 2> old{t, u};
  std::vector<std::uint32_t> slots;
  replace_tetrahedra(mesh, old, fresh, slots);
  if (created) *created = slots;
  return true;
}

bool try_face_swap(Mesh3& mesh, std::uint32_t h, double margin, std::vector<std::uint32_t>* created) {
  return face_swap(mesh, h, margin, created, nullptr);
}

}  // namespace dtlab
