// What the 2D and 3D transfers (transfer.cpp, transfer3.cpp) share besides the walk
// (algorithms/common/transfer_walk.hpp): the checks, the P1 integral, the P1 values of a field
// with the conservative global correction, and metrics interpolated as metrics. Internal to
// algorithms/adapt.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "algorithms/adapt/transfer.hpp"
#include "kernel/error.hpp"
#include "kernel/metric.hpp"

namespace dtlab::transfer_detail {

// The mesh's elements: triangles in 2D, tetrahedra in 3D (the messages say "element").
inline const auto& elements(const MeshData2& mesh) { return mesh.triangles; }
inline const auto& elements(const MeshData3& mesh) { return mesh.tetrahedra; }

// Each element's vertices in range; names the first that is not (numbered from 1).
template <class Mesh>
void check_elements(const Mesh& mesh, const char* which) {
  const auto& all = elements(mesh);
  for (std::size_t t = 0; t < all.size(); ++t) {
    for (const std::uint32_t v : all[t]) {
      if (v >= mesh.vertices.size()) {
        throw InputError(std::string("the ") + which + " mesh's element " + std::to_string(t + 1) + " uses vertex " +
                             std::to_string(v + 1) + " of " + std::to_string(mesh.vertices.size()),
                         {t + 1});
      }
    }
  }
}

template <class Mesh>
void check_field(const Mesh& old_mesh, std::span<const double> field, std::size_t components) {
  if (components == 0) throw InputError("a field to transfer needs at least one component");
  if (field.size() != components * old_mesh.vertices.size()) {
    throw InputError("the field has " + std::to_string(field.size()) + " values but the old mesh has " +
                     std::to_string(old_mesh.vertices.size()) + " vertices x " + std::to_string(components) +
                     " components");
  }
}

// The integral of component `component` of a P1 field over the elements: each element's
// `measure` (area, volume) times the mean of its vertices' values.
template <class Mesh, class Measure>
double integrate_elements(const Mesh& mesh, std::span<const double> field, std::size_t components,
                          std::size_t component, Measure measure) {
  check_elements(mesh, "integrated");
  if (field.size() != components * mesh.vertices.size()) throw InputError("integrate_p1: field size mismatch");
  double sum = 0.0;
  for (const auto& e : elements(mesh)) {
    double values = 0.0;
    for (const std::uint32_t v : e) values += field[v * components + component];
    sum += measure(e) * values / static_cast<double>(e.size());
  }
  return sum;
}

// transfer_field2 and 3 with their dimension's `weights_of` (transfer_weights2 or 3): the P1
// values at the new vertices, then (conservative) each component shifted by the constant that
// gives it the old integral (§12.2.6, global correction); the integrals into the stats.
template <class Mesh, class WeightsOf>
std::vector<double> apply_field(const Mesh& old_mesh, std::span<const double> field, std::size_t components,
                                const Mesh& new_mesh, const TransferOptions& options, TransferStats* stats,
                                WeightsOf weights_of) {
  check_field(old_mesh, field, components);
  TransferStats local;
  TransferStats& st = stats ? *stats : local;
  const auto weights = weights_of(old_mesh, new_mesh, options, &st);
  std::vector<double> out(new_mesh.vertices.size() * components, 0.0);
  for (std::size_t v = 0; v < weights.size(); ++v) {
    const auto& w = weights[v];
    for (std::size_t k = 0; k < components; ++k) {
      double sum = 0.0;
      for (std::size_t i = 0; i < w.vertices.size(); ++i) sum += w.weights[i] * field[w.vertices[i] * components + k];
      out[v * components + k] = sum;
    }
  }
  const std::vector<double> ones(new_mesh.vertices.size(), 1.0);
  const double measure = integrate_p1(new_mesh, ones, 1, 0);
  for (std::size_t k = 0; k < components; ++k) {
    const double before = integrate_p1(old_mesh, field, components, k);
    st.integral_old.push_back(before);
    if (options.conservative && measure > 0.0) {
      const double c = (before - integrate_p1(new_mesh, out, components, k)) / measure;
      for (std::size_t v = 0; v < new_mesh.vertices.size(); ++v) out[v * components + k] += c;
    }
    st.integral_new.push_back(integrate_p1(new_mesh, out, components, k));
  }
  return out;
}

inline void check_metrics(std::size_t old_vertices, std::size_t metrics) {
  if (metrics != old_vertices) {
    throw InputError("the old mesh has " + std::to_string(old_vertices) + " vertices but " + std::to_string(metrics) +
                     " metrics are given");
  }
}

// transfer_metrics2 and 3: metrics interpolated as metrics with the weights of `weights_of`
// (clamped to >= 0: rounding may leave -1e-17).
template <class Mesh, class Metric, class WeightsOf>
std::vector<Metric> apply_metrics(const Mesh& old_mesh, std::span<const Metric> metrics, const Mesh& new_mesh,
                                  const TransferOptions& options, TransferStats* stats, MetricInterpolation mode,
                                  WeightsOf weights_of) {
  check_metrics(old_mesh.vertices.size(), metrics.size());
  const auto weights = weights_of(old_mesh, new_mesh, options, stats);
  constexpr std::size_t n = std::tuple_size_v<decltype(weights[0].vertices)>;
  std::vector<Metric> out;
  out.reserve(weights.size());
  for (const auto& w : weights) {
    std::array<Metric, n> m;
    std::array<double, n> c;
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      m[i] = metrics[w.vertices[i]];
      c[i] = std::max(w.weights[i], 0.0);
      sum += c[i];
    }
    for (double& x : c) x /= sum;
    out.push_back(interpolate(std::span<const Metric>(m), std::span<const double>(c), mode));
  }
  return out;
}

}  // namespace dtlab::transfer_detail
