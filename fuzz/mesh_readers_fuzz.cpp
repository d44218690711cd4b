// libFuzzer target: arbitrary bytes through every file reader: 2D (Medit .mesh, Triangle
// .node/.ele/.poly, point files), 3D (Medit .mesh, TetGen .node/.ele/.face) and surfaces (OFF,
// STL ASCII and binary, TetGen .poly/.smesh and their facet triangulation). Each reader gets
// the same bytes, so one seed in any format serves them all and the others refuse it early. A
// reader may only return or throw dtlab::Error (ParseError for bad input); any other exception
// escapes and is reported as a crash. Whatever a reader accepts must survive a write/read round
// trip bit for bit, and the tetrahedra it hands to MeshData3 must be positive.
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/medit3.hpp"
#include "mesh/io/off_format.hpp"
#include "mesh/io/point_file.hpp"
#include "mesh/io/poly_format.hpp"
#include "mesh/io/stl_format.hpp"
#include "mesh/io/tetgen_format.hpp"
#include "mesh/io/tetgen_poly.hpp"
#include "mesh/io/triangle_format.hpp"

namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

bool same_bits(const std::vector<dtlab::Vec2>& a, const std::vector<dtlab::Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
        std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y)) {
      return false;
    }
  }
  return true;
}

bool same_bits(const std::vector<dtlab::Vec3>& a, const std::vector<dtlab::Vec3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
        std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y) ||
        std::bit_cast<std::uint64_t>(a[i].z) != std::bit_cast<std::uint64_t>(b[i].z)) {
      return false;
    }
  }
  return true;
}

// Every element's vertices in range and one reference per element: what a surface reader and
// triangulate_plc_facets promise.
bool well_formed_surface(const dtlab::MeshData3& mesh) {
  const std::size_t n = mesh.vertices.size();
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      if (v >= n) return false;
    }
  }
  for (const auto& e : mesh.edges) {
    if (e[0] >= n || e[1] >= n) return false;
  }
  return mesh.vertex_refs.size() == n && mesh.triangle_refs.size() == mesh.triangles.size() &&
         mesh.edge_refs.size() == mesh.edges.size() && mesh.tetrahedra.empty();
}

bool all_positive(const dtlab::MeshData3& mesh) {
  for (const auto& t : mesh.tetrahedra) {
    const auto& v = mesh.vertices;
    if (dtlab::uncounted::orient3d(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) != dtlab::Sign::Positive) return false;
  }
  return true;
}

