// Solution transfer (transfer.hpp): walk, P1 weights, boundary snap, global correction.
#include "algorithms/adapt/transfer.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "algorithms/adapt/transfer_apply.hpp"
#include "algorithms/common/transfer_walk.hpp"
#include "algorithms/spatial_sort.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/element_grid.hpp"
#include "mesh/mesh2.hpp"
#include "mesh/mesh2_from_data.hpp"

namespace dtlab {
namespace {

struct Snap {
  double distance = 0.0;
  double edge_length = 0.0;
  std::uint32_t a = 0, b = 0;  // segment a -> b (domain on its left)
  double s = 0.0;              // nearest point a + s (b - a)
  bool found = false;
};

void consider(const Mesh2& mesh, std::uint32_t ghost, const Vec2& p, Snap& best) {
  // Ghost (kInfinite, b, a): the boundary edge runs a -> b in the inner triangle.
  const std::uint32_t b = mesh.vertex(ghost, 1), a = mesh.vertex(ghost, 2);
  const Vec2 &pa = mesh.point(a), &pb = mesh.point(b);
  const Vec2 d = pb - pa;
  const double len2 = dot(d, d);
  double s = len2 > 0.0 ? dot(p - pa, d) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  const Vec2 q{pa.x + s * d.x, pa.y + s * d.y};
  const double dist = norm(p - q);
  if (!best.found || dist < best.distance) best = Snap{dist, std::sqrt(len2), a, b, s, true};
}

// The nearest point of the old boundary among `bound` boundary edges on each side of the ghost
// where the walk stopped (ghosts are linked around kInfinite along each boundary loop).
Snap nearest_boundary(const Mesh2& mesh, std::uint32_t ghost, const Vec2& p, std::uint32_t bound) {
  Snap best;
  consider(mesh, ghost, p, best);
  for (std::uint32_t side : {1u, 2u}) {
    std::uint32_t g = ghost;
    for (std::uint32_t k = 0; k < bound; ++k) {
      g = Mesh2::triangle_of(mesh.twin(Mesh2::half_edge(g, side)));
      if (g == ghost || !mesh.is_ghost(g)) break;
      consider(mesh, g, p, best);
    }
  }
  return best;
}

// The triangle holding a point the walk lost through a concavity or a hole, among the candidates
// of its bucket (exact orient2d, closed triangles), or kNone.
std::uint32_t settle(const Mesh2& mesh, const ElementGrid<Vec2>& grid, const Vec2& p) {
  for (const std::uint32_t t : grid.candidates(p)) {
    if (closed_triangle_holds(mesh.point(mesh.vertex(t, 0)), mesh.point(mesh.vertex(t, 1)), mesh.point(mesh.vertex(t, 2)), p))
      return t;
  }
  return Mesh2::kNone;
}

P1Weights weights_in(const Mesh2& mesh, std::uint32_t t, const Vec2& p) {
  const std::uint32_t v0 = mesh.vertex(t, 0), v1 = mesh.vertex(t, 1), v2 = mesh.vertex(t, 2);
  const Vec2 &a = mesh.point(v0), &b = mesh.point(v1), &c = mesh.point(v2);
  const double area = cross(b - a, c - a);
  double w0 = 1.0, w1 = 0.0, w2 = 0.0;
  if (area > 0.0) {
    w0 = cross(b - p, c - p) / area;
    w1 = cross(c - p, a - p) / area;
    w2 = 1.0 - w0 - w1;
  } else {
    // A sliver whose area rounds to 0: the value of its vertex nearest to p.
    const double d0 = norm(a - p), d1 = norm(b - p), d2 = norm(c - p);
    if (d1 < d0 && d1 <= d2) std::swap(w0, w1);
    else if (d2 < d0 && d2 < d1) std::swap(w0, w2);
  }
  return P1Weights{{v0, v1, v2}, {w0, w1, w2}};
}

// The 2D placement of a new vertex for the walk of algorithms/common/transfer_walk.hpp.
struct Walk2 {
  static constexpr const char* kSize = "the length of the nearest old boundary edge";
  const MeshData2& old_mesh;
  std::uint32_t boundary_search;
  const Mesh2 mesh = mesh2_from_data(old_mesh);  // names an invalid old mesh (numbered from 1)
  // Triangle t of the old mesh is slot t of `mesh` (mesh2_from_data).
  const ElementGrid<Vec2> grid{std::span<const Vec2>(old_mesh.vertices),
                               std::span<const std::array<std::uint32_t, 3>>(old_mesh.triangles)};
  std::uint32_t hint = Mesh2::kNone;

