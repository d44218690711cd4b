// Shared pieces of the 3D optimization operators (local.hpp): quality and length in the vertex
// metrics, the locks that keep operators off the boundary and the exterior, and the replacement
// of a set of tetrahedra ("simulation, then effective application" of book §8.6.1: callers
// decide on coordinates and exact orientation, this routine only rewires).
#include "algorithms/optimize3d/local.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "algorithms/common/replace_elements.hpp"
#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"

namespace dtlab::optimize3d_detail {

bool positive(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept {
  return orient3d(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d)) == Sign::Positive;
}


double quality_in(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma, const Metric3& mb,
                  const Metric3& mc, const Metric3& md) noexcept {
  if (ma.is_scalar() && mb.is_scalar() && mc.is_scalar() && md.is_scalar()) return shape_quality(a, b, c, d);
  return shape_quality(a, b, c, d, ma, mb, mc, md);
}

double positive_quality_in(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Metric3& ma,
                           const Metric3& mb, const Metric3& mc, const Metric3& md) noexcept {
  if (ma.is_scalar() && mb.is_scalar() && mc.is_scalar() && md.is_scalar()) return shape_quality_nonflat(a, b, c, d);
  return shape_quality_nonflat(a, b, c, d, ma, mb, mc, md);
}

double quality(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) noexcept {
  if (!positive(mesh, a, b, c, d)) return std::numeric_limits<double>::infinity();
  return positive_quality_in(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d), mesh.metric(a), mesh.metric(b),
                    mesh.metric(c), mesh.metric(d));
}

double quality_below(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                     double bound) noexcept {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Vec3 &pa = mesh.point(a), &pb = mesh.point(b), &pc = mesh.point(c), &pd = mesh.point(d);
  if (mesh.metrics_all_scalar() || (mesh.metric(a).is_scalar() && mesh.metric(b).is_scalar() &&
                                    mesh.metric(c).is_scalar() && mesh.metric(d).is_scalar())) {
    // Most candidates of a shell or a face swap lie far above the bound: refused on the value
    // (which measures |det|, whatever the orientation) before the exact orientation test.
    const double q = shape_quality_nonflat(pa, pb, pc, pd);
    return q < bound && positive(mesh, a, b, c, d) ? q : kInf;
  }
  if (!positive(mesh, a, b, c, d)) return kInf;
  double worst = 0.0;
  for (const std::uint32_t v : {a, b, c, d}) {
    worst = std::max(worst, shape_quality_nonflat(pa, pb, pc, pd, mesh.metric(v)));
    if (!(worst < bound)) return kInf;
  }
  return worst;
}

double tetrahedron_quality(const Mesh3& mesh, std::uint32_t t) noexcept {
  const auto v = mesh.tetrahedron(t);
  if (mesh.metrics_all_scalar())
    return shape_quality_nonflat(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
  return positive_quality_in(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), mesh.metric(v[0]),
                    mesh.metric(v[1]), mesh.metric(v[2]), mesh.metric(v[3]));
}

double edge_length(const Mesh3& mesh, std::uint32_t u, std::uint32_t v) noexcept {
  return dtlab::edge_length(mesh.point(u), mesh.metric(u), mesh.point(v), mesh.metric(v));
}

bool is_locked_facet(const Mesh3& mesh, std::uint32_t h) noexcept {
  if (mesh.is_constrained(h)) return true;
  const std::uint32_t t = Mesh3::tetrahedron_of(h), u = Mesh3::tetrahedron_of(mesh.twin(h));
  return !mesh.in_domain(t) || !mesh.in_domain(u) || mesh.ref(t) != mesh.ref(u);
}

bool is_free_edge(const Mesh3& mesh, std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& shell,
                  std::vector<std::uint32_t>& ring, std::uint32_t hint) {
  if (a == Mesh3::kInfinite || b == Mesh3::kInfinite) return false;
  // Both ends of a constrained edge are kOnBoundary (mesh3.hpp): the hash lookup only then.
  if ((mesh.flags(a) & Mesh3::kOnBoundary) && (mesh.flags(b) & Mesh3::kOnBoundary) && mesh.is_constrained_edge(a, b))
    return false;
  if (hint != Mesh3::kNone) {
    mesh.shell_at(hint, a, b, shell, &ring);
  } else if (!mesh.shell(a, b, shell, &ring)) {
    return false;
  }
  const int r = mesh.ref(shell.front());
  for (std::size_t k = 0; k < shell.size(); ++k) {
    const std::uint32_t t = shell[k];
    if (!mesh.in_domain(t) || mesh.ref(t) != r) return false;
    // The facet (a, b, ring[k+1]) between shell[k] and shell[k+1] lies opposite ring[k] in t.
    for (std::uint32_t i = 0; i < 4; ++i)
      if (mesh.vertex(t, i) == ring[k] && mesh.is_constrained(Mesh3::facet(t, i))) return false;
  }
  return true;
}

