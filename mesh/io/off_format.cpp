#include "mesh/io/off_format.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

// Messages count vertices and faces from 1, "vertex 3 of 8" after the file's line, as the Medit,
// poly and TetGen readers do; a vertex number inside a face is quoted as the file writes it (from
// 0) with its range. (Past the reader, dtlab constrain names facets as the file numbers them.)

// Extra numbers per vertex that the header's prefixes announce; a colour has 3 or 4.
struct VertexLayout {
  std::size_t fixed = 3;   // x y z, plus normal and texture coordinates
  bool has_colour = false;
};

bool starts_with_digit_or_sign(std::string_view t) {
  return !t.empty() && ((t[0] >= '0' && t[0] <= '9') || t[0] == '-' || t[0] == '+' || t[0] == '.');
}

// Parses "[ST][C][N]OFF"; refuses 4OFF, nOFF and anything else by name.
VertexLayout parse_header_keyword(const LineTokenizer& in) {
  const std::string_view kw = in.token(0);
  if (!kw.ends_with("OFF")) {
    in.fail("expected the OFF header keyword ([ST][C][N]OFF), found " +
            std::string(starts_with_digit_or_sign(kw) ? "the number " : "") + quote(kw));
  }
  std::string_view prefix = kw.substr(0, kw.size() - 3);
  VertexLayout layout;
  if (prefix.starts_with("ST")) {
    layout.fixed += 2;
    prefix.remove_prefix(2);
  }
  if (prefix.starts_with("C")) {
    layout.has_colour = true;
    prefix.remove_prefix(1);
  }
  if (prefix.starts_with("N")) {
    layout.fixed += 3;
    prefix.remove_prefix(1);
  }
  if (prefix == "4" || prefix == "4n") in.fail(quote(kw) + " is a 4D OFF variant; only 3D OFF is supported");
  if (prefix == "n") in.fail(quote(kw) + " gives its own vertex dimension (nOFF); only 3D OFF is supported");
  if (!prefix.empty()) in.fail("unknown OFF variant " + quote(kw) + " (supported: [ST][C][N]OFF)");
  return layout;
}

// What the reader collects: the vertices and each face's corners (in file order); read_off
// turns it into triangles, read_off_surface into one polygon facet per face.
struct OffContent {
  std::vector<Vec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

class OffReader {
 public:
  // polygons: faces of more than 3 vertices are read (read_off_surface) rather than refused.
  OffReader(std::istream& in, const std::string& name, bool polygons) : in_(in, name), polygons_(polygons) {}

  OffContent read() {
    if (!in_.next_line()) in_.fail_at(1, "empty file: missing the OFF header");
    const VertexLayout layout = parse_header_keyword(in_);
    if (in_.size() == 2 && in_.token(1) == "BINARY") in_.fail("binary OFF is not supported (only ASCII OFF)");
    std::size_t first_count = 1;
    if (in_.size() == 1) {
      const std::uint64_t header_line = in_.line();
      if (!in_.next_line()) in_.fail_at(header_line, "file ends before the counts (<#vertices> <#faces> <#edges>)");
      first_count = 0;
    }
    in_.expect_tokens(first_count + 3, "counts (<#vertices> <#faces> <#edges>)");
    const std::uint64_t nv = in_.count(first_count, "vertex count");
    const std::uint64_t nf = in_.count(first_count + 1, "face count");
    in_.count(first_count + 2, "edge count");
    read_vertices(nv, layout);
    read_faces(nf);
    if (in_.next_line()) {
      in_.fail("more lines than the header's " + std::to_string(nf) + " faces: " + quote(in_.token(0)));
    }
    return std::move(content_);
  }

