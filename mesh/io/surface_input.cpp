#include "mesh/io/surface_input.hpp"

#include <array>
#include <filesystem>

#include "kernel/error.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/obj_format.hpp"
#include "mesh/io/off_format.hpp"
#include "mesh/io/stl_format.hpp"

namespace dtlab {

namespace {

constexpr std::array<std::string_view, 6> kExtensions = {".off", ".obj", ".stl", ".poly", ".smesh", ".mesh"};

std::string lower_case(std::string s) {
  for (char& c : s) c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  return s;
}

// Medit numbers each element kind from 1: triangles, then quadrilaterals, then edges.
std::vector<FacetSection> medit_sections(const Plc3& plc) {
  std::size_t triangles = 0, quadrilaterals = 0;
  for (const PlcFacet3& f : plc.facets) {
    const std::size_t n = f.polygons.front().size();
    triangles += n == 3;
    quadrilaterals += n == 4;
  }
  return {{0, "triangle", 1}, {triangles, "quadrilateral", 1}, {triangles + quadrilaterals, "edge", 1}};
}

}  // namespace

std::string SurfaceInput::facet_name(std::size_t f) const {
  FacetSection s;
  s.begin = 0;
  for (const FacetSection& candidate : sections)
    if (candidate.begin <= f) s = candidate;
  return s.noun + " " + std::to_string(f - s.begin + s.first_number);
}

std::span<const std::string_view> surface_extensions() { return kExtensions; }

Plc3 plc_from_triangles(const MeshData3& mesh) {
  if (!mesh.tetrahedra.empty())
    throw InputError("a mesh with " + std::to_string(mesh.tetrahedra.size()) +
                     " tetrahedra is a volume mesh, where a surface is expected");
  Plc3 plc;
  plc.vertices = mesh.vertices;
  plc.vertex_markers = mesh.vertex_refs;
  plc.facets.reserve(mesh.triangles.size() + mesh.edges.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    plc.facets.push_back({{{t[0], t[1], t[2]}}, {}, mesh.triangle_refs.empty() ? 0 : mesh.triangle_refs[i]});
  }
  for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
    const auto& e = mesh.edges[i];
    plc.facets.push_back({{{e[0], e[1]}}, {}, mesh.edge_refs.empty() ? 0 : mesh.edge_refs[i]});
  }
  return plc;
}

namespace {

SurfaceInput read_by_extension(const std::string& path) {
  const std::string ext = lower_case(std::filesystem::path(path).extension().string());
  if (ext == ".off") return {read_off_surface(path), {{0, "face", 0}}, 0};
  if (ext == ".obj") return {read_obj_surface(path), {{0, "facet", 1}}, 1};
  if (ext == ".stl") return {plc_from_triangles(read_stl(path)), {{0, "facet", 0}}};
  if (ext == ".poly") return {read_tetgen_poly(path), {{0, "facet", 1}}};
  if (ext == ".smesh") return {read_tetgen_smesh(path), {{0, "facet", 1}}};
  if (ext == ".mesh") {
    SurfaceInput in{read_medit3_surface(path), {}};
    in.sections = medit_sections(in.plc);
    return in;
  }
  std::string list;
  for (std::size_t i = 0; i < kExtensions.size(); ++i) list += (i > 0 ? ", " : "") + std::string(kExtensions[i]);
  throw InputError(path + ": unknown surface file extension " + (ext.empty() ? std::string("(none)") : "'" + ext + "'") +
                   "; supported: " + list);
}

}  // namespace

SurfaceInput read_surface(const std::string& path) {
  SurfaceInput in = read_by_extension(path);
  // Every format can say "no facets" (OFF 0 0 0, an STL solid without facet, a Medit file
  // without Triangles): refused here, by file, before any mesher is handed an empty domain.
  if (in.plc.facets.empty())
    throw InputError(path + ": no facets (" + std::to_string(in.plc.vertices.size()) +
                     " vertices): an empty surface bounds no volume");
  return in;
}

}  // namespace dtlab
