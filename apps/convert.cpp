// `dtlab convert IN OUT [--binary] [--sol FILE] [--quality]`: a mesh from one format to another,
// each told by its extension (docs/formats.md): Medit .mesh/.meshb, Gmsh .msh (4.1 written; 4.1
// and 2.2 read), VTK .vtu (written), Triangle/TetGen .node/.ele(/.face), OFF, STL. Every
// reference, region and boundary marker is carried; whatever the target cannot hold (names in
// Medit, references in OFF/STL, edges in Triangle's .ele, ...) is named on stderr as a warning.
// Bad input exits 1 with the reader's message naming the item, and writes nothing: the output is
// written beside its place and renamed only once complete.

#include <cmath>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "apps/cli_util.hpp"
#include "apps/subcommands.hpp"
#include "kernel/error.hpp"
#include "kernel/quality.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/medit_binary.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/io/off_format.hpp"
#include "mesh/io/planar_mesh.hpp"
#include "mesh/io/stl_format.hpp"
#include "mesh/io/tetgen_format.hpp"
#include "mesh/io/triangle_format.hpp"
#include "mesh/io/vtu_format.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"

namespace dtlab::cli {

namespace {

struct ConvertArgs {
  std::string in;
  std::string out;
  bool binary = false;
  std::string sol;
  bool quality = false;
};

// A mesh of either dimension, with the names of its references.
struct AnyMesh {
  int dimension = 3;
  MeshData2 mesh2;
  MeshData3 mesh3;
  std::vector<PhysicalName> names;

