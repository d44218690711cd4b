#include "mesh/io/medit3.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

constexpr std::array<std::string_view, 4> kKeptKeywords = {"Vertices", "Edges", "Triangles", "Tetrahedra"};
constexpr std::array<std::string_view, 5> kSurfaceKeywords = {"Vertices", "Edges", "Triangles", "Quadrilaterals",
                                                              "Tetrahedra"};

class Medit3Reader {
 public:
  // quadrilaterals: read the Quadrilaterals section (read_medit3_surface) rather than refuse it.
  Medit3Reader(std::istream& in, const std::string& name, bool quadrilaterals = false,
               NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse)
      : in_(in, name), quadrilaterals_(quadrilaterals), tetrahedra_(tetrahedra) {}

  const std::vector<std::array<std::uint32_t, 4>>& quads() const noexcept { return quads_; }
  const std::vector<int>& quad_refs() const noexcept { return quad_refs_; }
  const std::vector<std::string>& notes() const noexcept { return skipped_.notes(); }

  MeshData3 read() {
    bool have_version = false;
    bool have_dimension = false;
    bool have_vertices = false;
    bool have_edges = false;
    bool have_triangles = false;
    bool have_tetrahedra = false;
    bool have_quadrilaterals = false;
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
        if (d == 2) in_.fail("Dimension 2: this is a 2D mesh, and this reader reads 3D meshes only");
        if (d != 3) in_.fail("Dimension " + std::to_string(d) + " is not 3");
        have_dimension = true;
      } else if (kw == "Vertices") {
        if (!have_dimension) in_.fail("Vertices before Dimension");
        if (have_vertices) in_.fail("second Vertices section");
        read_vertices();
        have_vertices = true;
      } else if (kw == "Edges") {
        begin_cells("Edges", have_vertices, have_edges);
        read_cells<2>("Edges", "edge", mesh_.edges, mesh_.edge_refs);
      } else if (kw == "Triangles") {
        begin_cells("Triangles", have_vertices, have_triangles);
        read_cells<3>("Triangles", "triangle", mesh_.triangles, mesh_.triangle_refs);
      } else if (kw == "Quadrilaterals" && quadrilaterals_) {
        begin_cells("Quadrilaterals", have_vertices, have_quadrilaterals);
        read_cells<4>("Quadrilaterals", "quadrilateral", quads_, quad_refs_);
      } else if (kw == "Tetrahedra") {
        begin_cells("Tetrahedra", have_vertices, have_tetrahedra);
        read_cells<4>("Tetrahedra", "tetrahedron", mesh_.tetrahedra, mesh_.tetrahedron_refs);
      } else if (io::MeditSkippedSections::is_skipped(kw)) {
        skipped_.skip(in_, kw);
      } else if (kw == "End") {
        in_.expect_tokens(1, "End");
        if (in_.next_line()) in_.fail("text after End: " + quote(in_.token(0)));
        skipped_.finish(in_, {mesh_.vertices.size(), mesh_.edges.size(), mesh_.triangles.size(), quads_.size()});
        return std::move(mesh_);
      } else {
        if (quadrilaterals_) {
          io::medit_refuse_keyword(in_, kw, "3D surface reader", kSurfaceKeywords);
        } else {
          io::medit_refuse_keyword(in_, kw, "3D reader", kKeptKeywords);
        }
      }
    }
    in_.fail_at(std::max<std::uint64_t>(in_.line(), 1), "file ends before End (truncated?)");
  }

 private:
  void begin_cells(std::string_view kw, bool have_vertices, bool& have_section) {
    if (!have_vertices) in_.fail(std::string(kw) + " before Vertices");
    if (have_section) in_.fail("second " + std::string(kw) + " section");
    have_section = true;
  }

  void read_vertices() {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    const std::uint64_t n = io::medit_section_count(in_, "Vertices");
    for (std::uint64_t i = 0; i < n; ++i) {
      io::medit_next_entry(in_, "Vertices", i, n);
      const std::string what = "vertex " + std::to_string(i + 1);
      in_.expect_tokens(4, what + " (x y z ref)");
      double c[3];
      for (std::size_t k = 0; k < 3; ++k) {
        c[k] = in_.real(k, what + kAxes[k]);
        io::check_coordinate(in_, c[k], what + kAxes[k]);
      }
      mesh_.vertices.push_back(Vec3{c[0], c[1], c[2]});
      mesh_.vertex_refs.push_back(io::int_field(in_, 3, what + " reference"));
    }
  }

  template <std::size_t N>
  void read_cells(std::string_view kw, std::string_view noun, std::vector<std::array<std::uint32_t, N>>& cells,
                  std::vector<int>& refs) {
    static constexpr const char* kFields[] = {"", "", " (v1 v2 ref)", " (v1 v2 v3 ref)", " (v1 v2 v3 v4 ref)"};
    const std::uint64_t n = io::medit_section_count(in_, kw);
    const std::uint64_t nv = mesh_.vertices.size();
    for (std::uint64_t i = 0; i < n; ++i) {
      io::medit_next_entry(in_, kw, i, n);
      const std::string what = std::string(noun) + " " + std::to_string(i + 1);
      in_.expect_tokens(N + 1, what + kFields[N]);
      std::array<std::uint32_t, N> cell{};
      for (std::size_t k = 0; k < N; ++k) cell[k] = io::vertex_number(in_, k, 1, nv, what);
      if constexpr (N == 4) {
        if (noun == "tetrahedron" && tetrahedra_ == NonPositiveTetrahedra::Refuse) check_positive(cell, what);
      }
      cells.push_back(cell);
      refs.push_back(io::int_field(in_, N, what + " reference"));
    }
  }

  // Medit's tetrahedra are positive; a negative or flat one is refused rather than reordered, so
  // that what is read is what the file says.
  void check_positive(const std::array<std::uint32_t, 4>& t, const std::string& what) const {
    const std::vector<Vec3>& v = mesh_.vertices;
    const Sign s = uncounted::orient3d(v[t[0]], v[t[1]], v[t[2]], v[t[3]]);
    if (s == Sign::Negative) {
      in_.fail(what + " is negatively oriented (Medit's tetrahedra have orient3d(v1, v2, v3, v4) > 0)");
    }
    if (s == Sign::Zero) in_.fail(what + " is flat: its four vertices are coplanar");
  }

  LineTokenizer in_;
  io::MeditSkippedSections skipped_{3};
  bool quadrilaterals_ = false;
  NonPositiveTetrahedra tetrahedra_ = NonPositiveTetrahedra::Refuse;
  MeshData3 mesh_;
  std::vector<std::array<std::uint32_t, 4>> quads_;
  std::vector<int> quad_refs_;
};

}  // namespace

