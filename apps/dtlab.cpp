// The `dtlab` command: one binary, one subcommand per capability as it lands. main() is in
// apps/main.cpp; this is the library's entry (apps/run.hpp).
#include <exception>
#include <iostream>
#include <new>

#include "apps/run.hpp"
#include "apps/subcommands.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/error.hpp"

namespace dtlab::cli {

int run(int argc, char** argv) {
  exit_code() = 0;
  CLI::App app{"dtlab: robust Delaunay triangulation and meshing on exact predicates"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version",
                       std::string("dtlab ") + dtlab::build_info::kVersion + " (commit " +
                           dtlab::build_info::kCommit + ", " + dtlab::build_info::kCompiler + ", " +
                           dtlab::build_info::kBuildType + ")");
  dtlab::cli::add_delaunay(app);
  dtlab::cli::add_verify(app);
  dtlab::cli::add_constrain(app);
  dtlab::cli::add_optimize(app);
  dtlab::cli::add_mesh(app);
  dtlab::cli::add_convert(app);
  dtlab::cli::add_quality(app);
  dtlab::cli::add_adapt(app);
  dtlab::cli::add_metric(app);
  dtlab::cli::add_plot(app);
  dtlab::cli::add_transfer(app);
  dtlab::cli::add_selfcheck(app);
  // Exit codes (docs/cli.md): 0 done, 1 refused (bad input or options, an unwritable output,
  // out of memory, an internal error: the message says which), 3 a --verify check failed;
  // nothing else. CLI11's own codes (105, 106, 109, ...) are folded into 1, its message prefixed.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help and --version print and exit 0
    // A bad option or value: one line naming it, like every other refusal (not CLI11's two lines,
    // whose first has no `dtlab:`).
    std::cerr << "dtlab: " << e.what() << " (see --help)\n";
    return 1;
  } catch (const dtlab::Error& e) {
    std::cerr << "dtlab: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "dtlab: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "dtlab: internal error: " << e.what() << "\n";
    return 1;
  }
  if (app.get_subcommands().empty()) {
    std::cout << app.help();
  }
  return dtlab::cli::exit_code();
}

}  // namespace dtlab::cli
