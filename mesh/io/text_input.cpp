#include "mesh/io/text_input.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"

namespace dtlab::io {

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Lower-case spellings of NaN and infinity, so that they get their own message.
bool names_non_finite(std::string_view t) {
  if (!t.empty() && (t.front() == '+' || t.front() == '-')) t.remove_prefix(1);
  std::string lower;
  for (char c : t.substr(0, 8)) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower.starts_with("nan") || lower.starts_with("inf");
}
}  // namespace

std::string quote(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

LineTokenizer::LineTokenizer(std::istream& in, std::string file_name)
    : in_(in), file_(std::move(file_name)) {}

bool LineTokenizer::next_line() {
  tokens_.clear();
  while (std::getline(in_, text_)) {
    ++line_;
    std::string_view rest(text_);
    if (const auto hash = rest.find('#'); hash != std::string_view::npos) rest = rest.substr(0, hash);
    std::size_t i = 0;
    while (i < rest.size()) {
      while (i < rest.size() && is_blank(rest[i])) ++i;
      const std::size_t start = i;
      while (i < rest.size() && !is_blank(rest[i])) ++i;
      if (i > start) tokens_.push_back(rest.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  if (in_.bad()) fail("read error");
  return false;
}

void LineTokenizer::fail(const std::string& reason) const { throw ParseError(file_, line_, reason); }

void LineTokenizer::fail_at(std::uint64_t line, const std::string& reason) const {
  throw ParseError(file_, line, reason);
}

std::string parse_real(std::string_view t, double& v) {
  // from_chars refuses a leading '+', which C and every mesh writer accept.
  std::string_view digits = t;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  if (names_non_finite(digits)) return " is not finite: " + quote(t);
  v = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  // Appended rather than "..." + quote(t): GCC 12 warns falsely (-Wrestrict) on the latter.
  if (ec == std::errc::result_out_of_range) return std::string(" ").append(quote(t)).append(" is out of the range of a double");
  if (ec != std::errc() || end != digits.data() + digits.size()) return " is not a number: " + quote(t);
  if (!std::isfinite(v)) return " is not finite: " + quote(t);
  return {};
}

std::string parse_integer(std::string_view t, std::int64_t& v) {
  std::string_view digits = t;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec == std::errc::result_out_of_range) return std::string(" ").append(quote(t)).append(" is too large");
  if (ec != std::errc() || end != digits.data() + digits.size()) return " is not an integer: " + quote(t);
  return {};
}

double LineTokenizer::real(std::size_t k, std::string_view what) const {
  if (k >= tokens_.size()) fail("missing " + std::string(what));
  double v = 0.0;
  if (const std::string problem = parse_real(tokens_[k], v); !problem.empty()) fail(std::string(what) + problem);
  return v;
}

std::int64_t LineTokenizer::integer(std::size_t k, std::string_view what) const {
  if (k >= tokens_.size()) fail("missing " + std::string(what));
  std::int64_t v = 0;
  if (const std::string problem = parse_integer(tokens_[k], v); !problem.empty()) fail(std::string(what) + problem);
  return v;
}

std::uint64_t LineTokenizer::count(std::size_t k, std::string_view what) const {
  const std::int64_t v = integer(k, what);
  if (v < 0) fail(std::string(what) + " is negative: " + quote(tokens_[k]));
  if (static_cast<std::uint64_t>(v) > std::numeric_limits<std::uint32_t>::max()) {
    fail(std::string(what) + " " + quote(tokens_[k]) + " exceeds the 32-bit index range");
  }
  return static_cast<std::uint64_t>(v);
}

void LineTokenizer::expect_tokens(std::size_t n, std::string_view what) const {
  if (tokens_.size() < n) {
    fail(std::string(what) + ": expected " + std::to_string(n) + " fields, found " +
         std::to_string(tokens_.size()));
  }
  if (tokens_.size() > n) {
    fail(std::string(what) + ": trailing text " + quote(tokens_[n]) + " after " + std::to_string(n) +
         " fields");
  }
}

void check_coordinate(const LineTokenizer& in, double v, std::string_view what) {
  if (coordinate_in_range(v)) return;
  in.fail(std::string(what) + " is " + coordinate_problem(v));
}

int int_field(const LineTokenizer& in, std::size_t k, const std::string& what) {
  const std::int64_t v = in.integer(k, what);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    in.fail(what + " " + std::to_string(v) + " does not fit an int");
  }
  return static_cast<int>(v);
}

std::uint32_t vertex_number(const LineTokenizer& in, std::size_t k, std::int64_t first, std::uint64_t count,
                            const std::string& what) {
  const std::int64_t v = in.integer(k, what + " vertex");
  // count < 2^32 (LineTokenizer::count), so first + count cannot overflow.
  if (count == 0) in.fail(what + ": vertex number " + std::to_string(v) + ", but there are no vertices");
  if (v < first || v - first >= static_cast<std::int64_t>(count)) {
    in.fail(what + ": vertex number " + std::to_string(v) + " out of range " + std::to_string(first) + ".." +
            std::to_string(first + static_cast<std::int64_t>(count) - 1));
  }
  return static_cast<std::uint32_t>(v - first);
}

void next_counted_entry(LineTokenizer& in, std::uint64_t i, std::uint64_t n, std::string_view noun) {
  const std::uint64_t last = in.line();
  if (!in.next_line()) {
    in.fail_at(std::max<std::uint64_t>(last, 1), "file ends after " + std::to_string(i) + " of " + std::to_string(n) +
                                                     " " + std::string(noun) + " (truncated?)");
  }
}

int list_entry_number(const LineTokenizer& in, std::uint64_t i, int first, const std::string& what) {
  const std::int64_t number = in.integer(0, what + " number");
  if (i == 0) {
    if (number != 0 && number != 1) {
      in.fail(what + " is numbered " + std::to_string(number) + "; the first one must be 0 or 1");
    }
    return static_cast<int>(number);
  }
  if (number != first + static_cast<std::int64_t>(i)) {
    in.fail(what + " is numbered " + std::to_string(number) + ", expected " +
            std::to_string(first + static_cast<std::int64_t>(i)) + " (numbers run consecutively)");
  }
  return first;
}

namespace {

constexpr std::array<std::string_view, 33> kMeditKeywords = {
    "MeshVersionFormatted", "Dimension",        "Vertices",          "Edges",
    "Triangles",            "Tetrahedra",       "End",               "Corners",
    "Ridges",               "RequiredVertices", "RequiredEdges",     "RequiredTriangles",
    "Quadrilaterals",       "Hexahedra",        "Prisms",            "Pyramids",
    "Normals",              "NormalAtVertices", "Tangents",          "TangentAtVertices",
    "Geometry",             "Identifier",       "Crack",             "Polygons",
    "SubDomainFromMesh",    "VertexOnGeometricVertex", "EdgeOnGeometricEdge", "RequiredQuadrilaterals",
    "EdgesP2",              "TrianglesP2",      "QuadrilateralsQ2",  "TetrahedraP2",
    "HexahedraQ2"};

bool iequals(std::string_view a, std::string_view b) {
  auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

// The integer after a keyword, on the keyword's line or alone on the next one.
std::int64_t keyword_integer(LineTokenizer& in, std::string_view kw, const std::string& what, bool is_count) {
  auto parse = [&](std::size_t k) { return is_count ? static_cast<std::int64_t>(in.count(k, what)) : in.integer(k, what); };
  if (in.size() >= 2) {
    in.expect_tokens(2, kw);
    return parse(1);
  }
  const std::uint64_t keyword_line = in.line();
  if (!in.next_line() || is_medit_keyword(in.token(0))) {
    in.fail_at(keyword_line, "missing " + std::string(is_count ? "count" : "value") + " after " + std::string(kw));
  }
  in.expect_tokens(1, what);
  return parse(0);
}

}  // namespace

bool is_medit_keyword(std::string_view t) {
  return std::find(kMeditKeywords.begin(), kMeditKeywords.end(), t) != kMeditKeywords.end();
}

std::int64_t medit_keyword_value(LineTokenizer& in, std::string_view kw) {
  return keyword_integer(in, kw, std::string(kw) + " value", false);
}

std::uint64_t medit_section_count(LineTokenizer& in, std::string_view kw) {
  return static_cast<std::uint64_t>(keyword_integer(in, kw, std::string(kw) + " count", true));
}

void medit_next_entry(LineTokenizer& in, std::string_view kw, std::uint64_t i, std::uint64_t n) {
  const std::uint64_t last = in.line();
  if (!in.next_line()) {
    in.fail_at(std::max<std::uint64_t>(last, 1), "file ends in " + std::string(kw) + " after " + std::to_string(i) +
                                                     " of " + std::to_string(n) + " entries (truncated?)");
  }
  if (is_medit_keyword(in.token(0))) {
    in.fail(std::string(kw) + " count is " + std::to_string(n) + " but only " + std::to_string(i) +
            " entries precede " + quote(in.token(0)));
  }
}

void medit_refuse_keyword(const LineTokenizer& in, std::string_view kw, std::string_view reader,
                          std::span<const std::string_view> kept) {
  if (is_medit_keyword(kw)) {
    std::string list;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (i > 0) list += i + 1 == kept.size() ? " and " : ", ";
      list += kept[i];
    }
    in.fail("Medit keyword " + quote(kw) + " is not supported by the " + std::string(reader) + " (it keeps " + list +
            ")");
  }
  for (std::string_view known : kMeditKeywords) {
    if (iequals(kw, known)) {
      in.fail("unknown keyword " + quote(kw) + " (keywords are case-sensitive: " + std::string(known) + ")");
    }
  }
  if (!kw.empty() && ((kw[0] >= '0' && kw[0] <= '9') || kw[0] == '-' || kw[0] == '+' || kw[0] == '.')) {
    in.fail("expected a keyword, found the number " + quote(kw) + " (more entries than the section's count?)");
  }
  in.fail("unknown keyword " + quote(kw));
}

namespace {

// What one entry of a skipped section holds: numbers into other sections, or reals.
struct SkippedLayout {
  std::string_view keyword;
  std::array<std::string_view, 2> targets;  // "" when unused; "Reals": `dimension` reals
  std::string_view what;                    // for the note
};

constexpr std::array<SkippedLayout, 12> kSkipped = {{
    {"Corners", {"Vertices", ""}, "corner vertices"},
    {"RequiredVertices", {"Vertices", ""}, "required vertices"},
    {"Ridges", {"Edges", ""}, "ridge edges"},
    {"RequiredEdges", {"Edges", ""}, "required edges"},
    {"RequiredTriangles", {"Triangles", ""}, "required triangles"},
    {"RequiredQuadrilaterals", {"Quadrilaterals", ""}, "required quadrilaterals"},
    {"Normals", {"Reals", ""}, "normal vectors"},
    {"Tangents", {"Reals", ""}, "tangent vectors"},
    {"NormalAtVertices", {"Vertices", "Normals"}, "vertex normals"},
    {"TangentAtVertices", {"Vertices", "Tangents"}, "vertex tangents"},
    {"Identifier", {"String", ""}, "the mesh's name"},
    {"Geometry", {"String", ""}, "the geometry file's name"},
}};

const SkippedLayout* skipped_layout(std::string_view kw) noexcept {
  for (const SkippedLayout& s : kSkipped) {
    if (s.keyword == kw) return &s;
  }
  return nullptr;
}

// Singular nouns of the numbered sections, for messages.
std::string_view singular(std::string_view target) {
  if (target == "Vertices") return "vertex";
  if (target == "Edges") return "edge";
  if (target == "Triangles") return "triangle";
  if (target == "Quadrilaterals") return "quadrilateral";
  if (target == "Normals") return "normal";
  return "tangent";
}

}  // namespace

bool MeditSkippedSections::is_skipped(std::string_view kw) noexcept { return skipped_layout(kw) != nullptr; }

void MeditSkippedSections::skip(LineTokenizer& in, std::string_view keyword) {
  // `keyword` views the current line, which the next line overwrites: keep a copy.
  const std::string name(keyword);
  const SkippedLayout& layout = *skipped_layout(name);
  if (std::find(seen_.begin(), seen_.end(), name) != seen_.end()) in.fail("second " + name + " section");
  seen_.push_back(name);
  const std::uint64_t keyword_line = in.line();

  if (layout.targets[0] == "String") {
    // The string's tokens: the rest of the keyword's line, or the whole next line.
    std::size_t first = 1;
    if (in.size() == 1) {
      if (!in.next_line() || is_medit_keyword(in.token(0))) in.fail_at(keyword_line, "missing string after " + name);
      first = 0;
    }
    const std::string_view open = in.token(first);
    const std::string_view close = in.token(in.size() - 1);
    if (!open.starts_with('"') || !close.ends_with('"') || (first + 1 == in.size() && open.size() < 2)) {
      in.fail(name + " must be followed by one \"quoted string\", found " + quote(open));
    }
    notes_.push_back("section " + name + " skipped (line " + std::to_string(keyword_line) + ": " +
                     std::string(layout.what) + ")");
    return;
  }

  const std::uint64_t n = medit_section_count(in, name);
  const bool reals = layout.targets[0] == "Reals";
  const std::size_t fields = reals ? static_cast<std::size_t>(dimension_) : (layout.targets[1].empty() ? 1 : 2);
  std::array<Reference, 2> refs;
  for (std::size_t k = 0; k < 2; ++k) refs[k] = {name, std::string(layout.targets[k]), 0, 0, 0};
  for (std::uint64_t i = 0; i < n; ++i) {
    medit_next_entry(in, name, i, n);
    const std::string what = name + " entry " + std::to_string(i + 1);
    if (reals) {
      in.expect_tokens(fields, what + (dimension_ == 2 ? " (x y)" : " (x y z)"));
      for (std::size_t k = 0; k < fields; ++k) in.real(k, what + " component " + std::to_string(k + 1));
      continue;
    }
    in.expect_tokens(fields, what + (fields == 1 ? " (a number)" : " (vertex number, " +
                                                                      std::string(singular(layout.targets[1])) +
                                                                      " number)"));
    for (std::size_t k = 0; k < fields; ++k) {
      const std::string field = what + ": " + std::string(singular(layout.targets[k])) + " number";
      const std::int64_t v = in.integer(k, field);
      if (v < 1) in.fail(field + " " + std::to_string(v) + " is not positive (" + name + " numbers from 1)");
      if (v > refs[k].max) refs[k] = {name, std::string(layout.targets[k]), v, in.line(), i + 1};
    }
  }
  if (!reals) {
    for (std::size_t k = 0; k < fields; ++k) {
      if (refs[k].max > 0) references_.push_back(refs[k]);
    }
  }
  if (name == "Normals") normals_ = n;
  if (name == "Tangents") tangents_ = n;
  notes_.push_back("section " + name + " skipped (" + std::to_string(n) + (n == 1 ? " entry" : " entries") +
                   " from line " + std::to_string(keyword_line) + ": " + std::string(layout.what) + ")");
}

void MeditSkippedSections::finish(const LineTokenizer& in, const Counts& counts) const {
  for (const Reference& r : references_) {
    std::uint64_t count = 0;
    if (r.target == "Vertices") count = counts.vertices;
    if (r.target == "Edges") count = counts.edges;
    if (r.target == "Triangles") count = counts.triangles;
    if (r.target == "Quadrilaterals") count = counts.quadrilaterals;
    if (r.target == "Normals") count = normals_;
    if (r.target == "Tangents") count = tangents_;
    if (static_cast<std::uint64_t>(r.max) > count) {
      in.fail_at(r.line, r.section + " entry " + std::to_string(r.entry) + ": " + std::string(singular(r.target)) +
                             " number " + std::to_string(r.max) + " out of range 1.." + std::to_string(count) +
                             " (the file has " + std::to_string(count) + " " + r.target + ")");
    }
  }
}

void deliver_notes(const std::vector<std::string>& notes, const std::string& file_name,
                   std::vector<std::string>* sink) {
  if (sink != nullptr) {
    sink->insert(sink->end(), notes.begin(), notes.end());
    return;
  }
  for (const std::string& note : notes) std::cerr << "warning: " << file_name << ": " << note << "\n";
}

}  // namespace dtlab::io
