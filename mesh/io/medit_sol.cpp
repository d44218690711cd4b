// Medit solution files (.sol / .solb) of libMeshb's GMF format: one SolAtVertices field, a
// scalar or a symmetric tensor, read and written in both encodings (see medit_sol.hpp).
#include "mesh/io/medit_sol.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <type_traits>

#include "kernel/error.hpp"
#include "mesh/io/binary_input.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;
using io::quote;

// libMeshb's keyword codes (enum GmfKwdCod) and field types.
constexpr std::int32_t kCodeDimension = 3;
constexpr std::int32_t kCodeEnd = 54;
constexpr std::int32_t kCodeSolAtVertices = 62;
constexpr std::int32_t kTypeScalar = 1;
constexpr std::int32_t kTypeVector = 2;
constexpr std::int32_t kTypeSymmetric = 3;
constexpr std::int32_t kTypeMatrix = 4;

constexpr std::array<std::string_view, 1> kKeptKeywords = {"SolAtVertices"};
// Entries are appended as read; reserving is capped so that a false count allocates nothing big.
constexpr std::size_t kMaxReserve = std::size_t{1} << 16;

std::size_t values_per_vertex(SolData::Kind kind, int dimension) {
  if (kind == SolData::Kind::Scalar) return 1;
  return dimension == 3 ? 6 : 3;
}

std::string type_problem(std::int64_t type) {
  const std::string t = "field type " + std::to_string(type);
  if (type == kTypeVector) return t + " (a vector) is not supported: this reader keeps a scalar (1) or a symmetric tensor (3)";
  if (type == kTypeMatrix) return t + " (a full matrix) is not supported: this reader keeps a scalar (1) or a symmetric tensor (3)";
  return t + " is not a Medit type (1 scalar, 2 vector, 3 symmetric tensor, 4 matrix)";
}

std::string fields_problem(std::int64_t fields) {
  if (fields < 1) return "SolAtVertices number of fields " + std::to_string(fields) + " is not positive";
  return "SolAtVertices with " + std::to_string(fields) +
         " fields: this reader keeps one field (a scalar or a symmetric tensor)";
}

// Names of the values of one vertex, for messages.
std::string field_names(SolData::Kind kind, int dimension) {
  if (kind == SolData::Kind::Scalar) return "value";
  return dimension == 3 ? "m11 m12 m22 m13 m23 m33" : "m11 m12 m22";
}

std::string value_name(SolData::Kind kind, std::size_t k) {
  static constexpr std::array<const char*, 6> kNames = {"m11", "m12", "m22", "m13", "m23", "m33"};
  return kind == SolData::Kind::Scalar ? "value" : kNames[k];
}

// --- ASCII -------------------------------------------------------------------------------------

class AsciiSolReader {
 public:
  AsciiSolReader(std::istream& in, const std::string& name) : in_(in, name) {}

  SolData read() {
    bool have_version = false;
    bool have_dimension = false;
    bool have_section = false;
    while (in_.next_line()) {
      const std::string_view kw = in_.token(0);
      if (!have_version && kw != "MeshVersionFormatted") {
        in_.fail("expected MeshVersionFormatted first, found " + quote(kw));
      }
      if (kw == "MeshVersionFormatted") {
        if (have_version) in_.fail("second MeshVersionFormatted");
        const std::int64_t v = io::medit_keyword_value(in_, "MeshVersionFormatted");
        if (v < 1 || v > 4) in_.fail("MeshVersionFormatted " + std::to_string(v) + " is not 1, 2, 3 or 4");
        have_version = true;
      } else if (kw == "Dimension") {
        if (have_dimension) in_.fail("second Dimension");
        const std::int64_t d = io::medit_keyword_value(in_, "Dimension");
        if (d != 2 && d != 3) in_.fail("Dimension " + std::to_string(d) + " is not 2 or 3");
        sol_.dimension = static_cast<int>(d);
        have_dimension = true;
      } else if (kw == "SolAtVertices") {
        if (!have_dimension) in_.fail("SolAtVertices before Dimension");
        if (have_section) in_.fail("second SolAtVertices section (this reader keeps one field)");
        read_section();
        have_section = true;
      } else if (kw == "End") {
        in_.expect_tokens(1, "End");
        if (!have_section) in_.fail("End before any SolAtVertices section");
        if (in_.next_line()) in_.fail("text after End: " + quote(in_.token(0)));
        return std::move(sol_);
      } else {
        refuse(kw);
      }
    }
    in_.fail_at(std::max<std::uint64_t>(in_.line(), 1), "file ends before End (truncated?)");
  }