 private:
  void read_vertices(std::uint64_t n, const VertexLayout& layout) {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "vertices");
      const std::string what = "vertex " + std::to_string(i + 1) + " of " + std::to_string(n);
      const bool with_alpha = layout.has_colour && in_.size() == layout.fixed + 4;
      in_.expect_tokens(layout.fixed + (layout.has_colour ? (with_alpha ? 4 : 3) : 0), what);
      double c[3];
      for (std::size_t k = 0; k < 3; ++k) {
        c[k] = in_.real(k, what + kAxes[k]);
        io::check_coordinate(in_, c[k], what + kAxes[k]);
      }
      for (std::size_t k = 3; k < in_.size(); ++k) in_.real(k, what + " field " + std::to_string(k + 1));
      content_.vertices.push_back(Vec3{c[0], c[1], c[2]});
    }
  }

  void read_faces(std::uint64_t n) {
    const std::uint64_t nv = content_.vertices.size();
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "faces");
      const std::string what = "face " + std::to_string(i + 1) + " of " + std::to_string(n);
      const std::uint64_t corners = in_.count(0, what + " vertex count");
      if (corners < 3) in_.fail(what + " has " + std::to_string(corners) + " vertices; a face needs 3");
      if (corners > 3 && !polygons_) {
        in_.fail(what + " has " + std::to_string(corners) +
                 " vertices: a polygon. read_off keeps triangles only (MeshData3); read_off_surface, which "
                 "`dtlab constrain` uses, reads polygons as PLC facets");
      }
      if (in_.size() < corners + 1) {
        in_.fail(what + ": expected " + std::to_string(corners) + " vertex numbers, found " +
                 std::to_string(in_.size() - 1));
      }
      const std::size_t colour = in_.size() - 1 - corners;
      if (colour != 0 && colour != 1 && colour != 3 && colour != 4) {
        in_.fail(what + ": " + std::to_string(colour) + " numbers after the vertex numbers; a face colour has 1, 3 or 4");
      }
      std::vector<std::uint32_t> face(corners);
      for (std::size_t k = 0; k < corners; ++k) face[k] = io::vertex_number(in_, 1 + k, 0, nv, what);
      for (std::size_t k = 1 + corners; k < in_.size(); ++k) in_.real(k, what + " colour");
      content_.faces.push_back(std::move(face));
    }
  }

  LineTokenizer in_;
  bool polygons_ = false;
  OffContent content_;
};

}  // namespace

MeshData3 read_off(std::istream& in, const std::string& file_name) {
  OffContent content = OffReader(in, file_name, false).read();
  MeshData3 mesh;
  mesh.vertices = std::move(content.vertices);
  mesh.vertex_refs.assign(mesh.vertices.size(), 0);
  mesh.triangles.reserve(content.faces.size());
  for (const auto& f : content.faces) mesh.triangles.push_back({f[0], f[1], f[2]});
  mesh.triangle_refs.assign(mesh.triangles.size(), 0);
  return mesh;
}

MeshData3 read_off(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_off(in, path);
}

Plc3 read_off_surface(std::istream& in, const std::string& file_name) {
  OffContent content = OffReader(in, file_name, true).read();
  Plc3 plc;
  plc.vertices = std::move(content.vertices);
  plc.vertex_markers.assign(plc.vertices.size(), 0);
  plc.facets.resize(content.faces.size());
  for (std::size_t f = 0; f < content.faces.size(); ++f) plc.facets[f].polygons.push_back(std::move(content.faces[f]));
  return plc;
}

Plc3 read_off_surface(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_off_surface(in, path);
}

void write_off(std::ostream& out, const MeshData3& mesh) {
  if (!mesh.edges.empty() || !mesh.tetrahedra.empty()) {
    throw InputError("OFF holds vertices and triangles only; this mesh has " + std::to_string(mesh.edges.size()) +
                     " edges and " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
  }
  io::check_cells(mesh.triangles, {}, mesh.vertices.size(), "triangle");
  std::string text = "OFF\n";
  io::append_integer(text, static_cast<std::int64_t>(mesh.vertices.size()));
  text += ' ';
  io::append_integer(text, static_cast<std::int64_t>(mesh.triangles.size()));
  text += " 0\n";
  for (const Vec3& p : mesh.vertices) {
    io::append_real(text, p.x);
    text += ' ';
    io::append_real(text, p.y);
    text += ' ';
    io::append_real(text, p.z);
    text += '\n';
  }
  for (const auto& t : mesh.triangles) {
    text += '3';
    for (std::uint32_t v : t) {
      text += ' ';
      io::append_integer(text, v);
    }
    text += '\n';
  }
  out << text;
}

void write_off(const std::string& path, const MeshData3& mesh) {
  std::ofstream out = io::open_for_writing(path);
  write_off(out, mesh);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
