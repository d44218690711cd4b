#include "algorithms/delaunay3d/delaunay3d.hpp"

#include "algorithms/delaunay3d/prepare.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {

Delaunay3dResult delaunay3d(std::span<const Vec3> points, const Delaunay3dOptions& options) {
  return delaunay3d(std::vector<Vec3>(points.begin(), points.end()), options);
}

Delaunay3dResult delaunay3d(std::vector<Vec3>&& points, const Delaunay3dOptions& options) {
  const Delaunay3dVariant* variant = &(options.variants ? *options.variants : delaunay3d_variants()).at(options.algorithm);
  if (options.threads == 0) throw InputError("delaunay3d: threads must be at least 1");
  return delaunay_call<Delaunay3dResult>([&](Delaunay3dResult& result) {
    result.tetrahedralization = Tetrahedralization3(std::move(points));
    PreparedPoints3 prepared = [&] {
      if (!variant->threaded || options.threads == 1) return prepare_points3(result.tetrahedralization.points(), options.seed);
      WorkerTeam team(options.threads);
      return prepare_points3(result.tetrahedralization.points(), options.seed, &team);
    }();
    if (prepared.degenerate_message.empty()) variant->run(prepared, options, result.tetrahedralization);
    return prepared;
  });
}

}  // namespace dtlab