 private:
  void read_section() {
    const std::uint64_t n = io::medit_section_count(in_, "SolAtVertices");
    const std::uint64_t count_line = in_.line();
    if (!in_.next_line()) {
      in_.fail_at(count_line, "file ends after the SolAtVertices count (expected the field types: 1 type)");
    }
    if (io::is_medit_keyword(in_.token(0))) {
      in_.fail("missing the field types (1 type) after the SolAtVertices count, found " + quote(in_.token(0)));
    }
    const std::int64_t fields = in_.integer(0, "SolAtVertices number of fields");
    if (fields != 1) in_.fail(fields_problem(fields));
    in_.expect_tokens(2, "SolAtVertices field types (1 type)");
    const std::int64_t type = in_.integer(1, "SolAtVertices field type");
    if (type != kTypeScalar && type != kTypeSymmetric) in_.fail("SolAtVertices " + type_problem(type));
    sol_.kind = type == kTypeScalar ? SolData::Kind::Scalar : SolData::Kind::Tensor;
    const std::size_t per = values_per_vertex(sol_.kind, sol_.dimension);
    const std::string names = field_names(sol_.kind, sol_.dimension);
    sol_.values.reserve(std::min<std::uint64_t>(n, kMaxReserve) * per);
    for (std::uint64_t i = 0; i < n; ++i) {
      io::medit_next_entry(in_, "SolAtVertices", i, n);
      const std::string what = "vertex " + std::to_string(i + 1);
      in_.expect_tokens(per, what + " (" + names + ")");
      for (std::size_t k = 0; k < per; ++k) {
        sol_.values.push_back(in_.real(k, what + " " + value_name(sol_.kind, k)));
      }
    }
  }

  [[noreturn]] void refuse(std::string_view kw) const {
    for (std::string_view prefix : {"SolAt", "ISolAt", "DSolAt", "HOSolAt"}) {
      if (kw.starts_with(prefix)) {
        in_.fail("keyword " + quote(kw) + " is not supported: this reader keeps SolAtVertices");
      }
    }
    io::medit_refuse_keyword(in_, kw, "solution reader", kKeptKeywords);
  }

  LineTokenizer in_;
  SolData sol_;
};

// --- Binary ------------------------------------------------------------------------------------

std::string keyword_name(std::int64_t code) {
  switch (code) {
    case 1: return " (MeshVersionFormatted)";
    case 4: return " (Vertices)";
    case 5: return " (Edges)";
    case 6: return " (Triangles)";
    case 8: return " (Tetrahedra)";
    case 63: return " (SolAtEdges)";
    case 64: return " (SolAtTriangles)";
    case 65: return " (SolAtQuadrilaterals)";
    case 66: return " (SolAtTetrahedra)";
    default: return "";
  }
}

class BinarySolReader {
 public:
  BinarySolReader(std::string_view bytes, const std::string& name) : bytes_(bytes), in_(bytes, name) {}

  SolData read() {
    need(0, 8, "the header (endianness word and version)");
    const std::uint32_t code = load(0, 4);
    if (code != 1) {
      in_.set_swapped(true);
      if (load(0, 4) != 1) fail(0, "first word " + std::to_string(code) + " is not 1: not a binary Medit file");
    }
    const std::int64_t version = signed32(4);
    if (version < 1 || version > 4) fail(4, "version " + std::to_string(version) + " is not 1, 2, 3 or 4");
    position_bytes_ = version >= 3 ? 8 : 4;
    count_bytes_ = version == 4 ? 8 : 4;
    real_bytes_ = version == 1 ? 4 : 8;

    bool have_dimension = false;
    bool have_section = false;
    std::size_t at = 8;
    // Each keyword moves `at` forward by at least its header, so the loop ends with the bytes.
    while (true) {
      const std::size_t start = at;
      if (at == bytes_.size()) fail(at, "file ends before End (truncated?)");
      need(at, 4 + position_bytes_, "a keyword header");
      const std::int64_t kw = signed32(at);
      const std::uint64_t next = load(at + 4, position_bytes_);
      at += 4 + position_bytes_;
      if (kw == kCodeDimension) {
        if (have_dimension) fail(start, "second Dimension");
        need(at, 4, "Dimension");
        const std::int64_t d = signed32(at);
        if (d != 2 && d != 3) fail(at, "Dimension " + std::to_string(d) + " is not 2 or 3");
        sol_.dimension = static_cast<int>(d);
        at += 4;
        have_dimension = true;
      } else if (kw == kCodeSolAtVertices) {
        if (!have_dimension) fail(start, "SolAtVertices before Dimension");
        if (have_section) fail(start, "second SolAtVertices section (this reader keeps one field)");
        at = read_section(at);
        have_section = true;
      } else if (kw == kCodeEnd) {
        if (!have_section) fail(start, "End before any SolAtVertices section");
        if (at != bytes_.size()) {
          fail(at, std::to_string(bytes_.size() - at) + " bytes after End");
        }
        return std::move(sol_);
      } else {
        fail(start, "keyword code " + std::to_string(kw) + keyword_name(kw) +
                        " is not supported: this reader keeps Dimension, SolAtVertices and End");
      }
      if (next != at) {
        fail(start + 4, "next-keyword offset " + std::to_string(next) + " is not where the next keyword begins (byte " +
                            std::to_string(at) + ")");
      }
    }
  }

