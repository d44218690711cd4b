// The constrained3d entry point (constrained3d.hpp): exact input checks, the Delaunay
// tetrahedralization of the input points, the chosen method's recovery (registry.hpp), the
// regions (§5.2), and the result arrays.
#include "algorithms/constrained3d/constrained3d.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "algorithms/constrained3d/context.hpp"
#include "algorithms/constrained3d/plc/plc_checks.hpp"
#include "algorithms/constrained3d/regions.hpp"
#include "algorithms/constrained3d/registry.hpp"
#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/mesh3.hpp"
#include "mesh/vertex_buckets.hpp"

namespace dtlab {

namespace {

using Clock = std::chrono::steady_clock;
using T3 = Tetrahedralization3;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The input edges (each once, a < b) and triangles with their edges. The edges are numbered in
// the order they first appear (triangle by triangle, side by side), found by grouping the sides
// on their lower vertex (vertex_buckets) rather than by a hash table: the sides at a vertex are
// few.
void build_constraints(const ConstrainedInput3& input, Constrained3dContext& c) {
  const std::size_t sides = 3 * input.triangles.size();
  const auto lower = [&](std::size_t h) {
    const auto& t = input.triangles[h / 3];
    return std::min(t[h % 3], t[(h + 1) % 3]);
  };
  const auto upper = [&](std::size_t h) {
    const auto& t = input.triangles[h / 3];
    return std::max(t[h % 3], t[(h + 1) % 3]);
  };
  const VertexBuckets by_lower = vertex_buckets(input.points.size(), sides, lower);
  const auto& start = by_lower.start;
  std::vector<std::uint32_t> order = by_lower.order;  // (big buckets are sorted below)
  // first[h]: the first side (lowest h) on the same edge as side h.
  std::vector<std::uint32_t> first(sides);
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto begin = order.begin() + start[v], end = order.begin() + start[v + 1];
    if (end - begin <= 16) {  // in increasing h: the first earlier side on the same edge
      for (auto i = begin; i != end; ++i) {
        first[*i] = *i;
        for (auto j = begin; j != i; ++j)
          if (upper(*j) == upper(*i)) {
            first[*i] = *j;
            break;
          }
      }
      continue;
    }
    // Many sides at one vertex (a fan's apex): sorted by upper vertex, then h.
    std::sort(begin, end, [&](std::uint32_t x, std::uint32_t y) {
      return upper(x) != upper(y) ? upper(x) < upper(y) : x < y;
    });
    for (auto i = begin; i != end; ++i)
      first[*i] = i != begin && upper(*(i - 1)) == upper(*i) ? first[*(i - 1)] : *i;
  }
  c.edges.reserve(sides / 2 + 3);
  c.facets.reserve(input.triangles.size());
  std::vector<std::uint32_t> edge_of(sides);
  for (std::uint32_t f = 0; f < input.triangles.size(); ++f) {
    ConstraintFacet3 facet;
    facet.corners = input.triangles[f];
    facet.ref = input.triangle_refs.empty() ? 0 : input.triangle_refs[f];
    for (int k = 0; k < 3; ++k) {
      const std::size_t h = 3 * std::size_t{f} + k;
      const std::uint32_t a = lower(h), b = upper(h);
      if (first[h] == h) {
        edge_of[h] = static_cast<std::uint32_t>(c.edges.size());
        ConstraintEdge3 edge;
        edge.a = a, edge.b = b, edge.face = f;
        edge.chain = {a, b};
        edge.t = {0.0, 1.0};
        c.edges.push_back(std::move(edge));
      } else {
        edge_of[h] = edge_of[first[h]];
      }
      facet.edges[k] = edge_of[h];
      facet.reversed[k] = facet.corners[k] != a;
    }
    c.facets.push_back(std::move(facet));
  }
}

}  // namespace

std::vector<Constrained3dMethodInfo> constrained3d_method_list() {
  std::vector<Constrained3dMethodInfo> list;
  for (const auto& m : constrained3d_methods()) list.push_back({m.name, m.description});
  return list;
}

