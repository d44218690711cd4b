// Medit solution files (mesh/io/medit_sol.hpp): ASCII .sol and binary .solb round trips in 2D and
// 3D, scalar and symmetric tensor, every bit kept (fixed awkward values and random bit patterns);
// binary versions 1-4 and both byte orders read; the layout libMeshb and MMG write (offsets,
// 32/64-bit words); Medit's component order for tensors (2D m11 m12 m22, 3D m11 m12 m22 m13 m23
// m33: the lower triangle row by row, as libMeshb documents it and MMG's reader swaps slots 2 and
// 3 into its own m11 m12 m13 m22 m23 m33); refusals: ParseError at the line (ASCII) or byte
// (binary) for every malformed file, every proper prefix of a binary file, InputError naming the
// vertex for a metric that is not positive definite and the counts for a solution that does not
// match its mesh.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/metric.hpp"
#include "mesh/io/medit_sol.hpp"

namespace dtlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same_sol(const SolData& a, const SolData& b) {
  EXPECT_EQ(a.dimension, b.dimension);
  EXPECT_EQ(a.kind, b.kind);
  ASSERT_EQ(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    EXPECT_TRUE(same_bits(a.values[i], b.values[i])) << "value " << i << ": " << a.values[i] << " vs " << b.values[i];
  }
}

// Finite doubles that a careless writer or reader would not bring back.
std::vector<double> awkward_doubles() {
  return {0.1,
          -0.0,
          0.0,
          1.0 / 3.0,
          -2.0 / 3.0,
          std::nextafter(1.0, 2.0),
          std::nextafter(1.0, 0.0),
          1e300,
          -1e-300,
          std::numeric_limits<double>::max(),
          std::numeric_limits<double>::lowest(),
          std::numeric_limits<double>::min(),
          123456789012345678.0,
          2.2250738585072014e-18,
          1e6,
          1e-6,
          5e-7,
          4.0,
          0.5,
          9.0,
          -17.25,
          3.0e-3,
          7.0,
          1.0};
}

SolData sample(int dimension, SolData::Kind kind, std::size_t vertices) {
  SolData s;
  s.dimension = dimension;
  s.kind = kind;
  const std::vector<double> v = awkward_doubles();
  for (std::size_t i = 0; i < vertices * s.values_per_vertex(); ++i) s.values.push_back(v[i % v.size()]);
  return s;
}

std::string write(const SolData& s, SolEncoding encoding = SolEncoding::Ascii, int version = 2) {
  std::ostringstream out;
  write_medit_sol(out, s, encoding, version);
  return out.str();
}

SolData read(const std::string& bytes, const std::string& name = "t.sol") {
  std::istringstream in(bytes);
  return read_medit_sol(in, name);
}

// The ParseError for `bytes`, with its line (ASCII) or byte (binary) and a part of its message.
void expect_parse_error(const std::string& bytes, std::uint64_t where, const std::string& needle) {
  try {
    const SolData s = read(bytes, "bad.sol");
    ADD_FAILURE() << "accepted (" << s.values.size() << " values); expected: " << needle;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "bad.sol");
    EXPECT_EQ(e.line(), where) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what() << "\n  expected: " << needle;
  }
}

// An InputError from `f` whose message holds every needle and whose items are `items`.
void expect_input_error(const std::function<void()>& f, const std::vector<std::string>& needles,
                        const std::vector<std::uint64_t>& items = {}) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected: " << needles.front();
  } catch (const InputError& e) {
    for (const std::string& n : needles) {
      EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what() << "\n  expected: " << n;
    }
    EXPECT_EQ(e.items(), items) << e.what();
  }
}

std::filesystem::path temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "dtlab_medit_sol_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

// --- A binary file built word by word, in either byte order ------------------------------------

class Solb {
 public:
  explicit Solb(int version, bool big_endian = false) : version_(version), big_(big_endian) {
    word(1);
    word(static_cast<std::uint32_t>(version));
  }
  std::size_t pos_bytes() const { return version_ >= 3 ? 8 : 4; }
  std::size_t count_bytes() const { return version_ == 4 ? 8 : 4; }

