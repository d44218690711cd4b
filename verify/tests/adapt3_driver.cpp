// adapt3_driver MESH SOL OUT [ROUNDS]: run_adapt3 (apps/adapt3.hpp) with --stats, for
// scripts/ugawg_adapt.py until apps/adapt.cpp registers `dtlab adapt` for 3D meshes.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "apps/adapt3.hpp"

int main(int argc, char** argv) {
  if (argc < 4 || argc > 5) {
    std::cerr << "usage: adapt3_driver MESH SOL OUT [ROUNDS]\n";
    return 2;
  }
  dtlab::cli::AdaptRequest r;
  r.mesh = argv[1];
  r.metric = argv[2];
  r.output = argv[3];
  if (argc == 5) r.max_rounds = static_cast<std::uint32_t>(std::strtoul(argv[4], nullptr, 10));
  r.stats = true;
  try {
    return dtlab::cli::run_adapt3(r);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
