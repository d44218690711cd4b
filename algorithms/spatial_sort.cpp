// Hilbert sort by quantised keys and a recursive radix sort; BRIO rounds by a stable partition
// (Amenta, Choi, Rote, SoCG 2003). See spatial_sort.hpp.
#include "algorithms/spatial_sort.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>

#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"
#include "mesh/memory_hints.hpp"
#include "mesh/uninitialized_vector.hpp"

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

// The 3D Hilbert index by Skilling's transposition ("Programming the Hilbert curve", AIP Conf.
// Proc. 707, 2004), bit by bit: the definition of the 3D curve (hilbert_index3_skilling), from
// which the table below is derived.
constexpr std::uint32_t skilling_index3(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) noexcept {
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

// The same curve as an automaton read one level (one octant) at a time, most significant first,
// like the 2D table: about five times faster than the transposition, which was 3 % of the 3D
// kernel's time and the largest part of the parallel variant's preparation (issue 23). A state
// is the symmetry of the cube (a permutation of the axes and a reflection of some) that maps the
// current sub-cube's part of the curve onto the whole curve: for the canonical curve, the
// octant c holds the digit D(c) and the sub-curve V(c) applied to the lower bits (the curve is
// self-similar), read off Skilling's curve of order 2; in state S, octant o is the canonical
// octant S(o) and the next state V(S(o)) after S. The states reachable from the identity are
// numbered in breadth-first order. Tested against skilling_index3 on every cell up to 2^5 a side
// and on random cells at 2^10.
struct CubeSymmetry {
  std::array<std::uint8_t, 3> axis{0, 1, 2};  // coordinate i of the image is coordinate axis[i]
  std::uint8_t flip = 0;                      // reflected when bit i is set (i = 0: x)
  constexpr bool operator==(const CubeSymmetry&) const = default;
  // Image of an octant (x bit 2, y bit 1, z bit 0).
  constexpr unsigned apply(unsigned octant) const {
    unsigned out = 0;
    for (unsigned i = 0; i < 3; ++i) out |= (((octant >> (2 - axis[i])) & 1u) ^ ((flip >> i) & 1u)) << (2 - i);
    return out;
  }
  // This one after `first`.
  constexpr CubeSymmetry after(const CubeSymmetry& first) const {
    CubeSymmetry out;
    for (unsigned i = 0; i < 3; ++i) {
      out.axis[i] = first.axis[axis[i]];
      out.flip |= static_cast<std::uint8_t>((((first.flip >> axis[i]) & 1u) ^ ((flip >> i) & 1u)) << i);
    }
    return out;
  }
};

constexpr std::array<CubeSymmetry, 48> cube_symmetries() {
  std::array<CubeSymmetry, 48> out{};
  constexpr std::array<std::array<std::uint8_t, 3>, 6> kPermutations = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (unsigned p = 0; p < 6; ++p)
    for (unsigned f = 0; f < 8; ++f) out[p * 8 + f] = CubeSymmetry{kPermutations[p], static_cast<std::uint8_t>(f)};
  return out;
}

struct HilbertTable3 {
  std::array<std::uint8_t, 32 * 8> entry{};  // by state and octant: next state << 3 | digit
  unsigned states = 0;
};

constexpr HilbertTable3 make_hilbert_table3() {
  const auto symmetries = cube_symmetries();
  // The canonical curve's digit and sub-curve symmetry of each octant, from the curve of order 2.
  std::array<unsigned, 8> digit{};
  std::array<CubeSymmetry, 8> sub{};
  for (unsigned c = 0; c < 8; ++c) {
    const unsigned cx = c >> 2, cy = (c >> 1) & 1u, cz = c & 1u;
    digit[c] = skilling_index3(2 * cx, 2 * cy, 2 * cz, 2) >> 3;
    bool found = false;
    for (const CubeSymmetry& u : symmetries) {
      bool fits = true;
      for (unsigned l = 0; l < 8 && fits; ++l) {
        const std::uint32_t whole = skilling_index3(2 * cx + (l >> 2), 2 * cy + ((l >> 1) & 1u), 2 * cz + (l & 1u), 2);
        const unsigned m = u.apply(l);
        fits = whole >> 3 == digit[c] && (whole & 7u) == skilling_index3(m >> 2, (m >> 1) & 1u, m & 1u, 1);
      }
      if (fits) {
        sub[c] = u;
        found = true;
        break;
      }
    }
    if (!found) throw "the 3D Hilbert curve is not self-similar";  // fails the build
  }
  HilbertTable3 table;
  std::array<CubeSymmetry, 32> state{};
  table.states = 1;  // state 0: the identity
  for (unsigned s = 0; s < table.states; ++s)
    for (unsigned o = 0; o < 8; ++o) {
      const unsigned c = state[s].apply(o);
      const CubeSymmetry next = sub[c].after(state[s]);
      unsigned t = 0;
      while (t < table.states && !(state[t] == next)) ++t;
      if (t == table.states) {
        if (t == state.size()) throw "more 3D Hilbert states than the table holds";
        state[table.states++] = next;
      }
      table.entry[s * 8 + o] = static_cast<std::uint8_t>(t << 3 | digit[c]);
    }
  return table;
}

constexpr HilbertTable3 kHilbertTable3 = make_hilbert_table3();

// Two levels at a time: by state and (x's two bits << 4 | y's << 2 | z's), the next state << 6 |
// the two digits. Halves the chain of dependent table reads.
struct HilbertPairTable3 {
  std::array<std::uint16_t, 32 * 64> entry{};
};

constexpr HilbertPairTable3 make_hilbert_pair_table3() {
  HilbertPairTable3 table;
  for (unsigned s = 0; s < kHilbertTable3.states; ++s)
    for (unsigned cell = 0; cell < 64; ++cell) {
      const unsigned x2 = cell >> 4, y2 = (cell >> 2) & 3u, z2 = cell & 3u;
      const unsigned high = (x2 >> 1) << 2 | (y2 >> 1) << 1 | (z2 >> 1);
      const unsigned low = (x2 & 1u) << 2 | (y2 & 1u) << 1 | (z2 & 1u);
      const unsigned e1 = kHilbertTable3.entry[s * 8 + high];
      const unsigned e2 = kHilbertTable3.entry[(e1 >> 3) * 8 + low];
      table.entry[s * 64 + cell] = static_cast<std::uint16_t>((e2 >> 3) << 6 | (e1 & 7u) << 3 | (e2 & 7u));
    }
  return table;
}

constexpr HilbertPairTable3 kHilbertPairTable3 = make_hilbert_pair_table3();

constexpr int kGridBits2 = 16;  // 2D cells: 2^16 x 2^16
constexpr int kGridBits3 = 10;  // 3D cells: 2^10 x 2^10 x 2^10

// Resizes v to n, elements unwritten, with fresh storage advised onto huge pages when it has to
// grow.
template <class T>
void resize_for_bulk(UninitializedVector<T>& v, std::size_t n) {
  if (v.capacity() < n) {
    UninitializedVector<T> fresh;
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
// Each pass counts the digits of every share of the array (one share per thread of `team`) and
// moves each share's words to their bucket's range after those of the shares before it: stable,
// so the result does not depend on the number of shares.
void radix_sort_upper32(UninitializedVector<std::uint64_t>& a, UninitializedVector<std::uint64_t>& scratch,
                        WorkerTeam* team) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = a.size();
  const std::size_t count_shares = shares(team);
  std::vector<std::uint32_t> count(count_shares * kBuckets);  // by share, then bucket
  resize_for_bulk(scratch, n);
  for (int pass = 0; pass < 3; ++pass) {
    const int shift = 32 + pass * kDigitBits;
    std::fill(count.begin(), count.end(), 0u);
    for_each_share(team, n, [&](std::size_t k, std::size_t begin, std::size_t end) {
      std::uint32_t* c = count.data() + k * kBuckets;
      for (std::size_t i = begin; i < end; ++i) ++c[(a[i] >> shift) & (kBuckets - 1)];
    });
    std::uint32_t sum = 0;
    for (std::size_t b = 0; b < kBuckets; ++b)
      for (std::size_t k = 0; k < count_shares; ++k) sum += std::exchange(count[k * kBuckets + b], sum);
    // Share 0's start in a[0]'s bucket is 0 and in the next bucket n: every word is in that
    // bucket, nothing moves.
    const std::size_t first = (a[0] >> shift) & (kBuckets - 1);
    if (count[first] == 0 && (first + 1 == kBuckets || count[first + 1] == n)) continue;
    for_each_share(team, n, [&](std::size_t k, std::size_t begin, std::size_t end) {
      std::uint32_t* c = count.data() + k * kBuckets;
      for (std::size_t i = begin; i < end; ++i) scratch[c[(a[i] >> shift) & (kBuckets - 1)]++] = a[i];
    });
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
  // (id, smallest id) and marked with kDroppedId in place. With `team`, the passes over a large
  // set and the sorts of its shared cells are shared out among its threads (same result).
  HilbertSorter(std::span<const Point> points, std::vector<std::pair<std::uint32_t, std::uint32_t>>* duplicates,
                WorkerTeam* team = nullptr)
      : points_(points), duplicates_(duplicates), team_(team) {}

  // With positions_are_ids, ids holds 0, 1, ..., n - 1: the sorted keys' position fields are
  // then the ids themselves, which saves a copy of the ids and a gather of random reads.
  void sort(std::span<std::uint32_t> ids, bool positions_are_ids = false) {
    const std::size_t n = ids.size();
    WorkerTeam* const team = n >= kParallelThreshold ? team_ : nullptr;
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
    auto extend = [&](std::array<double, Dim>& l, std::array<double, Dim>& h, std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j)
        for (int d = 0; d < Dim; ++d) {
          const double c = coordinate(points_[ids[j]], d);
          l[d] = std::min(l[d], c), h[d] = std::max(h[d], c);
        }
    };
    if (team == nullptr) {
      extend(lo, hi, 0, n);  // no per-share boxes: this runs once per shared cell of the recursion
    } else {
      std::vector<std::array<double, Dim>> share_lo(shares(team), lo), share_hi(shares(team), hi);
      for_each_share(team, n, [&](std::size_t k, std::size_t begin, std::size_t end) {
        extend(share_lo[k], share_hi[k], begin, end);
      });
      for (std::size_t k = 0; k < share_lo.size(); ++k)
        for (int d = 0; d < Dim; ++d) lo[d] = std::min(lo[d], share_lo[k][d]), hi[d] = std::max(hi[d], share_hi[k][d]);
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
    for_each_share(team, n, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) {
        std::array<std::uint32_t, Dim> q;
        for (int d = 0; d < Dim; ++d)
          q[d] = static_cast<std::uint32_t>(std::min((coordinate(points_[ids[k]], d) - lo[d]) * scale[d], kLast));
        keys_[k] = std::uint64_t{CellIndex(q)} << 32 | k;
      }
    });
    if (n < kRadixThreshold) {
      std::sort(keys_.begin(), keys_.end());  // positions are unique: stable by construction
    } else {
      radix_sort_upper32(keys_, scratch_, team);
    }
    if (positions_are_ids) {
      for_each_share(team, n, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) ids[k] = static_cast<std::uint32_t>(keys_[k]);
      });
    } else {
      resize_for_bulk(copy_, n);
      for_each_share(team, n, [&](std::size_t, std::size_t begin, std::size_t end) {
        std::copy(ids.begin() + begin, ids.begin() + end, copy_.begin() + begin);
      });
      for_each_share(team, n, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) ids[k] = copy_[keys_[k] & 0xFFFFFFFFu];
      });
    }
    // Runs of equal keys share one cell: sort them again on their own bounding box. Collect the
    // runs first, since the recursion reuses the buffers.
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t run_start = 0;
    for (std::size_t k = 1; k < n; ++k) {
      if ((keys_[k] >> 32) != (keys_[k - 1] >> 32)) {
        if (k - run_start > 1) runs.emplace_back(run_start, k - run_start);
        run_start = k;
      }
    }
    if (n - run_start > 1) runs.emplace_back(run_start, n - run_start);
    if (team == nullptr) {
      for (const auto& [start, length] : runs) sort(ids.subspan(start, length));
    } else {
      sort_runs_on_team(ids, runs, *team);
    }
  }

 private:
  static constexpr std::size_t kLeaf = 8;            // below this, a lexicographic sort is as good
  static constexpr std::size_t kRadixThreshold = 2048;  // below this, std::sort on the packed keys
  static constexpr std::size_t kParallelThreshold = std::size_t{1} << 16;  // below this, one thread

  // The runs (start, length) of `ids`, disjoint, sorted on the team's threads: each share of the
  // runs (about equal in points) by a sorter of its own, whose duplicates join this one's after.
  void sort_runs_on_team(std::span<std::uint32_t> ids, const std::vector<std::pair<std::size_t, std::size_t>>& runs,
                         WorkerTeam& team) {
    const std::size_t count = team.threads();
    std::vector<std::size_t> cut(count + 1, runs.size());  // share k sorts runs [cut[k], cut[k + 1])
    std::size_t total = 0, seen = 0;
    for (const auto& run : runs) total += run.second;
    cut[0] = 0;
    for (std::size_t r = 0, k = 1; r < runs.size() && k < count; ++r) {
      seen += runs[r].second;
      while (k < count && seen * count >= total * k) cut[k++] = r + 1;
    }
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(count);
    team.run(count, [&](std::size_t k, unsigned) {
      HilbertSorter sorter(points_, duplicates_ != nullptr ? &found[k] : nullptr);
      for (std::size_t r = cut[k]; r < cut[k + 1]; ++r) sorter.sort(ids.subspan(runs[r].first, runs[r].second));
    });
    if (duplicates_ != nullptr)
      for (const auto& share : found) duplicates_->insert(duplicates_->end(), share.begin(), share.end());
  }

  void drop(std::uint32_t& id, std::uint32_t kept) {
    if (duplicates_ == nullptr) return;
    duplicates_->emplace_back(id, kept);
    id |= kDroppedId;
  }

  std::span<const Point> points_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>>* duplicates_;
  WorkerTeam* team_;
  UninitializedVector<std::uint64_t> keys_, scratch_;
  UninitializedVector<std::uint32_t> copy_;
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

