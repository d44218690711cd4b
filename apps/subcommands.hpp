// Each subcommand of `dtlab` lives in its own file and registers itself on the app here.
#pragma once

#include <CLI/CLI.hpp>

namespace dtlab::cli {

void add_selfcheck(CLI::App& app);

}  // namespace dtlab::cli
