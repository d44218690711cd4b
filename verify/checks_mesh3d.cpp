// The exact checks of a 3D mesh (checks_mesh3d.hpp).
#include "verify/checks_mesh3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/tetrahedralization3.hpp"
#include "verify/checks_constrained3d.hpp"
#include "verify/surface_tiles3.hpp"

namespace dtlab {

namespace {

constexpr auto kFacetVertex = Tetrahedralization3::kFacetVertex;

ReportCounts counts_of(const MeshCheckReport3& r) {
  return {{"vertices", r.vertices},
          {"tetrahedra", r.tetrahedra},
          {"triangles", r.triangles},
          {"interior_facets", r.interior_facets},
          {"boundary_facets", r.boundary_facets},
          {"identical_triangles", r.identical_triangles},
          {"piece_triangles", r.piece_triangles},
          {"tile_triangles", r.tile_triangles},
          {"regions", r.regions}};
}

double volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(b - a, cross(c - a, d - a)); }

// Sorted vertex triple with the parity of the sort (true: an odd permutation of the given order).
std::pair<std::array<std::uint32_t, 3>, bool> sorted_facet(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::array<std::uint32_t, 3> f{a, b, c};
  bool odd = false;
  if (f[0] > f[1]) std::swap(f[0], f[1]), odd = !odd;
  if (f[1] > f[2]) std::swap(f[1], f[2]), odd = !odd;
  if (f[0] > f[1]) std::swap(f[0], f[1]), odd = !odd;
  return {f, odd};
}

using PointTriple = std::array<Vec3, 3>;
PointTriple sorted_points(const Vec3& a, const Vec3& b, const Vec3& c) {
  PointTriple t{a, b, c};
  std::sort(t.begin(), t.end(), [](const Vec3& x, const Vec3& y) { return x < y; });
  return t;
}
bool less_points(const PointTriple& x, const PointTriple& y) {
  for (int i = 0; i < 3; ++i) {
    if (x[i] < y[i]) return true;
    if (y[i] < x[i]) return false;
  }
  return false;
}

}  // namespace