MeshData3 read_medit3(std::istream& in, const std::string& file_name, std::vector<std::string>* notes,
                      NonPositiveTetrahedra tetrahedra) {
  Medit3Reader reader(in, file_name, false, tetrahedra);
  MeshData3 mesh = reader.read();
  io::deliver_notes(reader.notes(), file_name, notes);
  return mesh;
}

MeshData3 read_medit3(const std::string& path, std::vector<std::string>* notes, NonPositiveTetrahedra tetrahedra) {
  std::ifstream in = io::open_for_reading(path);
  return read_medit3(in, path, notes, tetrahedra);
}

Plc3 read_medit3_surface(std::istream& in, const std::string& file_name, std::vector<std::string>* notes) {
  Medit3Reader reader(in, file_name, true);
  MeshData3 mesh = reader.read();
  io::deliver_notes(reader.notes(), file_name, notes);
  if (!mesh.tetrahedra.empty()) {
    throw InputError(file_name + " has " + std::to_string(mesh.tetrahedra.size()) +
                     " tetrahedra: a volume mesh, where a surface (Vertices, Triangles, Quadrilaterals, Edges) is "
                     "expected");
  }
  Plc3 plc;
  plc.vertices = std::move(mesh.vertices);
  plc.vertex_markers = std::move(mesh.vertex_refs);
  plc.facets.reserve(mesh.triangles.size() + reader.quads().size() + mesh.edges.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    plc.facets.push_back({{{t[0], t[1], t[2]}}, {}, mesh.triangle_refs[i]});
  }
  for (std::size_t i = 0; i < reader.quads().size(); ++i) {
    const auto& q = reader.quads()[i];
    plc.facets.push_back({{{q[0], q[1], q[2], q[3]}}, {}, reader.quad_refs()[i]});
  }
  for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
    const auto& e = mesh.edges[i];
    plc.facets.push_back({{{e[0], e[1]}}, {}, mesh.edge_refs[i]});
  }
  return plc;
}

Plc3 read_medit3_surface(const std::string& path, std::vector<std::string>* notes) {
  std::ifstream in = io::open_for_reading(path);
  return read_medit3_surface(in, path, notes);
}

void write_medit3(std::ostream& out, const MeshData3& mesh) {
  const std::size_t nv = mesh.vertices.size();
  io::check_refs(mesh.vertex_refs, nv, "vertex");
  io::check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  io::check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");
  io::check_cells(mesh.tetrahedra, mesh.tetrahedron_refs, nv, "tetrahedron");

  std::string text = "MeshVersionFormatted 2\n\nDimension 3\n";
  if (nv > 0) {
    text += "\nVertices\n";
    io::append_integer(text, static_cast<std::int64_t>(nv));
    text += "\n";
    for (std::size_t i = 0; i < nv; ++i) {
      for (double c : {mesh.vertices[i].x, mesh.vertices[i].y, mesh.vertices[i].z}) {
        io::append_real(text, c);
        text += ' ';
      }
      io::append_integer(text, mesh.vertex_refs.empty() ? 0 : mesh.vertex_refs[i]);
      text += '\n';
    }
  }
  io::append_medit_cells(text, "Edges", mesh.edges, mesh.edge_refs);
  io::append_medit_cells(text, "Triangles", mesh.triangles, mesh.triangle_refs);
  io::append_medit_cells(text, "Tetrahedra", mesh.tetrahedra, mesh.tetrahedron_refs);
  text += "\nEnd\n";
  out << text;
}

void write_medit3(const std::string& path, const MeshData3& mesh) {
  std::ofstream out = io::open_for_writing(path);
  write_medit3(out, mesh);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
