// Each subcommand of `dtlab` lives in its own file and registers itself on the app here.
#pragma once

#include <CLI/CLI.hpp>

namespace dtlab::cli {

// The status main() returns: a subcommand's callback sets it (0 success, 1 bad input, 3 a check failed).
inline int& exit_code() {
  static int code = 0;
  return code;
}

void add_selfcheck(CLI::App& app);
void add_delaunay(CLI::App& app);
void add_verify(CLI::App& app);
void add_constrain(CLI::App& app);
void add_optimize(CLI::App& app);
void add_quality(CLI::App& app);
void add_mesh(CLI::App& app);
void add_convert(CLI::App& app);
void add_plot(CLI::App& app);
void add_adapt(CLI::App& app);
void add_metric(CLI::App& app);
void add_transfer(CLI::App& app);

}  // namespace dtlab::cli
