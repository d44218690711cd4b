// `dtlab selfcheck`: the kernel's self-check (filled in with the predicate stages).
#include "apps/subcommands.hpp"

namespace dtlab::cli {

void add_selfcheck(CLI::App& app) {
  app.add_subcommand("selfcheck", "Check the exact-predicate kernel on bundled near-degenerate inputs");
}

}  // namespace dtlab::cli
