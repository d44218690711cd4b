#include "mesh/io/triangle_format.hpp"

#include <cmath>
#include <limits>

#include <algorithm>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;

// Number of the first entry (0 or 1) or of a later one (first + i), as Triangle numbers them.
int entry_number(const LineTokenizer& in, std::uint64_t i, int first, const std::string& what) {
  const std::int64_t number = in.integer(0, what + " number");
  if (i == 0) {
    if (number != 0 && number != 1) {
      in.fail(what + " is numbered " + std::to_string(number) + "; the first one must be 0 or 1");
    }
    return static_cast<int>(number);
  }
  if (number != first + static_cast<std::int64_t>(i)) {
    in.fail(what + " is numbered " + std::to_string(number) + ", expected " +
            std::to_string(first + static_cast<std::int64_t>(i)) + " (numbers run consecutively)");
  }
  return first;
}

void next_entry(LineTokenizer& in, std::uint64_t i, std::uint64_t n, const char* noun) {
  const std::uint64_t last = in.line();
  if (!in.next_line()) {
    in.fail_at(std::max<std::uint64_t>(last, 1), "file ends after " + std::to_string(i) + " of " +
                                                     std::to_string(n) + " " + noun + " (truncated?)");
  }
}

void expect_end(LineTokenizer& in, std::uint64_t n, const char* noun) {
  if (in.next_line()) {
    in.fail("more lines than the header's " + std::to_string(n) + " " + noun + ": " + io::quote(in.token(0)));
  }
}

int marker(const LineTokenizer& in, std::size_t k, const std::string& what) {
  const std::int64_t m = in.integer(k, what);
  if (m < std::numeric_limits<int>::min() || m > std::numeric_limits<int>::max()) {
    in.fail(what + " " + std::to_string(m) + " does not fit an int");
  }
  return static_cast<int>(m);
}

template <class T>
void check_size(const std::vector<T>& v, std::size_t expected, const std::string& what) {
  if (v.size() != expected) {
    throw InputError(what + ": " + std::to_string(v.size()) + " values, expected " + std::to_string(expected));
  }
}

void check_first_index(int first, const char* what) {
  if (first != 0 && first != 1) throw InputError(std::string(what) + " is " + std::to_string(first) + ", not 0 or 1");
}

}  // namespace

TriangleNodes read_triangle_node(std::istream& stream, const std::string& file_name) {
  LineTokenizer in(stream, file_name);
  if (!in.next_line()) in.fail_at(1, "empty file: missing the header line (<#vertices> <dimension> ...)");
  if (in.size() > 4) in.fail("header: trailing text " + io::quote(in.token(4)) + " after 4 fields");
  const std::uint64_t n = in.count(0, "vertex count");
  if (in.size() > 1) {
    const std::int64_t dim = in.integer(1, "dimension");
    if (dim != 2) in.fail("dimension is " + std::to_string(dim) + "; a .node file for Triangle must be 2D");
  }
  TriangleNodes nodes;
  nodes.attribute_count = in.size() > 2 ? in.count(2, "attribute count") : 0;
  if (in.size() > 3) {
    const std::int64_t m = in.integer(3, "boundary marker count");
    if (m != 0 && m != 1) in.fail("boundary marker count is " + std::to_string(m) + ", not 0 or 1");
    nodes.has_markers = m == 1;
  }
  const std::size_t fields = 3 + nodes.attribute_count + (nodes.has_markers ? 1 : 0);
  for (std::uint64_t i = 0; i < n; ++i) {
    next_entry(in, i, n, "vertices");
    const std::string what = "vertex " + std::to_string(i + 1) + " of " + std::to_string(n);
    in.expect_tokens(fields, what);
    const int first = entry_number(in, i, nodes.first_index, what);
    if (i == 0) nodes.first_index = first;
    const Vec2 p{in.real(1, what + " x"), in.real(2, what + " y")};
    io::check_coordinate(in, p.x, what + " x");
    io::check_coordinate(in, p.y, what + " y");
    nodes.points.push_back(p);
    for (std::size_t a = 0; a < nodes.attribute_count; ++a) {
      nodes.attributes.push_back(in.real(3 + a, what + " attribute " + std::to_string(a + 1)));
    }
    if (nodes.has_markers) nodes.markers.push_back(marker(in, fields - 1, what + " boundary marker"));
  }
  expect_end(in, n, "vertices");
  return nodes;
}

