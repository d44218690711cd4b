// Small helpers shared by the subcommands: resource use, JSON fields, option validators.
#pragma once

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "verify/problem_report.hpp"  // json_string

namespace dtlab::cli {

// Peak resident set size of this process so far, in MB.
inline double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

inline std::string json_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Lower-case extension of a path, without the dot ("" if none).
inline std::string extension_of(std::string_view path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return "";
  std::string ext(path.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

// A validator for an integer option in [lo, hi]. CLI11 reads "-5" into an unsigned option as a
// huge number (or fails with "Could not convert"), so the sign is looked at first; CLI11 puts the
// option's name before the message ("--random: Value -5 is negative: ...").
inline CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& input) -> std::string {
        const std::size_t first = input.find_first_not_of(" \t");
        if (first != std::string::npos && input[first] == '-')
          return "Value " + input + " is negative: give an integer in " + range;
        std::uint64_t v = 0;
        if (!CLI::detail::lexical_cast(input, v)) return "Value " + input + " is not an integer (give one in " + range + ")";
        if (v < lo || v > hi) return "Value " + input + " not in range " + range;
        return {};
      },
      "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

}  // namespace dtlab::cli