MeshCheckReport3 check_mesh3d(const ConstrainedInput3& input, const Constrained3dResult& recovered, const MeshData3& out,
                              std::span<const Metric3> metrics,
                              const MeshCheckOptions3& options) {
  const std::uint32_t first_number = options.first_number;
  MeshCheckReport3 r;
  r.vertices = out.vertices.size();
  r.tetrahedra = out.tetrahedra.size();
  r.triangles = out.triangles.size();
  const auto name = [&](std::size_t i) { return std::to_string(i + first_number); };
  const std::size_t nv = out.vertices.size();
  {
    std::vector<Vec3> sorted(out.vertices);
    std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) { return a < b; });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i] == sorted[i - 1])
        r.add_problem("two output vertices at (" + std::to_string(sorted[i].x) + ", " + std::to_string(sorted[i].y) +
                      ", " + std::to_string(sorted[i].z) + ")");
  }
  // Tetrahedra: positive, volumes per reference, facets.
  std::map<int, double> volume_of;
  struct Facet {
    std::array<std::uint32_t, 3> v;
    bool odd;
    std::uint32_t tet;
  };
  std::vector<Facet> facets;
  facets.reserve(4 * out.tetrahedra.size());
  for (std::uint32_t t = 0; t < out.tetrahedra.size(); ++t) {
    const auto& v = out.tetrahedra[t];
    if (std::max({v[0], v[1], v[2], v[3]}) >= nv) {
      r.add_problem("tetrahedron " + name(t) + " uses a vertex out of range");
      continue;
    }
    const Vec3 &a = out.vertices[v[0]], &b = out.vertices[v[1]], &c = out.vertices[v[2]], &d = out.vertices[v[3]];
    if (orient3d(a, b, c, d) != Sign::Positive) r.add_problem("tetrahedron " + name(t) + " is not positive (exact orient3d)");
    const int ref = out.tetrahedron_refs.empty() ? 0 : out.tetrahedron_refs[t];
    volume_of[ref] += volume6(a, b, c, d) / 6.0;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto& f = kFacetVertex[i];
      const auto [key, odd] = sorted_facet(v[f[0]], v[f[1]], v[f[2]]);
      facets.push_back({key, odd, t});
    }
  }
  for (const auto& [ref, vol] : volume_of) r.volume += vol;
  std::sort(facets.begin(), facets.end(), [](const Facet& x, const Facet& y) { return x.v != y.v ? x.v < y.v : x.tet < y.tet; });
  // Output triangles by sorted vertex ids.
  std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> triangle_keys;
  for (std::uint32_t k = 0; k < out.triangles.size(); ++k) {
    const auto& f = out.triangles[k];
    if (std::max({f[0], f[1], f[2]}) >= nv) {
      r.add_problem("triangle " + name(k) + " uses a vertex out of range");
      continue;
    }
    triangle_keys.push_back({sorted_facet(f[0], f[1], f[2]).first, k});
  }
  std::sort(triangle_keys.begin(), triangle_keys.end());
  for (std::size_t k = 1; k < triangle_keys.size(); ++k)
    if (triangle_keys[k].first == triangle_keys[k - 1].first)
      r.add_problem("triangles " + name(triangle_keys[k - 1].second) + " and " + name(triangle_keys[k].second) + " are the same");
  const auto is_triangle = [&](const std::array<std::uint32_t, 3>& key) {
    const auto it = std::lower_bound(triangle_keys.begin(), triangle_keys.end(), std::make_pair(key, 0u));
    return it != triangle_keys.end() && it->first == key;
  };
  const auto facet_text = [&](const std::array<std::uint32_t, 3>& f) {
    return "(" + name(f[0]) + ", " + name(f[1]) + ", " + name(f[2]) + ")";
  };
  for (std::size_t k = 0; k < facets.size();) {
    std::size_t e = k + 1;
    while (e < facets.size() && facets[e].v == facets[k].v) ++e;
    if (e - k > 2) {
      r.add_problem("facet " + facet_text(facets[k].v) + " is in " + std::to_string(e - k) + " tetrahedra");
    } else if (e - k == 2) {
      ++r.interior_facets;
      if (facets[k].odd == facets[k + 1].odd)
        r.add_problem("tetrahedra " + name(facets[k].tet) + " and " + name(facets[k + 1].tet) + " lie on the same side of facet " +
                      facet_text(facets[k].v));
      const auto ref = [&](std::uint32_t t) { return out.tetrahedron_refs.empty() ? 0 : out.tetrahedron_refs[t]; };
      if (ref(facets[k].tet) != ref(facets[k + 1].tet) && !is_triangle(facets[k].v))
        r.add_problem("facet " + facet_text(facets[k].v) + " between two references is not an output triangle");
    } else {
      ++r.boundary_facets;
      if (!is_triangle(facets[k].v))
        r.add_problem("boundary facet " + facet_text(facets[k].v) + " of tetrahedron " + name(facets[k].tet) +
                      " is not an output triangle");
    }
    k = e;
  }
  for (const auto& [key, k] : triangle_keys) {
    const auto it = std::lower_bound(facets.begin(), facets.end(), key,
                                     [](const Facet& f, const std::array<std::uint32_t, 3>& x) { return f.v < x; });
    if (it == facets.end() || it->v != key) r.add_problem("triangle " + name(k) + " is not a facet of the tetrahedra");
  }

  // The recovered tetrahedralization of the input, itself checked exactly (its pieces an exact
  // subdivision of the input triangles, its Steiner points within their rounding bounds).
  const Constrained3dResult& cdt = recovered;
  {
    const ConstrainedCheckReport3 c =
        check_constrained3d(input, cdt, {.method = "recover", .first_number = first_number});
    r.add_problems(c, " (in the input's recovered tetrahedralization)");
  }

  // The boundary: every output triangle is a piece of the recovery (the same three points) with
  // its reference; every piece beside the domain is an output triangle.
  std::vector<std::pair<PointTriple, std::uint32_t>> piece_keys;
  for (std::uint32_t k = 0; k < cdt.triangles.size(); ++k) {
    const auto& f = cdt.triangles[k];
    piece_keys.push_back({sorted_points(cdt.vertices[f[0]], cdt.vertices[f[1]], cdt.vertices[f[2]]), k});
  }
  std::sort(piece_keys.begin(), piece_keys.end(), [](const auto& x, const auto& y) {
    return less_points(x.first, y.first) || (!less_points(y.first, x.first) && x.second < y.second);
  });
  const auto find_piece = [&](const PointTriple& pts) -> std::uint32_t {
    const auto it = std::lower_bound(piece_keys.begin(), piece_keys.end(), pts,
                                     [](const auto& x, const PointTriple& y) { return less_points(x.first, y); });
    return it != piece_keys.end() && !less_points(pts, it->first) ? it->second : 0xFFFFFFFFu;
  };
  std::vector<std::uint8_t> piece_seen(cdt.triangles.size(), 0);
  // Output triangles that are no piece: tiles of one (the surface cut in the size), placed in it.
  std::vector<std::uint32_t> tile_ids;
  std::vector<std::array<std::uint32_t, 3>> tiles;
  for (const auto& [key, k] : triangle_keys) {
    const auto& f = out.triangles[k];
    if (find_piece(sorted_points(out.vertices[f[0]], out.vertices[f[1]], out.vertices[f[2]])) == 0xFFFFFFFFu) {
      tile_ids.push_back(k);
      tiles.push_back(f);
    }
  }
  const std::vector<std::uint32_t> tile_piece = locate_tiles(cdt.vertices, cdt.triangles, out.vertices, tiles);
  std::vector<double> covered(cdt.triangles.size(), 0.0);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const std::uint32_t k = tile_ids[i], piece = tile_piece[i];
    if (piece == kNoPiece) {
      r.add_problem("triangle " + name(k) + " is no input triangle nor a piece of one, nor inside one");
      continue;
    }
    const auto& f = tiles[i];
    covered[piece] += triangle_area(out.vertices[f[0]], out.vertices[f[1]], out.vertices[f[2]]);
    ++r.tile_triangles;
    const int ref = out.triangle_refs.empty() ? 0 : out.triangle_refs[k];
    if (cdt.triangle_refs[piece] != ref)
      r.add_problem("triangle " + name(k) + " has reference " + std::to_string(ref) + ", its input triangle " +
                    name(cdt.triangle_face[piece]) + " " + std::to_string(cdt.triangle_refs[piece]));
  }
  for (const auto& [key, k] : triangle_keys) {
    const auto& f = out.triangles[k];
    const int ref = out.triangle_refs.empty() ? 0 : out.triangle_refs[k];
    const std::uint32_t piece = find_piece(sorted_points(out.vertices[f[0]], out.vertices[f[1]], out.vertices[f[2]]));
    if (piece == 0xFFFFFFFFu) continue;  // a tile, placed above
    piece_seen[piece] = 1;
    const std::uint32_t face = cdt.triangle_face[piece];
    const auto& g = input.triangles[face];
    const bool whole = sorted_points(input.points[g[0]], input.points[g[1]], input.points[g[2]]) ==
                       sorted_points(out.vertices[f[0]], out.vertices[f[1]], out.vertices[f[2]]);
    ++(whole ? r.identical_triangles : r.piece_triangles);
    if (cdt.triangle_refs[piece] != ref)
      r.add_problem("triangle " + name(k) + " has reference " + std::to_string(ref) + ", its input triangle " + name(face) +
                    " " + std::to_string(cdt.triangle_refs[piece]));
  }
  {
    // The pieces beside a domain tetrahedron of the recovery.
    std::vector<std::array<std::uint32_t, 3>> domain_facets;
    for (const auto& v : cdt.tetrahedra)
      for (std::uint32_t i = 0; i < 4; ++i) {
        const auto& f = kFacetVertex[i];
        domain_facets.push_back(sorted_facet(v[f[0]], v[f[1]], v[f[2]]).first);
      }
    std::sort(domain_facets.begin(), domain_facets.end());
    for (std::uint32_t k = 0; k < cdt.triangles.size(); ++k) {
      const auto& f = cdt.triangles[k];
      const double area = triangle_area(cdt.vertices[f[0]], cdt.vertices[f[1]], cdt.vertices[f[2]]);
      if (piece_seen[k]) {
        if (covered[k] > 0.0)
          r.add_problem("piece " + name(k) + " of input triangle " + name(cdt.triangle_face[k]) +
                        " is an output triangle and holds other output triangles");
        continue;
      }
      if (!std::binary_search(domain_facets.begin(), domain_facets.end(), sorted_facet(f[0], f[1], f[2]).first)) continue;
      // Tiled: the output triangles inside it cover its area (sums in doubles: relative 1e-9).
      if (covered[k] > 0.0 && std::fabs(covered[k] - area) <= 1e-9 * area) continue;
      r.add_problem("piece " + name(k) + " of input triangle " + name(cdt.triangle_face[k]) +
                    (covered[k] > 0.0 ? " is covered by output triangles over " + std::to_string(covered[k]) + " of its area " +
                                            std::to_string(area)
                                      : " is not an output triangle"));
    }
  }

  // Regions against the recovery's.
  {
    std::map<int, double> expected;
    for (std::size_t t = 0; t < cdt.tetrahedra.size(); ++t) {
      const auto& v = cdt.tetrahedra[t];
      expected[cdt.tetrahedron_regions[t]] +=
          volume6(cdt.vertices[v[0]], cdt.vertices[v[1]], cdt.vertices[v[2]], cdt.vertices[v[3]]) / 6.0;
    }
    for (const auto& [ref, vol] : expected) r.domain_volume += vol;
    r.regions = expected.size();
    for (const auto& [ref, vol] : expected) {
      const auto it = volume_of.find(ref);
      const double got = it == volume_of.end() ? 0.0 : it->second;
      if (std::fabs(got - vol) > 1e-9 * r.domain_volume)
        r.add_problem("region " + std::to_string(ref) + " has volume " + std::to_string(got) + ", the domain's region " +
                      std::to_string(vol));
    }
    for (const auto& [ref, vol] : volume_of)
      if (!expected.count(ref)) r.add_problem("reference " + std::to_string(ref) + " is no region of the domain");
  }
  if (r.problem_count == 0) {
    try {
      r.quality = measure_quality(out.vertices, out.tetrahedra, metrics);
    } catch (const InputError& e) {
      r.add_problem(std::string("quality: ") + e.what());
    }
  }
  r.ok = r.problem_count == 0;
  return r;
}

std::string to_json(const MeshCheckReport3& r) { return report_json(r, counts_of(r)); }
std::string to_text(const MeshCheckReport3& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
