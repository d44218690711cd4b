// One point at a time into a Delaunay tetrahedralization by splitting and flipping, for variant
// "flip" (flip.cpp): Joe, "Construction of three-dimensional Delaunay triangulations using local
// transformations" (CAGD 1991); Edelsbrunner & Shah, "Incremental topological flipping works
// for regular triangulations" (Algorithmica 1996).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "algorithms/delaunay3d/flip_mesh.hpp"
#include "algorithms/delaunay3d/flip_orientation.hpp"
#include "kernel/vec.hpp"
#include "mesh/tetrahedralization3.hpp"

namespace dtlab {

// How often each operation ran (for statistics and tests).
struct FlipCounts {
  std::size_t splits[3] = {0, 0, 0};  // 1->4 (inside), 2->6 (on a facet), n->2n (on an edge)
  std::size_t flips23 = 0, flips32 = 0, flips44 = 0;
  std::size_t blocked = 0;  // link facets not locally Delaunay that could not be flipped when met
  std::size_t retried = 0;  // blocked ones looked at again when the queue ran empty
};

class FlipInserter {
 public:
  // points: indexed by vertex id; records: empty, filled as points go in; first: a positive
  // tetrahedron, inserted by start().
  FlipInserter(const Vec3* points, std::vector<Tetrahedralization3::Record>& records,
               std::array<std::uint32_t, 4> first);

  // The first tetrahedron and its four ghosts.
  void start();
  // Inserts point p (a vertex id not in the tetrahedralization, distinct from all that are).
  void insert(std::uint32_t p);
  // Compacts the records (no dead slots).
  void finish() { mesh_.finish(); }

  const FlipCounts& counts() const noexcept { return counts_; }

 private:
  enum class Outcome { Done, Flipped, Blocked };
  struct Location {
    std::uint32_t tetrahedron;
    std::uint32_t zero_facets;  // bit i: p lies on the plane of facet i
  };

  Location locate(std::uint32_t p) const;
  void split(const Location& at, std::uint32_t p);
  void collect_shell(std::uint32_t t, std::uint32_t a, std::uint32_t b);
  void restore_delaunay(std::uint32_t p);
  Outcome try_flip(std::uint32_t h, std::uint32_t p);
  bool flip32(std::uint32_t t1, std::uint32_t t2, std::uint32_t t3, std::uint32_t e0, std::uint32_t e1,
              std::uint32_t f, std::uint32_t p, std::uint32_t d);
  bool flip44(std::uint32_t t1, std::uint32_t t2, std::uint32_t f_in_t1, std::uint32_t e0, std::uint32_t e1,
              std::uint32_t f, std::uint32_t p, std::uint32_t d);
  void commit(std::uint32_t p);
  bool conflicts(std::uint32_t t, std::uint32_t p) const noexcept;
  Sign facet_side(std::uint32_t t, std::uint32_t i, std::uint32_t p) const noexcept;

  const Vec3* p_;
  std::array<std::uint32_t, 4> first_;
  FlipMesh mesh_;
  FlipOrientation orientation_;
  FlipCounts counts_;
  std::uint32_t last_ = 0;       // a tetrahedron of the last insertion: where the next walk starts
  std::size_t flips_left_ = 0;   // the bound of the current insertion
  std::vector<std::uint32_t> old_, ids_, queue_, deferred_, retry_;
  std::vector<FlipMesh::Tuple> fresh_;
};

}  // namespace dtlab
