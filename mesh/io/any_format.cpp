#include "mesh/io/any_format.hpp"

#include <fstream>
#include <sstream>

#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/medit_binary.hpp"
#include "mesh/io/planar_mesh.hpp"
#include "mesh/io/tetgen_format.hpp"
#include "mesh/io/point_file.hpp"
#include "mesh/io/triangle_format.hpp"

namespace dtlab {

std::string extension_of(std::string_view path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return "";
  std::string ext(path.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

namespace {
std::string without_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext.empty() ? path : path.substr(0, path.size() - ext.size() - 1);
}
}  // namespace

int input_dimension(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "ele") return input_dimension(without_extension(path) + ".node");  // Triangle's or TetGen's
  if (ext == "meshb") return medit_binary_dimension(path);
  if (ext == "msh") return is_planar(read_gmsh(path, NonPositiveTetrahedra::Keep).mesh) ? 2 : 3;  // orientation aside
  if (ext != "node" && ext != "mesh" && ext != "poly") return point_file_dimension(path);
  std::ifstream in(path);
  if (!in) throw InputError("cannot open '" + path + "'");
  // The readers check everything else; this only looks for the dimension: a .node or .poly
  // header's second number (absent: 2, Triangle's default), a .mesh file's Dimension keyword
  // (absent: 3, Medit's default).
  std::string line;
  while (std::getline(in, line)) {
    const std::string content = line.substr(0, line.find('#'));
    std::istringstream words(content);
    std::string first, second;
    if (!(words >> first)) continue;
    if (ext != "mesh") return (words >> second) ? (second == "3" ? 3 : 2) : 2;
    if (first == "Dimension") {
      if (!(words >> second) && !(in >> second)) break;
      return second == "2" ? 2 : 3;
    }
  }
  return ext == "mesh" ? 3 : 2;
}

bool is_surface_input(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "off" || ext == "obj" || ext == "stl" || ext == "smesh") return true;
  if (ext == "poly" || ext == "mesh") return input_dimension(path) == 3;
  return false;
}

std::vector<Vec2> read_points2(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "node") return read_triangle_node(path).points;
  if (ext == "mesh") return read_medit2(path).vertices;
  if (ext == "meshb" || ext == "msh") return read_mesh2(path).vertices;
  return read_point_file2(path);
}

MeshData2 read_mesh2(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return read_medit2(path);
  if (ext == "meshb") return read_meshb2(path);
  if (ext == "msh") return planar_to_mesh2(read_gmsh(path).mesh, path);
  if (ext == "ele" || ext == "node") return read_triangle_mesh(without_extension(path));
  throw InputError("cannot read a mesh from '" + path + "': supported are .mesh, .meshb (Medit), .msh (Gmsh) and .ele (Triangle)");
}

void write_mesh2(const std::string& path, const MeshData2& mesh) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return write_medit2(path, mesh);
  if (ext == "meshb") return write_meshb2(path, mesh);
  if (ext == "msh") return write_gmsh(path, planar_to_mesh3(mesh), {});
  if (ext == "ele" || ext == "node") return write_triangle_mesh(without_extension(path), mesh);
  throw InputError("cannot write '" + path + "': supported outputs are .mesh, .meshb (Medit), .msh (Gmsh) and .ele (Triangle .node + .ele)");
}

std::vector<Vec3> read_points3(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return read_medit3(path).vertices;
  if (ext == "meshb" || ext == "msh") return read_mesh3(path).vertices;
  if (ext == "node") return read_tetgen_node(path).points;
  return read_point_file3(path);
}

MeshData3 read_mesh3(const std::string& path, NonPositiveTetrahedra tetrahedra) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return read_medit3(path, nullptr, tetrahedra);
  if (ext == "meshb") return read_meshb3(path, tetrahedra);
  if (ext == "msh") return read_gmsh(path, tetrahedra).mesh;
  if (ext == "ele" || ext == "node") return read_tetgen_mesh(without_extension(path));
  throw InputError("cannot read a 3D mesh from '" + path + "': supported are .mesh, .meshb (Medit), .msh (Gmsh) and .ele (TetGen)");
}

void write_mesh3(const std::string& path, const MeshData3& mesh) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return write_medit3(path, mesh);
  if (ext == "meshb") return write_meshb3(path, mesh);
  if (ext == "msh") return write_gmsh(path, mesh, {});
  if (ext == "ele" || ext == "node") return write_tetgen_mesh(without_extension(path), mesh);
  throw InputError("cannot write '" + path +
                   "': supported 3D outputs are .mesh, .meshb (Medit), .msh (Gmsh) and .ele (TetGen .node + .ele)");
}

}  // namespace dtlab
