// Medit binary meshes (.meshb): libMeshb's GMF keywords in binary, read and written for the 2D
// and 3D subsets of the ASCII readers (see medit_binary.hpp).
#include "mesh/io/medit_binary.hpp"

#include <array>
#include <iterator>
#include <limits>
#include <type_traits>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/binary_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

// libMeshb's keyword codes (enum GmfKwdCod).
constexpr std::int64_t kDimension = 3;
constexpr std::int64_t kVertices = 4;
constexpr std::int64_t kEdges = 5;
constexpr std::int64_t kTriangles = 6;
constexpr std::int64_t kTetrahedra = 8;
constexpr std::int64_t kEnd = 54;

std::string keyword_name(std::int64_t code) {
  switch (code) {
    case 1: return " (MeshVersionFormatted)";
    case 7: return " (Quadrilaterals)";
    case 9: return " (Prisms)";
    case 10: return " (Hexahedra)";
    case 13: return " (Corners)";
    case 14: return " (Ridges)";
    case 15: return " (RequiredVertices)";
    case 16: return " (RequiredEdges)";
    case 17: return " (RequiredTriangles)";
    case 20: return " (NormalAtVertices)";
    case 60: return " (Normals)";
    case 62: return " (SolAtVertices: a solution, read it as .solb)";
    default: return "";
  }
}

// The version's word sizes.
struct Layout {
  std::size_t position = 4;  // next-keyword offset
  std::size_t integer = 4;   // counts, vertex numbers, references
  std::size_t real = 8;
};

Layout layout_of(std::int64_t version) {
  return {version >= 3 ? std::size_t{8} : 4, version == 4 ? std::size_t{8} : 4, version == 1 ? std::size_t{4} : 8};
}

template <class Mesh>
class MeshbReader {
 public:
  static constexpr int kDim = std::is_same_v<Mesh, MeshData3> ? 3 : 2;

  MeshbReader(std::string_view bytes, const std::string& name,
              NonPositiveTetrahedra tetrahedra = NonPositiveTetrahedra::Refuse)
      : in_(bytes, name), tetrahedra_(tetrahedra) {}

  // Reads the header and stops after the Dimension keyword (only_dimension) or reads it all.
  Mesh read(int* dimension_only = nullptr) {
    const std::int64_t version = header();
    bool have_dimension = false;
    bool have_vertices = false;
    std::array<bool, 9> have{};
    std::size_t at = 8;
    // Each keyword moves `at` forward by at least its header, so the loop ends with the bytes.
    while (true) {
      const std::size_t start = at;
      if (at == in_.size()) in_.fail(at, "file ends before End (truncated?)");
      in_.need(at, 4 + lay_.position, "a keyword header");
      const std::int64_t kw = in_.signed32(at);
      const std::uint64_t next = in_.load(at + 4, lay_.position);
      at += 4 + lay_.position;
      if (kw == kDimension) {
        if (have_dimension) in_.fail(start, "second Dimension");
        in_.need(at, 4, "Dimension");
        const std::int64_t d = in_.signed32(at);
        if (dimension_only != nullptr && (d == 2 || d == 3)) {
          *dimension_only = static_cast<int>(d);
          return {};
        }
        if (d == 3 && kDim == 2) in_.fail(at, "Dimension 3: this is a 3D mesh, and this reader reads 2D meshes only");
        if (d == 2 && kDim == 3) in_.fail(at, "Dimension 2: this is a 2D mesh, and this reader reads 3D meshes only");
        if (d != kDim) in_.fail(at, "Dimension " + std::to_string(d) + " is not " + std::to_string(kDim));
        at += 4;
        have_dimension = true;
      } else if (kw == kVertices || kw == kEdges || kw == kTriangles || (kw == kTetrahedra && kDim == 3)) {
        if (dimension_only != nullptr) in_.fail(start, "no Dimension before the first section");
        const char* name = kw == kVertices ? "Vertices" : kw == kEdges ? "Edges" : kw == kTriangles ? "Triangles" : "Tetrahedra";
        if (kw == kVertices && !have_dimension) in_.fail(start, "Vertices before Dimension");
        if (kw != kVertices && !have_vertices) in_.fail(start, std::string(name) + " before Vertices");
        if (have[static_cast<std::size_t>(kw)]) in_.fail(start, std::string("second ") + name + " section");
        have[static_cast<std::size_t>(kw)] = true;
        if (kw == kVertices) {
          at = read_vertices(at);
          have_vertices = true;
        } else if (kw == kEdges) {
          at = read_cells<2>(at, "Edges", "edge", mesh_.edges, mesh_.edge_refs);
        } else if (kw == kTriangles) {
          at = read_cells<3>(at, "Triangles", "triangle", mesh_.triangles, mesh_.triangle_refs);
        } else if constexpr (kDim == 3) {
          at = read_cells<4>(at, "Tetrahedra", "tetrahedron", mesh_.tetrahedra, mesh_.tetrahedron_refs);
        }
      } else if (kw == kEnd) {
        if (dimension_only != nullptr) in_.fail(start, "End before Dimension");
        if (at != in_.size()) in_.fail(at, std::to_string(in_.size() - at) + " bytes after End");
        (void)version;
        return std::move(mesh_);
      } else {
        in_.fail(start, "keyword code " + std::to_string(kw) + keyword_name(kw) + " is not supported by the " +
                            std::to_string(kDim) + "D reader (it keeps Vertices, Edges, Triangles" +
                            (kDim == 3 ? ", Tetrahedra" : "") + ")");
      }
      if (next != at) {
        in_.fail(start + 4, "next-keyword offset " + std::to_string(next) +
                                " is not where the next keyword begins (byte " + std::to_string(at) + ")");
      }
    }
  }

