// The frequent moves of variant "flip" (flip_mesh.hpp), linked by their known structure: each new
// facet is either an outer facet of the old tetrahedra (its twin is read before any slot is
// overwritten) or shared by two new tetrahedra at positions fixed by the move. A new ghost may
// have had kInfinite moved to index 0; write() says how its indices moved.
#include <array>

#include "algorithms/delaunay3d/flip_mesh.hpp"

namespace dtlab {

namespace {

constexpr auto kFacet = Tetrahedralization3::kFacetVertex;

// Split 1->4: new tetrahedron i is (facet i of t, p); its facet k (opposite local vertex
// kFacet[i][k] of t) is shared with new tetrahedron j = kFacet[i][k], at the position of i in
// kFacet[j].
constexpr std::array<std::array<std::uint32_t, 3>, 4> split_partner() {
  std::array<std::array<std::uint32_t, 3>, 4> out{};
  for (std::uint32_t i = 0; i < 4; ++i)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t j = kFacet[i][k];
      for (std::uint32_t l = 0; l < 3; ++l)
        if (kFacet[j][l] == i) out[i][k] = l;
    }
  return out;
}
constexpr auto kSplitPartner = split_partner();

}  // namespace

void FlipMesh::split14(std::uint32_t t, std::uint32_t p, std::vector<std::uint32_t>& ids) {
  const Record old = r_[t];
  const std::uint32_t s[4] = {t, new_slot(), new_slot(), new_slot()};
  // (facet, p) needs no reordering: a ghost's facets through kInfinite list it first.
  for (std::uint32_t i = 0; i < 4; ++i) {
    const auto& f = kFacet[i];
    r_[s[i]].vertex = {old.vertex[f[0]], old.vertex[f[1]], old.vertex[f[2]], p};
    link(4 * s[i] + 3, old.neighbour[i]);
  }
  for (std::uint32_t i = 0; i < 4; ++i)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t j = kFacet[i][k];
      if (i < j) link(4 * s[i] + k, 4 * s[j] + kSplitPartner[i][k]);
    }
  ids.assign(s, s + 4);
}

// New k = (v[k], v[k+1], d, p): opposite p lies t2's facet opposite v[k+2], opposite d t1's;
// opposite v[k] it meets new k+1 opposite v[k+1].
void FlipMesh::flip23(std::uint32_t t1, std::uint32_t t2, const std::array<std::uint32_t, 3>& v, std::uint32_t p,
                      std::uint32_t d, std::vector<std::uint32_t>& ids) {
  std::uint32_t outer1[3], outer2[3];
  for (std::uint32_t k = 0; k < 3; ++k) {
    outer1[k] = twin_opposite(t1, v[(k + 2) % 3]);
    outer2[k] = twin_opposite(t2, v[(k + 2) % 3]);
  }
  const std::uint32_t s[3] = {t1, t2, new_slot()};
  std::uint32_t m[3];
  for (std::uint32_t k = 0; k < 3; ++k) m[k] = write(s[k], {v[k], v[(k + 1) % 3], d, p});
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t n = (k + 1) % 3;
    link(4 * s[k] + (3 ^ m[k]), outer2[k]);
    link(4 * s[k] + (2 ^ m[k]), outer1[k]);
    link(4 * s[k] + (0 ^ m[k]), 4 * s[n] + (1 ^ m[n]));
  }
  ids.assign(s, s + 3);
}

// A = (f, d, p, e0) and B = (d, f, p, e1) share (f, d, p); each of their other facets is the
// facet of t1, t2 or t3 opposite the other end of the edge.
void FlipMesh::flip32(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t e0, std::uint32_t e1,
                      std::uint32_t f, std::uint32_t p, std::uint32_t d, std::vector<std::uint32_t>& ids) {
  const std::uint32_t a[3] = {twin_opposite(t3, e1), twin_opposite(t1, e1), twin_opposite(t2, e1)};
  const std::uint32_t b[3] = {twin_opposite(t1, e0), twin_opposite(t3, e0), twin_opposite(t2, e0)};
  release(t3);
  const std::uint32_t ma = write(t1, {f, d, p, e0});
  const std::uint32_t mb = write(t2, {d, f, p, e1});
  for (std::uint32_t k = 0; k < 3; ++k) {
    link(4 * t1 + (k ^ ma), a[k]);
    link(4 * t2 + (k ^ mb), b[k]);
  }
  link(4 * t1 + (3 ^ ma), 4 * t2 + (3 ^ mb));
  ids.assign({t1, t2});
}

// N1 = (e1, f, d, p), N2 = (f, e0, d, p), N3 = (e0, x, d, p), N4 = (x, e1, d, p) around edge dp:
// facets 2 and 3 (opposite d, p) are outer, facets 0 and 1 face the neighbours in the cycle.
void FlipMesh::flip44(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t t4, std::uint32_t e0,
                      std::uint32_t e1, std::uint32_t f, std::uint32_t x, std::uint32_t p, std::uint32_t d,
                      std::vector<std::uint32_t>& ids) {
  const std::uint32_t outer[4][2] = {{twin_opposite(t1, e0), twin_opposite(t2, e0)},
                                     {twin_opposite(t1, e1), twin_opposite(t2, e1)},
                                     {twin_opposite(t4, e1), twin_opposite(t3, e1)},
                                     {twin_opposite(t4, e0), twin_opposite(t3, e0)}};
  const std::uint32_t s[4] = {t1, t2, t3, t4};
  const std::uint32_t m[4] = {write(s[0], {e1, f, d, p}), write(s[1], {f, e0, d, p}), write(s[2], {e0, x, d, p}),
                              write(s[3], {x, e1, d, p})};
  for (std::uint32_t k = 0; k < 4; ++k) {
    link(4 * s[k] + (2 ^ m[k]), outer[k][0]);
    link(4 * s[k] + (3 ^ m[k]), outer[k][1]);
  }
  auto facet = [&](std::uint32_t k, std::uint32_t i) { return 4 * s[k] + (i ^ m[k]); };
  link(facet(0, 0), facet(1, 1));
  link(facet(0, 1), facet(3, 0));
  link(facet(1, 0), facet(2, 1));
  link(facet(2, 0), facet(3, 1));
  ids.assign(s, s + 4);
}

}  // namespace dtlab