std::uint32_t hilbert_index3_skilling(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) noexcept {
  return skilling_index3(x, y, z, bits);
}

std::uint32_t hilbert_index3(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) noexcept {
  std::uint32_t index = 0;
  unsigned state = 0;
  int b = bits - 1;
  if ((bits & 1) != 0) {  // an odd level first, alone
    const unsigned octant = ((x >> b) & 1u) << 2 | ((y >> b) & 1u) << 1 | ((z >> b) & 1u);
    const std::uint8_t e = kHilbertTable3.entry[octant];
    index = e & 7u;
    state = e >> 3;
    --b;
  }
  for (b -= 1; b >= 0; b -= 2) {
    const unsigned cell = ((x >> b) & 3u) << 4 | ((y >> b) & 3u) << 2 | ((z >> b) & 3u);
    const std::uint16_t e = kHilbertPairTable3.entry[state * 64 + cell];
    index = index << 6 | (e & 63u);
    state = e >> 6;
  }
  return index;
}

namespace {

template <class Sorter, class Point>
std::vector<std::pair<std::uint32_t, std::uint32_t>> sort_unique(std::span<const Point> points,
                                                                 std::vector<std::uint32_t>& ids, WorkerTeam* team,
                                                                 bool positions_are_ids = false) {
  for (const std::uint32_t id : ids)
    if (id >= kDroppedId) throw InternalError("hilbert_sort_unique: id " + std::to_string(id) + " above 2^31 - 1");
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;
  Sorter sorter(points, &duplicates, team);
  sorter.sort(ids, positions_are_ids);
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
                                                                        std::vector<std::uint32_t>& ids,
                                                                        WorkerTeam* team) {
  return sort_unique<HilbertSorter2>(points, ids, team);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> hilbert_sort_unique(std::span<const Vec3> points,
                                                                        std::vector<std::uint32_t>& ids,
                                                                        WorkerTeam* team) {
  return sort_unique<HilbertSorter3>(points, ids, team);
}

namespace {

// The BRIO order of `ids` (in Hilbert order) into order[0, n), and into ranks[0, n) (unless
// null) the position in `ids` of each, n > first_round >= 1.
void brio_rounds(std::span<const std::uint32_t> ids, std::uint64_t seed, WorkerTeam* team, std::size_t first_round,
                 std::uint32_t* order, std::uint32_t* ranks) {
  const std::size_t n = ids.size();
  // Round sizes about n/2, n/4, ...: the deepest level keeps at least `first_round` points.
  const int last_level = std::bit_width(n / first_round) - 1;
  const auto rounds = static_cast<std::size_t>(last_level) + 1;
  // Round of an id: the deepest level (smallest round) is round 0.
  auto round_of = [&](std::uint32_t id) {
    const std::uint64_t r = mix64(seed + 0x9E3779B97F4A7C15ull * (std::uint64_t{id} + 1));
    return static_cast<std::size_t>(last_level - std::min(std::countr_zero(r), last_level));
  };
  // Stable counting sort by round, each share of the ids counted and dealt by one thread: share
  // s of round r starts after rounds < r and after the earlier shares' points of round r, so the
  // order is the one-thread order whatever the number of shares.
  const std::size_t share_count = shares(team);
  std::vector<std::size_t> start(share_count * rounds, 0);  // [share * rounds + round]
  for_each_share(team, n, [&](std::size_t s, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) ++start[s * rounds + round_of(ids[k])];
  });
  std::size_t at = 0;
  for (std::size_t r = 0; r < rounds; ++r)
    for (std::size_t s = 0; s < share_count; ++s) at += std::exchange(start[s * rounds + r], at);
  for_each_share(team, n, [&](std::size_t s, std::size_t begin, std::size_t end) {
    std::size_t* next = &start[s * rounds];
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t to = next[round_of(ids[k])]++;
      order[to] = ids[k];
      if (ranks != nullptr) ranks[to] = static_cast<std::uint32_t>(k);
    }
  });
}

}  // namespace