  Solb& word(std::uint64_t v, std::size_t n = 4) {
    bytes_ += encode(v, n);
    return *this;
  }
  // A keyword code and its next-keyword offset; `next` = kAuto: the end of what `body` appends.
  static constexpr std::uint64_t kAuto = ~std::uint64_t{0};
  Solb& keyword(std::int32_t code, const std::function<void(Solb&)>& body, std::uint64_t next = kAuto) {
    word(static_cast<std::uint32_t>(code));
    const std::size_t at = bytes_.size();
    word(0, pos_bytes());
    body(*this);
    bytes_.replace(at, pos_bytes(), encode(next == kAuto ? bytes_.size() : next, pos_bytes()));
    return *this;
  }
  Solb& dimension(int d) {
    return keyword(3, [d](Solb& b) { b.word(static_cast<std::uint32_t>(d)); });
  }
  // SolAtVertices: count, field count, types, then the values as doubles (version >= 2) or floats.
  Solb& section(std::uint64_t count, std::vector<std::int32_t> types, const std::vector<double>& values,
                std::uint64_t next = kAuto) {
    return keyword(
        62,
        [&](Solb& b) {
          b.word(count, b.count_bytes());
          b.word(static_cast<std::uint32_t>(types.size()));
          for (std::int32_t t : types) b.word(static_cast<std::uint32_t>(t));
          for (double v : values) {
            if (version_ == 1) {
              b.word(std::bit_cast<std::uint32_t>(static_cast<float>(v)));
            } else {
              b.word(std::bit_cast<std::uint64_t>(v), 8);
            }
          }
        },
        next);
  }
  Solb& end() {
    word(54);
    return word(0, pos_bytes());
  }
  std::string str() const { return bytes_; }

 private:
  // The n-byte word v in the file's byte order.
  std::string encode(std::uint64_t v, std::size_t n) const {
    std::string out;
    for (std::size_t k = 0; k < n; ++k) out += static_cast<char>((v >> (8 * (big_ ? n - 1 - k : k))) & 0xff);
    return out;
  }

  int version_;
  bool big_;
  std::string bytes_;
};

// --- Round trips ---------------------------------------------------------------------------------

struct Case {
  int dimension;
  SolData::Kind kind;
};
const Case kCases[] = {{2, SolData::Kind::Scalar}, {2, SolData::Kind::Tensor}, {3, SolData::Kind::Scalar}, {3, SolData::Kind::Tensor}};

TEST(MeditSol, AsciiRoundTripKeepsEveryBit) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << c.dimension << "D " << (c.kind == SolData::Kind::Scalar ? "scalar" : "tensor"));
    const SolData s = sample(c.dimension, c.kind, 17);
    const std::string text = write(s);
    EXPECT_EQ(detect_sol_encoding(text), SolEncoding::Ascii);
    expect_same_sol(read(text), s);
  }
}

TEST(MeditSol, BinaryRoundTripKeepsEveryBitInEachVersion) {
  for (int version : {2, 3, 4}) {
    for (const Case& c : kCases) {
      SCOPED_TRACE(testing::Message() << "version " << version << ", " << c.dimension << "D "
                                      << (c.kind == SolData::Kind::Scalar ? "scalar" : "tensor"));
      const SolData s = sample(c.dimension, c.kind, 17);
      const std::string bytes = write(s, SolEncoding::Binary, version);
      EXPECT_EQ(detect_sol_encoding(bytes), SolEncoding::Binary);
      expect_same_sol(read(bytes), s);
    }
  }
}

TEST(MeditSol, SubnormalsSurviveBothEncodings) {
  SolData s;
  s.kind = SolData::Kind::Scalar;
  s.values = {std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
              std::nextafter(std::numeric_limits<double>::min(), 0.0), 1e-310};
  expect_same_sol(read(write(s)), s);
  expect_same_sol(read(write(s, SolEncoding::Binary)), s);
}

TEST(MeditSol, EmptySolutionRoundTrips) {
  for (const Case& c : kCases) {
    const SolData s = sample(c.dimension, c.kind, 0);
    expect_same_sol(read(write(s)), s);
    expect_same_sol(read(write(s, SolEncoding::Binary, 3)), s);
  }
}

// Random values by bit pattern (every finite double is fair), any dimension, kind, encoding.
RC_GTEST_PROP(MeditSolProperty, RandomSolutionsRoundTripBitForBit, ()) {
  SolData s;
  s.dimension = *rc::gen::element(2, 3);
  s.kind = *rc::gen::element(SolData::Kind::Scalar, SolData::Kind::Tensor);
  const std::size_t n = *rc::gen::inRange<std::size_t>(0, 40);
  const auto bits = *rc::gen::container<std::vector<std::uint64_t>>(n * s.values_per_vertex(), rc::gen::arbitrary<std::uint64_t>());
  for (std::uint64_t b : bits) {
    const double v = std::bit_cast<double>(b);
    s.values.push_back(std::isfinite(v) ? v : std::bit_cast<double>(b & 0x800FFFFFFFFFFFFFull));  // exponent cleared: finite
  }
  const int version = *rc::gen::element(0, 2, 3, 4);  // 0: ASCII
  const std::string bytes = version == 0 ? write(s) : write(s, SolEncoding::Binary, version);
  const SolData back = read(bytes);
  RC_ASSERT(back.dimension == s.dimension);
  RC_ASSERT(back.kind == s.kind);
  RC_ASSERT(back.values.size() == s.values.size());
  for (std::size_t i = 0; i < s.values.size(); ++i) RC_ASSERT(same_bits(back.values[i], s.values[i]));
}

