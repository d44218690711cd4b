// libFuzzer target: arbitrary bytes through the finite-element format readers: Gmsh .msh (4.1
// and 2.2, ASCII and binary, told by $MeshFormat) and Medit binary .meshb (2D and 3D). A reader
// may only return or throw dtlab::Error (ParseError for bad input); any other exception escapes
// and is reported as a crash. Whatever a reader accepts must survive a write/read round trip bit
// for bit, in every encoding and version the writers have, with its physical names; the writers
// may refuse only what their headers say (Gmsh: a negative reference), and then with InputError.
// The tetrahedra handed to MeshData3 must be positive. The seeds (fuzz/corpus/mesh_formats) are
// the files of data/gmsh that Gmsh 4.8 wrote, and .meshb files dtlab wrote from them.
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/medit_binary.hpp"
#include "mesh/io/planar_mesh.hpp"

namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

bool same_bits(const dtlab::MeshData3& a, const dtlab::MeshData3& b) {
  if (!(a == b)) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a.vertices[i].x) != std::bit_cast<std::uint64_t>(b.vertices[i].x) ||
        std::bit_cast<std::uint64_t>(a.vertices[i].y) != std::bit_cast<std::uint64_t>(b.vertices[i].y) ||
        std::bit_cast<std::uint64_t>(a.vertices[i].z) != std::bit_cast<std::uint64_t>(b.vertices[i].z)) {
      return false;
    }
  }
  return true;
}

bool well_formed(const dtlab::MeshData3& m) {
  const std::size_t n = m.vertices.size();
  auto in_range = [n](const auto& cells) {
    for (const auto& c : cells) {
      for (std::uint32_t v : c) {
        if (v >= n) return false;
      }
    }
    return true;
  };
  for (const auto& t : m.tetrahedra) {
    const auto& v = m.vertices;
    if (t[0] >= n || t[1] >= n || t[2] >= n || t[3] >= n) return false;
    if (dtlab::uncounted::orient3d(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) != dtlab::Sign::Positive) return false;
  }
  return in_range(m.edges) && in_range(m.triangles) && m.vertex_refs.size() == n &&
         m.edge_refs.size() == m.edges.size() && m.triangle_refs.size() == m.triangles.size() &&
         m.tetrahedron_refs.size() == m.tetrahedra.size();
}

bool has_negative_ref(const dtlab::MeshData3& m) {
  for (const std::vector<int>* refs : {&m.vertex_refs, &m.edge_refs, &m.triangle_refs, &m.tetrahedron_refs}) {
    for (int r : *refs) {
      if (r < 0) return true;
    }
  }
  return false;
}

template <class Read>
void guarded(const std::string& bytes, Read&& read) {
  std::istringstream in(bytes);
  try {
    read(in);
  } catch (const dtlab::Error&) {
    // Refusing bad input is the readers' job.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);

  guarded(bytes, [](std::istream& in) {
    const dtlab::GmshMesh g = dtlab::read_gmsh(in, "fuzz.msh");
    require(well_formed(g.mesh));
    for (const dtlab::GmshEncoding e : {dtlab::GmshEncoding::Ascii, dtlab::GmshEncoding::Binary}) {
      std::stringstream again;
      try {
        dtlab::write_gmsh(again, g.mesh, g.names, e);
      } catch (const dtlab::InputError&) {
        require(has_negative_ref(g.mesh));
        continue;
      }
      require(!has_negative_ref(g.mesh));
      const dtlab::GmshMesh back = dtlab::read_gmsh(again, "rewritten.msh");
      require(same_bits(g.mesh, back.mesh) && back.names == g.names && back.notes.empty());
    }
    if (dtlab::is_planar(g.mesh)) {
      const dtlab::MeshData2 m2 = dtlab::planar_to_mesh2(g.mesh, "fuzz.msh");
      std::stringstream b;
      dtlab::write_meshb2(b, m2);
      require(same_bits(dtlab::planar_to_mesh3(dtlab::read_meshb2(b, "fuzz2.meshb")), dtlab::planar_to_mesh3(m2)));
    }
  });

  guarded(bytes, [](std::istream& in) {
    const dtlab::MeshData3 m = dtlab::read_meshb3(in, "fuzz3.meshb");
    require(well_formed(m));
    for (int version : {2, 3, 4}) {
      std::stringstream again;
      dtlab::write_meshb3(again, m, version);
      require(same_bits(m, dtlab::read_meshb3(again, "rewritten3.meshb")));
    }
  });

  guarded(bytes, [](std::istream& in) {
    const dtlab::MeshData2 m = dtlab::read_meshb2(in, "fuzz2.meshb");
    for (int version : {2, 4}) {
      std::stringstream again;
      dtlab::write_meshb2(again, m, version);
      require(same_bits(dtlab::planar_to_mesh3(m), dtlab::planar_to_mesh3(dtlab::read_meshb2(again, "rewritten2.meshb"))));
    }
  });

  guarded(bytes, [&](std::istream&) {
    const int d = dtlab::medit_binary_dimension(bytes, "fuzz.meshb");
    require(d == 2 || d == 3);
  });
  return 0;
}
