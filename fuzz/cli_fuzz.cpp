// libFuzzer target: bytes -> a `dtlab` command line and one or two input files -> the CLI run
// in-process (dtlab::cli::run, apps/run.hpp). The exit status must be 0 or 1 (3 only with
// --verify or from `dtlab verify`), and no exception but dtlab's may reach the command's entry:
// run() turns any other std::exception into "dtlab: internal error: ...", which this target
// reads on the captured stderr and traps on. A crash, an abort or a sanitizer report is a finding.
//
// Input layout:
//   byte 0      the subcommand (a fixed list, selfcheck left out: seconds per run)
//   byte 1      the first file's extension (a fixed list)
//   bytes 2-3   16 option bits: bit i adds the subcommand's option i (its own fixed list)
//   bytes 4-11  values for the options that take a number, one byte each, in order (a table of
//               numbers: 0, -1, nan, inf, 1e300, text, small positive ones)
//   bytes 12-13 the first file's length L (little endian, clamped to what is left)
//   then        L bytes of the first file, the rest the second file (a .sol, or the mesh of
//               `dtlab verify`) for the subcommands that read two.
// Bounded work: `dtlab mesh`, `optimize` and `adapt` always get --max-elements 5000 (issue 42
// item 4: the element estimate refuses what would make more), so the size table holds tiny
// sizes too (0.01, 1e-9); `dtlab mesh` gets no --metric/--size-map, `dtlab adapt` a coarse metric
// (size 1e100) written here at the mesh's vertex count, and `dtlab optimize --metric` is left
// out; --random takes at most 7 points. libFuzzer's -timeout and -rss_limit_mb catch what the
// estimate misses.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/run.hpp"
#include "kernel/error.hpp"
#include "mesh/io/any_format.hpp"

namespace {

struct Subcommand {
  const char* name;
  int files;                          // 1: the input; 2: the input and a second file
  const char* second_ext;             // the second file's extension
  std::vector<std::vector<std::string>> options;  // "#" stands for a value from kNumbers
};

// Values of numeric options (tiny sizes bounded by --max-elements, see the header).
const char* const kNumbers[] = {"0", "-1", "nan", "inf", "1e300", "abc", "0.5", "1", "2", "0.01",
                                "1e100", "-inf", "", "1e12", "1e-9", "7"};

const char* const kExtensions[] = {"node", "poly", "mesh", "ele", "msh", "off", "obj", "stl",
                                   "smesh", "txt", "meshb", "sol", "xyz", "vtu"};

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> list = {
      {"delaunay", 1, "", {{"-o", "out.mesh"}, {"-o", "out.ele"}, {"--verify"}, {"--stats"}, {"--algo", "divide-conquer"},
                           {"--algo", "sweep"}, {"--algo", "flip"}, {"--dim", "3"}, {"--algo", "parallel"},
                           {"--threads", "2"}, {"--random", "#"}, {"--seed", "#"}, {"--distribution", "grid"}}},
      {"verify", 2, "mesh", {{"--json"}}},
      {"constrain", 1, "", {{"-o", "out.mesh"}, {"--method", "conforming"}, {"--method", "recover"}, {"--method", "swap"},
                            {"--verify"}, {"--stats"}, {"--keep-exterior"}, {"--merge-coplanar"}, {"--remove-cavities"},
                            {"--steiner-limit", "#"}, {"--swap-order", "random"}}},
      {"mesh", 1, "", {{"-o", "out.mesh"}, {"--size", "#"}, {"--method", "front"}, {"--verify"}, {"--stats"},
                       {"--no-optimize"}, {"--resample-boundary"}, {"--remove-cavities"}, {"--no-remesh"},
                       {"--interpolation", "log-euclidean"}, {"--output-metric", "out.sol"}, {"--keep-boundary"}}},
      {"optimize", 1, "", {{"-o", "out.mesh"}, {"--size", "#"}, {"--rounds", "#"}, {"--shape-only"},
                           {"--split-boundary"}, {"--valence"}, {"--no-remesh"}, {"--stats"}}},
      {"quality", 2, "sol", {{"--size", "#"}, {"--json"}, {"--metric", "@2"}}},
      {"convert", 2, "sol", {{"out.mesh"}, {"out.msh"}, {"out.vtu"}, {"out.ele"}, {"out.off"}, {"out.stl"},
                             {"out.meshb"}, {"--binary"}, {"--quality"}, {"--sol", "@2"}}},
      {"plot", 2, "sol", {{"--histogram"}, {"--color", "reference"}, {"--metric", "@2"}}},
      {"adapt", 1, "", {{"-o", "out.mesh"}, {"--rounds", "#"}, {"--hgrad", "#"}, {"--keep-boundary"},
                        {"--hausd", "#"}, {"--ridge-angle", "#"}, {"--stats"}, {"--output-metric", "out.sol"}}},
      {"metric", 2, "sol", {{"--complexity", "#"}, {"--error", "#"}, {"--norm", "L2"}, {"--hgrad", "#"},
                            {"--hmin", "#"}, {"--hmax", "#"}, {"--relative", "#"}, {"--hessian", "l2"}, {"--stats"}}},
      {"transfer", 2, "sol", {{"--conservative"}, {"--stats"}}},
  };
  return list;
}

