// libFuzzer target: bytes -> 2D points -> every registered Delaunay variant. The first
// variant's output must pass verify_delaunay2d (topology, orientation, exact perturbed empty
// circle, hull coverage, duplicates unreferenced), and every other variant must return the same
// message, the same duplicates and the same canonical triangle set, with a closed structure and
// the input points left in place. Any failure prints the points (hex floats) and traps.
//
// Input layout: byte 0 picks how the payload becomes points, byte 1 is a parameter:
//   mode 0  raw doubles, 8 bytes per coordinate, mapped into the supported range
//           (gen::coordinate_from_bits: NaN, infinities and out-of-range exponents folded in);
//   mode 1  one byte per coordinate, its low 4 bits: a 16 x 16 lattice, full of collinear,
//           cocircular and repeated points;
//   mode 2  signed 16-bit integers: larger lattices, still exact;
//   mode 3  two bytes per coordinate, k and s: k / 2 moved by s % 4 nextafter steps, lattice
//           configurations a few ulps off degenerate.
// In modes 1-3 the parameter scales by 2^e, e = (byte 1 & 127) - 64, and its top bit then
// translates by (1e9, 1e9), which rounds small coordinates into further coincidences; results
// below the supported range are clamped into it (gen::clamp_to_range). At most
// kMaxPoints points are read; a trailing partial point is dropped.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "algorithms/delaunay2d/delaunay2d.hpp"
#include "algorithms/delaunay2d/registry.hpp"
#include "verify/checks2d.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace {

using dtlab::Vec2;

constexpr std::size_t kMaxPoints = 4096;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t left() const { return size_ - pos_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{byte()} << (8 * i);
    return v;
  }
  std::int16_t i16() {
    const unsigned lo = byte();
    return static_cast<std::int16_t>(lo | (unsigned{byte()} << 8));
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

std::vector<Vec2> decode(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const int mode = in.byte() % 4;
  const std::uint8_t parameter = in.byte();
  static constexpr std::size_t kBytesPerPoint[] = {16, 2, 4, 4};
  const std::size_t n = std::min(in.left() / kBytesPerPoint[mode], kMaxPoints);
  std::vector<Vec2> points(n);
  for (Vec2& p : points) {
    double* c[2] = {&p.x, &p.y};
    for (double* x : c) {
      switch (mode) {
        case 0: *x = dtlab::gen::coordinate_from_bits(in.u64()); break;
        case 1: *x = in.byte() & 15; break;
        case 2: *x = in.i16(); break;
        default: {
          const double k = static_cast<std::int8_t>(in.byte()) / 2.0;
          *x = dtlab::gen::nudge(k, static_cast<std::int8_t>(in.byte()) % 4);
        }
      }
    }
  }
  if (mode != 0) {
    const double scale = std::ldexp(1.0, (parameter & 127) - 64);
    const double shift = (parameter & 128) ? 1e9 : 0.0;
    // Scaling can push a nudged zero (2^-142) below the range: clamp it back in.
    for (Vec2& p : points) {
      p = {dtlab::gen::clamp_to_range(p.x * scale + shift), dtlab::gen::clamp_to_range(p.y * scale + shift)};
    }
  }
  return points;
}

[[noreturn]] void fail(const std::vector<Vec2>& points, const std::string& what) {
  std::fprintf(stderr, "delaunay2d_fuzz: %s\n%zu points:\n", what.c_str(), points.size());
  for (const Vec2& p : points) std::fprintf(stderr, "  %a %a\n", p.x, p.y);
  std::fflush(stderr);
  __builtin_trap();
}

struct Run {
  std::string variant;
  dtlab::Delaunay2dResult result;
  std::vector<dtlab::TriangleIds> triangles;
};

Run run(const std::string& variant, const std::vector<Vec2>& points) {
  Run r{variant, {}, {}};
  try {
    r.result = dtlab::delaunay2d(points, {.algorithm = variant});
    if (r.result.degenerate_message.empty()) r.result.triangulation.check_topology();
  } catch (const std::exception& e) {
    fail(points, variant + " threw: " + e.what());
  }
  const auto stored = r.result.triangulation.points();
  if (!std::equal(points.begin(), points.end(), stored.begin(), stored.end())) {
    fail(points, variant + ": triangulation.points() differs from the input");
  }
  r.triangles = r.result.triangulation.finite_triangles();
  if (!r.result.degenerate_message.empty() && !r.triangles.empty()) {
    fail(points, variant + ": triangles despite '" + r.result.degenerate_message + "'");
  }
  return r;
}

void verify(const std::vector<Vec2>& points, const Run& r) {
  const dtlab::CheckReport2 report = dtlab::verify_delaunay2d(points, r.triangles, r.result.duplicates);
  if (!report.ok) fail(points, r.variant + ": verify_delaunay2d: " + dtlab::to_text(report));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<Vec2> points = decode(data, size);
  const auto& variants = dtlab::delaunay2d_variants();
  const Run reference = run(std::string(variants.front().name), points);
  verify(points, reference);
  const std::vector<dtlab::TriangleIds> expected = dtlab::canonical_triangle_set(reference.triangles);
  for (const dtlab::Delaunay2dVariant& v : variants.entries().subspan(1)) {
    const Run r = run(std::string(v.name), points);
    // Equal triangle sets are equally valid; a differing one is verified to say who is wrong.
    if (r.result.degenerate_message != reference.result.degenerate_message ||
        r.result.duplicates != reference.result.duplicates ||
        dtlab::canonical_triangle_set(r.triangles) != expected) {
      verify(points, r);
      fail(points, r.variant + " differs from " + reference.variant + " (both pass verify_delaunay2d)");
    }
  }
  return 0;
}
