#include "mesh/io/tetgen_format.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;

// Moves to the header line; more than `max_fields` fields is an error.
void read_header(LineTokenizer& in, std::size_t max_fields, const char* layout) {
  if (!in.next_line()) in.fail_at(1, std::string("empty file: missing the header line (") + layout + ")");
  if (in.size() > max_fields) {
    in.fail("header: trailing text " + io::quote(in.token(max_fields)) + " after " + std::to_string(max_fields) +
            " fields");
  }
}

bool marker_flag(const LineTokenizer& in, std::size_t k) {
  if (in.size() <= k) return false;
  const std::int64_t m = in.integer(k, "boundary marker count");
  if (m != 0 && m != 1) in.fail("boundary marker count is " + std::to_string(m) + ", not 0 or 1");
  return m == 1;
}

void expect_end(LineTokenizer& in, std::uint64_t n, const char* noun) {
  if (in.next_line()) {
    in.fail("more lines than the header's " + std::to_string(n) + " " + noun + ": " + io::quote(in.token(0)));
  }
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

void check_vertex(std::uint32_t v, std::size_t vertex_count, const char* noun, std::size_t i) {
  if (v >= vertex_count) {
    throw InputError(std::string(noun) + " " + std::to_string(i) + ": vertex " + std::to_string(v) +
                         " out of range (" + std::to_string(vertex_count) + " vertices)",
                     {i});
  }
}

void append_reals(std::string& text, const std::vector<double>& values, std::size_t i, std::size_t per_item) {
  for (std::size_t a = 0; a < per_item; ++a) {
    text += ' ';
    io::append_real(text, values[i * per_item + a]);
  }
}

template <class Stream, class Write>
void write_file(const std::string& path, Write&& write) {
  Stream out = io::open_for_writing(path);
  write(out);
  out.flush();
  io::check_written(out, path);
}

}  // namespace

TetGenNodes read_tetgen_node(std::istream& stream, const std::string& file_name) {
  static constexpr const char* kAxes[] = {" x", " y", " z"};
  LineTokenizer in(stream, file_name);
  read_header(in, 4, "<#points> <dimension> <#attributes> <#boundary markers>");
  const std::uint64_t n = in.count(0, "point count");
  if (in.size() > 1) {
    const std::int64_t dim = in.integer(1, "dimension");
    if (dim != 3) in.fail("dimension is " + std::to_string(dim) + "; a .node file for TetGen must be 3D");
  }
  TetGenNodes nodes;
  nodes.attribute_count = in.size() > 2 ? in.count(2, "attribute count") : 0;
  nodes.has_markers = marker_flag(in, 3);
  const std::size_t fields = 4 + nodes.attribute_count + (nodes.has_markers ? 1 : 0);
  for (std::uint64_t i = 0; i < n; ++i) {
    io::next_counted_entry(in, i, n, "points");
    const std::string what = "point " + std::to_string(i + 1) + " of " + std::to_string(n);
    in.expect_tokens(fields, what);
    nodes.first_index = io::list_entry_number(in, i, nodes.first_index, what);
    double c[3];
    for (std::size_t k = 0; k < 3; ++k) {
      c[k] = in.real(1 + k, what + kAxes[k]);
      io::check_coordinate(in, c[k], what + kAxes[k]);
    }
    nodes.points.push_back(Vec3{c[0], c[1], c[2]});
    for (std::size_t a = 0; a < nodes.attribute_count; ++a) {
      nodes.attributes.push_back(in.real(4 + a, what + " attribute " + std::to_string(a + 1)));
    }
    if (nodes.has_markers) nodes.markers.push_back(io::int_field(in, fields - 1, what + " boundary marker"));
  }
  expect_end(in, n, "points");
  return nodes;
}

TetGenElements read_tetgen_ele(std::istream& stream, const std::string& file_name, const TetGenNodes& nodes) {
  LineTokenizer in(stream, file_name);
  read_header(in, 3, "<#tetrahedra> <nodes per tetrahedron> <#region attributes>");
  const std::uint64_t n = in.count(0, "tetrahedron count");
  std::size_t corners = 4;
  if (in.size() > 1) {
    const std::int64_t c = in.integer(1, "nodes per tetrahedron");
    if (c != 4 && c != 10) in.fail("nodes per tetrahedron is " + std::to_string(c) + ", not 4 or 10");
    corners = static_cast<std::size_t>(c);
  }
  TetGenElements elements;
  elements.vertex_first_index = nodes.first_index;
  elements.attribute_count = in.size() > 2 ? in.count(2, "region attribute count") : 0;
  const std::size_t fields = 1 + corners + elements.attribute_count;
  const std::vector<Vec3>& p = nodes.points;
  for (std::uint64_t i = 0; i < n; ++i) {
    io::next_counted_entry(in, i, n, "tetrahedra");
    const std::string what = "tetrahedron " + std::to_string(i + 1) + " of " + std::to_string(n);
    in.expect_tokens(fields, what);
    elements.first_index = io::list_entry_number(in, i, elements.first_index, what);
    std::array<std::uint32_t, 10> v{};
    for (std::size_t k = 0; k < corners; ++k) v[k] = io::vertex_number(in, 1 + k, nodes.first_index, p.size(), what);
    // One orientation for the whole file, decided exactly: the first tetrahedron sets it.
    const Sign s = uncounted::orient3d(p[v[0]], p[v[1]], p[v[2]], p[v[3]]);
    if (s == Sign::Zero) in.fail(what + " is flat: its four corners are coplanar");
    if (i == 0) {
      elements.orientation = s;
    } else if (s != elements.orientation) {
      in.fail(what + " is " + to_string(s) + "ly oriented, but the first tetrahedron is " +
              to_string(elements.orientation) + "ly oriented (one orientation per file)");
    }
    elements.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
    if (corners == 10) elements.midside.push_back({v[4], v[5], v[6], v[7], v[8], v[9]});
    for (std::size_t a = 0; a < elements.attribute_count; ++a) {
      elements.attributes.push_back(in.real(1 + corners + a, what + " attribute " + std::to_string(a + 1)));
    }
  }
  expect_end(in, n, "tetrahedra");
  return elements;
}