  transfer_detail::Placement<P1Weights> place(const Vec2& p) {
    const Mesh2::Location loc = mesh.locate(p, hint);
    if (loc.where != Mesh2::Where::Outside) {
      hint = loc.triangle;
      if (loc.where == Mesh2::Where::Vertex) return {{{loc.handle, loc.handle, loc.handle}, {1.0, 0.0, 0.0}}};
      return {weights_in(mesh, loc.triangle, p)};
    }
    const Snap snap = nearest_boundary(mesh, loc.triangle, p, boundary_search);
    hint = Mesh2::triangle_of(mesh.twin(Mesh2::half_edge(loc.triangle, 0)));
    // On the domain's side of its nearest boundary edge: the walk left through a concavity or a
    // hole, p may be inside after all.
    if (orient2d(mesh.point(snap.a), mesh.point(snap.b), p) != Sign::Negative) {
      const std::uint32_t t = settle(mesh, grid, p);
      if (t != Mesh2::kNone) {
        hint = t;
        return {weights_in(mesh, t, p), transfer_detail::Placed::Rescanned};
      }
    }
    return {{{snap.a, snap.b, snap.b}, {1.0 - snap.s, snap.s, 0.0}}, transfer_detail::Placed::Outside, snap.distance,
            snap.edge_length};
  }
};

}  // namespace

double integrate_p1(const MeshData2& mesh, std::span<const double> field, std::size_t components,
                    std::size_t component) {
  return transfer_detail::integrate_elements(mesh, field, components, component, [&](const auto& tri) {
    const Vec2 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    return 0.5 * cross(b - a, c - a);
  });
}

std::vector<P1Weights> transfer_weights2(const MeshData2& old_mesh, const MeshData2& new_mesh,
                                         const TransferOptions& options, TransferStats* stats) {
  if (old_mesh.triangles.empty()) throw InputError("the old mesh has no triangle");
  transfer_detail::check_elements(new_mesh, "new");
  Walk2 walk{old_mesh, options.boundary_search};
  std::vector<std::uint32_t> order(new_mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  hilbert_sort(new_mesh.vertices, order);
  for (std::uint32_t t = 0; t < walk.mesh.triangle_capacity() && walk.hint == Mesh2::kNone; ++t) {
    if (walk.mesh.is_alive(t) && !walk.mesh.is_ghost(t)) walk.hint = t;
  }
  return transfer_detail::transfer_walk(walk, std::span<const Vec2>(new_mesh.vertices), order, options.outside_limit,
                                        stats);
}

std::vector<Metric2> transfer_metrics2(const MeshData2& old_mesh, std::span<const Metric2> metrics,
                                       const MeshData2& new_mesh, const TransferOptions& options,
                                       TransferStats* stats, MetricInterpolation mode) {
  return transfer_detail::apply_metrics(old_mesh, metrics, new_mesh, options, stats, mode, transfer_weights2);
}

std::vector<double> transfer_field2(const MeshData2& old_mesh, std::span<const double> field, std::size_t components,
                                    const MeshData2& new_mesh, const TransferOptions& options, TransferStats* stats) {
  return transfer_detail::apply_field(old_mesh, field, components, new_mesh, options, stats, transfer_weights2);
}

}  // namespace dtlab