void write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// A scalar size of 1e100 at each vertex of the mesh (nothing to refine), or nothing if the mesh
// does not read: adapt then refuses the mesh first.
void write_coarse_metric(const std::string& mesh, const std::string& sol) {
  std::size_t n = 0;
  int dim = 2;
  try {
    dim = dtlab::input_dimension(mesh);
    n = dim == 3 ? dtlab::read_mesh3(mesh).vertices.size() : dtlab::read_mesh2(mesh).vertices.size();
  } catch (const dtlab::Error&) {
  }
  std::ofstream out(sol, std::ios::trunc);
  out << "MeshVersionFormatted 2\nDimension " << dim << "\nSolAtVertices\n" << n << "\n1 1\n";
  for (std::size_t i = 0; i < n; ++i) out << "1e100\n";
  out << "End\n";
}

std::string g_dir;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  char pattern[] = "/tmp/dtlab-cli-fuzz-XXXXXX";
  if (mkdtemp(pattern) == nullptr) std::abort();
  g_dir = pattern;
  if (chdir(g_dir.c_str()) != 0) std::abort();  // outputs are relative names: written here
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 14) return 0;
  const auto& subs = subcommands();
  const Subcommand& sub = subs[data[0] % subs.size()];
  const std::string ext = kExtensions[data[1] % std::size(kExtensions)];
  const unsigned bits = data[2] | (data[3] << 8);
  std::size_t value = 4;
  std::size_t first = data[12] | (data[13] << 8);
  const std::uint8_t* body = data + 14;
  const std::size_t body_size = size - 14;
  if (sub.files == 1 || first > body_size) first = body_size;

  const std::string input = g_dir + "/in." + ext;
  write_file(input, body, first);
  if (ext == "ele") write_file(g_dir + "/in.node", body + first, body_size - first);  // Triangle's pair
  const std::string second = g_dir + "/in2." + (sub.files == 2 ? sub.second_ext : "sol");
  if (sub.files == 2) write_file(second, body + first, body_size - first);

  std::vector<std::string> args = {"dtlab", sub.name};
  bool verify = std::string(sub.name) == "verify";
  if (std::string(sub.name) == "delaunay" && (bits >> 10 & 1)) {
    // --random N: the file is not read, N at most 100.
  } else if (std::string(sub.name) == "verify") {
    args.push_back(input);
    args.push_back(second);
  } else if (std::string(sub.name) == "transfer") {
    args.insert(args.end(), {input, second, input, "-o", "out.sol"});
  } else {
    args.push_back(input);
  }
  bool has_output = false;
  for (std::size_t i = 0; i < sub.options.size() && i < 16; ++i) {
    if (!(bits >> i & 1)) continue;
    for (const std::string& word : sub.options[i]) {
      if (word == "#") {
        std::string v = kNumbers[(value < 12 ? data[value++] : 0) % std::size(kNumbers)];
        if (sub.options[i][0] == "--random" && v != "abc" && v != "" && v != "nan") v = "7";
        args.push_back(v);
      } else if (word == "@2") {
        args.push_back(second);
      } else {
        args.push_back(word);
      }
      if (word == "--verify") verify = true;
      if (word.rfind("out.", 0) == 0) has_output = true;
    }
  }
  const std::string name = sub.name;
  if (name == "mesh" || name == "optimize" || name == "adapt") args.insert(args.end(), {"--max-elements", "5000"});
  if (name == "adapt") {
    const std::string metric = g_dir + "/coarse.sol";
    write_coarse_metric(input, metric);
    args.insert(args.end(), {"--metric", metric});
  }
  if (name == "metric" || name == "transfer") {
    if (name == "metric") args.insert(args.end(), {"--solution", second, "-o", "out.sol"});
  }
  if (name == "plot") args.insert(args.end(), {"-o", "out.svg"});
  if (name == "convert" && !has_output) args.push_back("out.mesh");

  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::ostringstream err, out;
  std::streambuf* const cerr_buf = std::cerr.rdbuf(err.rdbuf());
  std::streambuf* const cout_buf = std::cout.rdbuf(out.rdbuf());
  const int rc = dtlab::cli::run(static_cast<int>(args.size()), argv.data());
  std::cerr.rdbuf(cerr_buf);
  std::cout.rdbuf(cout_buf);

  const std::string message = err.str();
  const bool status_ok = rc == 0 || rc == 1 || (rc == 3 && verify);
  const bool foreign = message.find("dtlab: internal error:") != std::string::npos;
  if (!status_ok || foreign) {
    std::fprintf(stderr, "cli_fuzz: exit status %d%s\n  command:", rc,
                 foreign ? ", an exception that is not dtlab's" : "");
    for (const std::string& a : args) std::fprintf(stderr, " %s", a.c_str());
    std::fprintf(stderr, "\n  stderr: %s\n", message.c_str());
    __builtin_trap();
  }
  return 0;
}
