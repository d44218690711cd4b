// Line-oriented tokenizer shared by the ASCII mesh readers: comments, blank lines, strict
// number parsing, and ParseError messages that name the file and the 1-based line.
//
// A line is split on blanks (space, tab, CR, VT, FF); '#' starts a comment that runs to the end
// of the line. Numbers are parsed with std::from_chars, so the accepted syntax does not depend
// on the locale; a token must be a number in full (no trailing characters), and NaN, infinity
// or a value that overflows a double are refused.
#pragma once

#include <cstdint>
#include <istream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dtlab::io {

class LineTokenizer {
 public:
  LineTokenizer(std::istream& in, std::string file_name);

  // Moves to the next line that holds a token; false at the end of the input.
  bool next_line();

  std::uint64_t line() const noexcept { return line_; }
  const std::string& file_name() const noexcept { return file_; }
  std::size_t size() const noexcept { return tokens_.size(); }
  std::string_view token(std::size_t k) const { return tokens_.at(k); }

  // Number parsing of token k of the current line; `what` names the field in the message.
  double real(std::size_t k, std::string_view what) const;
  std::int64_t integer(std::size_t k, std::string_view what) const;
  // A non-negative count that fits an index of type std::uint32_t.
  std::uint64_t count(std::size_t k, std::string_view what) const;

  // Throws unless the current line has exactly n tokens ("missing ..." or "trailing ...").
  void expect_tokens(std::size_t n, std::string_view what) const;

  // Throws ParseError at the current line (or at `line`).
  [[noreturn]] void fail(const std::string& reason) const;
  [[noreturn]] void fail_at(std::uint64_t line, const std::string& reason) const;

 private:
  std::istream& in_;
  std::string file_;
  std::uint64_t line_ = 0;
  std::string text_;
  std::vector<std::string_view> tokens_;
};

// A token quoted for an error message: non-printable bytes escaped, long tokens shortened.
std::string quote(std::string_view token);

// The number syntax of LineTokenizer::real and integer, for readers with their own tokens: ""
// when `token` is a number in full, else the problem, to follow the field's name in a message
// (" is not a number: 'x'", " is not finite: 'nan'", " '1e999' is out of the range of a double").
std::string parse_real(std::string_view token, double& v);
std::string parse_integer(std::string_view token, std::int64_t& v);

// Checks a coordinate read at the tokenizer's current line against coordinate_range.hpp.
void check_coordinate(const LineTokenizer& in, double v, std::string_view what);

// Token k as an integer that fits an int (references, boundary markers, region numbers).
int int_field(const LineTokenizer& in, std::size_t k, const std::string& what);

// Token k as the number of one of `count` vertices numbered from `first` (0 or 1), returned
// 0-based; out of range is "<what>: vertex number V out of range first..first+count-1".
std::uint32_t vertex_number(const LineTokenizer& in, std::size_t k, std::int64_t first, std::uint64_t count,
                            const std::string& what);

// --- Counted lists (Triangle's and TetGen's .node, .ele, .poly, .face) --------------------------
//
// A header gives a count, then each entry sits on a line of its own, numbered in its first
// field from 0 or 1 (as the first entry says) and then consecutively.

// Moves to entry i (0-based) of n; at the end of the input, "file ends after i of n <noun>".
void next_counted_entry(LineTokenizer& in, std::uint64_t i, std::uint64_t n, std::string_view noun);

// Checks the number in field 0 of entry i: 0 or 1 for i = 0, first + i after. Returns the
// number of the first entry (0 or 1).
int list_entry_number(const LineTokenizer& in, std::uint64_t i, int first, const std::string& what);

// --- Medit (.mesh) sections, shared by the 2D and 3D readers ------------------------------------
//
// A section is a keyword, its count (on the keyword's line or alone on the next one), then one
// entry per line. Any Medit keyword ends a section, so a short section is reported as such.

// True for every keyword of the Medit format, kept by a reader or not.
bool is_medit_keyword(std::string_view t);

// The integer after keyword `kw` ("MeshVersionFormatted", "Dimension"), or a section's count.
std::int64_t medit_keyword_value(LineTokenizer& in, std::string_view kw);
std::uint64_t medit_section_count(LineTokenizer& in, std::string_view kw);

// Moves to entry i (0-based) of section `kw` of n entries, with messages for a short section.
void medit_next_entry(LineTokenizer& in, std::string_view kw, std::uint64_t i, std::uint64_t n);

// Refuses keyword `kw` that the reader does not handle: another Medit keyword ("not supported by
// the <reader>, which keeps <kept>"), a known keyword in the wrong case, a number (a section with
// more entries than its count), or an unknown word.
[[noreturn]] void medit_refuse_keyword(const LineTokenizer& in, std::string_view kw, std::string_view reader,
                                       std::span<const std::string_view> kept);

// --- Medit sections the readers check and skip --------------------------------------------------
//
// Feature and attribute data that MeshData2 and MeshData3 do not keep (libMeshb's layouts):
//   Corners, RequiredVertices          n, then n lines  vertex number
//   Ridges, RequiredEdges              n, then n lines  edge number (into Edges)
//   RequiredTriangles                  n, then n lines  triangle number
//   RequiredQuadrilaterals             n, then n lines  quadrilateral number
//   Normals, Tangents                  n, then n lines  `dimension` reals
//   NormalAtVertices                   n, then n lines  vertex number, normal number
//   TangentAtVertices                  n, then n lines  vertex number, tangent number
//   Identifier, Geometry               one "quoted string", on the keyword's line or the next
// Each is read in full and checked (its count against its entries, numbers from 1 in range of
// what they number, reals finite), then dropped with a note such as "section Corners skipped
// (8 entries from line 51: corner vertices)". The ranges are checked at End (finish), so the
// sections may come in any order; an out-of-range number is a ParseError at its line.
class MeditSkippedSections {
 public:
  explicit MeditSkippedSections(int dimension) : dimension_(dimension) {}

  static bool is_skipped(std::string_view kw) noexcept;

  // Reads section `keyword` (is_skipped) from its keyword line on; a second one is refused.
  void skip(LineTokenizer& in, std::string_view keyword);

  // The counts of the sections that the skipped ones number into; fails at the line of the first
  // number out of range.
  struct Counts {
    std::uint64_t vertices = 0;
    std::uint64_t edges = 0;
    std::uint64_t triangles = 0;
    std::uint64_t quadrilaterals = 0;
  };
  void finish(const LineTokenizer& in, const Counts& counts) const;

  // One line per skipped section, in file order.
  const std::vector<std::string>& notes() const noexcept { return notes_; }

 private:
  // The largest number of one field of a section, and where it was read.
  struct Reference {
    std::string section;
    std::string target;  // "Vertices", "Edges", ..., "Normals", "Tangents"
    std::int64_t max = 0;
    std::uint64_t line = 0;
    std::uint64_t entry = 0;
  };
  int dimension_;
  std::vector<std::string> seen_;
  std::vector<Reference> references_;
  std::uint64_t normals_ = 0;
  std::uint64_t tangents_ = 0;
  std::vector<std::string> notes_;
};

// Hands a reader's notes to `sink`, or, when `sink` is null, writes each to std::cerr as
// "warning: <file>: <note>", so that nothing a reader drops goes unsaid.
void deliver_notes(const std::vector<std::string>& notes, const std::string& file_name,
                   std::vector<std::string>* sink);

}  // namespace dtlab::io