 private:
  std::int64_t header() {
    in_.need(0, 8, "the header (endianness word and version)");
    const std::uint64_t code = in_.load(0, 4);
    if (code != 1) {
      in_.set_swapped(true);
      if (in_.load(0, 4) != 1) in_.fail(0, "first word " + std::to_string(code) + " is not 1: not a binary Medit file");
    }
    const std::int64_t version = in_.signed32(4);
    if (version < 1 || version > 4) in_.fail(4, "version " + std::to_string(version) + " is not 1, 2, 3 or 4");
    lay_ = layout_of(version);
    return version;
  }

  std::uint64_t read_count(std::size_t at, const char* kw, std::uint64_t entry_bytes) {
    in_.need(at, lay_.integer, std::string(kw) + " count");
    const std::int64_t n = in_.signed_word(at, lay_.integer);
    if (n < 0) in_.fail(at, std::string(kw) + " count " + std::to_string(n) + " is negative");
    if (static_cast<std::uint64_t>(n) > std::numeric_limits<std::uint32_t>::max()) {
      in_.fail(at, std::string(kw) + " count " + std::to_string(n) + " exceeds the 32-bit index range");
    }
    in_.need_items(at + lay_.integer, static_cast<std::uint64_t>(n), entry_bytes, kw);
    return static_cast<std::uint64_t>(n);
  }

  int reference(std::size_t at, const std::string& what) const {
    const std::int64_t r = in_.signed_word(at, lay_.integer);
    if (r < std::numeric_limits<int>::min() || r > std::numeric_limits<int>::max()) {
      in_.fail(at, what + " reference " + std::to_string(r) + " does not fit an int");
    }
    return static_cast<int>(r);
  }

  std::size_t read_vertices(std::size_t at) {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    const std::uint64_t n = read_count(at, "Vertices", kDim * lay_.real + lay_.integer);
    at += lay_.integer;
    mesh_.vertices.resize(n);
    mesh_.vertex_refs.resize(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string what = "vertex " + std::to_string(i + 1);
      double c[3] = {0, 0, 0};
      for (int k = 0; k < kDim; ++k) {
        c[k] = in_.real(at, lay_.real);
        if (!coordinate_in_range(c[k])) in_.fail(at, what + kAxes[k] + " is " + coordinate_problem(c[k]));
        at += lay_.real;
      }
      if constexpr (kDim == 3) {
        mesh_.vertices[i] = Vec3{c[0], c[1], c[2]};
      } else {
        mesh_.vertices[i] = Vec2{c[0], c[1]};
      }
      mesh_.vertex_refs[i] = reference(at, what);
      at += lay_.integer;
    }
    return at;
  }