 private:
  std::size_t read_section(std::size_t at) {
    need(at, count_bytes_ + 4, "the SolAtVertices header");
    const std::uint64_t raw_count = load(at, count_bytes_);
    const std::int64_t count =
        count_bytes_ == 4 ? static_cast<std::int32_t>(static_cast<std::uint32_t>(raw_count)) : static_cast<std::int64_t>(raw_count);
    if (count < 0) fail(at, "SolAtVertices count " + std::to_string(count) + " is negative");
    if (static_cast<std::uint64_t>(count) > std::numeric_limits<std::uint32_t>::max()) {
      fail(at, "SolAtVertices count " + std::to_string(count) + " exceeds the 32-bit index range");
    }
    at += count_bytes_;
    const std::int64_t fields = signed32(at);
    if (fields != 1) fail(at, fields_problem(fields));
    at += 4;
    need(at, 4, "the SolAtVertices field type");
    const std::int64_t type = signed32(at);
    if (type != kTypeScalar && type != kTypeSymmetric) fail(at, "SolAtVertices " + type_problem(type));
    at += 4;
    sol_.kind = type == kTypeScalar ? SolData::Kind::Scalar : SolData::Kind::Tensor;
    const std::size_t per = values_per_vertex(sol_.kind, sol_.dimension);
    // count < 2^32, per <= 6, real_bytes_ <= 8: no overflow in 64 bits.
    const std::uint64_t size = static_cast<std::uint64_t>(count) * per * real_bytes_;
    if (size > bytes_.size() - at) {
      fail(at, "SolAtVertices count " + std::to_string(count) + " needs " + std::to_string(size) +
                   " bytes of values, but the file has " + std::to_string(bytes_.size() - at) +
                   " left (truncated?)");
    }
    sol_.values.resize(static_cast<std::size_t>(count) * per);
    for (std::size_t i = 0; i < sol_.values.size(); ++i) {
      const double v = in_.real(at, real_bytes_);
      if (!std::isfinite(v)) {
        fail(at, "vertex " + std::to_string(i / per + 1) + " " + value_name(sol_.kind, i % per) +
                     " is not finite");
      }
      sol_.values[i] = v;
      at += real_bytes_;
    }
    return at;
  }

  std::uint64_t load(std::size_t at, std::size_t n) const { return in_.load(at, n); }
  std::int64_t signed32(std::size_t at) const { return in_.signed32(at); }
  void need(std::size_t at, std::size_t n, const std::string& what) const { in_.need(at, n, what); }
  [[noreturn]] void fail(std::size_t at, const std::string& reason) const { in_.fail(at, reason); }

  std::string_view bytes_;
  io::BinaryInput in_;
  std::size_t position_bytes_ = 4;
  std::size_t count_bytes_ = 4;
  std::size_t real_bytes_ = 8;
  SolData sol_;
};

// --- Writers -----------------------------------------------------------------------------------

void check_writable(const SolData& sol) {
  if (sol.dimension != 2 && sol.dimension != 3) {
    throw InputError("solution dimension " + std::to_string(sol.dimension) + " is not 2 or 3");
  }
  const std::size_t per = sol.values_per_vertex();
  if (sol.values.size() % per != 0) {
    throw InputError("solution: " + std::to_string(sol.values.size()) + " values are not a whole number of vertices (" +
                     std::to_string(per) + " per vertex)");
  }
  for (std::size_t i = 0; i < sol.values.size(); ++i) {
    if (!std::isfinite(sol.values[i])) {
      throw InputError("solution: vertex " + std::to_string(i / per + 1) + " has a value that is not finite", {i / per});
    }
  }
}