  MeshData3 as3() const { return dimension == 2 ? planar_to_mesh3(mesh2) : mesh3; }
};

void warn(const std::string& text) { std::cerr << "dtlab convert: warning: " << text << "\n"; }

std::string without_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext.empty() ? path : path.substr(0, path.size() - ext.size() - 1);
}

AnyMesh read_any(const std::string& path) {
  const std::string ext = extension_of(path);
  AnyMesh m;
  if (ext == "msh") {
    GmshMesh g = read_gmsh(path);
    for (const std::string& note : g.notes) warn(path + ": " + note);
    m.names = std::move(g.names);
    if (is_planar(g.mesh)) {
      m.dimension = 2;
      m.mesh2 = planar_to_mesh2(g.mesh, path);
    } else {
      m.mesh3 = std::move(g.mesh);
    }
    return m;
  }
  if (ext == "off") {
    m.mesh3 = read_off(path);
    return m;
  }
  if (ext == "stl") {
    m.mesh3 = read_stl(path);
    return m;
  }
  if (ext == "vtu") throw InputError("cannot read '" + path + "': .vtu is written, not read (docs/formats.md)");
  if (ext != "mesh" && ext != "meshb" && ext != "ele" && ext != "node") {
    throw InputError("cannot read '" + path +
                     "': supported inputs are .mesh, .meshb (Medit), .msh (Gmsh), .ele/.node (Triangle, TetGen), .off, "
                     ".stl");
  }
  const std::string dim_file = ext == "ele" ? without_extension(path) + ".node" : path;
  m.dimension = input_dimension(dim_file);
  if (m.dimension == 2) {
    m.mesh2 = read_mesh2(path);
  } else {
    m.mesh3 = read_mesh3(path);
  }
  return m;
}

std::size_t nonzero(const std::vector<int>& refs) {
  std::size_t n = 0;
  for (int r : refs) n += r != 0;
  return n;
}

// What a target without names loses.
void warn_names(const AnyMesh& m, const std::string& format) {
  if (m.names.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < m.names.size() && i < 6; ++i) {
    list += (i ? ", " : "") + std::to_string(m.names[i].tag) + " \"" + m.names[i].name + "\"";
  }
  if (m.names.size() > 6) list += ", ...";
  warn(std::to_string(m.names.size()) + " physical names not written (" + list + "): " + format +
       " has no place for names; the references themselves are kept");
}

// OFF and STL hold triangles only: what else there is, is named and left out.
MeshData3 surface_only(const MeshData3& m, const std::string& format, bool holds_refs) {
  if (!m.tetrahedra.empty()) {
    warn(std::to_string(m.tetrahedra.size()) + " tetrahedra not written: " + format + " holds triangles only" +
         (nonzero(m.tetrahedron_refs) ? " (their region references go with them)" : ""));
  }
  if (!m.edges.empty()) {
    warn(std::to_string(m.edges.size()) + " edges not written: " + format + " holds triangles only" +
         (nonzero(m.edge_refs) ? " (their references go with them)" : ""));
  }
  if (!holds_refs) {
    if (const std::size_t n = nonzero(m.triangle_refs); n > 0) {
      warn(std::to_string(n) + " triangle references not written: " + format + " has no references");
    }
    if (const std::size_t n = nonzero(m.vertex_refs); n > 0) {
      warn(std::to_string(n) + " vertex references not written: " + format + " has no references");
    }
  }
  MeshData3 s;
  s.vertices = m.vertices;
  s.vertex_refs = m.vertex_refs;
  s.triangles = m.triangles;
  s.triangle_refs = m.triangle_refs;
  return s;
}

// 1 / Q_K (kernel/quality.hpp) of the elements, 1 equilateral, 0 flat; -1 for the boundary pieces.
VtuField quality_field(const MeshData3& m, int dimension) {
  VtuField f{"quality", 1, {}};
  f.values.assign(m.edges.size(), -1.0);
  const auto& p = m.vertices;
  for (const auto& t : m.triangles) {
    if (dimension == 3) {
      f.values.push_back(-1.0);
      continue;
    }
    const double q = shape_quality(Vec2{p[t[0]].x, p[t[0]].y}, Vec2{p[t[1]].x, p[t[1]].y}, Vec2{p[t[2]].x, p[t[2]].y});
    f.values.push_back(std::isfinite(q) && q > 0 ? 1.0 / q : 0.0);
  }
  for (const auto& t : m.tetrahedra) {
    const double q = shape_quality(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    f.values.push_back(std::isfinite(q) && q > 0 ? 1.0 / q : 0.0);
  }
  return f;
}

// `path`: where to write (a scratch folder); args.out names the output in messages.
void write_any(const std::string& path, const AnyMesh& m, const ConvertArgs& args) {
  const std::string ext = extension_of(path);
  if (args.binary && ext != "msh" && ext != "stl") {
    throw InputError("--binary applies to .msh and .stl outputs (Medit binary is .meshb), not '" + args.out + "'");
  }
  if ((!args.sol.empty() || args.quality) && ext != "vtu") {
    throw InputError("--sol and --quality add fields to a .vtu output, not to '" + args.out + "'");
  }
  if (ext == "mesh" || ext == "meshb") {
    warn_names(m, ext == "mesh" ? "Medit .mesh" : "Medit .meshb");
    if (ext == "mesh") {
      if (m.dimension == 2) return write_medit2(path, m.mesh2);
      return write_medit3(path, m.mesh3);
    }
    if (m.dimension == 2) return write_meshb2(path, m.mesh2);
    return write_meshb3(path, m.mesh3);
  }
  if (ext == "msh") return write_gmsh(path, m.as3(), m.names, args.binary ? GmshEncoding::Binary : GmshEncoding::Ascii);
  if (ext == "vtu") {
    warn_names(m, "VTK .vtu");
    const MeshData3 mesh = m.as3();
    VtuFields fields;
    if (!args.sol.empty()) {
      const SolData sol = read_medit_sol(args.sol);
      check_sol_matches(sol, mesh.vertices.size(), args.sol);
      if (sol.dimension != m.dimension) {
        throw InputError(args.sol + ": a " + std::to_string(sol.dimension) + "D solution for a " +
                         std::to_string(m.dimension) + "D mesh");
      }
      fields.point_data.push_back({sol.kind == SolData::Kind::Scalar ? "size" : "metric",
                                   static_cast<int>(sol.values_per_vertex()), sol.values});
    }
    if (args.quality) fields.cell_data.push_back(quality_field(mesh, m.dimension));
    return write_vtu(path, mesh, fields);
  }
  if (ext == "ele" || ext == "node") {
    const std::string base = without_extension(path);
    if (m.dimension == 2) {
      warn_names(m, "Triangle .node/.ele");
      if (!m.mesh2.edges.empty()) {
        warn(std::to_string(m.mesh2.edges.size()) + " edges not written: Triangle's .node/.ele has no edges" +
             (nonzero(m.mesh2.edge_refs) ? " (their boundary references go with them)" : ""));
      }
      return write_triangle_mesh(base, m.mesh2);
    }
    warn_names(m, "TetGen .node/.ele/.face");
    if (!m.mesh3.edges.empty()) {
      warn(std::to_string(m.mesh3.edges.size()) + " edges not written: TetGen's .node/.ele/.face has no edges" +
           (nonzero(m.mesh3.edge_refs) ? " (their references go with them)" : ""));
    }
    return write_tetgen_mesh(base, m.mesh3);
  }
  if (ext == "off" || ext == "stl") {
    const std::string format = ext == "off" ? "OFF" : "STL";
    warn_names(m, format);
    const MeshData3 s = surface_only(m.as3(), format, false);
    if (ext == "off") return write_off(path, s);
    return write_stl(path, s, args.binary ? StlEncoding::Binary : StlEncoding::Ascii);
  }
  throw InputError("cannot write '" + args.out +
                   "': supported outputs are .mesh, .meshb (Medit), .msh (Gmsh 4.1), .vtu (VTK), .ele/.node "
                   "(Triangle, TetGen), .off, .stl");
}

void run_convert(const ConvertArgs& args) {
  StagedOutputs outputs({args.out});
  const AnyMesh m = read_any(args.in);
  outputs.write(args.out, [&](const std::string& path) { write_any(path, m, args); });
  outputs.commit();
}

}  // namespace

void add_convert(CLI::App& app) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Convert a mesh between formats, told by the extensions: .mesh .meshb (Medit), .msh (Gmsh; 4.1 and 2.2 read, "
      "4.1 written), .vtu (VTK, written), .ele/.node (Triangle 2D, TetGen 3D), .off, .stl. References, regions and "
      "boundary markers are kept; what the target cannot hold is named on stderr. docs/formats.md has the table.");
  cmd->add_option("IN", args->in, "input mesh")->required();
  cmd->add_option("OUT", args->out, "output mesh (Triangle/TetGen: OUT.ele writes OUT.node, OUT.ele [, OUT.face])")
      ->required();
  cmd->add_flag("--binary", args->binary, "binary .msh (MSH 4.1 binary) or .stl output");
  cmd->add_option("--sol", args->sol, ".vtu output: a Medit .sol/.solb at the vertices, written as point data "
                                      "(\"size\" or \"metric\")");
  cmd->add_flag("--quality", args->quality,
                ".vtu output: cell data \"quality\" = 1/Q_K of each element (1 equilateral, 0 flat; -1 on boundary "
                "pieces)");
  cmd->callback([args] {
    run_convert(*args);
    exit_code() = 0;
  });
}

}  // namespace dtlab::cli
