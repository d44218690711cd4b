// The `dtlab` command as a function: main() (apps/main.cpp) calls it, and so does the CLI fuzz
// target (fuzz/cli_fuzz.cpp), in-process.
#pragma once

namespace dtlab::cli {

// Parses argv, runs the subcommand and returns the exit status (docs/cli.md, "Exit codes"):
// 0 done, 1 refused (a `dtlab: ...` line on stderr), 3 a --verify check failed. Each call builds
// its own CLI11 app; the status a subcommand sets (exit_code()) is reset first.
int run(int argc, char** argv);

}  // namespace dtlab::cli
