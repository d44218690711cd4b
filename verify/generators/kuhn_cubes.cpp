// Unit cubes cut into Kuhn's tetrahedra (kuhn_cubes.hpp).
#include "verify/generators/kuhn_cubes.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

#include "kernel/predicates.hpp"

namespace dtlab::gen {

MeshData3 kuhn_cubes(const std::vector<std::array<int, 3>>& corners, int ref_of_second) {
  MeshData3 d;
  std::map<std::array<int, 3>, std::uint32_t> id;
  auto vertex = [&](std::array<int, 3> c) {
    const auto [it, fresh] = id.emplace(c, static_cast<std::uint32_t>(d.vertices.size()));
    if (fresh) {
      d.vertices.push_back({double(c[0]), double(c[1]), double(c[2])});
      d.vertex_refs.push_back(0);
    }
    return it->second;
  };
  std::array<int, 3> perm{0, 1, 2};
  for (std::size_t k = 0; k < corners.size(); ++k) {
    std::sort(perm.begin(), perm.end());
    do {
      // The path from the cell's corner to the opposite one along the axes in this order.
      std::array<int, 3> c = corners[k];
      std::array<std::uint32_t, 4> t;
      t[0] = vertex(c);
      for (int s = 0; s < 3; ++s) {
        ++c[perm[s]];
        t[s + 1] = vertex(c);
      }
      if (orient3d(d.vertices[t[0]], d.vertices[t[1]], d.vertices[t[2]], d.vertices[t[3]]) == Sign::Negative)
        std::swap(t[2], t[3]);
      d.tetrahedra.push_back(t);
      d.tetrahedron_refs.push_back(k == 1 ? ref_of_second : 0);
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
  return d;
}

}  // namespace dtlab::gen