TriangleElements read_triangle_ele(std::istream& stream, const std::string& file_name, const TriangleNodes& nodes) {
  LineTokenizer in(stream, file_name);
  if (!in.next_line()) in.fail_at(1, "empty file: missing the header line (<#triangles> <nodes per triangle> ...)");
  if (in.size() > 3) in.fail("header: trailing text " + io::quote(in.token(3)) + " after 3 fields");
  const std::uint64_t n = in.count(0, "triangle count");
  std::size_t corners = 3;
  if (in.size() > 1) {
    const std::int64_t c = in.integer(1, "nodes per triangle");
    if (c != 3 && c != 6) in.fail("nodes per triangle is " + std::to_string(c) + ", not 3 or 6");
    corners = static_cast<std::size_t>(c);
  }
  TriangleElements elements;
  elements.vertex_first_index = nodes.first_index;
  elements.attribute_count = in.size() > 2 ? in.count(2, "attribute count") : 0;
  const std::size_t fields = 1 + corners + elements.attribute_count;
  const std::int64_t lo = nodes.first_index;
  const std::int64_t hi = lo + static_cast<std::int64_t>(nodes.points.size()) - 1;
  for (std::uint64_t i = 0; i < n; ++i) {
    next_entry(in, i, n, "triangles");
    const std::string what = "triangle " + std::to_string(i + 1) + " of " + std::to_string(n);
    in.expect_tokens(fields, what);
    const int first = entry_number(in, i, elements.first_index, what);
    if (i == 0) elements.first_index = first;
    std::array<std::uint32_t, 6> v{};
    for (std::size_t k = 0; k < corners; ++k) {
      const std::int64_t id = in.integer(1 + k, what + " node");
      if (id < lo || id > hi) {
        in.fail(what + ": node " + std::to_string(id) + " out of range " + std::to_string(lo) + ".." +
                std::to_string(hi));
      }
      v[k] = static_cast<std::uint32_t>(id - lo);
    }
    elements.triangles.push_back({v[0], v[1], v[2]});
    if (corners == 6) elements.midside.push_back({v[3], v[4], v[5]});
    for (std::size_t a = 0; a < elements.attribute_count; ++a) {
      elements.attributes.push_back(in.real(1 + corners + a, what + " attribute " + std::to_string(a + 1)));
    }
  }
  expect_end(in, n, "triangles");
  return elements;
}

TriangleNodes read_triangle_node(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_triangle_node(in, path);
}

TriangleElements read_triangle_ele(const std::string& path, const TriangleNodes& nodes) {
  std::ifstream in = io::open_for_reading(path);
  return read_triangle_ele(in, path, nodes);
}

void write_triangle_node(std::ostream& out, const TriangleNodes& nodes) {
  const std::size_t n = nodes.points.size();
  check_first_index(nodes.first_index, "TriangleNodes::first_index");
  check_size(nodes.attributes, n * nodes.attribute_count, "TriangleNodes::attributes");
  check_size(nodes.markers, nodes.has_markers ? n : 0, "TriangleNodes::markers");
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += " 2 ";
  io::append_integer(text, static_cast<std::int64_t>(nodes.attribute_count));
  text += nodes.has_markers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + nodes.first_index);
    text += ' ';
    io::append_real(text, nodes.points[i].x);
    text += ' ';
    io::append_real(text, nodes.points[i].y);
    for (std::size_t a = 0; a < nodes.attribute_count; ++a) {
      text += ' ';
      io::append_real(text, nodes.attributes[i * nodes.attribute_count + a]);
    }
    if (nodes.has_markers) {
      text += ' ';
      io::append_integer(text, nodes.markers[i]);
    }
    text += '\n';
  }
  out << text;
}

