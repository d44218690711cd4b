// constrained3d_inputs OUTDIR: writes the Schönhardt family as OFF surfaces (outward triangles),
// the inputs of scripts/bench_constrained3d.py that no file ships: Schönhardt's polyhedron at
// three twists, twisted n-gonal prisms, a stack of twisted prisms, Bagemihl polyhedra and
// Chazelle's polyhedron
// (verify/generators/schonhardt.hpp). Prints one file name per line.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "verify/generators/schonhardt.hpp"
#include "mesh/io/mesh_data3.hpp"
#include "mesh/io/off_format.hpp"

namespace {

void write(const std::filesystem::path& dir, const std::string& name, const dtlab::ClosedSurface3& surface) {
  dtlab::MeshData3 mesh;
  mesh.vertices = surface.points;
  mesh.triangles = surface.triangles;
  const std::filesystem::path path = dir / (name + ".off");
  dtlab::write_off(path.string(), mesh);
  std::printf("%s\n", path.string().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    for (const int twist : {5, 30, 55}) write(dir, "schonhardt_" + std::to_string(twist), dtlab::schonhardt_polyhedron(twist));
    for (const int sides : {4, 6, 8})
      write(dir, "twisted_prism_" + std::to_string(sides),
            dtlab::twisted_prism({.sides = sides, .twist_degrees = 90.0 / sides}));
    write(dir, "prism_stack_3x3", dtlab::twisted_prism({.sides = 3, .twist_degrees = 30, .layers = 3}));
    for (const int n : {7, 16, 40}) write(dir, "bagemihl_" + std::to_string(n), dtlab::bagemihl_polyhedron(n));
    for (const int n : {2, 4, 8}) write(dir, "chazelle_" + std::to_string(n), dtlab::chazelle_polyhedron(n));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "constrained3d_inputs: %s\n", e.what());
    return 1;
  }
  return 0;
}
