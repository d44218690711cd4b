// A hash table from facets (three vertex ids, in any order) to a 32-bit value: DeWall's active
// face list in variant "divide-conquer" (the open facets of the built tetrahedra, each with its
// handle), the walls between regions of a constrained tetrahedralization. Open addressing with
// linear probing and backward-shift deletion: no allocation per facet.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

class FacetTable {
 public:
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;
  using Key = std::array<std::uint32_t, 3>;  // sorted vertex ids

  static Key key(std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {a, b, c};
  }

  FacetTable() { rehash(1024); }

  std::size_t size() const noexcept { return size_; }

  // Room for n facets without a rehash.
  void reserve(std::size_t n) {
    std::size_t capacity = slots_.size();
    while (capacity < 2 * n + 2) capacity *= 2;
    if (capacity != slots_.size()) rehash(capacity);
  }

  // A hash of the facet, independent of the table's size (home() is this one, masked).
  static std::uint64_t hash(const Key& k) noexcept {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + k[1] * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + k[2] * 0x94D049BB133111EBull;
    h ^= h >> 32;
    return h;
  }

  // If `k` is in the table, removes it and returns its value; else records it with `handle` and
  // returns kAbsent.
  std::uint32_t take_or_insert(const Key& k, std::uint32_t handle) {
    std::size_t i = home(k);
    for (std::size_t probes = 0; probes <= mask_; ++probes, i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.handle == kAbsent) {
        s = {k, handle};
        if (++size_ * 2 > slots_.size()) rehash(2 * slots_.size());
        return kAbsent;
      }
      if (same(s.key, k)) {
        const std::uint32_t found = s.handle;
        erase_at(i);
        return found;
      }
    }
    throw InternalError("facet table full");
  }

  // Records `k` with `handle` unless it is in the table already; whether it was recorded.
  bool insert(const Key& k, std::uint32_t handle) {
    if (find(k) != kAbsent) return false;
    take_or_insert(k, handle);
    return true;
  }

  // The value of `k`, kAbsent if it is not in the table.
  std::uint32_t find(const Key& k) const noexcept {
    std::size_t i = home(k);
    for (std::size_t probes = 0; probes <= mask_; ++probes, i = (i + 1) & mask_) {
      if (slots_[i].handle == kAbsent) break;
      if (same(slots_[i].key, k)) return slots_[i].handle;
    }
    return kAbsent;
  }

  // Removes `k`, which must be in the table.
  void erase(const Key& k) {
    std::size_t i = home(k);
    for (std::size_t probes = 0; probes <= mask_; ++probes, i = (i + 1) & mask_) {
      if (slots_[i].handle == kAbsent) break;
      if (same(slots_[i].key, k)) {
        erase_at(i);
        return;
      }
    }
    throw InternalError("facet table: erasing a facet that is not there");
  }

 private:
  struct Slot {
    Key key;
    std::uint32_t handle = kAbsent;
  };

  static bool same(const Key& s, const Key& t) noexcept { return s[0] == t[0] && s[1] == t[1] && s[2] == t[2]; }

  std::size_t home(const Key& k) const noexcept { return static_cast<std::size_t>(hash(k)) & mask_; }

  // Backward-shift deletion: moves later entries of the probe run into the hole when their home
  // is not between the hole and them, so that lookups never need tombstones.
  void erase_at(std::size_t hole) noexcept {
    std::size_t j = hole;
    for (;;) {
      j = (j + 1) & mask_;
      if (slots_[j].handle == kAbsent) break;
      const std::size_t k = home(slots_[j].key);
      const bool stays = hole <= j ? (hole < k && k <= j) : (hole < k || k <= j);
      if (stays) continue;
      slots_[hole] = slots_[j];
      hole = j;
    }
    slots_[hole].handle = kAbsent;
    --size_;
  }

  void rehash(std::size_t capacity) {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    size_ = 0;
    for (const Slot& s : old)
      if (s.handle != kAbsent) take_or_insert(s.key, s.handle);
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace dtlab