std::vector<std::uint32_t> brio_order_of_sorted(std::span<const std::uint32_t> ids, std::uint64_t seed,
                                                std::size_t first_round) {
  first_round = std::max<std::size_t>(first_round, 1);
  if (ids.size() <= first_round) return {ids.begin(), ids.end()};
  std::vector<std::uint32_t> order(ids.size());
  brio_rounds(ids, seed, nullptr, first_round, order.data(), nullptr);
  return order;
}

BrioOrder brio_order_of_sorted(std::span<const std::uint32_t> ids, std::uint64_t seed, WorkerTeam* team,
                               bool with_ranks, std::size_t first_round) {
  const std::size_t n = ids.size();
  first_round = std::max<std::size_t>(first_round, 1);
  BrioOrder out;
  out.ids.resize(n);  // written once below, not zero-filled first
  if (with_ranks) out.ranks.resize(n);
  if (n <= first_round) {
    std::copy(ids.begin(), ids.end(), out.ids.begin());
    std::iota(out.ranks.begin(), out.ranks.end(), std::uint32_t{0});
    return out;
  }
  populate_for_writing(out.ids.data(), out.ids.data() + n);  // one call, not a fault a page
  populate_for_writing(out.ranks.data(), out.ranks.data() + out.ranks.size());
  brio_rounds(ids, seed, team, first_round, out.ids.data(), with_ranks ? out.ranks.data() : nullptr);
  return out;
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
DistinctPoints distinct_in_hilbert_order_impl(std::span<const P> points, WorkerTeam* team) {
  DistinctPoints out;
  out.distinct.reserve(points.size());  // written once, not zero-filled first
  populate_for_writing(out.distinct.data(), out.distinct.data() + points.size());  // one call, not a fault a page
  for (std::size_t i = 0; i < points.size(); ++i) out.distinct.push_back(static_cast<std::uint32_t>(i));
  using Sorter = std::conditional_t<std::is_same_v<P, Vec2>, HilbertSorter2, HilbertSorter3>;
  const auto dropped = sort_unique<Sorter>(points, out.distinct, team, /*positions_are_ids=*/true);
  out.duplicates.reserve(dropped.size());
  out.duplicate_of.reserve(dropped.size());
  for (const auto& [duplicate, original] : dropped) {
    out.duplicates.push_back(duplicate);
    out.duplicate_of.push_back(original);
  }
  return out;
}
}  // namespace

DistinctPoints distinct_in_hilbert_order(std::span<const Vec2> points, WorkerTeam* team) {
  return distinct_in_hilbert_order_impl(points, team);
}

DistinctPoints distinct_in_hilbert_order(std::span<const Vec3> points, WorkerTeam* team) {
  return distinct_in_hilbert_order_impl(points, team);
}

}  // namespace dtlab
