// Hilbert sort by quantised keys and a recursive radix sort; BRIO rounds by a stable partition
// (Amenta, Choi, Rote, SoCG 2003). See spatial_sort.hpp.
#include "algorithms/spatial_sort.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <string>
#include <utility>

#include "kernel/error.hpp"
#include "mesh/memory_hints.hpp"

namespace dtlab {

namespace {

// The Hilbert curve as a four-state automaton read one grid level at a time, most significant
// first. A state is the transform (complement both coordinates: f; swap them: s) that maps the
// current sub-square onto the canonical one, whose quadrants are visited in the order
// (0,0) (0,1) (1,1) (1,0). Entering quadrant (rx, ry) of the canonical square composes the
// transform with a swap when ry = 0, and with a complement too when rx = 1 as well.
// The table reads four levels at once: entry = (8 bits of index << 2) | next state.
struct HilbertTable2 {
  std::array<std::uint16_t, 4 * 256> entry{};
};

constexpr HilbertTable2 make_hilbert_table2() {
  HilbertTable2 table;
  for (unsigned state = 0; state < 4; ++state) {
    for (unsigned x4 = 0; x4 < 16; ++x4) {
      for (unsigned y4 = 0; y4 < 16; ++y4) {
        unsigned f = state & 1u, s = state >> 1;
        unsigned digits = 0;
        for (int level = 3; level >= 0; --level) {
          const unsigned tx = ((x4 >> level) & 1u) ^ f;
          const unsigned ty = ((y4 >> level) & 1u) ^ f;
          const unsigned rx = s ? ty : tx;
          const unsigned ry = s ? tx : ty;
          digits = (digits << 2) | ((3u * rx) ^ ry);
          if (ry == 0) {
            f ^= rx;
            s ^= 1u;
          }
        }
        table.entry[state * 256 + (x4 << 4 | y4)] = static_cast<std::uint16_t>(digits << 2 | (s << 1 | f));
      }
    }
  }
  return table;
}

constexpr HilbertTable2 kHilbertTable2 = make_hilbert_table2();

constexpr int kGridBits2 = 16;  // 2D cells: 2^16 x 2^16
constexpr int kGridBits3 = 10;  // 3D cells: 2^10 x 2^10 x 2^10

// Resizes v to n, with fresh storage advised onto huge pages when it has to grow.
template <class T>
void resize_for_bulk(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) {
    std::vector<T> fresh;
    fresh.reserve(n);
    advise_huge_pages(fresh.data(), n * sizeof(T));
    v.swap(fresh);
  }
  v.resize(n);
}

inline double coordinate(const Vec2& p, int k) noexcept { return k == 0 ? p.x : p.y; }
inline double coordinate(const Vec3& p, int k) noexcept { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

// Marks an id to drop, in hilbert_sort_unique: ids stay below 2^31.
constexpr std::uint32_t kDroppedId = 0x80000000u;

// Stable LSD radix sort of (key << 32 | position) words by their upper 32 bits, 11 bits a pass.
void radix_sort_upper32(std::vector<std::uint64_t>& a, std::vector<std::uint64_t>& scratch) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = a.size();
  std::vector<std::uint32_t> count(3 * kBuckets, 0);
  for (const std::uint64_t w : a) {
    const auto key = static_cast<std::uint32_t>(w >> 32);
    ++count[key & (kBuckets - 1)];
    ++count[kBuckets + ((key >> kDigitBits) & (kBuckets - 1))];
    ++count[2 * kBuckets + (key >> (2 * kDigitBits))];
  }
  resize_for_bulk(scratch, n);
  for (int pass = 0; pass < 3; ++pass) {
    std::uint32_t* c = count.data() + pass * kBuckets;
    const int shift = 32 + pass * kDigitBits;
    if (c[(a[0] >> shift) & (kBuckets - 1)] == n) continue;  // one bucket: nothing moves
    std::uint32_t sum = 0;
    for (std::size_t b = 0; b < kBuckets; ++b) sum += std::exchange(c[b], sum);
    for (const std::uint64_t w : a) scratch[c[(w >> shift) & (kBuckets - 1)]++] = w;
    a.swap(scratch);
  }
}

// The recursive Hilbert sort, for any dimension: points are quantised on a grid over their
// bounding box, sorted by the Hilbert index of their cell (CellIndex, Dim * GridBits <= 32 bits),
// and every run of points sharing a cell is sorted again on its own bounding box.
template <class Point, int Dim, int GridBits, std::uint32_t (*CellIndex)(const std::array<std::uint32_t, Dim>&)>
class HilbertSorter {
 public:
  static_assert(Dim * GridBits <= 32);
  // With `duplicates`, every id whose point equals that of a smaller id is recorded there as
  // (id, smallest id) and marked with kDroppedId in place.
  HilbertSorter(std::span<const Point> points, std::vector<std::pair<std::uint32_t, std::uint32_t>>* duplicates)
      : points_(points), duplicates_(duplicates) {}

