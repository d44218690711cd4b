#include "mesh/io/surface_input.hpp"

#include <array>
#include <filesystem>

#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/off_format.hpp"
#include "mesh/io/stl_format.hpp"

namespace dtlab {

namespace {

constexpr std::array<std::string_view, 5> kExtensions = {".off", ".stl", ".poly", ".smesh", ".mesh"};

std::string lower_case(std::string s) {
  for (char& c : s) c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  return s;
}

SurfaceInput from_plc(Plc3 plc) {
  SurfaceInput input;
  input.surface = triangulate_plc_facets(plc);
  input.holes = std::move(plc.holes);
  input.regions = std::move(plc.regions);
  return input;
}

}  // namespace

std::span<const std::string_view> surface_extensions() { return kExtensions; }

SurfaceInput read_surface(const std::string& path) {
  const std::string ext = lower_case(std::filesystem::path(path).extension().string());
  if (ext == ".off") return {read_off(path), {}, {}};
  if (ext == ".stl") return {read_stl(path), {}, {}};
  if (ext == ".poly") return from_plc(read_tetgen_poly(path));
  if (ext == ".smesh") return from_plc(read_tetgen_smesh(path));
  if (ext == ".mesh") {
    MeshData3 mesh = read_medit3(path);
    if (!mesh.tetrahedra.empty()) {
      throw InputError(path + " has " + std::to_string(mesh.tetrahedra.size()) +
                       " tetrahedra: a volume mesh, where a surface (Vertices, Triangles, Edges) is expected");
    }
    return {std::move(mesh), {}, {}};
  }
  std::string list;
  for (std::size_t i = 0; i < kExtensions.size(); ++i) list += (i > 0 ? ", " : "") + std::string(kExtensions[i]);
  throw InputError(path + ": unknown surface file extension " + (ext.empty() ? std::string("(none)") : "'" + ext + "'") +
                   "; supported: " + list);
}

}  // namespace dtlab
