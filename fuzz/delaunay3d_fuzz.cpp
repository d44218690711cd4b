// libFuzzer target: bytes -> 3D points -> every built 3D Delaunay variant. The output of
// "incremental" must pass verify_delaunay3d (closed 3-manifold, positive tetrahedra, perturbed
// empty sphere, convex hull under the ghost rule, exact coverage, duplicates unreferenced), and
// every other variant must return the same message, the same duplicates and the same canonical
// tetrahedron set. Registered stubs (InternalError "... not built yet") are skipped; an
// InputError (a coordinate the predicates do not support) ends the run quietly. Any failure
// prints the points (hex floats) and traps.
//
// Input layout: byte 0 picks how the payload becomes points, byte 1 is a parameter:
//   mode 0  raw doubles, 8 bytes per coordinate, mapped into the supported range
//           (gen::coordinate_from_bits);
//   mode 1  one byte per coordinate, its low 2 bits: a 4 x 4 x 4 grid, where almost every
//           5-subset is cospherical or has 4 coplanar points;
//   mode 2  one byte per coordinate, its low 4 bits: a 16 x 16 x 16 lattice;
//   mode 3  signed 16-bit integers: larger lattices, still exact.
// In modes 1-3 the parameter scales by 2^e, e = (byte 1 & 127) - 64, and its top bit then
// translates by (1e9, 1e9, 1e9), which rounds small coordinates into further coincidences.
// At most kMaxPoints points are read; a trailing partial point is dropped.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "algorithms/delaunay3d/delaunay3d.hpp"
#include "algorithms/delaunay3d/registry.hpp"
#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "verify/checks3d.hpp"
#include "verify/generators/near_degenerate.hpp"

namespace {

using dtlab::Vec3;

constexpr std::size_t kMaxPoints = 1024;
constexpr const char* kReference = "incremental";

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

std::vector<Vec3> decode(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const int mode = in.byte() % 4;
  const std::uint8_t parameter = in.byte();
  static constexpr std::size_t kBytesPerPoint[] = {24, 3, 3, 6};
  const std::size_t n = std::min(in.left() / kBytesPerPoint[mode], kMaxPoints);
  std::vector<Vec3> points(n);
  for (Vec3& p : points) {
    for (double* x : {&p.x, &p.y, &p.z}) {
      switch (mode) {
        case 0: *x = dtlab::gen::coordinate_from_bits(in.u64()); break;
        case 1: *x = in.byte() & 3; break;
        case 2: *x = in.byte() & 15; break;
        default: *x = in.i16();
      }
    }
  }
  if (mode != 0) {
    const double scale = std::ldexp(1.0, (parameter & 127) - 64);
    const double shift = (parameter & 128) ? 1e9 : 0.0;
    for (Vec3& p : points) {
      p = {dtlab::gen::clamp_to_range(p.x * scale + shift), dtlab::gen::clamp_to_range(p.y * scale + shift),
           dtlab::gen::clamp_to_range(p.z * scale + shift)};
    }
  }
  return points;
}

[[noreturn]] void fail(const std::vector<Vec3>& points, const std::string& what) {
  std::fprintf(stderr, "delaunay3d_fuzz: %s\n%zu points:\n", what.c_str(), points.size());
  for (const Vec3& p : points) std::fprintf(stderr, "  %a %a %a\n", p.x, p.y, p.z);
  std::fflush(stderr);
  __builtin_trap();
}

struct Run {
  bool built = true;  // false: a registered stub
  dtlab::Delaunay3dResult result;
};

Run run(const std::string& variant, const std::vector<Vec3>& points) {
  Run r;
  try {
    r.result = dtlab::delaunay3d(points, {.algorithm = variant});
  } catch (const dtlab::InternalError& e) {
    if (std::string(e.what()).find("not built yet") == std::string::npos) fail(points, variant + " threw: " + e.what());
    r.built = false;
  } catch (const std::exception& e) {
    fail(points, variant + " threw: " + e.what());
  }
  return r;
}

void verify(const std::vector<Vec3>& points, const std::string& variant, const Run& r) {
  const dtlab::CheckReport3 report =
      dtlab::verify_delaunay3d(points, r.result.tetrahedralization, r.result.duplicates);
  if (!report.ok) fail(points, variant + ": verify_delaunay3d: " + dtlab::to_text(report));
  if (!r.result.degenerate_message.empty() && r.result.tetrahedralization.tetrahedron_count() != 0) {
    fail(points, variant + ": tetrahedra despite '" + r.result.degenerate_message + "'");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<Vec3> points = decode(data, size);
  try {
    dtlab::check_coordinates(points);
  } catch (const dtlab::InputError&) {
    return 0;  // not an input the predicates support: refused, as it should be
  }
  const Run reference = run(kReference, points);
  verify(points, kReference, reference);
  const auto expected = dtlab::canonical_tetrahedron_set(reference.result.tetrahedralization);
  for (const dtlab::Delaunay3dVariant& v : dtlab::delaunay3d_variants()) {
    const std::string name(v.name);
    if (name == kReference) continue;
    const Run r = run(name, points);
    if (!r.built) continue;
    // Equal tetrahedron sets are equally valid; a differing one is verified to say who is wrong.
    if (r.result.degenerate_message != reference.result.degenerate_message ||
        r.result.duplicates != reference.result.duplicates ||
        dtlab::canonical_tetrahedron_set(r.result.tetrahedralization) != expected) {
      verify(points, name, r);
      fail(points, name + " differs from " + kReference + " (both pass verify_delaunay3d)");
    }
  }
  return 0;
}
