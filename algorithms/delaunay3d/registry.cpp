#include "algorithms/delaunay3d/registry.hpp"

#include <array>

namespace dtlab {

// Each variant's run function lives in its own file.
void delaunay3d_incremental(const PreparedPoints3& input, const Delaunay3dOptions& options,
                            Tetrahedralization3& tetrahedralization);

namespace {

constexpr std::array kVariants = {
    Delaunay3dVariant{"incremental",
                      "reduced incremental method (Delaunay kernel, book §2.4-2.6): BRIO/Hilbert order, "
                      "visibility walk from the last insertion, cavity grown by adjacency, ball joined to its "
                      "boundary, deleted tetrahedra recycled",
                      &delaunay3d_incremental},
};

}  // namespace

std::span<const Delaunay3dVariant> delaunay3d_variants() noexcept { return kVariants; }

const Delaunay3dVariant* find_delaunay3d_variant(std::string_view name) noexcept {
  for (const Delaunay3dVariant& v : kVariants)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace dtlab
