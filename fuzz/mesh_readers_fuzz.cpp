// libFuzzer target: arbitrary bytes through every 2D file reader (Medit .mesh, Triangle
// .node/.ele, point files). A reader may only return or throw dtlab::Error (ParseError for bad
// input); any other exception escapes and is reported as a crash. Whatever a reader accepts
// must survive a write/read round trip bit for bit.
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kernel/error.hpp"
#include "mesh/io/medit.hpp"
#include "mesh/io/point_file.hpp"
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
  guarded(text, [](std::istream& in) { dtlab::point_file_dimension(in, "fuzz.pts"); });
  return 0;
}
