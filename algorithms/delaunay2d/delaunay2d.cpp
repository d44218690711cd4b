#include "algorithms/delaunay2d/delaunay2d.hpp"

#include "algorithms/delaunay2d/prepare.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "kernel/error.hpp"

namespace dtlab {

Delaunay2dResult delaunay2d(std::span<const Vec2> points, const Delaunay2dOptions& options) {
  const Delaunay2dVariant* variant = &(options.variants ? *options.variants : delaunay2d_variants()).at(options.algorithm);
  return delaunay_call<Delaunay2dResult>([&](Delaunay2dResult& result) {
    PreparedPoints2 prepared = prepare_points2(points, options.seed);
    std::vector<Vec2> copy;
    copy.reserve(points.size());
    advise_huge_pages(copy.data(), points.size() * sizeof(Vec2));
    copy.assign(points.begin(), points.end());
    result.triangulation = Triangulation2(std::move(copy));
    if (prepared.degenerate_message.empty()) variant->run(prepared, result.triangulation);
    return prepared;
  });
}

}  // namespace dtlab