  template <std::size_t N>
  std::size_t read_cells(std::size_t at, const char* kw, const char* noun,
                         std::vector<std::array<std::uint32_t, N>>& cells, std::vector<int>& refs) {
    const std::uint64_t n = read_count(at, kw, (N + 1) * lay_.integer);
    at += lay_.integer;
    const std::uint64_t nv = mesh_.vertices.size();
    cells.resize(n);
    refs.resize(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string what = std::string(noun) + " " + std::to_string(i + 1);
      for (std::size_t k = 0; k < N; ++k) {
        const std::int64_t v = in_.signed_word(at, lay_.integer);
        if (v < 1 || static_cast<std::uint64_t>(v) > nv) {
          in_.fail(at, what + ": vertex number " + std::to_string(v) +
                           (nv == 0 ? ", but there are no vertices" : " out of range 1.." + std::to_string(nv)));
        }
        cells[i][k] = static_cast<std::uint32_t>(v - 1);
        at += lay_.integer;
      }
      if constexpr (N == 4 && kDim == 3) {
        const auto& p = mesh_.vertices;
        const auto& t = cells[i];
        const Sign s = tetrahedra_ == NonPositiveTetrahedra::Keep
                           ? Sign::Positive
                           : uncounted::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
        if (s == Sign::Negative) {
          in_.fail(at, what + " is negatively oriented (Medit's tetrahedra have orient3d(v1, v2, v3, v4) > 0)");
        }
        if (s == Sign::Zero) in_.fail(at, what + " is flat: its four vertices are coplanar");
      }
      refs[i] = reference(at, what);
      at += lay_.integer;
    }
    return at;
  }

  io::BinaryInput in_;
  NonPositiveTetrahedra tetrahedra_ = NonPositiveTetrahedra::Refuse;
  Layout lay_;
  Mesh mesh_;
};

std::string slurp(std::istream& in, const std::string& file_name) {
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ParseError(file_name, 0, "read error");
  return bytes;
}

// One keyword: code, next offset (filled in by finish()), data.
class MeshbWriter {
 public:
  explicit MeshbWriter(int version) : lay_(layout_of(version)), version_(version) {
    if (version < 2 || version > 4) {
      throw InputError("binary Medit version " + std::to_string(version) + " is not 2, 3 or 4 (version 1 stores floats)");
    }
    io::store_le(bytes_, 1, 4);
    io::store_le(bytes_, static_cast<std::uint64_t>(version), 4);
  }

  void begin(std::int64_t code) {
    close();
    io::store_le(bytes_, static_cast<std::uint64_t>(code), 4);
    open_ = bytes_.size();
    io::store_le(bytes_, 0, lay_.position);
  }
  void integer(std::int64_t v) { io::store_le(bytes_, static_cast<std::uint64_t>(v), lay_.integer); }
  void small(std::int64_t v) { io::store_le(bytes_, static_cast<std::uint64_t>(v), 4); }
  void real(double v) { io::store_le_real(bytes_, v); }

  void count(std::size_t n, const char* kw) {
    if (lay_.integer == 4 && n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
      throw InputError(std::string("binary Medit version ") + std::to_string(version_) + " counts in 32 bits; " + kw +
                       " has " + std::to_string(n) + " entries (use version 4)");
    }
    integer(static_cast<std::int64_t>(n));
  }

  template <std::size_t N>
  void cells(std::int64_t code, const char* kw, const std::vector<std::array<std::uint32_t, N>>& cells,
             const std::vector<int>& refs) {
    if (cells.empty()) return;
    begin(code);
    count(cells.size(), kw);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      for (std::uint32_t v : cells[i]) integer(static_cast<std::int64_t>(v) + 1);
      integer(refs.empty() ? 0 : refs[i]);
    }
  }

  void finish(std::ostream& out) {
    begin(kEnd);
    open_ = std::string::npos;  // End's offset stays 0
    if (lay_.position == 4 && bytes_.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
      throw InputError("binary Medit version 2 has 32-bit offsets; this mesh needs " + std::to_string(bytes_.size()) +
                       " bytes (use version 3)");
    }
    out.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
  }

 private:
  // Sets the open keyword's next offset to the current end.
  void close() {
    if (open_ == std::string::npos) return;
    std::string word;
    io::store_le(word, bytes_.size(), lay_.position);
    bytes_.replace(open_, lay_.position, word);
    open_ = std::string::npos;
  }

  Layout lay_;
  int version_;
  std::string bytes_;
  std::size_t open_ = std::string::npos;
};

