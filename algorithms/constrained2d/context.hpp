// What a constrained method receives (registry.hpp): the mesh (the Delaunay triangulation of the
// input points to start with), the input segments after validation (endpoints mapped to the
// kept copy of duplicate points, duplicates removed), and the result to report into.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "algorithms/constrained2d/constrained2d.hpp"
#include "algorithms/constrained2d/constrained_mesh.hpp"
#include "kernel/error.hpp"

namespace dtlab {

struct Constrained2dContext {
  ConstrainedMesh2& mesh;
  // segments[k] is input segment ids[k]; ids ascending.
  std::span<const std::array<std::uint32_t, 2>> segments;
  std::span<const std::uint32_t> ids;
  const Constrained2dOptions& options;
  Constrained2dResult& result;

  // Item i (0-based) as messages number it (Constrained2dOptions::first_number).
  std::string number(std::uint64_t i) const { return std::to_string(i + options.first_number); }

  // The endpoints of input segment `id` (after duplicate points were merged).
  const std::array<std::uint32_t, 2>& input_segment(std::uint32_t id) const {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    DTLAB_ASSERT(it != ids.end() && *it == id);
    return segments[static_cast<std::size_t>(it - ids.begin())];
  }

  void note(std::string message) const {
    if (result.messages.size() < Constrained2dResult::kMaxMessages) result.messages.push_back(std::move(message));
    ++result.message_count;
  }
};

// Inserts every segment (enforce.cpp): splits at vertices on it, merges overlaps, splits
// crossings at their correctly rounded intersection, and enforces each piece by edge swaps
// along its pipe (§3.3.3). On return every piece is a constrained edge.
void resolve_and_enforce_segments(const Constrained2dContext& context);

}  // namespace dtlab
