// What the 2D and 3D optimization operators aim at and how they compare (book §5.3, §7, §9):
// the unit mesh, whose edges have metric length in [1/sqrt2, sqrt2] (an edge shorter is
// collapsed, one longer split; a collapse may not create an edge longer than the upper bound, so
// that the two never undo each other), the margin of a strict improvement, and the control space
// the operators read.
#pragma once

#include <functional>

namespace dtlab {

inline constexpr double kShortEdgeLength = 0.70710678118654752440;  // 1/sqrt2
inline constexpr double kLongEdgeLength = 1.41421356237309504880;   // sqrt2
// A strict improvement is one below (1 - margin) times the old value: no cycling on rounding.
inline constexpr double kImprovementMargin = 1e-6;

// The metric wanted at any point of the domain (the mesher's control space, a constant size,
// ...). An empty function means "interpolate from the neighbouring vertices" (split) or "keep
// the vertex's metric" (relocation).
template <class Metric, class Vec>
using MetricField = std::function<Metric(const Vec&)>;

}  // namespace dtlab