  void sort(std::span<std::uint32_t> ids) {
    const std::size_t n = ids.size();
    if (n <= 1) return;
    if (n <= kLeaf) {
      std::sort(ids.begin(), ids.end(), [this](std::uint32_t i, std::uint32_t j) {
        const auto c = points_[i] <=> points_[j];
        return c < 0 || (c == 0 && i < j);
      });
      // Equal points meet only in a leaf or in an all-equal run: both are handled here.
      std::size_t first = 0;
      for (std::size_t k = 1; k < n; ++k) {
        if (points_[ids[k]] == points_[ids[first]]) {
          drop(ids[k], ids[first]);
        } else {
          first = k;
        }
      }
      return;
    }
    std::array<double, Dim> lo, hi;
    for (int d = 0; d < Dim; ++d) lo[d] = hi[d] = coordinate(points_[ids[0]], d);
    for (const std::uint32_t i : ids)
      for (int d = 0; d < Dim; ++d) {
        const double c = coordinate(points_[i], d);
        lo[d] = std::min(lo[d], c), hi[d] = std::max(hi[d], c);
      }
    if (lo == hi) {  // all duplicates of one point
      std::sort(ids.begin(), ids.end());
      for (std::size_t k = 1; k < n; ++k) drop(ids[k], ids[0]);
      return;
    }
    // Each axis scaled on its own, so that the points fill the grid. The quantisation is a
    // heuristic (no decision depends on it) but a function of the coordinates: equal points
    // get equal keys at every level of the recursion.
    constexpr double kCells = 1u << GridBits;
    constexpr double kLast = kCells - 1;
    std::array<double, Dim> scale;
    for (int d = 0; d < Dim; ++d) scale[d] = hi[d] > lo[d] ? kCells / (hi[d] - lo[d]) : 0.0;
    resize_for_bulk(keys_, n);
    for (std::size_t k = 0; k < n; ++k) {
      std::array<std::uint32_t, Dim> q;
      for (int d = 0; d < Dim; ++d)
        q[d] = static_cast<std::uint32_t>(std::min((coordinate(points_[ids[k]], d) - lo[d]) * scale[d], kLast));
      keys_[k] = std::uint64_t{CellIndex(q)} << 32 | k;
    }
    if (n < kRadixThreshold) {
      std::sort(keys_.begin(), keys_.end());  // positions are unique: stable by construction
    } else {
      radix_sort_upper32(keys_, scratch_);
    }
    resize_for_bulk(copy_, n);
    std::copy(ids.begin(), ids.end(), copy_.begin());
    // Runs of equal keys share one cell: sort them again on their own bounding box. Collect the
    // runs first, since the recursion reuses the buffers.
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t run_start = 0;
    for (std::size_t k = 0; k < n; ++k) {
      ids[k] = copy_[keys_[k] & 0xFFFFFFFFu];
      if (k > 0 && (keys_[k] >> 32) != (keys_[k - 1] >> 32)) {
        if (k - run_start > 1) runs.emplace_back(run_start, k - run_start);
        run_start = k;
      }
    }
    if (n - run_start > 1) runs.emplace_back(run_start, n - run_start);
    for (const auto& [start, length] : runs) sort(ids.subspan(start, length));
  }

