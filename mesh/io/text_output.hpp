// Number formatting shared by the ASCII mesh writers.
//
// Doubles are written with std::to_chars in its shortest form that reads back to the same
// double (C++17 guarantees the round trip), so a write/read cycle keeps every bit, -0 included.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

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

// Writers accept an empty refs vector (0 for every element) or one ref per element.
inline void check_refs(const std::vector<int>& refs, std::size_t count, const char* noun) {
  if (!refs.empty() && refs.size() != count) {
    throw InputError(std::string(noun) + " references: " + std::to_string(refs.size()) + " for " +
                     std::to_string(count) + " elements");
  }
}

// Throws InputError naming the first element with a vertex out of range, or refs of the wrong size.
template <std::size_t N>
void check_cells(const std::vector<std::array<std::uint32_t, N>>& cells, const std::vector<int>& refs,
                 std::size_t vertex_count, const char* noun) {
  check_refs(refs, cells.size(), noun);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::uint32_t v : cells[i]) {
      if (v >= vertex_count) {
        throw InputError(std::string(noun) + " " + std::to_string(i) + ": vertex " + std::to_string(v) +
                             " out of range (" + std::to_string(vertex_count) + " vertices)",
                         {i});
      }
    }
  }
}

// A Medit section of elements: keyword, count, then "v1 .. vN ref" numbered from 1; nothing if empty.
template <std::size_t N>
void append_medit_cells(std::string& out, const char* keyword, const std::vector<std::array<std::uint32_t, N>>& cells,
                        const std::vector<int>& refs) {
  if (cells.empty()) return;
  out += "\n";
  out += keyword;
  out += "\n";
  append_integer(out, static_cast<std::int64_t>(cells.size()));
  out += "\n";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::uint32_t v : cells[i]) {
      append_integer(out, static_cast<std::int64_t>(v) + 1);
      out += ' ';
    }
    append_integer(out, refs.empty() ? 0 : refs[i]);
    out += '\n';
  }
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