TEST(MeditSol, FilesByExtension) {
  const SolData s = sample(3, SolData::Kind::Tensor, 5);
  const std::string ascii = temp_path("m.sol").string();
  const std::string binary = temp_path("m.solb").string();
  write_medit_sol(ascii, s);
  write_medit_sol(binary, s);
  std::ifstream a(ascii, std::ios::binary), b(binary, std::ios::binary);
  const std::string abytes((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
  const std::string bbytes((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
  EXPECT_EQ(abytes.rfind("MeshVersionFormatted 2\n", 0), 0u);
  EXPECT_EQ(detect_sol_encoding(bbytes), SolEncoding::Binary);
  expect_same_sol(read_medit_sol(ascii), s);
  expect_same_sol(read_medit_sol(binary), s);
  // Writing twice gives the same bytes.
  write_medit_sol(binary, s);
  std::ifstream b2(binary, std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(b2)), std::istreambuf_iterator<char>()), bbytes);
  EXPECT_THROW(read_medit_sol(temp_path("missing.sol").string()), ParseError);
}

// --- Layout ------------------------------------------------------------------------------------

TEST(MeditSol, AsciiLayout) {
  SolData s;
  s.dimension = 2;
  s.kind = SolData::Kind::Tensor;
  s.values = {4, 0.5, 9, 100, -1.25, 1e-6};
  EXPECT_EQ(write(s),
            "MeshVersionFormatted 2\n\nDimension 2\n\nSolAtVertices\n2\n1 3\n4 0.5 9\n100 -1.25 1e-06\n\nEnd\n");
  s.kind = SolData::Kind::Scalar;
  s.dimension = 3;
  s.values = {0.1, 0.25};
  EXPECT_EQ(write(s), "MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n2\n1 1\n0.1\n0.25\n\nEnd\n");
}

// The bytes MMG's writer (MMG5_saveSolHeader) and libMeshb produce in version 2: 1, version,
// Dimension (3) with next offset 20 and the dimension, SolAtVertices (62) with the offset of End,
// count, 1 field, its type, the doubles; End (54) with offset 0.
TEST(MeditSol, BinaryLayoutIsLibMeshbs) {
  SolData s;
  s.dimension = 3;
  s.kind = SolData::Kind::Tensor;
  s.values = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::string v2 = write(s, SolEncoding::Binary, 2);
  const std::string expected = Solb(2).dimension(3).section(2, {3}, s.values).end().str();
  EXPECT_EQ(v2, expected);
  auto word = [&](const std::string& b, std::size_t at) {
    std::uint32_t w;
    std::memcpy(&w, b.data() + at, 4);
    return w;  // the test machine is little-endian, as the writer's output
  };
  ASSERT_EQ(v2.size(), 8u + 12 + (4 + 4 + 4 + 4 + 4 + 96) + 8);
  EXPECT_EQ(word(v2, 0), 1u);
  EXPECT_EQ(word(v2, 4), 2u);
  EXPECT_EQ(word(v2, 8), 3u);
  EXPECT_EQ(word(v2, 12), 20u);
  EXPECT_EQ(word(v2, 16), 3u);
  EXPECT_EQ(word(v2, 20), 62u);
  EXPECT_EQ(word(v2, 24), 40u + 96);
  EXPECT_EQ(word(v2, 28), 2u);
  EXPECT_EQ(word(v2, 32), 1u);
  EXPECT_EQ(word(v2, 36), 3u);
  EXPECT_EQ(word(v2, 136), 54u);
  EXPECT_EQ(word(v2, 140), 0u);
  // Versions 3 and 4: 64-bit offsets; version 4 also a 64-bit count.
  EXPECT_EQ(write(s, SolEncoding::Binary, 3), Solb(3).dimension(3).section(2, {3}, s.values).end().str());
  EXPECT_EQ(write(s, SolEncoding::Binary, 4), Solb(4).dimension(3).section(2, {3}, s.values).end().str());
  EXPECT_EQ(write(s, SolEncoding::Binary, 3).size(), v2.size() + 3 * 4);
  EXPECT_EQ(write(s, SolEncoding::Binary, 4).size(), v2.size() + 4 * 4);
}

TEST(MeditSol, BigEndianFilesRead) {
  for (int version : {1, 2, 3, 4}) {
    SCOPED_TRACE(testing::Message() << "version " << version);
    const std::vector<double> v = {4, 0.5, 9, 0.25, -0.125, 16};
    const std::string big = Solb(version, true).dimension(2).section(2, {3}, v).end().str();
    const std::string little = Solb(version, false).dimension(2).section(2, {3}, v).end().str();
    EXPECT_EQ(detect_sol_encoding(big), SolEncoding::Binary);
    const SolData a = read(big), b = read(little);
    expect_same_sol(a, b);
    EXPECT_EQ(a.dimension, 2);
    EXPECT_EQ(a.kind, SolData::Kind::Tensor);
    EXPECT_EQ(a.values, v);  // exact in floats too
  }
}

TEST(MeditSol, Version1StoresFloats) {
  const std::string bytes = Solb(1).dimension(2).section(3, {1}, {0.1, 2.5, 1e-3}).end().str();
  const SolData s = read(bytes);
  ASSERT_EQ(s.values.size(), 3u);
  EXPECT_EQ(s.values[0], static_cast<double>(0.1f));
  EXPECT_EQ(s.values[1], 2.5);
  EXPECT_EQ(s.values[2], static_cast<double>(1e-3f));
  // The writer keeps every bit, so it does not write floats.
  expect_input_error([] { write(sample(2, SolData::Kind::Scalar, 1), SolEncoding::Binary, 1); }, {"version 1"});
}

// --- Medit's component order -----------------------------------------------------------------------

TEST(MeditSol, TensorComponentsInMeditOrder2D) {
  // m11 = 4, m12 = 0.5, m22 = 9: lengths 2 along x, 3 along y.
  const std::string text = "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n1\n1 3\n4 0.5 9\nEnd\n";
  const std::vector<Metric2> m = metrics2_from_sol(read(text), "t.sol");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].m, (std::array<double, 3>{4, 0.5, 9}));
  EXPECT_EQ(m[0].length({1, 0}), 2.0);
  EXPECT_EQ(m[0].length({0, 1}), 3.0);
  EXPECT_DOUBLE_EQ(m[0].length({1, 1}), std::sqrt(4 + 2 * 0.5 + 9));
  // And back: sol_from_metrics writes the same line.
  const std::string back = write(sol_from_metrics(m));
  EXPECT_NE(back.find("\n1 3\n4 0.5 9\n"), std::string::npos) << back;
}

