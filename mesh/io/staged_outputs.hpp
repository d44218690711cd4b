// Outputs written under temporary names beside their targets and moved into place together once
// all of them are written: a command that fails half-way (a bad second output, a writer that
// throws) leaves no file behind, neither a partial one nor the first of two (docs/cli.md, "Exit
// codes and outputs").
//
//   StagedOutputs outputs({args.output, args.output_metric});  // unwritable targets refused now
//   ...the work...
//   outputs.write(args.output, [&](const std::string& path) { write_mesh2(path, mesh); });
//   outputs.write(args.output_metric, [&](const std::string& path) { write_medit_sol(path, sol); });
//   outputs.commit();
//
// Each write goes to a scratch folder in the target's folder (.dtlab-partial-PID-N: the move is a
// rename), under the target's file name; a writer that adds siblings (OUT.node and OUT.face
// beside OUT.ele) writes them there too, and they move with it.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace dtlab {

// An InputError naming `target` unless a file can be written there: its folder exists, is a
// folder and is writable, and `target` is not itself a folder.
void check_output_target(const std::string& target);

class StagedOutputs {
 public:
  // check_output_target for each non-empty target, before any work is done.
  explicit StagedOutputs(std::initializer_list<std::string> targets = {});
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();  // removes whatever was not committed

  // Runs write(path), `path` standing for `target` in a scratch folder; an empty target does
  // nothing. An InputError from the writer names `target`, not the scratch path; a filesystem
  // error is an InputError naming `target`.
  void write(const std::string& target, const std::function<void(const std::string&)>& write);

  // Moves every file written into its target's folder (a file of the same name is replaced).
  void commit();

 private:
  struct Scratch {
    std::string folder;         // .dtlab-partial-PID-N beside the target
    std::string target_folder;  // "" for the working directory
  };
  std::vector<Scratch> scratch_;
};

}  // namespace dtlab
