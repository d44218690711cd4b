#include "mesh/tetrahedralization3_build.hpp"

#include <algorithm>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;

struct FacetEntry {
  std::array<std::uint32_t, 3> key;  // sorted vertex ids (kInfinite sorts last)
  std::uint32_t handle;
  bool operator<(const FacetEntry& o) const noexcept { return key != o.key ? key < o.key : handle < o.handle; }
};

std::string tet_name(std::uint32_t t) { return "tetrahedron " + std::to_string(std::uint64_t{t} + 1); }

// Pairs every facet of records [first, end) with the other facet over the same three vertices.
// Returns the facets left alone (boundary facets).
std::vector<std::uint32_t> match_facets(T3& tet, std::uint32_t first, bool ghosts) {
  std::vector<FacetEntry> entries;
  const auto& records = tet.records();
  entries.reserve(4 * (records.size() - first));
  for (std::uint32_t t = first; t < records.size(); ++t)
    for (std::uint32_t i = 0; i < 4; ++i) {
      auto v = tet.facet_vertices(T3::facet(t, i));
      std::sort(v.begin(), v.end());
      entries.push_back({v, T3::facet(t, i)});
    }
  std::sort(entries.begin(), entries.end());
  std::vector<std::uint32_t> alone;
  for (std::size_t k = 0; k < entries.size();) {
    std::size_t end = k + 1;
    while (end < entries.size() && entries[end].key == entries[k].key) ++end;
    const std::uint32_t g = entries[k].handle;
    if (end - k > 2 && ghosts) {
      // Ghost facets hold kInfinite (sorted last) and a boundary edge.
      const auto& key = entries[k].key;
      throw InputError("the boundary is not a closed 2-manifold: edge " + std::to_string(std::uint64_t{key[0]} + 1) + "-" +
                           std::to_string(std::uint64_t{key[1]} + 1) + " lies on " + std::to_string(end - k) +
                           " boundary facets",
                       {key[0], key[1]});
    }
    if (end - k > 2) {
      const std::uint32_t t = T3::tetrahedron_of(g);
      throw InputError("a facet of " + tet_name(t) + " is shared by " + std::to_string(end - k) + " tetrahedra", {t});
    }
    if (end - k == 2) {
      const std::uint32_t h = entries[k + 1].handle;
      // Twins list their vertices in opposite cyclic orders.
      const auto a = tet.facet_vertices(g), b = tet.facet_vertices(h);
      const bool opposite = (a[0] == b[0] && a[1] == b[2]) || (a[0] == b[1] && a[1] == b[0]) ||
                            (a[0] == b[2] && a[1] == b[1]);
      if (!opposite) {
        const std::uint32_t s = T3::tetrahedron_of(g), t = T3::tetrahedron_of(h);
        throw InputError(tet_name(s) + " and " + tet_name(t) +
                             " lie on the same side of their common facet (inconsistent orientation)",
                         {s, t});
      }
      tet.link(g, h);
    } else {
      alone.push_back(g);
    }
    k = end;
  }
  return alone;
}

}  // namespace

Tetrahedralization3 tetrahedralization_from_tetrahedra(std::vector<Vec3> points,
                                                       std::span<const std::array<std::uint32_t, 4>> tetrahedra) {
  const std::size_t n = points.size();
  if (tetrahedra.size() > T3::kMaxTetrahedra / 2)
    throw InputError(std::to_string(tetrahedra.size()) + " tetrahedra: more than a Tetrahedralization3 can index");
  T3 tet(std::move(points));
  tet.reserve_tetrahedra(tetrahedra.size() + tetrahedra.size() / 2 + 8);
  for (std::uint32_t t = 0; t < tetrahedra.size(); ++t) {
    const auto& v = tetrahedra[t];
    for (const std::uint32_t x : v)
      if (x >= n)
        throw InputError(tet_name(t) + " refers to vertex " + std::to_string(std::uint64_t{x} + 1) + " but there are " +
                             std::to_string(n) + " vertices",
                         {t});
    if (v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] || v[2] == v[3])
      throw InputError(tet_name(t) + " repeats a vertex", {t});
    tet.mutable_records().push_back({v, {T3::kNone, T3::kNone, T3::kNone, T3::kNone}});
  }
  const std::vector<std::uint32_t> boundary = match_facets(tet, 0, false);
  // A ghost (kInfinite, f0, f1, f2) across each boundary facet listed (f0, f1, f2): its facet 0
  // lists the same vertices in the opposite cyclic order (tetrahedralization3.hpp).
  const auto first_ghost = static_cast<std::uint32_t>(tet.tetrahedron_count());
  for (const std::uint32_t h : boundary) {
    const auto f = tet.facet_vertices(h);
    tet.mutable_records().push_back({{T3::kInfinite, f[0], f[1], f[2]}, {h, T3::kNone, T3::kNone, T3::kNone}});
    tet.mutable_records()[T3::tetrahedron_of(h)].neighbour[T3::index_in_tetrahedron(h)] =
        T3::facet(static_cast<std::uint32_t>(tet.tetrahedron_count() - 1), 0);
  }
  // Ghost facets 1-3 hold kInfinite and a boundary edge: matched like the others.
  std::vector<std::uint32_t> open = match_facets(tet, first_ghost, true);
  open.erase(std::remove_if(open.begin(), open.end(), [](std::uint32_t h) { return T3::index_in_tetrahedron(h) == 0; }),
             open.end());
  if (!open.empty()) {
    const auto f = tet.facet_vertices(open.front());
    const std::uint32_t a = f[0] == T3::kInfinite ? f[1] : f[0];
    const std::uint32_t b = f[2] == T3::kInfinite ? f[1] : f[2];
    throw InputError("the boundary is not a closed 2-manifold: edge " + std::to_string(std::uint64_t{a} + 1) + "-" +
                         std::to_string(std::uint64_t{b} + 1) + " lies on one boundary facet only",
                     {a, b});
  }
  return tet;
}

}  // namespace dtlab