TetGenFaces read_tetgen_face(std::istream& stream, const std::string& file_name, const TetGenNodes& nodes) {
  LineTokenizer in(stream, file_name);
  read_header(in, 2, "<#faces> <#boundary markers>");
  const std::uint64_t n = in.count(0, "face count");
  TetGenFaces faces;
  faces.vertex_first_index = nodes.first_index;
  faces.has_markers = marker_flag(in, 1);
  const std::size_t fields = faces.has_markers ? 5 : 4;
  for (std::uint64_t i = 0; i < n; ++i) {
    io::next_counted_entry(in, i, n, "faces");
    const std::string what = "face " + std::to_string(i + 1) + " of " + std::to_string(n);
    in.expect_tokens(fields, what);
    faces.first_index = io::list_entry_number(in, i, faces.first_index, what);
    std::array<std::uint32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) t[k] = io::vertex_number(in, 1 + k, nodes.first_index, nodes.points.size(), what);
    faces.triangles.push_back(t);
    if (faces.has_markers) faces.markers.push_back(io::int_field(in, 4, what + " boundary marker"));
  }
  expect_end(in, n, "faces");
  return faces;
}

TetGenNodes read_tetgen_node(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_tetgen_node(in, path);
}

TetGenElements read_tetgen_ele(const std::string& path, const TetGenNodes& nodes) {
  std::ifstream in = io::open_for_reading(path);
  return read_tetgen_ele(in, path, nodes);
}

TetGenFaces read_tetgen_face(const std::string& path, const TetGenNodes& nodes) {
  std::ifstream in = io::open_for_reading(path);
  return read_tetgen_face(in, path, nodes);
}

void write_tetgen_node(std::ostream& out, const TetGenNodes& nodes) {
  const std::size_t n = nodes.points.size();
  check_first_index(nodes.first_index, "TetGenNodes::first_index");
  check_size(nodes.attributes, n * nodes.attribute_count, "TetGenNodes::attributes");
  check_size(nodes.markers, nodes.has_markers ? n : 0, "TetGenNodes::markers");
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += " 3 ";
  io::append_integer(text, static_cast<std::int64_t>(nodes.attribute_count));
  text += nodes.has_markers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + nodes.first_index);
    for (double c : {nodes.points[i].x, nodes.points[i].y, nodes.points[i].z}) {
      text += ' ';
      io::append_real(text, c);
    }
    append_reals(text, nodes.attributes, i, nodes.attribute_count);
    if (nodes.has_markers) {
      text += ' ';
      io::append_integer(text, nodes.markers[i]);
    }
    text += '\n';
  }
  out << text;
}

void write_tetgen_ele(std::ostream& out, const TetGenElements& elements, std::size_t vertex_count) {
  const std::size_t n = elements.tetrahedra.size();
  check_first_index(elements.first_index, "TetGenElements::first_index");
  check_first_index(elements.vertex_first_index, "TetGenElements::vertex_first_index");
  check_size(elements.attributes, n * elements.attribute_count, "TetGenElements::attributes");
  if (!elements.midside.empty()) check_size(elements.midside, n, "TetGenElements::midside");
  const std::size_t corners = elements.midside.empty() ? 4 : 10;
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += corners == 4 ? " 4 " : " 10 ";
  io::append_integer(text, static_cast<std::int64_t>(elements.attribute_count));
  text += '\n';
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + elements.first_index);
    for (std::size_t k = 0; k < corners; ++k) {
      const std::uint32_t v = k < 4 ? elements.tetrahedra[i][k] : elements.midside[i][k - 4];
      check_vertex(v, vertex_count, "tetrahedron", i);
      text += ' ';
      io::append_integer(text, static_cast<std::int64_t>(v) + elements.vertex_first_index);
    }
    append_reals(text, elements.attributes, i, elements.attribute_count);
    text += '\n';
  }
  out << text;
}

