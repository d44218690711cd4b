// Small helpers shared by the subcommands: resource use, JSON fields, option validators.
#pragma once

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <string_view>

#include "kernel/error.hpp"
#include "kernel/metric.hpp"  // check_size
#include "mesh/io/any_format.hpp"  // extension_of
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

// A --size H given as text: parsed and refused with the project's message (exit 1) unless
// positive and finite, instead of CLI11's checks (which pass NaN and print 309 digits for 0).
inline double parse_size(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double h = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(h) || !(h > 0.0))
    throw InputError("--size " + text + ": give a positive finite size H (the metric H^-2 I)");
  check_size(h, "--size");  // 1e200 would give H^-2 = 0 (kernel/metric.hpp: the sizes a metric holds)
  return h;
}

// The mesh file a command that measures or draws a mesh (`dtlab quality`, `dtlab plot`) reads:
// a .mesh/.meshb/.msh, a .ele or .node, or the base name of a .node/.ele pair; a surface or a
// .poly/.vtu refused by name.
inline std::string mesh_input_path(const std::string& given, const std::string& command) {
  const std::string ext = extension_of(given);
  if (ext == "mesh" || ext == "meshb" || ext == "msh" || ext == "ele" || ext == "node") return given;
  if (ext == "off" || ext == "stl" || ext == "obj")
    throw InputError(given + ": ." + ext + " holds a surface; dtlab " + command +
                     " reads 2D triangle and 3D tetrahedron meshes (.mesh, .meshb, .msh, .ele/.node)");
  if (ext == "poly" || ext == "vtu")
    throw InputError(given + ": ." + ext + " is not a mesh dtlab " + command +
                     " reads (mesh it first, e.g. `dtlab mesh` or `dtlab constrain`)");
  return given + ".ele";
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
