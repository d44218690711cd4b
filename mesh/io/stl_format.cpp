#include "mesh/io/stl_format.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFirstFacet = 84;
constexpr std::size_t kFacetBytes = 50;

std::uint32_t load_u32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  return v;
}

void store_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xff);
}

bool iequals(std::string_view a, std::string_view b) {
  auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

bool begins_with_solid(std::string_view bytes) {
  const std::size_t start = bytes.find_first_not_of(" \t\r\n\v\f");
  if (start == std::string_view::npos) return false;
  return bytes.size() - start >= 5 && iequals(bytes.substr(start, 5), "solid");
}

std::uint64_t binary_size_for(std::string_view bytes) {
  return kFirstFacet + kFacetBytes * static_cast<std::uint64_t>(load_u32(bytes, kHeaderBytes));
}

// Vertices merged when their coordinates are bitwise identical; numbered by first appearance.
class VertexMerger {
 public:
  explicit VertexMerger(MeshData3& mesh) : mesh_(mesh) {}

  std::uint32_t index(const Vec3& p) {
    const Key key{std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y), std::bit_cast<std::uint64_t>(p.z)};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (inserted) {
      if (mesh_.vertices.size() == std::numeric_limits<std::uint32_t>::max()) {
        throw InputError("more distinct STL vertices than a 32-bit index can number");
      }
      mesh_.vertices.push_back(p);
      mesh_.vertex_refs.push_back(0);
    }
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = 0x9e3779b97f4a7c15ULL;
      for (std::uint64_t v : k) h = (h ^ v) * 0xff51afd7ed558ccdULL + (h >> 29);
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  MeshData3& mesh_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

class AsciiStlReader {
 public:
  AsciiStlReader(std::istream& in, const std::string& name) : in_(in, name), merger_(mesh_) {}

  MeshData3 read() {
    if (!in_.next_line()) in_.fail_at(1, "empty file: an ASCII STL begins with 'solid'");
    int solid = 0;
    do {
      if (!iequals(in_.token(0), "solid")) {
        in_.fail("expected 'solid' (the start of solid " + std::to_string(solid) + "), found " + quote(in_.token(0)));
      }
      read_solid(solid);
      ++solid;
    } while (in_.next_line());
    return std::move(mesh_);
  }

 private:
  // Moves to the next line, which must begin with `keyword` and have `fields` tokens.
  void expect_line(std::string_view keyword, std::size_t fields, const std::string& what) {
    next(what);
    if (!iequals(in_.token(0), keyword)) {
      in_.fail(what + ": expected " + quote(keyword) + ", found " + quote(in_.token(0)));
    }
    in_.expect_tokens(fields, what + " (" + std::string(keyword) + " line)");
  }

  void next(const std::string& what) {
    const std::uint64_t last = in_.line();
    if (!in_.next_line()) in_.fail_at(last, "file ends in " + what + " (truncated?)");
  }

  void read_solid(int solid) {
    const std::string solid_name = "solid " + std::to_string(solid);
    for (;;) {
      next(solid_name + " before its endsolid");
      if (iequals(in_.token(0), "endsolid")) return;
      const std::string what = "facet " + std::to_string(facet_count_);
      if (!iequals(in_.token(0), "facet")) {
        in_.fail("expected 'facet normal' or 'endsolid' in " + solid_name + ", found " + quote(in_.token(0)));
      }
      if (in_.size() < 2 || !iequals(in_.token(1), "normal")) in_.fail(what + ": expected 'facet normal nx ny nz'");
      in_.expect_tokens(5, what + " (facet normal nx ny nz)");
      expect_line("outer", 2, what);
      if (!iequals(in_.token(1), "loop")) in_.fail(what + ": expected 'outer loop', found " + quote(in_.token(1)));
      std::array<std::uint32_t, 3> t{};
      for (std::size_t k = 0; k < 3; ++k) {
        next(what);
        if (iequals(in_.token(0), "endloop")) {
          in_.fail(what + " has " + std::to_string(k) + " vertices; an STL facet has 3");
        }
        t[k] = merger_.index(vertex(what + " vertex " + std::to_string(k + 1)));
      }
      next(what);
      if (iequals(in_.token(0), "vertex")) in_.fail(what + " has more than 3 vertices; an STL facet has 3");
      if (!iequals(in_.token(0), "endloop")) in_.fail(what + ": expected 'endloop', found " + quote(in_.token(0)));
      in_.expect_tokens(1, what + " (endloop line)");
      expect_line("endfacet", 1, what);
      mesh_.triangles.push_back(t);
      mesh_.triangle_refs.push_back(solid);
      ++facet_count_;
    }
  }

  Vec3 vertex(const std::string& what) {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    if (!iequals(in_.token(0), "vertex")) in_.fail(what + ": expected 'vertex x y z', found " + quote(in_.token(0)));
    in_.expect_tokens(4, what + " (vertex x y z)");
    double c[3];
    for (std::size_t k = 0; k < 3; ++k) {
      c[k] = in_.real(1 + k, what + kAxes[k]);
      io::check_coordinate(in_, c[k], what + kAxes[k]);
    }
    return {c[0], c[1], c[2]};
  }

  LineTokenizer in_;
  MeshData3 mesh_;
  VertexMerger merger_;
  std::uint64_t facet_count_ = 0;  // over all solids, to name facets uniquely
};

MeshData3 read_binary_stl(std::string_view bytes, const std::string& file_name) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  const std::uint32_t n = load_u32(bytes, kHeaderBytes);
  MeshData3 mesh;
  VertexMerger merger(mesh);
  for (std::uint32_t f = 0; f < n; ++f) {
    const std::size_t facet = kFirstFacet + kFacetBytes * static_cast<std::size_t>(f);
    std::array<std::uint32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      double c[3];
      for (std::size_t a = 0; a < 3; ++a) {
        const std::size_t at = facet + 12 + 12 * k + 4 * a;
        c[a] = static_cast<double>(std::bit_cast<float>(load_u32(bytes, at)));
        if (!coordinate_in_range(c[a])) {
          throw ParseError(file_name, at,
                           "at byte " + std::to_string(at) + ": facet " + std::to_string(f) + " vertex " +
                               std::to_string(k + 1) + " " + kAxes[a] + " is " + coordinate_problem(c[a]));
        }
      }
      t[k] = merger.index({c[0], c[1], c[2]});
    }
    mesh.triangles.push_back(t);
  }
  mesh.triangle_refs.assign(mesh.triangles.size(), 0);
  return mesh;
}