TEST(MeditSol, TensorComponentsInMeditOrder3D) {
  // The file's m11 m12 m22 m13 m23 m33 = 1 0.125 4 0.25 0.5 9: a distinct value in each slot, so a
  // reader that took the upper triangle row by row (m11 m12 m13 m22 m23 m33, MMG's own storage)
  // would see m13 = 4, m22 = 0.25 and length 0.5 along y instead of 2.
  const std::string text = "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n1\n1 3\n1 0.125 4 0.25 0.5 9\nEnd\n";
  const std::vector<Metric3> m = metrics3_from_sol(read(text), "t.sol");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].m, (std::array<double, 6>{1, 0.125, 4, 0.25, 0.5, 9}));
  EXPECT_EQ(m[0].length({1, 0, 0}), 1.0);
  EXPECT_EQ(m[0].length({0, 1, 0}), 2.0);
  EXPECT_EQ(m[0].length({0, 0, 1}), 3.0);
  EXPECT_DOUBLE_EQ(m[0].length({1, 1, 0}), std::sqrt(1 + 2 * 0.125 + 4));  // m12
  EXPECT_DOUBLE_EQ(m[0].length({1, 0, 1}), std::sqrt(1 + 2 * 0.25 + 9));   // m13
  EXPECT_DOUBLE_EQ(m[0].length({0, 1, 1}), std::sqrt(4 + 2 * 0.5 + 9));    // m23
  const std::string back = write(sol_from_metrics(m));
  EXPECT_NE(back.find("\n1 3\n1 0.125 4 0.25 0.5 9\n"), std::string::npos) << back;
  // The binary file holds the same order.
  const SolData b = read(Solb(2).dimension(3).section(1, {3}, {1, 0.125, 4, 0.25, 0.5, 9}).end().str());
  EXPECT_EQ(metrics3_from_sol(b, "t.solb")[0].m, m[0].m);
}

TEST(MeditSol, MetricsRoundTripThroughFiles) {
  std::vector<Metric2> m2;
  std::vector<Metric3> m3;
  for (int i = 0; i < 20; ++i) {
    const double a = 0.3 * i;
    m2.push_back(Metric2::from_sizes({std::cos(a), std::sin(a)}, 0.1 + i, 1e-2 * (i + 1)));
    const Vec3 e1{std::cos(a), std::sin(a), 0}, e2{-std::sin(a) * 0.6, std::cos(a) * 0.6, 0.8};
    m3.push_back(Metric3::from_sizes(e1, e2, 1.0 + i, 0.5, 1e-2 * (i + 1)));
  }
  for (SolEncoding e : {SolEncoding::Ascii, SolEncoding::Binary}) {
    EXPECT_EQ(metrics2_from_sol(read(write(sol_from_metrics(m2), e)), "m.sol"), m2);
    EXPECT_EQ(metrics3_from_sol(read(write(sol_from_metrics(m3), e)), "m.sol"), m3);
  }
}

