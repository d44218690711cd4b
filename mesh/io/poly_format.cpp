#include "mesh/io/poly_format.hpp"

#include <algorithm>
#include <filesystem>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;

class PolyReader {
 public:
  PolyReader(std::istream& in, const std::string& name) : in_(in, name) {}

  // `load_nodes` is called only if the vertex count is 0.
  template <class LoadNodes>
  PolyData2 read(LoadNodes&& load_nodes) {
    const std::uint64_t n = read_vertex_header();
    if (n == 0) {
      take_nodes(load_nodes());
    } else {
      read_vertices(n);
    }
    read_segments();
    read_holes();
    read_regions();
    return std::move(poly_);
  }

 private:
  // Moves to a section's header line, which must hold between 1 and `max_fields` fields; a longer
  // line is most likely one entry too many in the section before.
  void next_header(const std::string& header, std::size_t max_fields, const char* previous) {
    const std::uint64_t last = in_.line();
    if (!in_.next_line()) in_.fail_at(std::max<std::uint64_t>(last, 1), "file ends before the " + header);
    if (in_.size() > max_fields) {
      in_.fail("expected the " + header + ", found " + std::to_string(in_.size()) + " fields (more " + previous +
               " than the count says?)");
    }
  }

  int marker_count(std::size_t k, const std::string& what) {
    const std::int64_t m = in_.integer(k, what);
    if (m != 0 && m != 1) in_.fail(what + " is " + std::to_string(m) + ", not 0 or 1");
    return static_cast<int>(m);
  }

  Vec2 point(std::size_t k, const std::string& what) {
    const Vec2 p{in_.real(k, what + " x"), in_.real(k + 1, what + " y")};
    io::check_coordinate(in_, p.x, what + " x");
    io::check_coordinate(in_, p.y, what + " y");
    return p;
  }

  std::uint64_t read_vertex_header() {
    if (!in_.next_line()) in_.fail_at(1, "empty file: missing the header line (<#vertices> <dimension> ...)");
    if (in_.size() > 4) in_.fail("header: trailing text " + io::quote(in_.token(4)) + " after 4 fields");
    const std::uint64_t n = in_.count(0, "vertex count");
    if (in_.size() > 1) {
      const std::int64_t dim = in_.integer(1, "dimension");
      if (dim != 2) in_.fail("dimension is " + std::to_string(dim) + "; a .poly file for Triangle must be 2D");
    }
    poly_.attribute_count = in_.size() > 2 ? in_.count(2, "attribute count") : 0;
    poly_.has_point_markers = in_.size() > 3 && marker_count(3, "boundary marker count") == 1;
    return n;
  }

  void take_nodes(const TriangleNodes* nodes) {
    if (nodes == nullptr) return;
    poly_.points = nodes->points;
    poly_.attribute_count = nodes->attribute_count;
    poly_.attributes = nodes->attributes;
    poly_.has_point_markers = nodes->has_markers;
    poly_.point_markers = nodes->markers;
    poly_.first_index = nodes->first_index;
  }

  void read_vertices(std::uint64_t n) {
    const std::size_t fields = 3 + poly_.attribute_count + (poly_.has_point_markers ? 1 : 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "vertices");
      const std::string what = "vertex " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(fields, what);
      poly_.first_index = io::list_entry_number(in_, i, poly_.first_index, what);
      poly_.points.push_back(point(1, what));
      for (std::size_t a = 0; a < poly_.attribute_count; ++a) {
        poly_.attributes.push_back(in_.real(3 + a, what + " attribute " + std::to_string(a + 1)));
      }
      if (poly_.has_point_markers) poly_.point_markers.push_back(io::int_field(in_, fields - 1, what + " boundary marker"));
    }
  }

  void read_segments() {
    next_header("segment header (<#segments> [<#boundary markers>])", 2, "vertices");
    const std::uint64_t n = in_.count(0, "segment count");
    poly_.has_segment_markers = in_.size() > 1 && marker_count(1, "segment boundary marker count") == 1;
    const std::size_t fields = poly_.has_segment_markers ? 4 : 3;
    int first = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "segments");
      const std::string what = "segment " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(fields, what);
      first = io::list_entry_number(in_, i, first, what);
      std::array<std::uint32_t, 2> s{};
      for (std::size_t k = 0; k < 2; ++k) {
        s[k] = io::vertex_number(in_, 1 + k, poly_.first_index, poly_.points.size(), what);
      }
      poly_.segments.push_back(s);
      if (poly_.has_segment_markers) poly_.segment_markers.push_back(io::int_field(in_, 3, what + " boundary marker"));
    }
  }

  void read_holes() {
    next_header("hole count (<#holes>)", 1, "segments");
    const std::uint64_t n = in_.count(0, "hole count");
    int first = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "holes");
      const std::string what = "hole " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(3, what + " (<hole #> <x> <y>)");
      first = io::list_entry_number(in_, i, first, what);
      poly_.holes.push_back(point(1, what));
    }
  }

  // The region section is optional: the file may end after the holes.
  void read_regions() {
    if (!in_.next_line()) return;
    if (in_.size() > 1) {
      in_.fail("expected the optional region count (<#regions>) alone on its line, found " +
               std::to_string(in_.size()) + " fields (more holes than the count says?)");
    }
    const std::uint64_t n = in_.count(0, "region count");
    int first = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "regions");
      const std::string what = "region " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(5, what + " (<region #> <x> <y> <attribute> <maximum area>)");
      first = io::list_entry_number(in_, i, first, what);
      PolyRegion r;
      r.point = point(1, what);
      r.attribute = in_.real(3, what + " attribute");
      r.max_area = in_.real(4, what + " maximum area");
      poly_.regions.push_back(r);
    }
    if (in_.next_line()) {
      in_.fail("text after the last region (more regions than the count says?): " + io::quote(in_.token(0)));
    }
  }

  LineTokenizer in_;
  PolyData2 poly_;
};

