// Errors at the API are values that name the offending items (STYLE.md, guideline 6).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace dtlab {

// Base of every error dtlab throws at its API.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Input that dtlab refuses: the message says what is wrong, `items` lists the offending input
// indices (points, segments, faces: the message says which kind), 0-based.
class InputError : public Error {
 public:
  InputError(const std::string& message, std::vector<std::uint64_t> items = {})
      : Error(message), items_(std::move(items)) {}
  const std::vector<std::uint64_t>& items() const noexcept { return items_; }

 private:
  std::vector<std::uint64_t> items_;
};

// A file that cannot be read: file, line and reason are in the message and in the fields.
class ParseError : public Error {
 public:
  ParseError(std::string file, std::uint64_t line, const std::string& reason)
      : Error(file + ":" + std::to_string(line) + ": " + reason), file_(std::move(file)), line_(line) {}
  const std::string& file() const noexcept { return file_; }
  std::uint64_t line() const noexcept { return line_; }

 private:
  std::string file_;
  std::uint64_t line_;
};

// An internal invariant failed: a bug in dtlab, reported with file and line, never an abort.
class InternalError : public Error {
 public:
  using Error::Error;
};

[[noreturn]] void throw_internal_error(const char* condition, const char* file, int line);

}  // namespace dtlab

// Internal invariant check that reports file and line (STYLE.md, guideline 6).
#define DTLAB_ASSERT(condition) \
  ((condition) ? static_cast<void>(0) : ::dtlab::throw_internal_error(#condition, __FILE__, __LINE__))
