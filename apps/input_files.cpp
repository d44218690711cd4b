#include "apps/input_files.hpp"

#include "apps/cli_util.hpp"
#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/point_file.hpp"
#include "mesh/io/triangle_format.hpp"

namespace dtlab::cli {

namespace {
std::string without_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext.empty() ? path : path.substr(0, path.size() - ext.size() - 1);
}
}  // namespace

int input_dimension(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "node" || ext == "mesh") return 2;
  return point_file_dimension(path);
}

std::vector<Vec2> read_points2(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "node") return read_triangle_node(path).points;
  if (ext == "mesh") return read_medit2(path).vertices;
  return read_point_file2(path);
}

MeshData2 read_mesh2(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return read_medit2(path);
  if (ext == "ele" || ext == "node") return read_triangle_mesh(without_extension(path));
  throw InputError("cannot read a mesh from '" + path + "': supported are .mesh (Medit) and .ele (Triangle)");
}

void write_mesh2(const std::string& path, const MeshData2& mesh) {
  const std::string ext = extension_of(path);
  if (ext == "mesh") return write_medit2(path, mesh);
  if (ext == "ele" || ext == "node") return write_triangle_mesh(without_extension(path), mesh);
  throw InputError("cannot write '" + path + "': supported outputs are .mesh (Medit) and .ele (Triangle .node + .ele)");
}

}  // namespace dtlab::cli