template <class T>
void check_size(const std::vector<T>& v, std::size_t expected, const std::string& what) {
  if (v.size() != expected) {
    throw InputError(what + ": " + std::to_string(v.size()) + " values, expected " + std::to_string(expected));
  }
}

void append_point(std::string& text, const Vec2& p) {
  text += ' ';
  io::append_real(text, p.x);
  text += ' ';
  io::append_real(text, p.y);
}

}  // namespace

PolyData2 read_triangle_poly(std::istream& in, const std::string& file_name, const TriangleNodes* separate_nodes) {
  return PolyReader(in, file_name).read([&] { return separate_nodes; });
}

PolyData2 read_triangle_poly(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  TriangleNodes nodes;
  return PolyReader(in, path).read([&] {
    nodes = read_triangle_node(std::filesystem::path(path).replace_extension(".node").string());
    return &nodes;
  });
}

void write_triangle_poly(std::ostream& out, const PolyData2& poly) {
  const std::size_t n = poly.points.size();
  if (poly.first_index != 0 && poly.first_index != 1) {
    throw InputError("PolyData2::first_index is " + std::to_string(poly.first_index) + ", not 0 or 1");
  }
  check_size(poly.attributes, n * poly.attribute_count, "PolyData2::attributes");
  check_size(poly.point_markers, poly.has_point_markers ? n : 0, "PolyData2::point_markers");
  check_size(poly.segment_markers, poly.has_segment_markers ? poly.segments.size() : 0, "PolyData2::segment_markers");
  io::check_cells(poly.segments, {}, n, "segment");

  const std::int64_t first = poly.first_index;
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += " 2 ";
  io::append_integer(text, static_cast<std::int64_t>(poly.attribute_count));
  text += poly.has_point_markers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + first);
    append_point(text, poly.points[i]);
    for (std::size_t a = 0; a < poly.attribute_count; ++a) {
      text += ' ';
      io::append_real(text, poly.attributes[i * poly.attribute_count + a]);
    }
    if (poly.has_point_markers) {
      text += ' ';
      io::append_integer(text, poly.point_markers[i]);
    }
    text += '\n';
  }

  io::append_integer(text, static_cast<std::int64_t>(poly.segments.size()));
  text += poly.has_segment_markers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < poly.segments.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + first);
    for (std::uint32_t v : poly.segments[i]) {
      text += ' ';
      io::append_integer(text, static_cast<std::int64_t>(v) + first);
    }
    if (poly.has_segment_markers) {
      text += ' ';
      io::append_integer(text, poly.segment_markers[i]);
    }
    text += '\n';
  }

  io::append_integer(text, static_cast<std::int64_t>(poly.holes.size()));
  text += '\n';
  for (std::size_t i = 0; i < poly.holes.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + first);
    append_point(text, poly.holes[i]);
    text += '\n';
  }

  io::append_integer(text, static_cast<std::int64_t>(poly.regions.size()));
  text += '\n';
  for (std::size_t i = 0; i < poly.regions.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + first);
    append_point(text, poly.regions[i].point);
    text += ' ';
    io::append_real(text, poly.regions[i].attribute);
    text += ' ';
    io::append_real(text, poly.regions[i].max_area);
    text += '\n';
  }
  out << text;
}

void write_triangle_poly(const std::string& path, const PolyData2& poly) {
  std::ofstream out = io::open_for_writing(path);
  write_triangle_poly(out, poly);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
