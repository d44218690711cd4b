#include "mesh/io/medit.hpp"

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

constexpr std::array<std::string_view, 3> kKeptKeywords = {"Vertices", "Edges", "Triangles"};

class MeditReader {
 public:
  MeditReader(std::istream& in, const std::string& name) : in_(in, name) {}

  const std::vector<std::string>& notes() const noexcept { return skipped_.notes(); }

  MeshData2 read() {
    bool have_version = false;
    bool have_dimension = false;
    bool have_vertices = false;
    bool have_edges = false;
    bool have_triangles = false;
    while (in_.next_line()) {
      const std::string_view kw = in_.token(0);
      if (!have_version && kw != "MeshVersionFormatted") {
        in_.fail("expected MeshVersionFormatted first, found " + quote(kw));
      }
      if (kw == "MeshVersionFormatted") {
        if (have_version) in_.fail("second MeshVersionFormatted");
        const std::int64_t v = io::medit_keyword_value(in_, "MeshVersionFormatted");
        if (v < 1 || v > 4) in_.fail("MeshVersionFormatted " + std::to_string(v) + " is not 1, 2, 3 or 4");
        have_version = true;
      } else if (kw == "Dimension") {
        if (have_dimension) in_.fail("second Dimension");
        const std::int64_t d = io::medit_keyword_value(in_, "Dimension");
        if (d == 3) in_.fail("Dimension 3: this is a 3D mesh, and this reader reads 2D meshes only");
        if (d != 2) in_.fail("Dimension " + std::to_string(d) + " is not 2");
        have_dimension = true;
      } else if (kw == "Vertices") {
        if (!have_dimension) in_.fail("Vertices before Dimension");
        if (have_vertices) in_.fail("second Vertices section");
        read_vertices();
        have_vertices = true;
      } else if (kw == "Edges") {
        if (!have_vertices) in_.fail("Edges before Vertices");
        if (have_edges) in_.fail("second Edges section");
        read_cells<2>("Edges", "edge", mesh_.edges, mesh_.edge_refs);
        have_edges = true;
      } else if (kw == "Triangles") {
        if (!have_vertices) in_.fail("Triangles before Vertices");
        if (have_triangles) in_.fail("second Triangles section");
        read_cells<3>("Triangles", "triangle", mesh_.triangles, mesh_.triangle_refs);
        have_triangles = true;
      } else if (io::MeditSkippedSections::is_skipped(kw)) {
        skipped_.skip(in_, kw);
      } else if (kw == "End") {
        in_.expect_tokens(1, "End");
        if (in_.next_line()) in_.fail("text after End: " + quote(in_.token(0)));
        skipped_.finish(in_, {mesh_.vertices.size(), mesh_.edges.size(), mesh_.triangles.size(), 0});
        return std::move(mesh_);
      } else {
        io::medit_refuse_keyword(in_, kw, "2D reader", kKeptKeywords);
      }
    }
    in_.fail_at(std::max<std::uint64_t>(in_.line(), 1), "file ends before End (truncated?)");
  }

 private:
  void read_vertices() {
    const std::uint64_t n = io::medit_section_count(in_, "Vertices");
    for (std::uint64_t i = 0; i < n; ++i) {
      io::medit_next_entry(in_, "Vertices", i, n);
      const std::string what = "vertex " + std::to_string(i + 1);
      in_.expect_tokens(3, what + " (x y ref)");
      const Vec2 p{in_.real(0, what + " x"), in_.real(1, what + " y")};
      io::check_coordinate(in_, p.x, what + " x");
      io::check_coordinate(in_, p.y, what + " y");
      mesh_.vertices.push_back(p);
      mesh_.vertex_refs.push_back(io::int_field(in_, 2, what + " reference"));
    }
  }

  template <std::size_t N>
  void read_cells(std::string_view kw, std::string_view noun, std::vector<std::array<std::uint32_t, N>>& cells,
                  std::vector<int>& refs) {
    const std::uint64_t n = io::medit_section_count(in_, kw);
    const std::uint64_t nv = mesh_.vertices.size();
    for (std::uint64_t i = 0; i < n; ++i) {
      io::medit_next_entry(in_, kw, i, n);
      const std::string what = std::string(noun) + " " + std::to_string(i + 1);
      in_.expect_tokens(N + 1, what + (N == 2 ? " (v1 v2 ref)" : " (v1 v2 v3 ref)"));
      std::array<std::uint32_t, N> cell{};
      for (std::size_t k = 0; k < N; ++k) cell[k] = io::vertex_number(in_, k, 1, nv, what);
      cells.push_back(cell);
      refs.push_back(io::int_field(in_, N, what + " reference"));
    }
  }

  LineTokenizer in_;
  io::MeditSkippedSections skipped_{2};
  MeshData2 mesh_;
};

}  // namespace

MeshData2 read_medit2(std::istream& in, const std::string& file_name, std::vector<std::string>* notes) {
  MeditReader reader(in, file_name);
  MeshData2 mesh = reader.read();
  io::deliver_notes(reader.notes(), file_name, notes);
  return mesh;
}

MeshData2 read_medit2(const std::string& path, std::vector<std::string>* notes) {
  std::ifstream in = io::open_for_reading(path);
  return read_medit2(in, path, notes);
}

void write_medit2(std::ostream& out, const MeshData2& mesh) {
  const std::size_t nv = mesh.vertices.size();
  io::check_refs(mesh.vertex_refs, nv, "vertex");
  io::check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  io::check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");

  std::string text = "MeshVersionFormatted 2\n\nDimension 2\n";
  if (nv > 0) {
    text += "\nVertices\n";
    io::append_integer(text, static_cast<std::int64_t>(nv));
    text += "\n";
    for (std::size_t i = 0; i < nv; ++i) {
      io::append_real(text, mesh.vertices[i].x);
      text += ' ';
      io::append_real(text, mesh.vertices[i].y);
      text += ' ';
      io::append_integer(text, mesh.vertex_refs.empty() ? 0 : mesh.vertex_refs[i]);
      text += '\n';
    }
  }
  io::append_medit_cells(text, "Edges", mesh.edges, mesh.edge_refs);
  io::append_medit_cells(text, "Triangles", mesh.triangles, mesh.triangle_refs);
  text += "\nEnd\n";
  out << text;
}

void write_medit2(const std::string& path, const MeshData2& mesh) {
  std::ofstream out = io::open_for_writing(path);
  write_medit2(out, mesh);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