TEST(MeditSol, ScalarSizesGiveIsotropicMetrics) {
  SolData s;
  s.kind = SolData::Kind::Scalar;
  s.values = {0.5, 2};
  const std::vector<Metric2> m = metrics2_from_sol(s, "h.sol");
  EXPECT_EQ(m[0], Metric2::isotropic(0.5));
  EXPECT_EQ(m[1], Metric2::isotropic(2));
  s.dimension = 3;
  EXPECT_EQ(metrics3_from_sol(s, "h.sol")[1], Metric3::isotropic(2));
}

// --- ASCII refusals ----------------------------------------------------------------------------

std::string ascii(const std::string& body) { return "MeshVersionFormatted 2\nDimension 2\n" + body; }

TEST(MeditSol, AsciiAcceptsMeditsOwnVariations) {
  // Values on the keyword's next line, comments, blank lines, CRLF, the count on the keyword's line.
  const std::string text =
      "# a comment\r\nMeshVersionFormatted\r\n 2\r\n\r\nDimension\n3\n\nSolAtVertices 2\n1 1 # one scalar\n  0.5  \n+2\n\n End \n";
  const SolData s = read(text);
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.values, (std::vector<double>{0.5, 2}));
}

TEST(MeditSol, AsciiRefusesMalformedHeaders) {
  expect_parse_error("", 1, "file ends before End");
  expect_parse_error("Dimension 2\n", 1, "expected MeshVersionFormatted first");
  expect_parse_error("MeshVersionFormatted 5\n", 1, "MeshVersionFormatted 5 is not 1, 2, 3 or 4");
  expect_parse_error("MeshVersionFormatted 0\n", 1, "is not 1, 2, 3 or 4");
  expect_parse_error("MeshVersionFormatted 2\nMeshVersionFormatted 2\n", 2, "second MeshVersionFormatted");
  expect_parse_error("MeshVersionFormatted 2\nDimension 4\n", 2, "Dimension 4 is not 2 or 3");
  expect_parse_error("MeshVersionFormatted 2\nDimension 1\n", 2, "Dimension 1 is not 2 or 3");
  expect_parse_error("MeshVersionFormatted 2\nDimension 2\nDimension 3\n", 3, "second Dimension");
  expect_parse_error("MeshVersionFormatted 2\nSolAtVertices\n1\n1 1\n1\nEnd\n", 2, "SolAtVertices before Dimension");
  expect_parse_error(ascii("End\n"), 3, "End before any SolAtVertices");
}

TEST(MeditSol, AsciiRefusesOtherFieldTypes) {
  expect_parse_error(ascii("SolAtVertices\n1\n1 2\n1 2\nEnd\n"), 5, "field type 2 (a vector) is not supported");
  expect_parse_error(ascii("SolAtVertices\n1\n1 4\n1 0 0 1\nEnd\n"), 5, "field type 4 (a full matrix) is not supported");
  expect_parse_error(ascii("SolAtVertices\n1\n1 7\n1\nEnd\n"), 5, "field type 7 is not a Medit type");
  expect_parse_error(ascii("SolAtVertices\n1\n1 0\n1\nEnd\n"), 5, "field type 0 is not a Medit type");
  expect_parse_error(ascii("SolAtVertices\n1\n2 1 1\n1 2\nEnd\n"), 5, "2 fields: this reader keeps one field");
  expect_parse_error(ascii("SolAtVertices\n1\n0\n1\nEnd\n"), 5, "number of fields 0 is not positive");
  expect_parse_error(ascii("SolAtVertices\n1\n1\n1\nEnd\n"), 5, "SolAtVertices field types (1 type): expected 2 fields, found 1");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1 1\n1\nEnd\n"), 5, "SolAtVertices field types (1 type): trailing text");
  expect_parse_error(ascii("SolAtVertices\n1\nEnd\n"), 5, "missing the field types");
  expect_parse_error(ascii("SolAtVertices\n1\n"), 4, "file ends after the SolAtVertices count");
}

TEST(MeditSol, AsciiRefusesOtherKeywords) {
  expect_parse_error(ascii("SolAtTriangles\n1\n1 1\n1\nEnd\n"), 3, "keyword 'SolAtTriangles' is not supported");
  expect_parse_error(ascii("SolAtTetrahedra\n1\n1 1\n1\nEnd\n"), 3, "is not supported: this reader keeps SolAtVertices");
  expect_parse_error(ascii("HOSolAtTrianglesP2\n1\n1 1\n1\nEnd\n"), 3, "is not supported");
  for (const char* kw : {"Vertices", "Triangles", "Foo", "solatvertices"}) {
    SCOPED_TRACE(kw);
    try {
      read(ascii(std::string(kw) + "\n1\n1 1\n1\nEnd\n"), "bad.sol");
      ADD_FAILURE() << kw << " accepted";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 3u);
      EXPECT_NE(std::string(e.what()).find(kw), std::string::npos) << e.what();
    }
  }
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n1\nSolAtVertices\n1\n1 1\n1\nEnd\n"), 7, "second SolAtVertices section");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n1\nEnd\nEnd\n"), 8, "text after End");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n1\nEnd\n0.5\n"), 8, "text after End");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n1\nEnd 2\n"), 7, "End: trailing text");
}

