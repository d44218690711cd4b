// VTK XML .vtu writer (see vtu_format.hpp; VTK's "VTK File Formats", XML UnstructuredGrid).
#include "mesh/io/vtu_format.hpp"

#include <cmath>

#include "kernel/error.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

constexpr int kVtkLine = 3;
constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void open_array(std::string& s, const char* type, const std::string& name, int components) {
  s += "        <DataArray type=\"";
  s += type;
  s += "\"";
  if (!name.empty()) s += " Name=\"" + xml_escaped(name) + "\"";
  if (components != 1) s += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  s += " format=\"ascii\">\n";
}

void close_array(std::string& s) {
  if (!s.empty() && s.back() != '\n') s += '\n';
  s += "        </DataArray>\n";
}

// Values, `per_line` to a line.
template <class T>
void append_values(std::string& s, const std::vector<T>& values, std::size_t per_line) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    s += (i % per_line == 0) ? "          " : " ";
    if constexpr (std::is_floating_point_v<T>) {
      io::append_real(s, values[i]);
    } else {
      io::append_integer(s, static_cast<std::int64_t>(values[i]));
    }
    if ((i + 1) % per_line == 0 || i + 1 == values.size()) s += '\n';
  }
}

void check_field(const VtuField& f, std::size_t count, const char* where) {
  if (f.components < 1 || f.values.size() != count * static_cast<std::size_t>(f.components)) {
    throw InputError(std::string(where) + " field '" + f.name + "': " + std::to_string(f.values.size()) + " values for " +
                     std::to_string(count) + " " + (where[0] == 'p' ? "points" : "cells") + " of " +
                     std::to_string(f.components) + " components");
  }
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    if (!std::isfinite(f.values[i])) {
      throw InputError(std::string(where) + " field '" + f.name + "': value " + std::to_string(i) + " is not finite", {i});
    }
  }
}

void append_fields(std::string& s, const std::vector<VtuField>& fields) {
  for (const VtuField& f : fields) {
    open_array(s, "Float64", f.name, f.components);
    append_values(s, f.values, static_cast<std::size_t>(f.components));
    close_array(s);
  }
}

}  // namespace

void write_vtu(std::ostream& out, const MeshData3& mesh, const VtuFields& fields) {
  const std::size_t nv = mesh.vertices.size();
  io::check_refs(mesh.vertex_refs, nv, "vertex");
  io::check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  io::check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");
  io::check_cells(mesh.tetrahedra, mesh.tetrahedron_refs, nv, "tetrahedron");
  const std::size_t nc = mesh.edges.size() + mesh.triangles.size() + mesh.tetrahedra.size();
  for (const VtuField& f : fields.point_data) check_field(f, nv, "point");
  for (const VtuField& f : fields.cell_data) check_field(f, nc, "cell");

  std::vector<int> refs;
  std::vector<int> dims;
  std::vector<std::uint32_t> connectivity;
  std::vector<std::uint64_t> offsets;
  std::vector<int> types;
  refs.reserve(nc);
  auto add = [&](const auto& cells, const std::vector<int>& r, int dim, int type) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
      connectivity.insert(connectivity.end(), cells[i].begin(), cells[i].end());
      offsets.push_back(connectivity.size());
      types.push_back(type);
      refs.push_back(r.empty() ? 0 : r[i]);
      dims.push_back(dim);
    }
  };
  add(mesh.edges, mesh.edge_refs, 1, kVtkLine);
  add(mesh.triangles, mesh.triangle_refs, 2, kVtkTriangle);
  add(mesh.tetrahedra, mesh.tetrahedron_refs, 3, kVtkTetra);

  std::string s =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n";
  s += "    <Piece NumberOfPoints=\"" + std::to_string(nv) + "\" NumberOfCells=\"" + std::to_string(nc) + "\">\n";
  s += "      <PointData>\n";
  std::vector<int> vertex_refs = mesh.vertex_refs;
  vertex_refs.resize(nv, 0);
  open_array(s, "Int32", "vertex_ref", 1);
  append_values(s, vertex_refs, 16);
  close_array(s);
  append_fields(s, fields.point_data);
  s += "      </PointData>\n      <CellData>\n";
  open_array(s, "Int32", "ref", 1);
  append_values(s, refs, 16);
  close_array(s);
  open_array(s, "UInt8", "dimension", 1);
  append_values(s, dims, 32);
  close_array(s);
  append_fields(s, fields.cell_data);
  s += "      </CellData>\n      <Points>\n";
  std::vector<double> xyz;
  xyz.reserve(3 * nv);
  for (const Vec3& p : mesh.vertices) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  open_array(s, "Float64", "Points", 3);
  append_values(s, xyz, 3);
  close_array(s);
  s += "      </Points>\n      <Cells>\n";
  open_array(s, "Int64", "connectivity", 1);
  append_values(s, connectivity, 12);
  close_array(s);
  open_array(s, "Int64", "offsets", 1);
  append_values(s, offsets, 16);
  close_array(s);
  open_array(s, "UInt8", "types", 1);
  append_values(s, types, 32);
  close_array(s);
  s += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  out << s;
}

void write_vtu(const std::string& path, const MeshData3& mesh, const VtuFields& fields) {
  std::ofstream out = io::open_for_writing(path);
  write_vtu(out, mesh, fields);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
