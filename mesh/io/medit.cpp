#include "mesh/io/medit.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string_view>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

// Medit keywords that a 2D triangle mesh does not carry here: named so that the message can say
// "not supported" rather than "unknown".
constexpr std::array<std::string_view, 21> kOtherMeditKeywords = {
    "Corners",          "Ridges",           "RequiredVertices", "RequiredEdges",
    "RequiredTriangles", "Quadrilaterals",  "Tetrahedra",       "Hexahedra",
    "Prisms",           "Pyramids",         "Normals",          "NormalAtVertices",
    "Tangents",         "TangentAtVertices", "Geometry",        "Identifier",
    "Crack",            "Polygons",         "SubDomainFromMesh", "VertexOnGeometricVertex",
    "EdgeOnGeometricEdge"};

bool is_section_keyword(std::string_view t) {
  return t == "Vertices" || t == "Edges" || t == "Triangles" || t == "End" || t == "Dimension" ||
         t == "MeshVersionFormatted" ||
         std::find(kOtherMeditKeywords.begin(), kOtherMeditKeywords.end(), t) != kOtherMeditKeywords.end();
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

class MeditReader {
 public:
  MeditReader(std::istream& in, const std::string& name) : in_(in, name) {}

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
        const std::int64_t v = value_after_keyword("MeshVersionFormatted");
        if (v < 1 || v > 4) in_.fail("MeshVersionFormatted " + std::to_string(v) + " is not 1, 2, 3 or 4");
        have_version = true;
      } else if (kw == "Dimension") {
        if (have_dimension) in_.fail("second Dimension");
        const std::int64_t d = value_after_keyword("Dimension");
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
      } else if (kw == "End") {
        in_.expect_tokens(1, "End");
        if (in_.next_line()) in_.fail("text after End: " + quote(in_.token(0)));
        return std::move(mesh_);
      } else {
        unknown_keyword(kw);
      }
    }
    in_.fail_at(std::max<std::uint64_t>(in_.line(), 1), "file ends before End (truncated?)");
  }

 private:
  [[noreturn]] void unknown_keyword(std::string_view kw) const {
    if (std::find(kOtherMeditKeywords.begin(), kOtherMeditKeywords.end(), kw) != kOtherMeditKeywords.end()) {
      in_.fail("Medit keyword " + quote(kw) +
               " is not supported by the 2D reader (it keeps Vertices, Edges and Triangles)");
    }
    for (std::string_view known : {"MeshVersionFormatted", "Dimension", "Vertices", "Edges", "Triangles", "End"}) {
      if (iequals(kw, known)) {
        in_.fail("unknown keyword " + quote(kw) + " (keywords are case-sensitive: " + std::string(known) + ")");
      }
    }
    if (!kw.empty() && ((kw[0] >= '0' && kw[0] <= '9') || kw[0] == '-' || kw[0] == '+' || kw[0] == '.')) {
      in_.fail("expected a keyword, found the number " + quote(kw) + " (more entries than the section's count?)");
    }
    in_.fail("unknown keyword " + quote(kw));
  }

  // The integer after a keyword, on the keyword's line or alone on the next one.
  std::int64_t value_after_keyword(std::string_view kw) {
    if (in_.size() >= 2) {
      in_.expect_tokens(2, kw);
      return in_.integer(1, std::string(kw) + " value");
    }
    const std::uint64_t keyword_line = in_.line();
    if (!in_.next_line() || is_section_keyword(in_.token(0))) {
      in_.fail_at(keyword_line, "missing value after " + std::string(kw));
    }
    in_.expect_tokens(1, std::string(kw) + " value");
    return in_.integer(0, std::string(kw) + " value");
  }

  std::uint64_t section_count(std::string_view kw) {
    if (in_.size() >= 2) {
      in_.expect_tokens(2, kw);
      return in_.count(1, std::string(kw) + " count");
    }
    const std::uint64_t keyword_line = in_.line();
    if (!in_.next_line() || is_section_keyword(in_.token(0))) {
      in_.fail_at(keyword_line, "missing count after " + std::string(kw));
    }
    in_.expect_tokens(1, std::string(kw) + " count");
    return in_.count(0, std::string(kw) + " count");
  }

  // Moves to entry i (0-based) of a section of n entries, with messages for a short section.
  void next_entry(std::string_view kw, std::uint64_t i, std::uint64_t n) {
    const std::uint64_t last = in_.line();
    if (!in_.next_line()) {
      in_.fail_at(std::max<std::uint64_t>(last, 1), "file ends in " + std::string(kw) + " after " +
                                                        std::to_string(i) + " of " + std::to_string(n) +
                                                        " entries (truncated?)");
    }
    if (is_section_keyword(in_.token(0))) {
      in_.fail(std::string(kw) + " count is " + std::to_string(n) + " but only " + std::to_string(i) +
               " entries precede " + quote(in_.token(0)));
    }
  }

  int reference(std::size_t k, const std::string& what) {
    const std::int64_t r = in_.integer(k, what);
    if (r < std::numeric_limits<int>::min() || r > std::numeric_limits<int>::max()) {
      in_.fail(what + " " + std::to_string(r) + " does not fit an int");
    }
    return static_cast<int>(r);
  }

  void read_vertices() {
    const std::uint64_t n = section_count("Vertices");
    for (std::uint64_t i = 0; i < n; ++i) {
      next_entry("Vertices", i, n);
      const std::string what = "vertex " + std::to_string(i + 1);
      in_.expect_tokens(3, what + " (x y ref)");
      const Vec2 p{in_.real(0, what + " x"), in_.real(1, what + " y")};
      io::check_coordinate(in_, p.x, what + " x");
      io::check_coordinate(in_, p.y, what + " y");
      mesh_.vertices.push_back(p);
      mesh_.vertex_refs.push_back(reference(2, what + " reference"));
    }
  }

  template <std::size_t N>
  void read_cells(std::string_view kw, std::string_view noun, std::vector<std::array<std::uint32_t, N>>& cells,
                  std::vector<int>& refs) {
    const std::uint64_t n = section_count(kw);
    const std::uint64_t nv = mesh_.vertices.size();
    for (std::uint64_t i = 0; i < n; ++i) {
      next_entry(kw, i, n);
      const std::string what = std::string(noun) + " " + std::to_string(i + 1);
      in_.expect_tokens(N + 1, what + (N == 2 ? " (v1 v2 ref)" : " (v1 v2 v3 ref)"));
      std::array<std::uint32_t, N> cell{};
      for (std::size_t k = 0; k < N; ++k) {
        const std::int64_t v = in_.integer(k, what + " vertex");
        if (v < 1 || static_cast<std::uint64_t>(v) > nv) {
          in_.fail(what + ": vertex number " + std::to_string(v) + " out of range 1.." + std::to_string(nv));
        }
        cell[k] = static_cast<std::uint32_t>(v - 1);
      }
      cells.push_back(cell);
      refs.push_back(reference(N, what + " reference"));
    }
  }

  LineTokenizer in_;
  MeshData2 mesh_;
};

