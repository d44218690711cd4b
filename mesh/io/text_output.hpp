// Number formatting shared by the ASCII mesh writers.
//
// Doubles are written with std::to_chars in its shortest form that reads back to the same
// double (C++17 guarantees the round trip), so a write/read cycle keeps every bit, -0 included.
#pragma once

#include <charconv>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>

#include "kernel/error.hpp"

namespace dtlab::io {

inline void append_real(std::string& out, double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  DTLAB_ASSERT(ec == std::errc());
  out.append(buf, end);
}

inline void append_integer(std::string& out, std::int64_t v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  DTLAB_ASSERT(ec == std::errc());
  out.append(buf, end);
}

// Opens `path` for writing or throws Error naming it.
inline std::ofstream open_for_writing(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error("cannot open " + path + " for writing");
  return out;
}

// Throws Error naming `path` if a write to `out` failed.
inline void check_written(const std::ostream& out, const std::string& path) {
  if (!out) throw Error("write to " + path + " failed");
}

// Opens `path` for reading or throws ParseError (line 0) naming it.
inline std::ifstream open_for_reading(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, "cannot open file");
  return in;
}

}  // namespace dtlab::io