 private:
  static constexpr std::size_t kLeaf = 8;            // below this, a lexicographic sort is as good
  static constexpr std::size_t kRadixThreshold = 2048;  // below this, std::sort on the packed keys

  void drop(std::uint32_t& id, std::uint32_t kept) {
    if (duplicates_ == nullptr) return;
    duplicates_->emplace_back(id, kept);
    id |= kDroppedId;
  }

  std::span<const Point> points_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>>* duplicates_;
  std::vector<std::uint64_t> keys_, scratch_;
  std::vector<std::uint32_t> copy_;
};

std::uint32_t cell_index2(const std::array<std::uint32_t, 2>& q) { return hilbert_index2(q[0], q[1]); }
std::uint32_t cell_index3(const std::array<std::uint32_t, 3>& q) {
  return hilbert_index3(q[0], q[1], q[2], kGridBits3);
}
using HilbertSorter2 = HilbertSorter<Vec2, 2, kGridBits2, &cell_index2>;
using HilbertSorter3 = HilbertSorter<Vec3, 3, kGridBits3, &cell_index3>;

// SplitMix64 finaliser (Steele, Lea, Flood, OOPSLA 2014): a well-mixed 64-bit hash of (seed, id).
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

std::uint32_t hilbert_index2(std::uint32_t x, std::uint32_t y) noexcept {
  std::uint32_t index = 0;
  unsigned state = 0;
  for (int shift = kGridBits2 - 4; shift >= 0; shift -= 4) {
    const unsigned cell = ((x >> shift) & 15u) << 4 | ((y >> shift) & 15u);
    const std::uint16_t e = kHilbertTable2.entry[state * 256 + cell];
    index = index << 8 | (e >> 2);
    state = e & 3u;
  }
  return index;
}

std::uint32_t hilbert_index3(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) noexcept {
  // Skilling's transposition ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004).
  std::uint32_t X[3] = {x, y, z};
  // Undo the excess work of the Gray code level by level, top down: where the level's bit of a
  // coordinate is set, invert the lower bits of X[0]; where it is clear, exchange the lower bits
  // of X[0] and that coordinate. Written without branches (the bits are data).
  for (std::uint32_t q = 1u << (bits - 1); q > 1; q >>= 1) {
    const std::uint32_t low = q - 1;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t set = 0u - static_cast<std::uint32_t>((X[i] & q) != 0);
      const std::uint32_t t = (X[0] ^ X[i]) & low & ~set;
      X[0] ^= t ^ (low & set);
      X[i] ^= t;
    }
  }
  // Gray encode.
  X[1] ^= X[0];
  X[2] ^= X[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = 1u << (bits - 1); q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  X[0] ^= t, X[1] ^= t, X[2] ^= t;
  // The index interleaves the transposed bits, X[0] most significant within each level.
  std::uint32_t index = 0;
  for (int b = bits - 1; b >= 0; --b)
    index = index << 3 | ((X[0] >> b) & 1u) << 2 | ((X[1] >> b) & 1u) << 1 | ((X[2] >> b) & 1u);
  return index;
}

namespace {

template <class Sorter, class Point>
std::vector<std::pair<std::uint32_t, std::uint32_t>> sort_unique(std::span<const Point> points,
                                                                 std::vector<std::uint32_t>& ids) {
  for (const std::uint32_t id : ids)
    if (id >= kDroppedId) throw InternalError("hilbert_sort_unique: id " + std::to_string(id) + " above 2^31 - 1");
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;
  Sorter sorter(points, &duplicates);
  sorter.sort(ids);
  if (!duplicates.empty()) std::erase_if(ids, [](std::uint32_t id) { return (id & kDroppedId) != 0; });
  std::sort(duplicates.begin(), duplicates.end());
  return duplicates;
}

}  // namespace

void hilbert_sort(std::span<const Vec2> points, std::span<std::uint32_t> ids) {
  HilbertSorter2 sorter(points, nullptr);
  sorter.sort(ids);
}

void hilbert_sort(std::span<const Vec3> points, std::span<std::uint32_t> ids) {
  HilbertSorter3 sorter(points, nullptr);
  sorter.sort(ids);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> hilbert_sort_unique(std::span<const Vec2> points,
                                                                        std::vector<std::uint32_t>& ids) {
  return sort_unique<HilbertSorter2>(points, ids);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> hilbert_sort_unique(std::span<const Vec3> points,
                                                                        std::vector<std::uint32_t>& ids) {
  return sort_unique<HilbertSorter3>(points, ids);
}

std::vector<std::uint32_t> brio_order_of_sorted(std::span<const std::uint32_t> ids, std::uint64_t seed,
                                                std::size_t first_round) {
  const std::size_t n = ids.size();
  first_round = std::max<std::size_t>(first_round, 1);
  if (n <= first_round) return {ids.begin(), ids.end()};
  // Round sizes about n/2, n/4, ...: the deepest level keeps at least `first_round` points.
  const int last_level = std::bit_width(n / first_round) - 1;
  auto level_of = [&](std::uint32_t id) {
    const std::uint64_t r = mix64(seed + 0x9E3779B97F4A7C15ull * (std::uint64_t{id} + 1));
    return std::min(std::countr_zero(r), last_level);
  };
  // Stable counting sort: deepest level (smallest round) first.
  std::vector<std::size_t> start(static_cast<std::size_t>(last_level) + 2, 0);
  for (const std::uint32_t id : ids) ++start[static_cast<std::size_t>(last_level - level_of(id)) + 1];
  for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
  std::vector<std::uint32_t> order(n);
  for (const std::uint32_t id : ids) order[start[static_cast<std::size_t>(last_level - level_of(id))]++] = id;
  return order;
}

std::vector<std::uint32_t> brio_order(std::span<const Vec2> points, std::span<const std::uint32_t> ids,
                                      std::uint64_t seed, std::size_t first_round) {
  std::vector<std::uint32_t> sorted(ids.begin(), ids.end());
  hilbert_sort(points, sorted);
  return brio_order_of_sorted(sorted, seed, first_round);
}

std::vector<std::uint32_t> brio_order(std::span<const Vec3> points, std::span<const std::uint32_t> ids,
                                      std::uint64_t seed, std::size_t first_round) {
  std::vector<std::uint32_t> sorted(ids.begin(), ids.end());
  hilbert_sort(points, sorted);
  return brio_order_of_sorted(sorted, seed, first_round);
}

namespace {
template <class P>
DistinctPoints distinct_in_hilbert_order_impl(std::span<const P> points) {
  DistinctPoints out;
  out.distinct.resize(points.size());
  std::iota(out.distinct.begin(), out.distinct.end(), 0u);
  const auto dropped = hilbert_sort_unique(points, out.distinct);
  out.duplicates.reserve(dropped.size());
  out.duplicate_of.reserve(dropped.size());
  for (const auto& [duplicate, original] : dropped) {
    out.duplicates.push_back(duplicate);
    out.duplicate_of.push_back(original);
  }
  return out;
}
}  // namespace

DistinctPoints distinct_in_hilbert_order(std::span<const Vec2> points) {
  return distinct_in_hilbert_order_impl(points);
}

DistinctPoints distinct_in_hilbert_order(std::span<const Vec3> points) {
  return distinct_in_hilbert_order_impl(points);
}

}  // namespace dtlab