template <class Mesh>
void write_meshb(std::ostream& out, const Mesh& mesh, int version) {
  constexpr int kDim = std::is_same_v<Mesh, MeshData3> ? 3 : 2;
  const std::size_t nv = mesh.vertices.size();
  io::check_refs(mesh.vertex_refs, nv, "vertex");
  io::check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  io::check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");
  if constexpr (kDim == 3) io::check_cells(mesh.tetrahedra, mesh.tetrahedron_refs, nv, "tetrahedron");

  MeshbWriter w(version);
  w.begin(kDimension);
  w.small(kDim);
  if (nv > 0) {
    w.begin(kVertices);
    w.count(nv, "Vertices");
    for (std::size_t i = 0; i < nv; ++i) {
      w.real(mesh.vertices[i].x);
      w.real(mesh.vertices[i].y);
      if constexpr (kDim == 3) w.real(mesh.vertices[i].z);
      w.integer(mesh.vertex_refs.empty() ? 0 : mesh.vertex_refs[i]);
    }
  }
  w.cells(kEdges, "Edges", mesh.edges, mesh.edge_refs);
  w.cells(kTriangles, "Triangles", mesh.triangles, mesh.triangle_refs);
  if constexpr (kDim == 3) w.cells(kTetrahedra, "Tetrahedra", mesh.tetrahedra, mesh.tetrahedron_refs);
  w.finish(out);
}

template <class Mesh>
void write_meshb_file(const std::string& path, const Mesh& mesh, int version) {
  std::ofstream out = io::open_for_writing(path);
  write_meshb(out, mesh, version);
  out.flush();
  io::check_written(out, path);
}

std::string slurp_file(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return slurp(in, path);
}

}  // namespace

bool is_medit_binary(std::string_view bytes) noexcept {
  if (bytes.size() < 4) return false;
  const bool little = bytes[0] == 1 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0;
  const bool big = bytes[0] == 0 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 1;
  return little || big;
}

int medit_binary_dimension(std::string_view bytes, const std::string& file_name) {
  int d = 0;
  MeshbReader<MeshData3>(bytes, file_name).read(&d);
  return d;
}

int medit_binary_dimension(const std::string& path) { return medit_binary_dimension(slurp_file(path), path); }

MeshData2 read_meshb2(std::istream& in, const std::string& file_name) {
  const std::string bytes = slurp(in, file_name);
  return MeshbReader<MeshData2>(bytes, file_name).read();
}

MeshData2 read_meshb2(const std::string& path) {
  const std::string bytes = slurp_file(path);
  return MeshbReader<MeshData2>(bytes, path).read();
}

MeshData3 read_meshb3(std::istream& in, const std::string& file_name, NonPositiveTetrahedra tetrahedra) {
  const std::string bytes = slurp(in, file_name);
  return MeshbReader<MeshData3>(bytes, file_name, tetrahedra).read();
}

MeshData3 read_meshb3(const std::string& path, NonPositiveTetrahedra tetrahedra) {
  const std::string bytes = slurp_file(path);
  return MeshbReader<MeshData3>(bytes, path, tetrahedra).read();
}

void write_meshb2(std::ostream& out, const MeshData2& mesh, int version) { write_meshb(out, mesh, version); }
void write_meshb2(const std::string& path, const MeshData2& mesh, int version) { write_meshb_file(path, mesh, version); }
void write_meshb3(std::ostream& out, const MeshData3& mesh, int version) { write_meshb(out, mesh, version); }
void write_meshb3(const std::string& path, const MeshData3& mesh, int version) { write_meshb_file(path, mesh, version); }

}  // namespace dtlab