std::uint32_t local_edge(const Mesh3& mesh, std::uint32_t t, std::uint32_t a, std::uint32_t b) noexcept {
  // kEdgeOf[i][j]: the index of edge ij.
  static constexpr std::uint32_t kEdgeOf[4][4] = {{6, 0, 1, 2}, {0, 6, 3, 4}, {1, 3, 6, 5}, {2, 4, 5, 6}};
  std::uint32_t i = 4, j = 4;
  for (std::uint32_t k = 0; k < 4; ++k) {
    if (mesh.vertex(t, k) == a) i = k;
    if (mesh.vertex(t, k) == b) j = k;
  }
  DTLAB_ASSERT(i < 4 && j < 4 && i != j);
  return kEdgeOf[i][j];
}

bool is_free_vertex(const Mesh3& mesh, std::uint32_t v, std::vector<std::uint32_t>& ball) {
  if (v >= mesh.vertex_capacity() || mesh.is_dead_vertex(v)) return false;
  if ((mesh.flags(v) & (Mesh3::kFixed | Mesh3::kOnBoundary)) != 0) return false;
  mesh.ball(v, ball);
  const int r = mesh.ref(ball.front());
  for (const std::uint32_t t : ball) {
    if (!mesh.in_domain(t) || mesh.ref(t) != r) return false;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t w = mesh.vertex(t, i);
      if (w != v && mesh.is_constrained(Mesh3::facet(t, i))) return false;
    }
  }
  return true;
}

double worst_quality(const Mesh3& mesh, std::span<const std::uint32_t> tetrahedra) noexcept {
  double worst = 0.0;
  for (const std::uint32_t t : tetrahedra) worst = std::max(worst, tetrahedron_quality(mesh, t));
  return worst;
}

double worst_quality(const Mesh3& mesh, std::span<const NewTetrahedron> tetrahedra) noexcept {
  double worst = 0.0;
  for (const NewTetrahedron& n : tetrahedra) worst = std::max(worst, quality(mesh, n.v[0], n.v[1], n.v[2], n.v[3]));
  return worst;
}

namespace {

// The 3D side of replace_elements (algorithms/common/replace_elements.hpp): facets, keyed by
// their sorted vertices, the same for both copies.
struct TetrahedronSide {
  static constexpr std::uint32_t kFacets = 4;
  static constexpr const char* kWho = "optimize3d";
  static constexpr const char* kElement = "tetrahedron";
  using Key = std::array<std::uint32_t, 3>;
  static std::uint32_t facet(std::uint32_t t, std::uint32_t i) noexcept { return Mesh3::facet(t, i); }
  static std::uint32_t element_of(std::uint32_t h) noexcept { return Mesh3::tetrahedron_of(h); }
  static Key key(const Mesh3& mesh, std::uint32_t h) noexcept {
    Key v = mesh.facet_vertices(h);
    std::sort(v.begin(), v.end());
    return v;
  }
  static const Key& mate(const Key& k) noexcept { return k; }
  static int ref(const Mesh3& mesh, std::uint32_t h) noexcept { return mesh.facet_ref(h); }
  static void set_outer(Mesh3& mesh, std::uint32_t h, bool c, int r) { mesh.set_facet(h, c, r); }
  static void remove(Mesh3& mesh, std::uint32_t t) { mesh.remove_tetrahedron(t); }
  static std::uint32_t add(Mesh3& mesh, const NewTetrahedron& n) {
    return mesh.add_tetrahedron(n.v[0], n.v[1], n.v[2], n.v[3], n.ref);
  }
  static std::string describe(const Key& k) {
    return "facet (" + std::to_string(k[0]) + ", " + std::to_string(k[1]) + ", " + std::to_string(k[2]) + ")";
  }
};

}  // namespace

// vertex_tetrahedron of the boundary's vertices: add_tetrahedron sets it for every vertex of a
// new tetrahedron, and every outer facet's vertices are in one. Facets between two new
// tetrahedra are unconstrained.
void replace_tetrahedra(Mesh3& mesh, std::span<const std::uint32_t> old_tetrahedra,
                        std::span<const NewTetrahedron> new_tetrahedra, std::vector<std::uint32_t>& slots) {
  replace_elements<TetrahedronSide>(mesh, old_tetrahedra, new_tetrahedra, slots,
                                    [&](std::uint32_t h, const auto&) { mesh.set_facet_both(h, false); });
}

}  // namespace dtlab::optimize3d_detail