void write_triangle_ele(std::ostream& out, const TriangleElements& elements, std::size_t vertex_count) {
  const std::size_t n = elements.triangles.size();
  check_first_index(elements.first_index, "TriangleElements::first_index");
  check_first_index(elements.vertex_first_index, "TriangleElements::vertex_first_index");
  check_size(elements.attributes, n * elements.attribute_count, "TriangleElements::attributes");
  if (!elements.midside.empty()) check_size(elements.midside, n, "TriangleElements::midside");
  const std::size_t corners = elements.midside.empty() ? 3 : 6;
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += corners == 3 ? " 3 " : " 6 ";
  io::append_integer(text, static_cast<std::int64_t>(elements.attribute_count));
  text += '\n';
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + elements.first_index);
    for (std::size_t k = 0; k < corners; ++k) {
      const std::uint32_t v = k < 3 ? elements.triangles[i][k] : elements.midside[i][k - 3];
      if (v >= vertex_count) {
        throw InputError("triangle " + std::to_string(i) + ": vertex " + std::to_string(v) + " out of range (" +
                             std::to_string(vertex_count) + " vertices)",
                         {i});
      }
      text += ' ';
      io::append_integer(text, static_cast<std::int64_t>(v) + elements.vertex_first_index);
    }
    for (std::size_t a = 0; a < elements.attribute_count; ++a) {
      text += ' ';
      io::append_real(text, elements.attributes[i * elements.attribute_count + a]);
    }
    text += '\n';
  }
  out << text;
}

void write_triangle_node(const std::string& path, const TriangleNodes& nodes) {
  std::ofstream out = io::open_for_writing(path);
  write_triangle_node(out, nodes);
  out.flush();
  io::check_written(out, path);
}

void write_triangle_ele(const std::string& path, const TriangleElements& elements, std::size_t vertex_count) {
  std::ofstream out = io::open_for_writing(path);
  write_triangle_ele(out, elements, vertex_count);
  out.flush();
  io::check_written(out, path);
}

MeshData2 to_mesh_data(const TriangleNodes& nodes, const TriangleElements& elements) {
  if (!elements.midside.empty()) {
    throw InputError("a 6-node triangle mesh has midside nodes, which MeshData2 cannot hold");
  }
  MeshData2 mesh;
  mesh.vertices = nodes.points;
  mesh.vertex_refs = nodes.has_markers ? nodes.markers : std::vector<int>(nodes.points.size(), 0);
  mesh.triangles = elements.triangles;
  mesh.triangle_refs.assign(elements.triangles.size(), 0);
  if (elements.attribute_count > 0) {
    bool integral = true;
    for (std::size_t i = 0; i < elements.triangles.size() && integral; ++i) {
      const double a = elements.attributes[i * elements.attribute_count];
      integral = a == std::floor(a) && a >= std::numeric_limits<int>::min() && a <= std::numeric_limits<int>::max();
    }
    if (integral) {
      for (std::size_t i = 0; i < elements.triangles.size(); ++i) {
        mesh.triangle_refs[i] = static_cast<int>(elements.attributes[i * elements.attribute_count]);
      }
    }
  }
  return mesh;
}

TriangleNodes to_triangle_nodes(const MeshData2& mesh) {
  TriangleNodes nodes;
  nodes.points = mesh.vertices;
  if (!mesh.vertex_refs.empty()) {
    check_size(mesh.vertex_refs, mesh.vertices.size(), "MeshData2::vertex_refs");
    nodes.has_markers = true;
    nodes.markers = mesh.vertex_refs;
  }
  return nodes;
}

TriangleElements to_triangle_elements(const MeshData2& mesh) {
  TriangleElements elements;
  elements.triangles = mesh.triangles;
  if (!mesh.triangle_refs.empty()) {
    check_size(mesh.triangle_refs, mesh.triangles.size(), "MeshData2::triangle_refs");
    elements.attribute_count = 1;
    elements.attributes.assign(mesh.triangle_refs.begin(), mesh.triangle_refs.end());
  }
  return elements;
}

MeshData2 read_triangle_mesh(const std::string& base) {
  const TriangleNodes nodes = read_triangle_node(base + ".node");
  return to_mesh_data(nodes, read_triangle_ele(base + ".ele", nodes));
}

void write_triangle_mesh(const std::string& base, const MeshData2& mesh) {
  write_triangle_node(base + ".node", to_triangle_nodes(mesh));
  write_triangle_ele(base + ".ele", to_triangle_elements(mesh), mesh.vertices.size());
}

}  // namespace dtlab
