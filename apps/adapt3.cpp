// Placeholder until the 3D adaptation lands (branch adapt3d): refuses 3D input with a named error
// rather than pretending. Replaced by the real 3D path of `dtlab adapt`.
#include "apps/adapt3.hpp"

#include "kernel/error.hpp"

namespace dtlab::cli {

int run_adapt3(const Adapt3CliArgs& args) {
  throw InputError(args.input + ": 3D adaptation is not available in this build yet");
}

}  // namespace dtlab::cli