TEST(MeditSol, AsciiRefusesCountsThatDoNotMatchTheEntries) {
  // Fewer entries than the count: the End keyword is where entry 3 should be.
  expect_parse_error(ascii("SolAtVertices\n3\n1 1\n1\n2\nEnd\n"), 8, "SolAtVertices count is 3 but only 2 entries precede 'End'");
  // More: the third value is where a keyword should be.
  expect_parse_error(ascii("SolAtVertices\n2\n1 1\n1\n2\n3\nEnd\n"), 8, "found the number '3' (more entries than the section's count?)");
  // Truncated in the middle of the entries, or before End.
  expect_parse_error(ascii("SolAtVertices\n3\n1 1\n1\n2\n"), 7, "file ends in SolAtVertices after 2 of 3 entries");
  expect_parse_error(ascii("SolAtVertices\n2\n1 1\n1\n2\n"), 7, "file ends before End");
  expect_parse_error(ascii("SolAtVertices\n-1\n1 1\nEnd\n"), 4, "negative");
  expect_parse_error(ascii("SolAtVertices\n99999999999\n1 1\nEnd\n"), 4, "32-bit");
}

TEST(MeditSol, AsciiRefusesBadEntries) {
  // A tensor line with two values, or four; two scalars on one line.
  expect_parse_error(ascii("SolAtVertices\n2\n1 3\n1 0 1\n1 0\nEnd\n"), 7, "vertex 2 (m11 m12 m22): expected 3 fields, found 2");
  expect_parse_error(ascii("SolAtVertices\n2\n1 3\n1 0 1\n1 0 1 0\nEnd\n"), 7, "vertex 2 (m11 m12 m22): trailing text");
  expect_parse_error(ascii("SolAtVertices\n2\n1 1\n1 2\nEnd\n"), 6, "vertex 1");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\nnan\nEnd\n"), 6, "vertex 1 value is not finite");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n-inf\nEnd\n"), 6, "not finite");
  expect_parse_error(ascii("SolAtVertices\n1\n1 1\n1e999\nEnd\n"), 6, "out of the range of a double");
  expect_parse_error(ascii("SolAtVertices\n1\n1 3\n1 0x1 1\nEnd\n"), 6, "vertex 1 m12 is not a number");
  expect_parse_error(ascii("SolAtVertices\n1\n1 3\n1 0 1,5\nEnd\n"), 6, "vertex 1 m22 is not a number");
}

// --- Binary refusals ---------------------------------------------------------------------------

std::string good_solb(int version) {
  return Solb(version).dimension(2).section(2, {3}, {4, 0.5, 9, 1, 0, 1}).end().str();
}

// Every proper prefix of a valid file is refused by a ParseError saying "byte", and the whole is read.
TEST(MeditSol, BinaryRefusesEveryTruncation) {
  for (int version : {1, 2, 3, 4}) {
    const std::string bytes = good_solb(version);
    EXPECT_EQ(read(bytes).values.size(), 6u);
    for (std::size_t n = 4; n < bytes.size(); ++n) {
      try {
        read(bytes.substr(0, n));
        ADD_FAILURE() << "version " << version << ": a prefix of " << n << " of " << bytes.size() << " bytes was accepted";
      } catch (const ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("byte"), std::string::npos) << e.what();
        EXPECT_LE(e.line(), n) << e.what();
      }
    }
  }
}

TEST(MeditSol, BinaryRefusesMalformedHeaders) {
  {
    std::string bytes = good_solb(2);
    bytes[4] = 5;  // version 5
    expect_parse_error(bytes, 4, "version 5 is not 1, 2, 3 or 4");
  }
  expect_parse_error(Solb(2).dimension(4).section(1, {1}, {1}).end().str(), 16, "Dimension 4 is not 2 or 3");
  expect_parse_error(Solb(2).dimension(2).dimension(2).section(1, {1}, {1}).end().str(), 20, "second Dimension");
  expect_parse_error(Solb(2).section(1, {1}, {1}).end().str(), 8, "SolAtVertices before Dimension");
  expect_parse_error(Solb(2).dimension(2).end().str(), 20, "End before any SolAtVertices");
  expect_parse_error(Solb(2).dimension(2).section(1, {1}, {1}).section(1, {1}, {1}).end().str(), 48,
                     "second SolAtVertices section");
  // A file that ends where a keyword should begin.
  expect_parse_error(Solb(2).dimension(2).section(1, {1}, {1}).str(), 48, "file ends before End");
}