void write_ascii(std::ostream& out, const SolData& sol) {
  const std::size_t per = sol.values_per_vertex();
  std::string text = "MeshVersionFormatted 2\n\nDimension ";
  io::append_integer(text, sol.dimension);
  text += "\n\nSolAtVertices\n";
  io::append_integer(text, static_cast<std::int64_t>(sol.vertex_count()));
  text += sol.kind == SolData::Kind::Scalar ? "\n1 1\n" : "\n1 3\n";
  for (std::size_t i = 0; i < sol.values.size(); ++i) {
    io::append_real(text, sol.values[i]);
    text += (i + 1) % per == 0 ? '\n' : ' ';
  }
  text += "\nEnd\n";
  out << text;
}

void store(std::string& out, std::uint64_t v, std::size_t n) { io::store_le(out, v, n); }

void write_binary(std::ostream& out, const SolData& sol, int version) {
  if (version < 2 || version > 4) {
    throw InputError("binary solution version " + std::to_string(version) + " is not 2, 3 or 4 (version 1 stores floats)");
  }
  const std::size_t n = sol.vertex_count();
  if (version < 4 && n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw InputError("binary solution version " + std::to_string(version) + " counts in 32 bits; this solution has " +
                     std::to_string(n) + " vertices (use version 4)");
  }
  const std::size_t pb = version >= 3 ? 8 : 4;
  const std::size_t cb = version == 4 ? 8 : 4;
  std::string bytes;
  store(bytes, 1, 4);
  store(bytes, static_cast<std::uint64_t>(version), 4);
  // Dimension, then SolAtVertices, each with the offset of the keyword after it.
  const std::size_t section = 8 + 4 + pb + 4;
  store(bytes, kCodeDimension, 4);
  store(bytes, section, pb);
  store(bytes, static_cast<std::uint64_t>(sol.dimension), 4);
  const std::size_t end = section + 4 + pb + cb + 8 + 8 * sol.values.size();
  store(bytes, kCodeSolAtVertices, 4);
  store(bytes, end, pb);
  store(bytes, n, cb);
  store(bytes, 1, 4);
  store(bytes, sol.kind == SolData::Kind::Scalar ? kTypeScalar : kTypeSymmetric, 4);
  for (double v : sol.values) store(bytes, std::bit_cast<std::uint64_t>(v), 8);
  DTLAB_ASSERT(bytes.size() == end);
  store(bytes, kCodeEnd, 4);
  store(bytes, 0, pb);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// --- Metrics -----------------------------------------------------------------------------------

std::string components(std::span<const double> c) {
  std::string s = "(";
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (k > 0) s += ", ";
    io::append_real(s, c[k]);
  }
  return s + ")";
}

template <class M, int D>
std::vector<M> metrics_from_sol(const SolData& sol, const std::string& file) {
  if (sol.dimension != D) {
    throw InputError(file + ": a " + std::to_string(sol.dimension) + "D solution where a " + std::to_string(D) +
                     "D metric is expected");
  }
  const std::size_t per = sol.values_per_vertex();
  if (sol.values.size() % per != 0) {
    throw InputError(file + ": " + std::to_string(sol.values.size()) + " values are not a whole number of vertices");
  }
  std::vector<M> metrics(sol.vertex_count());
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::span<const double> c(sol.values.data() + i * per, per);
    const std::string what = file + ": vertex " + std::to_string(i + 1) + ": ";
    for (double v : c) {
      if (!std::isfinite(v)) throw InputError(what + "value " + components(c) + " is not finite", {i});
    }
    if (sol.kind == SolData::Kind::Scalar) {
      if (!(c[0] > 0.0)) throw InputError(what + "size " + components(c) + " is not positive", {i});
      if (!is_representable_size(c[0])) {
        throw InputError(what + "size " + components(c) + " is out of the representable range (" +
                             components(std::array{kMinMetricSize, kMaxMetricSize}).substr(1) +
                             " (h^-2 and the metric's determinant normal doubles)",
                         {i});
      }
      metrics[i] = M::isotropic(c[0]);
    } else {
      std::copy(c.begin(), c.end(), metrics[i].m.begin());
      if (!metrics[i].is_positive_definite()) {
        throw InputError(what + "tensor " + components(c) + " is not positive definite", {i});
      }
      // Bounded eigenvalues: its sizes (lambda^-1/2) representable, as a scalar size's above.
      for (const double h : sizes(metrics[i])) {
        if (!is_representable_size(h)) {
          std::string size;
          io::append_real(size, h);
          throw InputError(what + "tensor " + components(c) + " has a size " + size + " out of the representable range " +
                               components(std::array{kMinMetricSize, kMaxMetricSize}) +
                               " (its eigenvalues and determinant normal doubles)",
                           {i});
        }
      }
    }
  }
  return metrics;
}

