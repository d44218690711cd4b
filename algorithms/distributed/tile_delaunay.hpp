// One tile's part of a distributed Delaunay triangulation (book §13.3; the tile-and-exchange
// scheme of Peterka, Morozov and Phillips, "High-performance computation of distributed-memory
// parallel 3D Voronoi and Delaunay tessellation", SC 2014, and of Caraffa, Memari, Yirci and
// Brédif's distributed Delaunay; written from their descriptions). No message layer here: the
// caller moves the messages (mpi/ over MPI, or distributed_in_process.hpp in one process).
//
// A round, on every tile at once:
//   1. triangulate_and_ask(): the Delaunay triangulation of what the tile knows (its own points
//      and the ghosts received so far); for every element with an own vertex, a question to each
//      other tile whose box meets the element's circumball (for an element on the hull of what
//      is known, the half-space beyond its hull facet);
//   2. answer(questions): each tile's own points in conflict with a question's element (exact,
//      perturbed in-circle / in-sphere: the nearest two; its own hull vertices beyond or on the
//      hull facet, exact orientation), each point sent to a tile once;
//   3. receive(answers): the new ghosts; the caller ends the rounds when no tile got any.
// Then every element with an own vertex has no point of any tile in conflict: it is an element of
// the Delaunay triangulation of all the points, and so is the star of every own vertex. Because
// the symbolic perturbation ranks points by their coordinates alone
// (kernel/predicates/perturbation.hpp), the elements are those of the sequential call for every
// tile count, degenerate input included. Each element is reported by one tile: the one holding its
// lowest-id vertex.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "algorithms/distributed/kd_tiles.hpp"
#include "kernel/vec.hpp"

namespace dtlab {

template <int kDim>
struct TileDelaunayTypes;
template <>
struct TileDelaunayTypes<2> {
  using Vec = Vec2;
};
template <>
struct TileDelaunayTypes<3> {
  using Vec = Vec3;
};

template <int kDim>
class TileDelaunay {
 public:
  using Vec = typename TileDelaunayTypes<kDim>::Vec;
  using Element = std::array<std::uint32_t, kDim + 1>;  // global ids, positive orientation

  // What a tile asks another: the points in conflict with an element.
  struct Question {
    enum Kind : std::uint64_t { Ball = 0, Beyond = 1, Everything = 2 };  // 64 bits: no padding (questions are compared as bytes)
    std::uint64_t kind = Ball;
    // Ball: the element's vertices (positively oriented). Beyond: a hull facet's kDim vertices,
    // then the element's other vertex (the side that is not beyond).
    std::array<Vec, kDim + 1> points{};
  };
  // A point sent to another tile: its global id, where it is, and its tile.
  struct Ghost {
    std::uint32_t id = 0;
    std::uint32_t tile = 0;
    Vec point{};
  };

  static_assert(sizeof(Question) == 8 + (kDim + 1) * sizeof(Vec), "no padding in a question");

  struct Counts {
    std::uint64_t rounds = 0;
    std::uint64_t ghosts = 0;            // points of other tiles this tile received
    std::uint64_t questions_sent = 0;
    std::uint64_t ghosts_sent = 0;       // own points sent (each to a tile once)
    double seconds_triangulating = 0.0;  // over the rounds
  };

  // `own_ids` ascending global ids with their points; `boxes` every tile's box (the tile's own
  // included) by tile number; `tile` this one's number.
  TileDelaunay(std::uint32_t tile, std::vector<TileBox<Vec>> boxes, std::vector<std::uint32_t> own_ids,
               std::vector<Vec> own_points);

  // Before the first round (optional, a head start: the rounds are correct without it): to each
  // other tile, the own points within kSeedLayers mean spacings of its box (the ghost zone of
  // Peterka et al.), so that the first triangulation holds the layer the neighbours' elements
  // need and the first questions ask with small balls.
  static constexpr double kSeedLayers = 2.0;
  std::vector<std::vector<Ghost>> seed();
  std::vector<std::vector<Question>> triangulate_and_ask();
  std::vector<std::vector<Ghost>> answer(const std::vector<std::vector<Question>>& questions);
  // Whether any of the ghosts was new.
  bool receive(const std::vector<std::vector<Ghost>>& ghosts);

  // The elements of the last triangulation whose lowest-id vertex is this tile's, each turned so
  // that its lowest id comes first (orientation kept), sorted.
  std::vector<Element> owned_elements() const;
  // Why the last triangulation had no elements (too few distinct points, all collinear or
  // coplanar), or empty.
  const std::string& degenerate_message() const noexcept { return degenerate_; }
  const Counts& counts() const noexcept { return counts_; }
  std::uint32_t own_point_count() const noexcept { return static_cast<std::uint32_t>(own_ids_.size()); }

 private:
  std::uint32_t tile_;
  std::vector<TileBox<Vec>> boxes_;
  std::vector<std::uint32_t> own_ids_;
  std::vector<Vec> own_points_;
  std::vector<Ghost> ghosts_;                    // received, any order
  std::vector<std::uint32_t> own_hull_;          // own points on the hull of the own points
  bool own_hull_known_ = false;
  void find_own_hull();
  std::vector<std::vector<std::uint8_t>> sent_;  // [tile][own index]: sent to that tile
  // [tile]: the questions (their bytes) that tile asked and got nothing for. The answer stays
  // nothing (own points are fixed, what was sent only grows): a question asked again in a later
  // round, as most are, is not searched again.
  std::vector<std::unordered_set<std::string>> answered_empty_;
  // The last triangulation: its points' global ids and tiles, its elements in local indices.
  std::vector<std::uint32_t> local_ids_, local_tiles_;
  std::vector<Element> local_elements_;
  std::string degenerate_;
  Counts counts_;
  struct ElementHash {
    std::size_t operator()(const Element& e) const noexcept {
      std::size_t h = 0;
      for (const std::uint32_t v : e) h = h * 0x9E3779B97F4A7C15ull + v;
      return h;
    }
  };
  // Elements already asked about, by sorted global ids.
  std::unordered_set<Element, ElementHash> asked_;
};

// An element turned so that its lowest id comes first, with the same orientation
// (mesh/canonical_element.hpp).
std::array<std::uint32_t, 3> canonical_element(const std::array<std::uint32_t, 3>& e);
std::array<std::uint32_t, 4> canonical_element(const std::array<std::uint32_t, 4>& e);

}  // namespace dtlab