Constrained3dResult constrained3d(const ConstrainedInput3& input, const Constrained3dOptions& options) {
  const auto start = Clock::now();
  const PredicateStats stats_before = predicate_stats();
  const Constrained3dMethod* method = &constrained3d_methods().at(options.method);
  if (!input.triangle_refs.empty() && input.triangle_refs.size() != input.triangles.size())
    throw InputError("constrained3d: " + std::to_string(input.triangle_refs.size()) + " triangle references for " +
                     std::to_string(input.triangles.size()) + " triangles");
  if (input.points.size() >= T3::kMaxPoints) throw InputError("constrained3d: too many points");
  check_coordinates(input.points, "point");
  check_coordinates(input.holes, "hole point");
  for (std::size_t i = 0; i < input.regions.size(); ++i)
    check_coordinates(std::span<const Vec3>(&input.regions[i].point, 1), "region point " + std::to_string(i + 1));
  if (input.triangles.empty()) throw InputError("constrained3d: no triangles");
  check_plc(input.points, input.triangles, input.triangle_name);

  Constrained3dResult r;
  r.seconds.checks = since(start);
  auto phase = Clock::now();
  Constrained3dContext c;
  {
    Delaunay3dResult d = delaunay3d(input.points);
    if (!d.degenerate_message.empty()) throw InputError("constrained3d: " + d.degenerate_message);
    c.mesh = std::move(d.tetrahedralization);
  }
  r.seconds.delaunay = since(phase);
  c.input_point_count = static_cast<std::uint32_t>(input.points.size());
  const std::uint64_t limit = std::uint64_t{options.steiner_limit_factor} * (input.points.size() + input.triangles.size());
  c.steiner_limit = static_cast<std::uint32_t>(std::min<std::uint64_t>(limit, T3::kMaxPoints - input.points.size()));
  build_constraints(input, c);
  c.keep_exterior = options.keep_exterior;

  method->run(c);
  r.messages = std::move(c.messages);
  r.seconds.edge_recovery = c.edge_seconds;
  r.seconds.face_recovery = c.face_seconds;

  phase = Clock::now();
  for (std::uint32_t f = 0; f < c.facets.size(); ++f)
    for (const auto& p : c.facets[f].pieces) {
      r.triangles.push_back(p);
      r.triangle_face.push_back(f);
      r.triangle_refs.push_back(c.facets[f].ref);
    }
  TetrahedronComponents comp = tetrahedron_components(c.mesh, r.triangles);
  std::vector<bool> removed(comp.count, false);
  if (!options.keep_exterior && comp.exterior != T3::kNone) removed[comp.exterior] = true;
  for (std::size_t h = 0; h < input.holes.size(); ++h) {
    const std::uint32_t t = tetrahedron_containing(c.mesh, input.holes[h]);
    if (t == T3::kNone) {
      r.messages.push_back("hole point " + std::to_string(h + 1) + " is outside the mesh: ignored");
    } else {
      removed[comp.component[t]] = true;
    }
  }
  if (options.remove_cavities) {
    const std::vector<bool> cavity =
        cavity_components(c.mesh, comp, r.triangle_face, surface_shells(input.triangles));
    std::size_t removed_cavities = 0;
    for (std::uint32_t k = 0; k < comp.count; ++k)
      if (cavity[k] && !removed[k]) removed[k] = true, ++removed_cavities;
    r.messages.push_back(std::to_string(removed_cavities) +
                         " cavity region(s) removed (bounded only by shells nested inside another)");
  }
  std::vector<int> attribute(comp.count, 0);
  std::vector<bool> seeded(comp.count, false);
  for (std::size_t i = 0; i < input.regions.size(); ++i) {
    const std::uint32_t t = tetrahedron_containing(c.mesh, input.regions[i].point);
    if (t == T3::kNone) {
      r.messages.push_back("region point " + std::to_string(i + 1) + " is outside the mesh: ignored");
      continue;
    }
    attribute[comp.component[t]] = input.regions[i].attribute;
    seeded[comp.component[t]] = true;
  }
  std::vector<int> number(comp.count, -1);
  int next = 1;
  r.slot_regions.assign(c.mesh.tetrahedron_count(), Mesh3::kExterior);
  for (std::uint32_t t = 0; t < c.mesh.tetrahedron_count(); ++t) {
    const std::uint32_t k = comp.component[t];
    if (c.mesh.is_ghost(t) || removed[k]) continue;
    if (number[k] < 0) {
      number[k] = k == comp.exterior ? 0 : (input.regions.empty() ? next++ : (seeded[k] ? attribute[k] : 0));
      if (k != comp.exterior) ++r.region_count;
    }
    r.tetrahedra.push_back(c.mesh.records()[t].vertex);
    r.tetrahedron_regions.push_back(number[k]);
    r.slot_regions[t] = number[k];
  }
  r.triangle_facets = std::move(comp.wall_facet);
  r.seconds.regions = since(phase);

  r.vertices.assign(c.mesh.points().begin(), c.mesh.points().end());
  r.input_point_count = c.input_point_count;
  r.steiner = std::move(c.steiner);
  for (const auto& s : r.steiner) {
    if (s.kind == SteinerPoint3::Kind::OnEdge) ++r.steiner_points.on_edges;
    if (s.kind == SteinerPoint3::Kind::OnFace) ++r.steiner_points.on_faces;
    if (s.kind == SteinerPoint3::Kind::Interior) ++r.steiner_points.interior;
  }
  r.rounding_checks_failed = c.rounding_checks_failed;
  r.rounds = c.rounds;
  r.constrained_delaunay = c.constrained_delaunay;
  r.tetrahedralization = std::move(c.mesh);
  r.predicate_stats = predicate_stats() - stats_before;
  r.seconds.total = since(start);
  return r;
}

}  // namespace dtlab