template <class Read>
void guarded(const std::string& text, Read&& read) {
  std::istringstream in(text);
  try {
    read(in);
  } catch (const dtlab::Error&) {
    // Refusing bad input is the readers' job.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);

  guarded(text, [](std::istream& in) {
    const dtlab::MeshData2 mesh = dtlab::read_medit2(in, "fuzz.mesh");
    std::stringstream again;
    dtlab::write_medit2(again, mesh);
    const dtlab::MeshData2 back = dtlab::read_medit2(again, "rewritten.mesh");
    require(same_bits(mesh.vertices, back.vertices) && mesh.vertex_refs == back.vertex_refs &&
            mesh.edges == back.edges && mesh.edge_refs == back.edge_refs && mesh.triangles == back.triangles &&
            mesh.triangle_refs == back.triangle_refs);
  });

  // The same bytes as a .node file, then as a .ele file over those nodes or over five fixed ones.
  dtlab::TriangleNodes nodes;
  guarded(text, [&](std::istream& in) {
    nodes = dtlab::read_triangle_node(in, "fuzz.node");
    std::stringstream again;
    dtlab::write_triangle_node(again, nodes);
    require(same_bits(nodes.points, dtlab::read_triangle_node(again, "rewritten.node").points));
  });
  if (nodes.points.empty()) {
    nodes.points = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}};
    nodes.first_index = size > 0 && (data[0] & 1) ? 0 : 1;
  }
  guarded(text, [&](std::istream& in) {
    const dtlab::TriangleElements e = dtlab::read_triangle_ele(in, "fuzz.ele", nodes);
    std::stringstream again;
    dtlab::write_triangle_ele(again, e, nodes.points.size());
    require(dtlab::read_triangle_ele(again, "rewritten.ele", nodes).triangles == e.triangles);
  });

  guarded(text, [](std::istream& in) {
    const std::vector<dtlab::Vec2> points = dtlab::read_point_file2(in, "fuzz.xy");
    std::stringstream again;
    dtlab::write_point_file(again, points);
    require(same_bits(points, dtlab::read_point_file2(again, "rewritten.xy")));
  });
  guarded(text, [](std::istream& in) { dtlab::read_point_file3(in, "fuzz.xyz"); });

  guarded(text, [](std::istream& in) {
    const dtlab::PolyData2 poly = dtlab::read_triangle_poly(in, "fuzz.poly");
    std::stringstream again;
    dtlab::write_triangle_poly(again, poly);
    const dtlab::PolyData2 back = dtlab::read_triangle_poly(again, "rewritten.poly");
    require(back == poly && same_bits(poly.points, back.points) && same_bits(poly.holes, back.holes));
  });

  guarded(text, [](std::istream& in) {
    const dtlab::MeshData3 mesh = dtlab::read_medit3(in, "fuzz3.mesh");
    require(all_positive(mesh));
    std::stringstream again;
    dtlab::write_medit3(again, mesh);
    const dtlab::MeshData3 back = dtlab::read_medit3(again, "rewritten3.mesh");
    require(back == mesh && same_bits(mesh.vertices, back.vertices));
  });

  // TetGen: the bytes as a .node, then as a .ele and a .face over those nodes or over five fixed
  // ones in general position (so that some tetrahedra are not flat).
  dtlab::TetGenNodes nodes3;
  guarded(text, [&](std::istream& in) {
    nodes3 = dtlab::read_tetgen_node(in, "fuzz.node");
    std::stringstream again;
    dtlab::write_tetgen_node(again, nodes3);
    const dtlab::TetGenNodes back = dtlab::read_tetgen_node(again, "rewritten.node");
    require(same_bits(nodes3.points, back.points) && back.markers == nodes3.markers &&
            back.attributes.size() == nodes3.attributes.size());
  });
  if (nodes3.points.empty()) {
    nodes3.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    nodes3.first_index = size > 0 && (data[0] & 1) ? 0 : 1;
  }
  guarded(text, [&](std::istream& in) {
    const dtlab::TetGenElements e = dtlab::read_tetgen_ele(in, "fuzz.ele", nodes3);
    std::stringstream again;
    dtlab::write_tetgen_ele(again, e, nodes3.points.size());
    const dtlab::TetGenElements back = dtlab::read_tetgen_ele(again, "rewritten.ele", nodes3);
    require(back.tetrahedra == e.tetrahedra && back.midside == e.midside && back.orientation == e.orientation);
    if (e.midside.empty()) require(all_positive(dtlab::to_mesh_data3(nodes3, e)));
  });
  guarded(text, [&](std::istream& in) {
    const dtlab::TetGenFaces f = dtlab::read_tetgen_face(in, "fuzz.face", nodes3);
    std::stringstream again;
    dtlab::write_tetgen_face(again, f, nodes3.points.size());
    const dtlab::TetGenFaces back = dtlab::read_tetgen_face(again, "rewritten.face", nodes3);
    require(back.triangles == f.triangles && back.markers == f.markers);
  });
  guarded(text, [](std::istream& in) { dtlab::point_file_dimension(in, "fuzz.pts"); });

  // Surfaces. OFF and STL: whatever is read is a well-formed surface and comes back bit for bit;
  // STL's vertices are merged and numbered by first use, so its write/read cycle is exact too.
  guarded(text, [](std::istream& in) {
    const dtlab::MeshData3 mesh = dtlab::read_off(in, "fuzz.off");
    require(well_formed_surface(mesh));
    std::stringstream again;
    dtlab::write_off(again, mesh);
    const dtlab::MeshData3 back = dtlab::read_off(again, "rewritten.off");
    require(back == mesh && same_bits(mesh.vertices, back.vertices));
  });
  guarded(text, [&](std::istream& in) {
    const dtlab::MeshData3 mesh = dtlab::read_stl(in, "fuzz.stl");
    require(well_formed_surface(mesh));
    const bool binary = dtlab::detect_stl_encoding(text) == dtlab::StlEncoding::Binary;
    // ASCII coordinates need not be floats; binary ones always are, so both encodings apply.
    for (const dtlab::StlEncoding e : {dtlab::StlEncoding::Ascii, dtlab::StlEncoding::Binary}) {
      if (e == dtlab::StlEncoding::Binary && !binary) continue;
      std::stringstream again;
      dtlab::write_stl(again, mesh, e);
      require(dtlab::detect_stl_encoding(again.str()) == e);
      const dtlab::MeshData3 back = dtlab::read_stl(again, "rewritten.stl");
      require(back.triangles == mesh.triangles && same_bits(mesh.vertices, back.vertices));
    }
  });

  // TetGen PLCs: round trip of the whole Plc3, then the facet triangulation, which may refuse a
  // polygon (InputError) but otherwise returns a well-formed surface with the PLC's vertices.
  using ReadPlc = dtlab::Plc3 (*)(std::istream&, const std::string&, const dtlab::TetGenNodes*);
  for (const ReadPlc read : {static_cast<ReadPlc>(dtlab::read_tetgen_poly), static_cast<ReadPlc>(dtlab::read_tetgen_smesh)}) {
    const bool smesh = read == static_cast<ReadPlc>(dtlab::read_tetgen_smesh);
    guarded(text, [&](std::istream& in) {
      const dtlab::Plc3 plc = read(in, smesh ? "fuzz.smesh" : "fuzz.poly", nullptr);
      std::stringstream again;
      if (smesh) {
        dtlab::write_tetgen_smesh(again, plc);
      } else {
        dtlab::write_tetgen_poly(again, plc);
      }
      const dtlab::Plc3 back = read(again, "rewritten", nullptr);
      require(back == plc && same_bits(plc.vertices, back.vertices) && same_bits(plc.holes, back.holes));
      const dtlab::MeshData3 surface = dtlab::triangulate_plc_facets(plc);
      require(well_formed_surface(surface) && same_bits(surface.vertices, plc.vertices));
    });
  }
  return 0;
}