void check_surface_only(const MeshData3& mesh) {
  if (!mesh.edges.empty() || !mesh.tetrahedra.empty()) {
    throw InputError("STL holds triangles only; this mesh has " + std::to_string(mesh.edges.size()) + " edges and " +
                     std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
  }
  io::check_cells(mesh.triangles, {}, mesh.vertices.size(), "triangle");
}

// A unit normal computed in doubles (a construction, used by viewers only), or 0 for a flat triangle.
Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double length = norm(n);
  if (!(length > 0.0) || !std::isfinite(length)) return {0.0, 0.0, 0.0};
  return (1.0 / length) * n;
}

void write_ascii(std::ostream& out, const MeshData3& mesh) {
  std::string text = "solid dtlab\n";
  auto append_vec = [&](const Vec3& p) {
    for (double c : {p.x, p.y, p.z}) {
      text += ' ';
      io::append_real(text, c);
    }
  };
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    text += "  facet normal";
    append_vec(unit_normal(a, b, c));
    text += "\n    outer loop\n";
    for (const Vec3* p : {&a, &b, &c}) {
      text += "      vertex";
      append_vec(*p);
      text += '\n';
    }
    text += "    endloop\n  endfacet\n";
  }
  text += "endsolid dtlab\n";
  out << text;
}

