#include "mesh/io/staged_outputs.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "kernel/error.hpp"

namespace dtlab {

namespace fs = std::filesystem;

namespace {

std::string folder_of(const std::string& target) { return fs::path(target).parent_path().string(); }

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

[[noreturn]] void refuse(const std::string& target, const std::string& why) {
  throw InputError("cannot write '" + target + "': " + why);
}

}  // namespace

void check_output_target(const std::string& target) {
  const std::string folder = folder_of(target);
  const std::string shown = folder.empty() ? "." : folder;
  std::error_code ec;
  const fs::file_status folder_status = fs::status(shown, ec);
  if (!fs::exists(folder_status)) refuse(target, "no folder '" + shown + "'");
  if (!fs::is_directory(folder_status)) refuse(target, "'" + shown + "' is not a folder");
  if (::access(shown.c_str(), W_OK | X_OK) != 0) refuse(target, "the folder '" + shown + "' is not writable");
  if (fs::path(target).filename().empty() || fs::is_directory(fs::status(target, ec)))
    refuse(target, "it is a folder (give a file name)");
}

StagedOutputs::StagedOutputs(std::initializer_list<std::string> targets) {
  for (const std::string& target : targets)
    if (!target.empty()) check_output_target(target);
}

StagedOutputs::~StagedOutputs() {
  for (const Scratch& s : scratch_) {
    std::error_code ignored;
    fs::remove_all(s.folder, ignored);
  }
}

void StagedOutputs::write(const std::string& target, const std::function<void(const std::string&)>& write) {
  if (target.empty()) return;
  check_output_target(target);
  const std::string target_folder = folder_of(target);
  const std::string name = ".dtlab-partial-" + std::to_string(::getpid()) + "-" + std::to_string(scratch_.size());
  const std::string folder = target_folder.empty() ? name : (fs::path(target_folder) / name).string();
  std::error_code ec;
  fs::remove_all(folder, ec);
  if (!fs::create_directory(folder, ec) || ec) refuse(target, ec ? ec.message() : "cannot make a scratch folder");
  scratch_.push_back({folder, target_folder});
  const std::string path = (fs::path(folder) / fs::path(target).filename()).string();
  try {
    write(path);
  } catch (const InputError& e) {  // the writer names the scratch path: name the target
    throw InputError(replace_all(e.what(), folder + "/", target_folder.empty() ? "" : target_folder + "/"), e.items());
  } catch (const fs::filesystem_error& e) {
    refuse(target, e.code().message());
  }
}

void StagedOutputs::commit() {
  for (const Scratch& s : scratch_) {
    std::error_code ec;
    fs::directory_iterator files(s.folder, ec);
    if (ec) refuse(s.folder, ec.message());
    for (const fs::directory_entry& entry : files) {
      const fs::path to = fs::path(s.target_folder) / entry.path().filename();
      fs::rename(entry.path(), to, ec);
      if (ec) refuse(to.string(), ec.message());
    }
    fs::remove_all(s.folder, ec);
  }
  scratch_.clear();
}

}  // namespace dtlab