template <class M, int D>
SolData sol_from(std::span<const M> metrics) {
  SolData sol;
  sol.dimension = D;
  sol.kind = SolData::Kind::Tensor;
  sol.values.reserve(metrics.size() * sol.values_per_vertex());
  for (const M& m : metrics) sol.values.insert(sol.values.end(), m.m.begin(), m.m.end());
  return sol;
}

}  // namespace

std::size_t SolData::values_per_vertex() const noexcept { return dtlab::values_per_vertex(kind, dimension); }

SolEncoding detect_sol_encoding(std::string_view bytes) noexcept {
  if (bytes.size() < 4) return SolEncoding::Ascii;
  const bool little = bytes[0] == 1 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0;
  const bool big = bytes[0] == 0 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 1;
  return little || big ? SolEncoding::Binary : SolEncoding::Ascii;
}

SolData read_medit_sol(std::istream& in, const std::string& file_name) {
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ParseError(file_name, 0, "read error");
  if (detect_sol_encoding(bytes) == SolEncoding::Binary) return BinarySolReader(bytes, file_name).read();
  std::istringstream text(bytes);
  return AsciiSolReader(text, file_name).read();
}

SolData read_medit_sol(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_medit_sol(in, path);
}

void write_medit_sol(std::ostream& out, const SolData& sol, SolEncoding encoding, int version) {
  check_writable(sol);
  if (encoding == SolEncoding::Ascii) {
    write_ascii(out, sol);
  } else {
    write_binary(out, sol, version);
  }
}

void write_medit_sol(const std::string& path, const SolData& sol) {
  const bool binary = path.size() >= 5 && path.compare(path.size() - 5, 5, ".solb") == 0;
  std::ofstream out = io::open_for_writing(path);
  write_medit_sol(out, sol, binary ? SolEncoding::Binary : SolEncoding::Ascii);
  out.flush();
  io::check_written(out, path);
}

std::vector<Metric2> metrics2_from_sol(const SolData& sol, const std::string& file) {
  return metrics_from_sol<Metric2, 2>(sol, file);
}

std::vector<Metric3> metrics3_from_sol(const SolData& sol, const std::string& file) {
  return metrics_from_sol<Metric3, 3>(sol, file);
}

SolData sol_from_metrics(std::span<const Metric2> metrics) { return sol_from<Metric2, 2>(metrics); }
SolData sol_from_metrics(std::span<const Metric3> metrics) { return sol_from<Metric3, 3>(metrics); }

template <class Metric>
std::vector<Metric> read_metrics(const std::string& file, std::size_t vertex_count) {
  const SolData sol = read_medit_sol(file);
  check_sol_matches(sol, vertex_count, file);
  if constexpr (std::is_same_v<Metric, Metric2>)
    return metrics2_from_sol(sol, file);
  else
    return metrics3_from_sol(sol, file);
}
template std::vector<Metric2> read_metrics<Metric2>(const std::string&, std::size_t);
template std::vector<Metric3> read_metrics<Metric3>(const std::string&, std::size_t);

void check_sol_matches(const SolData& sol, std::size_t vertex_count, const std::string& file) {
  // vertex_count() rounds down: a partial vertex would otherwise pass for the one before it.
  if (sol.values.size() % sol.values_per_vertex() != 0) {
    throw InputError(file + ": " + std::to_string(sol.values.size()) + " values are not a whole number of vertices (" +
                     std::to_string(sol.values_per_vertex()) + " per vertex)");
  }
  if (sol.vertex_count() != vertex_count) {
    throw InputError(file + " has a solution at " + std::to_string(sol.vertex_count()) + " vertices, but the mesh has " +
                     std::to_string(vertex_count));
  }
}

}  // namespace dtlab