template <std::size_t N>
void check_cells(const std::vector<std::array<std::uint32_t, N>>& cells, const std::vector<int>& refs,
                 std::size_t nv, const char* noun) {
  if (!refs.empty() && refs.size() != cells.size()) {
    throw InputError(std::string(noun) + " references: " + std::to_string(refs.size()) + " for " +
                     std::to_string(cells.size()) + " elements");
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::uint32_t v : cells[i]) {
      if (v >= nv) {
        throw InputError(std::string(noun) + " " + std::to_string(i) + ": vertex " + std::to_string(v) +
                             " out of range (" + std::to_string(nv) + " vertices)",
                         {i});
      }
    }
  }
}

template <std::size_t N>
void append_cells(std::string& out, const char* keyword, const std::vector<std::array<std::uint32_t, N>>& cells,
                  const std::vector<int>& refs) {
  if (cells.empty()) return;
  out += "\n";
  out += keyword;
  out += "\n";
  io::append_integer(out, static_cast<std::int64_t>(cells.size()));
  out += "\n";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::uint32_t v : cells[i]) {
      io::append_integer(out, static_cast<std::int64_t>(v) + 1);
      out += ' ';
    }
    io::append_integer(out, refs.empty() ? 0 : refs[i]);
    out += '\n';
  }
}

}  // namespace

MeshData2 read_medit2(std::istream& in, const std::string& file_name) {
  return MeditReader(in, file_name).read();
}

MeshData2 read_medit2(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_medit2(in, path);
}

void write_medit2(std::ostream& out, const MeshData2& mesh) {
  const std::size_t nv = mesh.vertices.size();
  if (!mesh.vertex_refs.empty() && mesh.vertex_refs.size() != nv) {
    throw InputError("vertex references: " + std::to_string(mesh.vertex_refs.size()) + " for " +
                     std::to_string(nv) + " vertices");
  }
  check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");

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
  append_cells(text, "Edges", mesh.edges, mesh.edge_refs);
  append_cells(text, "Triangles", mesh.triangles, mesh.triangle_refs);
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
