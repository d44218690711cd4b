// The quality statistics of a triangle or tetrahedron mesh, as the book prints them (§7.13,
// §8.2, §8.7: Tables 7.1-8.3: np, ne, Q_M and the share of elements with Q_K in [1,2], ]2,3],
// ]3,10], > 10) and as the UGAWG benchmarks measure a mesh against a metric (Alauzet, Loseille
// 2016: the share of unit edges, l in [1/sqrt2, sqrt2], and the mean-ratio quality). One report
// for every mesher, `dtlab quality`, `dtlab mesh --stats`, the tests and the benchmarks.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include "kernel/metric.hpp"
#include "kernel/vec.hpp"
#include "mesh/mesh2.hpp"
#include "mesh/mesh3.hpp"

namespace dtlab {

// Undefined figures (a mean over no elements, metric figures without a metric) are NaN; Q_M is
// +infinity when an element is flat. quality_json prints both as null.
struct QualityReport {
  static constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();
  // The bins of the book's tables: Q in [1,2], ]2,3], ]3,10], > 10. The first one also holds
  // the values a few ulps below 1 of rounded equilateral elements; the last one flat elements.
  static constexpr std::array<double, 3> kBinUpperBounds{2.0, 3.0, 10.0};

  int dimension = 2;
  bool has_metric = false;

  std::uint64_t points = 0;    // given, used by an element or not
  std::uint64_t vertices = 0;  // used by at least one element (the book's np)
  std::uint64_t elements = 0;  // ne

  // Q_K of kernel/quality.hpp (1 = equilateral), in the vertex metrics when there are metrics.
  double quality_worst = kUndefined;  // Q_M = max Q_K
  double quality_mean = kUndefined;   // over the elements whose Q_K is finite (not flat)
  std::array<std::uint64_t, 4> quality_bins{};
  std::array<double, 4> quality_shares{};  // quality_bins / elements (all 0 without elements)

  // Degrees, of the Euclidean elements: the triangles' angles (2D), the dihedral angles (3D).
  double angle_min = kUndefined;
  double angle_max = kUndefined;

  // Each edge of the mesh once.
  std::uint64_t edges = 0;
  double edge_length_min = kUndefined;  // Euclidean
  double edge_length_max = kUndefined;
  double edge_length_mean = kUndefined;
  // With metrics only: lengths l = (la - lb) / ln(la / lb) (kernel/metric.hpp edge_length).
  double metric_length_min = kUndefined;
  double metric_length_max = kUndefined;
  double metric_length_mean = kUndefined;
  std::uint64_t unit_edges = 0;          // l in [1/sqrt2, sqrt2]
  double unit_edge_share = kUndefined;   // unit_edges / edges

  // Mean ratio (kernel/quality.hpp; 1 = equilateral, 0 flat, negative inverted) in the metric of
  // the element's vertex with the largest determinant (the smallest unit ball: the strictest of
  // the vertex metrics, as the UGAWG papers take it); the identity without metrics.
  double mean_ratio_worst = kUndefined;  // the smallest
  double mean_ratio_mean = kUndefined;

  // Sum of the signed areas (volumes): the domain's measure for a valid mesh.
  double measure = 0.0;
  // Decided exactly (orient2d / orient3d): negative and zero orientation. They are measured like
  // the others (a flat element has Q_K = +infinity, mean ratio 0).
  std::uint64_t inverted = 0;
  std::uint64_t flat = 0;
};

// `metrics`: empty (no metric) or one per point. Throws InputError naming the element with a
// vertex out of range, the used vertex with a coordinate out of kernel/coordinate_range.hpp or
// a metric that is not positive definite, or the count when metrics are neither empty nor one
// per point. Deterministic: the same input gives the same report, bit for bit.
QualityReport measure_quality(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                              std::span<const Metric2> metrics = {});
QualityReport measure_quality(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 4>> tetrahedra,
                              std::span<const Metric3> metrics = {});

// The report of a shared mesh's domain (Mesh2::domain / Mesh3::domain) in its vertex metrics.
QualityReport domain_quality(const Mesh2& mesh);
QualityReport domain_quality(const Mesh3& mesh);

// One JSON object on one line, keys in a fixed order (the same set for every report of one
// dimension; the angle keys are min_angle_deg / max_angle_deg in 2D, min_dihedral_deg /
// max_dihedral_deg in 3D, the measure is area or volume); doubles in the shortest form that
// reads back to the same value; NaN and infinities as null.
std::string quality_json(const QualityReport& report);

// A text block like the book's tables, one figure per line, ending in a newline.
std::string quality_table(const QualityReport& report);

}  // namespace dtlab