void write_tetgen_face(std::ostream& out, const TetGenFaces& faces, std::size_t vertex_count) {
  const std::size_t n = faces.triangles.size();
  check_first_index(faces.first_index, "TetGenFaces::first_index");
  check_first_index(faces.vertex_first_index, "TetGenFaces::vertex_first_index");
  check_size(faces.markers, faces.has_markers ? n : 0, "TetGenFaces::markers");
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(n));
  text += faces.has_markers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < n; ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + faces.first_index);
    for (std::uint32_t v : faces.triangles[i]) {
      check_vertex(v, vertex_count, "face", i);
      text += ' ';
      io::append_integer(text, static_cast<std::int64_t>(v) + faces.vertex_first_index);
    }
    if (faces.has_markers) {
      text += ' ';
      io::append_integer(text, faces.markers[i]);
    }
    text += '\n';
  }
  out << text;
}

void write_tetgen_node(const std::string& path, const TetGenNodes& nodes) {
  write_file<std::ofstream>(path, [&](std::ostream& out) { write_tetgen_node(out, nodes); });
}

void write_tetgen_ele(const std::string& path, const TetGenElements& elements, std::size_t vertex_count) {
  write_file<std::ofstream>(path, [&](std::ostream& out) { write_tetgen_ele(out, elements, vertex_count); });
}

void write_tetgen_face(const std::string& path, const TetGenFaces& faces, std::size_t vertex_count) {
  write_file<std::ofstream>(path, [&](std::ostream& out) { write_tetgen_face(out, faces, vertex_count); });
}

MeshData3 to_mesh_data3(const TetGenNodes& nodes, const TetGenElements& elements, const TetGenFaces* faces) {
  if (!elements.midside.empty()) {
    throw InputError("a 10-node tetrahedral mesh has midside nodes, which MeshData3 cannot hold");
  }
  MeshData3 mesh;
  mesh.vertices = nodes.points;
  mesh.vertex_refs = nodes.has_markers ? nodes.markers : std::vector<int>(nodes.points.size(), 0);
  mesh.tetrahedra = elements.tetrahedra;
  if (elements.orientation == Sign::Negative) {
    for (auto& t : mesh.tetrahedra) std::swap(t[2], t[3]);
  }
  mesh.tetrahedron_refs.assign(elements.tetrahedra.size(), 0);
  if (elements.attribute_count > 0) {
    bool integral = true;
    for (std::size_t i = 0; i < elements.tetrahedra.size() && integral; ++i) {
      const double a = elements.attributes[i * elements.attribute_count];
      integral = a == std::floor(a) && a >= std::numeric_limits<int>::min() && a <= std::numeric_limits<int>::max();
    }
    if (integral) {
      for (std::size_t i = 0; i < elements.tetrahedra.size(); ++i) {
        mesh.tetrahedron_refs[i] = static_cast<int>(elements.attributes[i * elements.attribute_count]);
      }
    }
  }
  if (faces != nullptr) {
    mesh.triangles = faces->triangles;
    mesh.triangle_refs = faces->has_markers ? faces->markers : std::vector<int>(faces->triangles.size(), 0);
  }
  return mesh;
}

TetGenNodes to_tetgen_nodes(const MeshData3& mesh) {
  TetGenNodes nodes;
  nodes.points = mesh.vertices;
  if (!mesh.vertex_refs.empty()) {
    check_size(mesh.vertex_refs, mesh.vertices.size(), "MeshData3::vertex_refs");
    nodes.has_markers = true;
    nodes.markers = mesh.vertex_refs;
  }
  return nodes;
}

TetGenElements to_tetgen_elements(const MeshData3& mesh) {
  TetGenElements elements;
  elements.tetrahedra = mesh.tetrahedra;
  if (!mesh.tetrahedron_refs.empty()) {
    check_size(mesh.tetrahedron_refs, mesh.tetrahedra.size(), "MeshData3::tetrahedron_refs");
    elements.attribute_count = 1;
    elements.attributes.assign(mesh.tetrahedron_refs.begin(), mesh.tetrahedron_refs.end());
  }
  return elements;
}

TetGenFaces to_tetgen_faces(const MeshData3& mesh) {
  TetGenFaces faces;
  faces.triangles = mesh.triangles;
  if (!mesh.triangle_refs.empty()) {
    check_size(mesh.triangle_refs, mesh.triangles.size(), "MeshData3::triangle_refs");
    faces.has_markers = true;
    faces.markers = mesh.triangle_refs;
  }
  return faces;
}

MeshData3 read_tetgen_mesh(const std::string& base) {
  const TetGenNodes nodes = read_tetgen_node(base + ".node");
  const TetGenElements elements = read_tetgen_ele(base + ".ele", nodes);
  if (!std::filesystem::exists(base + ".face")) return to_mesh_data3(nodes, elements);
  const TetGenFaces faces = read_tetgen_face(base + ".face", nodes);
  return to_mesh_data3(nodes, elements, &faces);
}

void write_tetgen_mesh(const std::string& base, const MeshData3& mesh) {
  write_tetgen_node(base + ".node", to_tetgen_nodes(mesh));
  write_tetgen_ele(base + ".ele", to_tetgen_elements(mesh), mesh.vertices.size());
  write_tetgen_face(base + ".face", to_tetgen_faces(mesh), mesh.vertices.size());
}

}  // namespace dtlab
