// The domain of a constrained triangulation, the "empty mesh" of book §5.2: triangles coloured
// by connected component across non-constrained edges; the components reached from the hull's
// ghosts across non-constrained hull edges are the exterior, removed unless kept; a hole point
// removes its component; a region point gives its component an attribute (later seeds win).
#include <string>
#include <vector>

#include "algorithms/constrained2d/domain.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh2.hpp"

namespace dtlab {

namespace {

using T2 = Triangulation2;

std::uint32_t finite_triangle_at(ConstrainedMesh2& mesh, const Vec2& p, std::uint32_t start) {
  const ConstrainedMesh2::Location at = mesh.locate(p, start);
  switch (at.where) {
    case ConstrainedMesh2::Where::Triangle: return at.triangle;
    case ConstrainedMesh2::Where::Edge: return T2::triangle_of(at.handle);
    case ConstrainedMesh2::Where::Vertex: return mesh.triangle_of_vertex(at.handle);
    case ConstrainedMesh2::Where::Outside: break;
  }
  return T2::kNone;
}

void check_seed(const Vec2& p, const std::string& what, std::size_t k, std::uint32_t first_number) {
  if (!coordinate_in_range(p.x) || !coordinate_in_range(p.y))
    throw InputError(what + " " + std::to_string(k + first_number) + " has a coordinate out of the supported range (" +
                         coordinate_problem(coordinate_in_range(p.x) ? p.y : p.x) + ")",
                     {k});
}

}  // namespace

void build_domain(const Constrained2dContext& context, std::span<const Vec2> holes,
                  std::span<const RegionSeed2> regions) {
  ConstrainedMesh2& mesh = context.mesh;
  const Triangulation2& tri = mesh.tri();
  Constrained2dResult& result = context.result;
  const auto count = static_cast<std::uint32_t>(tri.triangle_count());
  for (std::size_t k = 0; k < holes.size(); ++k) check_seed(holes[k], "hole", k, context.options.first_number);
  for (std::size_t k = 0; k < regions.size(); ++k) check_seed(regions[k].point, "region", k, context.options.first_number);

  std::vector<std::uint32_t> component(count, T2::kNone);
  std::uint32_t components = 0;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t t0 = 0; t0 < count; ++t0) {
    if (tri.is_ghost(t0) || component[t0] != T2::kNone) continue;
    component[t0] = components;
    queue.assign(1, t0);
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = T2::half_edge(t, i);
        const std::uint32_t u = T2::triangle_of(tri.twin(h));
        if (mesh.constraint(h) != T2::kNone || tri.is_ghost(u) || component[u] != T2::kNone) continue;
        component[u] = components;
        queue.push_back(u);
      }
    }
    ++components;
  }

  std::vector<std::uint8_t> removed(components, 0);
  std::vector<int> attribute(components, 0);
  if (context.segments.empty()) {
    context.note("no segments: the whole convex hull is the domain");
  } else if (!context.options.keep_exterior) {
    for (std::uint32_t t = 0; t < count; ++t) {
      if (!tri.is_ghost(t) || mesh.constraint(T2::half_edge(t, 0)) != T2::kNone) continue;
      removed[component[T2::triangle_of(tri.twin(T2::half_edge(t, 0)))]] = 1;
    }
  }
  std::uint32_t start = 0;
  while (start < count && tri.is_ghost(start)) ++start;
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const std::uint32_t t = finite_triangle_at(mesh, holes[k], start);
    if (t == T2::kNone) {
      context.note("hole " + context.number(k) + " lies outside the convex hull: ignored");
      continue;
    }
    removed[component[t]] = 1;
  }
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const std::uint32_t t = finite_triangle_at(mesh, regions[k].point, start);
    if (t == T2::kNone || removed[component[t]]) {
      context.note("region " + context.number(k) + " lies outside the domain: ignored");
      continue;
    }
    attribute[component[t]] = regions[k].attribute;
  }

  result.triangles.clear();
  result.triangle_region.clear();
  result.slot_regions.assign(count, Mesh2::kExterior);
  for (std::uint32_t t = 0; t < count; ++t) {
    if (tri.is_ghost(t) || removed[component[t]]) continue;
    result.triangles.push_back({tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)});
    result.triangle_region.push_back(attribute[component[t]]);
    result.slot_regions[t] = attribute[component[t]];
  }
}

}  // namespace dtlab
