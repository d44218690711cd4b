#include "mesh/io/obj_format.hpp"

#include <array>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

constexpr std::array<std::string_view, 8> kSkipped = {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib"};
constexpr std::array<std::string_view, 15> kFreeForm = {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
                                                        "parm", "trim", "hole", "scrv", "sp", "end", "con", "call"};

template <std::size_t N>
bool one_of(std::string_view t, const std::array<std::string_view, N>& list) {
  for (std::string_view k : list)
    if (t == k) return true;
  return false;
}

class ObjReader {
 public:
  ObjReader(std::istream& in, const std::string& name) : in_(in, name) {}

  Plc3 read() {
    while (in_.next_line()) {
      const std::string_view kw = in_.token(0);
      if (in_.token(in_.size() - 1) == "\\") in_.fail("a line continued with '\\' is not supported");
      if (kw == "v") {
        read_vertex();
      } else if (kw == "f") {
        read_face();
      } else if (kw == "l") {
        read_polyline();
      } else if (kw == "p") {
        for (std::size_t k = 1; k < in_.size(); ++k) corner(k, "point");
      } else if (one_of(kw, kSkipped)) {
        continue;
      } else if (one_of(kw, kFreeForm)) {
        in_.fail("free-form geometry (" + quote(kw) + ") is not supported; only v, f, l and p are read");
      } else {
        in_.fail("unknown OBJ keyword " + quote(kw));
      }
    }
    // Positive vertex numbers may name vertices given later in the file: checked now.
    for (const auto& [facet, line] : forward_) {
      for (const std::uint32_t v : plc_.facets[facet].polygons[0])
        if (v >= plc_.vertices.size())
          in_.fail_at(line, "vertex number " + std::to_string(std::uint64_t{v} + 1) + " out of range 1.." +
                                std::to_string(plc_.vertices.size()));
    }
    plc_.vertex_markers.assign(plc_.vertices.size(), 0);
    return std::move(plc_);
  }

 private:
  void read_vertex() {
    static constexpr const char* kAxes[] = {"vertex x", "vertex y", "vertex z"};
    const std::size_t n = in_.size() - 1;
    if (n != 3 && n != 4 && n != 6)
      in_.fail("vertex " + std::to_string(plc_.vertices.size() + 1) + ": expected x y z [w] or x y z r g b, found " +
               std::to_string(n) + " numbers");
    double c[3];
    for (std::size_t k = 0; k < 3; ++k) {
      c[k] = in_.real(k + 1, kAxes[k]);
      io::check_coordinate(in_, c[k], kAxes[k]);
    }
    if (n == 4 && in_.real(4, "vertex w") != 1.0)
      in_.fail("vertex " + std::to_string(plc_.vertices.size() + 1) + ": w = " + std::string(in_.token(4)) +
               "; rational vertices (w other than 1) are not supported");
    for (std::size_t k = 4; n == 6 && k <= 6; ++k) in_.real(k, "vertex colour");
    plc_.vertices.push_back({c[0], c[1], c[2]});
  }

  // Corner token k ("v", "v/vt", "v//vn", "v/vt/vn") as a 0-based vertex id; sets forward when it
  // names a vertex not read yet.
  std::uint32_t corner(std::size_t k, std::string_view what, bool* forward = nullptr) {
    const std::string_view t = in_.token(k);
    std::vector<std::string_view> parts;
    for (std::size_t from = 0;;) {
      const std::size_t slash = t.find('/', from);
      parts.push_back(t.substr(from, slash == std::string_view::npos ? std::string_view::npos : slash - from));
      if (slash == std::string_view::npos) break;
      from = slash + 1;
    }
    std::int64_t index = 0, unused = 0;
    const bool well_formed = parts.size() <= 3 && parse_integer(parts[0], index) &&
                             (parts.size() < 2 || parse_integer(parts[1], unused) || (parts[1].empty() && parts.size() == 3)) &&
                             (parts.size() < 3 || parse_integer(parts[2], unused));
    if (!well_formed) in_.fail(std::string(what) + ": corner " + quote(t) + " is not v, v/vt, v//vn or v/vt/vn");
    const std::string_view v = parts[0];
    const auto n = static_cast<std::int64_t>(plc_.vertices.size());
    if (index == 0) in_.fail(std::string(what) + ": vertex number 0 (OBJ counts vertices from 1)");
    if (index < 0) {
      if (-index > n)
        in_.fail(std::string(what) + ": vertex number " + std::string(v) + " reaches back past the first vertex (" +
                 std::to_string(n) + " read so far)");
      return static_cast<std::uint32_t>(n + index);
    }
    if (index > static_cast<std::int64_t>(UINT32_MAX))
      in_.fail(std::string(what) + ": vertex number " + std::string(v) + " out of range");
    if (index > n && forward != nullptr) *forward = true;
    return static_cast<std::uint32_t>(index - 1);
  }

  static bool parse_integer(std::string_view t, std::int64_t& out) {
    if (t.empty()) return false;
    std::size_t i = t[0] == '-' || t[0] == '+' ? 1 : 0;
    if (i == t.size()) return false;
    std::int64_t v = 0;
    for (; i < t.size(); ++i) {
      if (t[i] < '0' || t[i] > '9' || v > (INT64_MAX - 9) / 10) return false;
      v = 10 * v + (t[i] - '0');
    }
    out = t[0] == '-' ? -v : v;
    return true;
  }

  void read_face() {
    const std::string what = "face " + std::to_string(faces_ + 1);
    ++faces_;
    if (in_.size() < 4)
      in_.fail(what + " has " + std::to_string(in_.size() - 1) + " corners; a face needs 3");
    std::vector<std::uint32_t> polygon;
    bool forward = false;
    for (std::size_t k = 1; k < in_.size(); ++k) polygon.push_back(corner(k, what, &forward));
    add_facet(std::move(polygon), forward);
  }

  void read_polyline() {
    const std::string what = "polyline " + std::to_string(++polylines_);
    if (in_.size() < 3) in_.fail(what + " has " + std::to_string(in_.size() - 1) + " vertices; a line needs 2");
    bool forward = false;
    std::uint32_t previous = corner(1, what, &forward);
    for (std::size_t k = 2; k < in_.size(); ++k) {
      bool f = forward;
      const std::uint32_t v = corner(k, what, &f);
      add_facet({previous, v}, f);
      previous = v;
    }
  }

  void add_facet(std::vector<std::uint32_t> polygon, bool forward) {
    if (forward) forward_.push_back({plc_.facets.size(), in_.line()});
    plc_.facets.push_back({{std::move(polygon)}, {}, 0});
  }

  LineTokenizer in_;
  Plc3 plc_;
  std::uint64_t faces_ = 0, polylines_ = 0;
  std::vector<std::pair<std::size_t, std::uint64_t>> forward_;  // (facet, line) naming later vertices
};

}  // namespace

Plc3 read_obj_surface(std::istream& in, const std::string& file_name) { return ObjReader(in, file_name).read(); }

Plc3 read_obj_surface(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_obj_surface(in, path);
}

}  // namespace dtlab
