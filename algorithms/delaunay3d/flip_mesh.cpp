// FlipMesh: slots, free list and the facet matching behind every split and flip of variant
// "flip" (flip_mesh.hpp).
#include "algorithms/delaunay3d/flip_mesh.hpp"

#include <algorithm>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

using T3 = Tetrahedralization3;
constexpr std::uint32_t kInf = T3::kInfinite;
constexpr std::uint32_t kNone = T3::kNone;
constexpr auto kFacet = T3::kFacetVertex;
// Records added to the array at a time: an eighth of it, from 64 to 4096 (a small mesh pages in
// no large chunk it never uses).
constexpr std::size_t kMinChunk = 64, kChunk = 4096;

std::array<std::uint32_t, 3> sorted_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept {
  if (x > y) std::swap(x, y);
  if (y > z) std::swap(y, z);
  if (x > y) std::swap(x, y);
  return {x, y, z};
}

}  // namespace

FlipMesh::FlipMesh(std::vector<Record>& records) : records_(records) {
  DTLAB_ASSERT(records.empty());
  r_ = records_.data();
  free_.reserve(1024);
  entries_.reserve(256);
  old_sorted_.reserve(64);
}

FlipMesh::FlipMesh(std::vector<Record>& records, Adopt) : records_(records), count_(records.size()) {
  r_ = records_.data();
  free_.reserve(64);
  entries_.reserve(256);
  old_sorted_.reserve(64);
}

// k more slots at the end. The vector's size runs ahead of count_ by a chunk so that most calls
// only count; its capacity grows by a quarter when exhausted (the caller reserves the expected
// size up front).
void FlipMesh::grow(std::size_t k) {
  const std::size_t need = count_ + k;
  if (need > records_.size()) {
    if (need > T3::kMaxTetrahedra)  // a size limit of the input, not a bug
      throw InputError("the Delaunay tetrahedralization of these points needs more than " +
                       std::to_string(T3::kMaxTetrahedra) + " tetrahedra (32-bit facet handles)");
    const std::size_t size = std::min<std::size_t>(need + std::clamp(need / 8, kMinChunk, kChunk), T3::kMaxTetrahedra);
    if (size > records_.capacity()) records_.reserve(std::max(size, records_.capacity() + records_.capacity() / 4));
    records_.resize(size);
    r_ = records_.data();
  }
  count_ = need;
}

// The even permutations that bring index k to 0 are the double transpositions j -> j ^ k.
std::uint32_t FlipMesh::write(std::uint32_t t, const Tuple& v) noexcept {
  const std::uint32_t m = v[1] == kInf ? 1u : v[2] == kInf ? 2u : v[3] == kInf ? 3u : 0u;
  for (std::uint32_t j = 0; j < 4; ++j) r_[t].vertex[j ^ m] = v[j];
  return m;
}

void FlipMesh::release(std::uint32_t t) {
  r_[t].vertex[0] = kNone;
  free_.push_back(t);
}

std::uint32_t FlipMesh::twin_opposite(std::uint32_t t, std::uint32_t v) const noexcept {
  const auto& w = r_[t].vertex;
  const std::uint32_t i = w[0] == v ? 0u : w[1] == v ? 1u : w[2] == v ? 2u : 3u;
  return r_[t].neighbour[i];
}

std::uint32_t FlipMesh::new_slot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    return t;
  }
  grow(1);
  return static_cast<std::uint32_t>(count_ - 1);
}

void FlipMesh::replace(std::span<const std::uint32_t> old, std::span<const Tuple> fresh, std::vector<std::uint32_t>& ids) {
  // Outer facets of the old region, read before any slot is overwritten.
  old_sorted_.assign(old.begin(), old.end());
  std::sort(old_sorted_.begin(), old_sorted_.end());
  entries_.clear();
  for (const std::uint32_t t : old) {
    const Record& rec = r_[t];
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t outer = rec.neighbour[i];
      if (std::binary_search(old_sorted_.begin(), old_sorted_.end(), outer >> 2)) continue;
      const auto& f = kFacet[i];
      entries_.push_back({sorted_key(rec.vertex[f[0]], rec.vertex[f[1]], rec.vertex[f[2]]), outer, true});
    }
  }

  ids.clear();
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    const std::uint32_t t = k < old.size() ? old[k] : new_slot();
    ids.push_back(t);
    write(t, fresh[k]);
  }
  for (std::size_t k = fresh.size(); k < old.size(); ++k) release(old[k]);
  for (const std::uint32_t t : ids) {
    const auto& v = r_[t].vertex;
    for (std::uint32_t i = 0; i < 4; ++i) {
      const auto& f = kFacet[i];
      entries_.push_back({sorted_key(v[f[0]], v[f[1]], v[f[2]]), 4 * t + i, false});
    }
  }

  // Each facet key occurs exactly twice: an old outer facet and the new facet that takes its
  // place, or two new facets that face each other.
  std::sort(entries_.begin(), entries_.end(), [](const FacetEntry& a, const FacetEntry& b) { return a.key < b.key; });
  for (std::size_t k = 0; k < entries_.size(); k += 2) {
    if (k + 1 >= entries_.size() || entries_[k].key != entries_[k + 1].key ||
        (k + 2 < entries_.size() && entries_[k + 2].key == entries_[k].key) ||
        (entries_[k].outer && entries_[k + 1].outer))
      throw InternalError("3D Delaunay flip: the new tetrahedra do not fit the facets of the ones they replace");
    const std::uint32_t g = entries_[k].handle, h = entries_[k + 1].handle;
    r_[g >> 2].neighbour[g & 3u] = h;
    r_[h >> 2].neighbour[h & 3u] = g;
  }
}

void FlipMesh::finish() {
  std::sort(free_.begin(), free_.end());
  const std::size_t live = count_ - free_.size();
  std::size_t source = count_;
  for (const std::uint32_t hole : free_) {
    if (hole >= live) break;
    do --source;
    while (r_[source].vertex[0] == kNone);
    r_[hole] = r_[source];
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t h = r_[hole].neighbour[i];
      r_[h >> 2].neighbour[h & 3u] = 4 * hole + i;
    }
    r_[source].vertex[0] = kNone;
  }
  count_ = live;
  free_.clear();
  records_.resize(count_);
  r_ = records_.data();
}

}  // namespace dtlab
