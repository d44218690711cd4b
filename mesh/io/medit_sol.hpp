// Medit solution files: one field at the vertices of a mesh, in ASCII (.sol) or binary (.solb),
// as INRIA's libMeshb writes them and MMG and the UGAWG benchmarks exchange metrics in.
//
//   ASCII (.sol)                       Binary (.solb): 32-bit words in the writer's byte order,
//   MeshVersionFormatted 2             which the first word (1) tells; then keywords, each an int
//   Dimension 2                        code, the file offset of the next keyword (32 bits in
//   SolAtVertices                      versions 1-2, 64 bits in 3-4), and its data:
//   n                                    int 1, int version (1-4)
//   1 type                               Dimension (code 3): int dimension
//   n lines: 1, 3 or 6 reals             SolAtVertices (62): count (int32; int64 in version 4),
//   End                                    int 1, int type, count x size reals (float in
//                                          version 1, double from version 2)
//                                        End (54): offset 0, nothing after it
//
// One field (the "1" before the type) of type 1 (scalar: a size h, or any scalar) or 3 (a
// symmetric tensor, Medit's order: 2D m11 m12 m22, 3D m11 m12 m22 m13 m23 m33). The ASCII reader
// follows mesh/io/medit.hpp's rules (keyword values on the keyword's line or the next, '#'
// comments, one entry per line, MeshVersionFormatted first, Dimension before SolAtVertices, End
// last). ParseError for everything else: in an ASCII file at its line; in a binary file the error's
// line() is the byte offset and the message says "byte": another field type or several fields,
// another keyword (SolAtTriangles, Vertices, ...), a second section, a count that does not match
// the entries, a count larger than the rest of the file can hold (refused before anything is
// allocated), a next-keyword offset that is not where the next keyword begins, a value that is
// NaN or infinite, anything after End, a file that ends before End.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/metric.hpp"

namespace dtlab {

struct SolData {
  enum class Kind : std::uint8_t { Scalar, Tensor };

  int dimension = 2;
  Kind kind = Kind::Scalar;
  std::vector<double> values;  // values_per_vertex() per vertex, vertex after vertex

  // 1 for a scalar, 3 (2D) or 6 (3D) for a tensor.
  std::size_t values_per_vertex() const noexcept;
  std::size_t vertex_count() const noexcept { return values.size() / values_per_vertex(); }

  friend bool operator==(const SolData&, const SolData&) = default;
};

enum class SolEncoding : std::uint8_t { Ascii, Binary };

// Binary iff the first word is 1 in either byte order; the bytes are the whole file (or its start).
SolEncoding detect_sol_encoding(std::string_view bytes) noexcept;

// Either encoding, told by the content; `file_name` names the input in error messages.
SolData read_medit_sol(std::istream& in, const std::string& file_name);
SolData read_medit_sol(const std::string& path);

// ASCII writes version 2 (doubles in their shortest exact form); binary writes `version` 2, 3 or 4
// (doubles, little-endian), so a write/read cycle keeps every bit. InputError for a dimension
// other than 2 or 3, values not a whole number of vertices, a value that is not finite, or a
// count beyond the version's 32-bit count.
void write_medit_sol(std::ostream& out, const SolData& sol, SolEncoding encoding = SolEncoding::Ascii,
                     int version = 2);
// Binary iff `path` ends in ".solb".
void write_medit_sol(const std::string& path, const SolData& sol);

// The solution as vertex metrics: a scalar h is Metric::isotropic(h), a tensor its components.
// InputError naming `file` and the vertex (numbered from 1 in the message, as Medit numbers them;
// 0-based in items()): a value that is not finite, h <= 0, a tensor that is not positive
// definite; also a solution of the other dimension.
std::vector<Metric2> metrics2_from_sol(const SolData& sol, const std::string& file);
std::vector<Metric3> metrics3_from_sol(const SolData& sol, const std::string& file);
// A tensor solution holding the metrics.
SolData sol_from_metrics(std::span<const Metric2> metrics);
SolData sol_from_metrics(std::span<const Metric3> metrics);

// InputError naming `file` unless the solution has exactly `vertex_count` vertices.
void check_sol_matches(const SolData& sol, std::size_t vertex_count, const std::string& file);

// The metric at each of `vertex_count` vertices from the .sol/.solb `file` (sizes or tensors):
// read, checked against the count, converted (the three steps above). Metric2 or Metric3.
template <class Metric>
std::vector<Metric> read_metrics(const std::string& file, std::size_t vertex_count);

}  // namespace dtlab