TEST(MeditSol, BinaryRefusesOtherKeywordsAndTypes) {
  const auto other = [](std::int32_t code) {
    return Solb(2).dimension(2).keyword(code, [](Solb& b) { b.word(1).word(1).word(1).word(0, 8); }).end().str();
  };
  expect_parse_error(other(64), 20, "keyword code 64 (SolAtTriangles) is not supported");
  expect_parse_error(other(4), 20, "keyword code 4 (Vertices) is not supported");
  expect_parse_error(other(999), 20, "keyword code 999 is not supported");
  expect_parse_error(Solb(2).dimension(2).section(1, {2}, {1, 2}).end().str(), 36, "field type 2 (a vector)");
  expect_parse_error(Solb(2).dimension(2).section(1, {4}, {1, 0, 0, 1}).end().str(), 36, "field type 4 (a full matrix)");
  expect_parse_error(Solb(2).dimension(2).section(1, {9}, {1}).end().str(), 36, "field type 9 is not a Medit type");
  expect_parse_error(Solb(2).dimension(2).section(1, {1, 1}, {1, 2}).end().str(), 32, "2 fields");
  expect_parse_error(Solb(2).dimension(2).section(1, {}, {}).end().str(), 32, "number of fields 0 is not positive");
}

TEST(MeditSol, BinaryRefusesCountsThatDoNotMatchTheValues) {
  // More vertices counted than values stored: refused before anything is allocated.
  expect_parse_error(Solb(2).dimension(2).section(5, {1}, {1, 2}).end().str(), 40,
                     "SolAtVertices count 5 needs 40 bytes of values, but the file has 24 left (truncated?)");
  expect_parse_error(Solb(2).dimension(2).section(2'000'000'000, {3}, {1, 0, 1}).end().str(), 40, "(truncated?)");
  expect_parse_error(Solb(4).dimension(2).section(std::uint64_t{1} << 40, {1}, {1}).end().str(), 36,
                     "exceeds the 32-bit index range");
  expect_parse_error(Solb(2).dimension(2).section(0xFFFFFFFFu, {1}, {1}).end().str(), 28, "count -1 is negative");
  // Fewer: the next keyword's offset is not where the values end (and the extra value is read as one).
  expect_parse_error(Solb(2).dimension(2).section(1, {1}, {1, 2}).end().str(), 24, "next-keyword offset 56 is not where the next keyword begins (byte 48)");
  // An offset that points elsewhere.
  expect_parse_error(Solb(2).dimension(2).section(1, {1}, {1}, 100).end().str(), 24, "next-keyword offset 100");
  expect_parse_error(Solb(3).dimension(2).section(1, {1}, {1}, 0).end().str(), 28, "next-keyword offset 0");
  {
    std::string bytes = good_solb(2);
    bytes[12] = 21;  // Dimension's offset
    expect_parse_error(bytes, 12, "next-keyword offset 21 is not where the next keyword begins (byte 20)");
  }
  expect_parse_error(good_solb(2) + "x", 96, "1 bytes after End");
  expect_parse_error(good_solb(3) + std::string(8, '\0'), 108, "8 bytes after End");
}

TEST(MeditSol, BinaryRefusesNonFiniteValues) {
  expect_parse_error(Solb(2).dimension(2).section(2, {3}, {1, 0, 1, 1, kNaN, 1}).end().str(), 40 + 4 * 8,
                     "vertex 2 m12 is not finite");
  expect_parse_error(Solb(2).dimension(3).section(1, {1}, {kInf}).end().str(), 40, "vertex 1 value is not finite");
  expect_parse_error(Solb(1).dimension(2).section(1, {1}, {-kInf}).end().str(), 40, "not finite");
}

// --- Metrics and counts ------------------------------------------------------------------------

SolData tensors2(std::vector<double> values) {
  SolData s;
  s.kind = SolData::Kind::Tensor;
  s.values = std::move(values);
  return s;
}

TEST(MeditSol, MetricsRefuseTensorsThatAreNotPositiveDefinite) {
  // Vertex 3 (item 2) indefinite; then semi-definite (det 0), a negative m11, a negative size.
  expect_input_error([] { metrics2_from_sol(tensors2({1, 0, 1, 2, 0, 2, 1, 2, 1}), "m.sol"); },
                     {"m.sol", "vertex 3", "tensor (1, 2, 1) is not positive definite"}, {2});
  expect_input_error([] { metrics2_from_sol(tensors2({1, 1, 1}), "m.sol"); }, {"vertex 1", "not positive definite"}, {0});
  expect_input_error([] { metrics2_from_sol(tensors2({1, 0, 1, -1, 0, -1}), "m.sol"); }, {"vertex 2", "not positive definite"},
                     {1});
  expect_input_error([] { metrics2_from_sol(tensors2({0, 0, 0}), "m.sol"); }, {"vertex 1", "not positive definite"}, {0});
  expect_input_error([] { metrics2_from_sol(tensors2({1, 0, kNaN}), "m.sol"); }, {"vertex 1", "not finite"}, {0});
  SolData s3;
  s3.dimension = 3;
  s3.kind = SolData::Kind::Tensor;
  s3.values = {1, 0, 1, 0, 0, 1, /* vertex 2: m23 = 2 makes the y-z block indefinite */ 1, 0, 1, 0, 2, 1};
  expect_input_error([&] { metrics3_from_sol(s3, "m3.sol"); }, {"m3.sol", "vertex 2", "not positive definite"}, {1});
  SolData h;
  h.kind = SolData::Kind::Scalar;
  h.values = {0.1, 0.0};
  expect_input_error([&] { metrics2_from_sol(h, "h.sol"); }, {"h.sol", "vertex 2", "size (0) is not positive"}, {1});
  h.values = {-0.5};
  expect_input_error([&] { metrics2_from_sol(h, "h.sol"); }, {"vertex 1", "is not positive"}, {0});
  h.values = {1e-200};  // h^-2 overflows
  expect_input_error([&] { metrics2_from_sol(h, "h.sol"); }, {"vertex 1", "size (1e-200) is out of the representable range"}, {0});
  h.values = {1, 1e200};  // h^-2 underflows to 0 (it was called an overflow)
  expect_input_error([&] { metrics2_from_sol(h, "h.sol"); }, {"vertex 2", "size (1e+200) is out of the representable range"}, {1});
  // Tensors: bounded eigenvalues (issue 42): 1e300 I is positive definite, but its size 1e-150
  // is not representable (its determinant overflows in 2D already).
  expect_input_error([] { metrics2_from_sol(tensors2({1, 0, 1, 1e300, 0, 1e300}), "t.sol"); },
                     {"t.sol", "vertex 2", "has a size 1e-150 out of the representable range"}, {1});
  SolData t3;
  t3.dimension = 3;
  t3.kind = SolData::Kind::Tensor;
  t3.values = {1e-120, 0, 1, 0, 0, 1};  // size 1e60 along x
  expect_input_error([&] { metrics3_from_sol(t3, "t3.sol"); }, {"vertex 1", "has a size 1e+60 out of"}, {0});
}

TEST(MeditSol, MetricsRefuseTheOtherDimension) {
  expect_input_error([] { metrics3_from_sol(tensors2({1, 0, 1}), "m.sol"); }, {"m.sol", "2D solution where a 3D metric"});
  SolData s3 = sample(3, SolData::Kind::Scalar, 1);
  s3.values = {1};
  expect_input_error([&] { metrics2_from_sol(s3, "m.sol"); }, {"m.sol", "3D solution where a 2D metric"});
  expect_input_error([] { metrics2_from_sol(tensors2({1, 0, 1, 1}), "m.sol"); }, {"not a whole number of vertices"});
}

TEST(MeditSol, CountMustMatchTheMesh) {
  const SolData s = sample(2, SolData::Kind::Tensor, 4);
  EXPECT_NO_THROW(check_sol_matches(s, 4, "m.sol"));
  expect_input_error([&] { check_sol_matches(s, 5, "m.sol"); }, {"m.sol", "4 vertices", "the mesh has 5"});
  expect_input_error([&] { check_sol_matches(s, 0, "m.sol"); }, {"m.sol", "the mesh has 0"});
  // A solution whose values are not a whole number of vertices matches no mesh.
  SolData odd = s;
  odd.values.pop_back();
  expect_input_error([&] { check_sol_matches(odd, 3, "m.sol"); }, {"m.sol", "not a whole number of vertices"});
}

TEST(MeditSol, WriterRefusesWhatItCannotWrite) {
  SolData s = sample(2, SolData::Kind::Tensor, 2);
  s.dimension = 4;
  expect_input_error([&] { write(s); }, {"dimension 4 is not 2 or 3"});
  s.dimension = 2;
  s.values.push_back(1);
  expect_input_error([&] { write(s, SolEncoding::Binary); }, {"7 values are not a whole number of vertices (3 per vertex)"});
  s.values = {1, 0, 1, 1, kInf, 1};
  expect_input_error([&] { write(s); }, {"vertex 2", "not finite"}, {1});
  s.values = {1, 0, 1};
  expect_input_error([&] { write(s, SolEncoding::Binary, 5); }, {"version 5"});
  // Nothing was written on a refusal.
  std::ostringstream out;
  s.values = {kNaN, 0, 1};
  EXPECT_THROW(write_medit_sol(out, s, SolEncoding::Binary), InputError);
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace dtlab
