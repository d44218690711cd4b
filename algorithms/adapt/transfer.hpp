// Transfer of vertex fields from an old triangle (or tetrahedral) mesh to the vertices of a new one (book §9.8,
// §12.2.6): P1 interpolation at each new vertex, located by the exact visibility walk of Mesh2
// (each walk starts where the previous one ended, new vertices visited in Hilbert order, so the
// total cost is near linear). A new vertex outside the old mesh (a curved boundary discretised
// differently) takes the value at its nearest point on the old boundary. The conservative option
// is the global correction form (Alauzet & Mehrenberger 2010 discuss the full P1-conservative
// scheme on a supermesh; this is not it): a constant shift makes the integral of the P1 field
// over the new mesh equal to the one over the old mesh, up to rounding.
#pragma once

#include <cstddef>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/metric.hpp"
#include "mesh/io/mesh_data.hpp"
#include "mesh/io/mesh_data3.hpp"

namespace dtlab {

struct TransferOptions {
  // Shift every component by a constant so that its integral over the new mesh equals the one
  // over the old mesh (global correction, not a supermesh projection).
  bool conservative = false;
  // Boundary edges searched on each side of the one where the walk left the old mesh.
  std::uint32_t boundary_search = 64;
  // A point farther from the old boundary than this factor times the length of the nearest old
  // boundary edge is an error (not a discretisation gap of a curved boundary).
  double outside_limit = 1.0;
};

struct TransferStats {
  std::size_t located = 0;   // new vertices found inside the old mesh
  std::size_t snapped = 0;   // new vertices outside, given the nearest boundary point's value
  std::size_t rescanned = 0; // walks that left through a concavity, settled by the bucket grid (mesh/element_grid.hpp)
  double max_outside_distance = 0.0;
  std::vector<double> integral_old, integral_new;  // per component, after the correction
};

// Where each new vertex takes its value from: three old vertices and their weights (non-negative
// up to rounding, summing to 1; a snapped vertex has weights on a boundary edge's two ends, an old
// vertex hit exactly weight 1 on it). Throws as transfer_field2 does, field size aside.
struct P1Weights {
  std::array<std::uint32_t, 3> vertices{};
  std::array<double, 3> weights{};
};
std::vector<P1Weights> transfer_weights2(const MeshData2& old_mesh, const MeshData2& new_mesh,
                                         const TransferOptions& options = {}, TransferStats* stats = nullptr);

// `field` holds `components` values per old vertex (vertex-major). Returns `components` values
// per new vertex. Throws InputError for a field size that is not components x old vertices, an
// invalid old mesh (mesh2_from_data's checks, numbered from 1), a new vertex beyond the limit.
std::vector<double> transfer_field2(const MeshData2& old_mesh, std::span<const double> field, std::size_t components,
                                    const MeshData2& new_mesh, const TransferOptions& options = {},
                                    TransferStats* stats = nullptr);

// Metrics transferred as metrics (kernel/metric.hpp interpolate with the weights above), so the
// result stays positive definite; InputError if the counts differ. No conservative option.
std::vector<Metric2> transfer_metrics2(const MeshData2& old_mesh, std::span<const Metric2> metrics,
                                       const MeshData2& new_mesh, const TransferOptions& options = {},
                                       TransferStats* stats = nullptr,
                                       MetricInterpolation mode = MetricInterpolation::Sizes);

// Integral of a P1 field (one component, `component` of `components`) over the triangles.
double integrate_p1(const MeshData2& mesh, std::span<const double> field, std::size_t components,
                    std::size_t component);

// --- 3D (transfer3.cpp): the same on tetrahedral meshes. A new vertex is located by the exact
// walk of Mesh3 from the previous one's tetrahedron (Hilbert order), settled by the bucket grid
// of the old tetrahedra when the walk leaves through a concavity; a vertex outside takes the
// value at its nearest point on the old boundary triangles (those of its bucket in a grid over
// them, all of them when the bucket has none). outside_limit is taken against the longest edge
// of the nearest boundary triangle; boundary_search is not used.
struct P1Weights3 {
  std::array<std::uint32_t, 4> vertices{};
  std::array<double, 4> weights{};
};
std::vector<P1Weights3> transfer_weights3(const MeshData3& old_mesh, const MeshData3& new_mesh,
                                          const TransferOptions& options = {}, TransferStats* stats = nullptr);
std::vector<double> transfer_field3(const MeshData3& old_mesh, std::span<const double> field, std::size_t components,
                                    const MeshData3& new_mesh, const TransferOptions& options = {},
                                    TransferStats* stats = nullptr);
std::vector<Metric3> transfer_metrics3(const MeshData3& old_mesh, std::span<const Metric3> metrics,
                                       const MeshData3& new_mesh, const TransferOptions& options = {},
                                       TransferStats* stats = nullptr,
                                       MetricInterpolation mode = MetricInterpolation::Sizes);
double integrate_p1(const MeshData3& mesh, std::span<const double> field, std::size_t components,
                    std::size_t component);

}  // namespace dtlab