// Exactly representable as float32 (checked before converting: a double beyond the float range
// has no defined conversion).
bool is_float(double c) {
  if (std::isnan(c) || std::fabs(c) > static_cast<double>(std::numeric_limits<float>::max())) return false;
  return static_cast<double>(static_cast<float>(c)) == c;
}

void write_binary(std::ostream& out, const MeshData3& mesh) {
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError("binary STL counts facets in 32 bits; this mesh has " + std::to_string(mesh.triangles.size()));
  }
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      const Vec3& p = mesh.vertices[v];
      for (double c : {p.x, p.y, p.z}) {
        if (!is_float(c)) {
          std::string value;
          io::append_real(value, c);
          throw InputError("vertex " + std::to_string(v) + ": coordinate " + value +
                               " is not exactly a float32, which binary STL stores",
                           {v});
        }
      }
    }
  }
  std::string bytes = "dtlab binary STL";
  bytes.resize(kHeaderBytes, ' ');
  store_u32(bytes, static_cast<std::uint32_t>(mesh.triangles.size()));
  auto append_vec = [&](const Vec3& p) {
    for (double c : {p.x, p.y, p.z}) store_u32(bytes, std::bit_cast<std::uint32_t>(static_cast<float>(c)));
  };
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    append_vec(unit_normal(a, b, c));
    append_vec(a);
    append_vec(b);
    append_vec(c);
    bytes += '\0';
    bytes += '\0';
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

StlEncoding detect_stl_encoding(std::string_view bytes) {
  if (bytes.size() >= kFirstFacet && binary_size_for(bytes) == bytes.size()) return StlEncoding::Binary;
  return StlEncoding::Ascii;
}

MeshData3 read_stl(std::istream& in, const std::string& file_name) {
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ParseError(file_name, 0, "read error");
  if (detect_stl_encoding(bytes) == StlEncoding::Binary) return read_binary_stl(bytes, file_name);
  if (bytes.empty()) throw ParseError(file_name, 1, "empty file: neither an ASCII nor a binary STL");
  const std::string binary_rule =
      bytes.size() < kFirstFacet
          ? "it is too short for a binary STL (" + std::to_string(bytes.size()) + " bytes, at least 84)"
          : "as a binary STL its size would be 84 + 50 x " + std::to_string(load_u32(bytes, kHeaderBytes)) + " = " +
                std::to_string(binary_size_for(bytes)) + " bytes (the facet count at byte 80), but it has " +
                std::to_string(bytes.size());
  if (!begins_with_solid(bytes)) {
    throw ParseError(file_name, bytes.size() < kFirstFacet ? 1 : kHeaderBytes,
                     "not an STL file: it does not begin with 'solid' (ASCII STL), and " + binary_rule);
  }
  // ASCII STL is text; NUL bytes mean a binary file whose header begins with "solid" but whose
  // size is off (truncated, or padded).
  if (const std::size_t nul = bytes.find('\0'); nul != std::string::npos) {
    const auto line = 1 + static_cast<std::uint64_t>(std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
    throw ParseError(file_name, line,
                     "a NUL byte at byte " + std::to_string(nul) +
                         ": not an ASCII STL although it begins with 'solid', and " + binary_rule);
  }
  std::istringstream text(bytes);
  return AsciiStlReader(text, file_name).read();
}

MeshData3 read_stl(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_stl(in, path);
}

void write_stl(std::ostream& out, const MeshData3& mesh, StlEncoding encoding) {
  check_surface_only(mesh);
  if (encoding == StlEncoding::Ascii) {
    write_ascii(out, mesh);
  } else {
    write_binary(out, mesh);
  }
}

void write_stl(const std::string& path, const MeshData3& mesh, StlEncoding encoding) {
  std::ofstream out = io::open_for_writing(path);
  write_stl(out, mesh, encoding);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
