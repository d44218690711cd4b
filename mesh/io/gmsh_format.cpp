// Gmsh .msh files: MSH 4.1 and 2.2 read, 4.1 written, both encodings (see gmsh_format.hpp and
// Gmsh's reference manual, section "MSH file format"). ASCII values are read as a stream of
// tokens across lines, as Gmsh itself reads them; binary values through io::BinaryInput.
#include "mesh/io/gmsh_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/binary_input.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::quote;

// Gmsh's element types that MeshData3 holds, and the names of the others for messages.
constexpr int kPoint = 15;
constexpr int kLine = 1;
constexpr int kTriangle = 2;
constexpr int kTetrahedron = 4;

int nodes_of(int type) {
  switch (type) {
    case kPoint: return 1;
    case kLine: return 2;
    case kTriangle: return 3;
    case kTetrahedron: return 4;
    default: return 0;
  }
}

int dimension_of(int type) {
  switch (type) {
    case kPoint: return 0;
    case kLine: return 1;
    case kTriangle: return 2;
    default: return 3;
  }
}

std::string type_name(std::int64_t type) {
  switch (type) {
    case 1: return "2-node line";
    case 2: return "3-node triangle";
    case 3: return "4-node quadrangle";
    case 4: return "4-node tetrahedron";
    case 5: return "8-node hexahedron";
    case 6: return "6-node prism";
    case 7: return "5-node pyramid";
    case 8: return "3-node second-order line";
    case 9: return "6-node second-order triangle";
    case 10: return "9-node second-order quadrangle";
    case 11: return "10-node second-order tetrahedron";
    case 12: return "27-node second-order hexahedron";
    case 13: return "18-node second-order prism";
    case 14: return "14-node second-order pyramid";
    case 15: return "1-node point";
    case 16: return "8-node second-order quadrangle";
    case 17: return "20-node second-order hexahedron";
    case 18: return "15-node second-order prism";
    case 19: return "13-node second-order pyramid";
    default: return type >= 20 && type <= 140 ? "higher-order or special element" : "not a Gmsh element type";
  }
}

std::string type_problem(std::uint64_t tag, std::int64_t type) {
  return "element " + std::to_string(tag) + " is of type " + std::to_string(type) + " (" + type_name(type) +
         "), which dtlab's meshes cannot hold (they keep 1-node points, 2-node lines, 3-node triangles and 4-node "
         "tetrahedra)";
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// The file in memory, read from its start: tokens (in ASCII files and the ASCII parts of binary
// ones) and binary words. Every value read sets the location that fail() names.
class MshInput {
 public:
  MshInput(std::string_view bytes, const std::string& name) : bin_(bytes, name), bytes_(bytes), file_(name) {}

  bool binary() const noexcept { return binary_; }
  void set_binary(bool swapped) {
    binary_ = true;
    bin_.set_swapped(swapped);
  }
  std::size_t position() const noexcept { return pos_; }
  std::string_view bytes() const noexcept { return bytes_; }
  const std::string& file_name() const noexcept { return file_; }

  // The next blank-separated token; "" at the end of the file.
  std::string_view token() {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
    loc_line_ = line_;
    loc_byte_ = pos_;
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    return bytes_.substr(start, pos_ - start);
  }

  // After a header line of a binary file: blanks, then the one '\n' before the binary data.
  void skip_line_end() {
    while (pos_ < bytes_.size() && (bytes_[pos_] == ' ' || bytes_[pos_] == '\t' || bytes_[pos_] == '\r')) ++pos_;
    if (pos_ >= bytes_.size() || bytes_[pos_] != '\n') fail_here("expected the end of the line before binary data");
    ++pos_;
    ++line_;
  }

  // A quoted name after blanks on the current line ($PhysicalNames).
  std::string quoted(const std::string& what) {
    while (pos_ < bytes_.size() && (bytes_[pos_] == ' ' || bytes_[pos_] == '\t')) ++pos_;
    loc_line_ = line_;
    loc_byte_ = pos_;
    if (pos_ >= bytes_.size() || bytes_[pos_] != '"') fail(what + " is not a quoted name");
    const std::size_t close = bytes_.find_first_of("\"\n", pos_ + 1);
    if (close == std::string_view::npos || bytes_[close] != '"') fail(what + ": the quote is not closed on its line");
    std::string name(bytes_.substr(pos_ + 1, close - pos_ - 1));
    pos_ = close + 1;
    return name;
  }

  std::int64_t ascii_integer(const std::string& what) {
    const std::string_view t = token();
    if (t.empty()) fail("file ends in " + what + " (truncated?)");
    if (t.front() == '$') fail("expected " + what + ", found " + quote(t) + " (fewer entries than the count?)");
    std::int64_t v = 0;
    if (const std::string problem = io::parse_integer(t, v); !problem.empty()) fail(what + problem);
    return v;
  }

  // An int: 4 bytes in binary.
  int int_value(const std::string& what) {
    std::int64_t v = 0;
    if (binary_) {
      mark_binary(4, what);
      v = bin_.signed32(pos_);
      pos_ += 4;
    } else {
      v = ascii_integer(what);
      if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
        fail(what + " " + std::to_string(v) + " does not fit an int");
      }
    }
    return static_cast<int>(v);
  }

  // A size_t (counts, tags in 4.1): 8 bytes in binary; never negative.
  std::uint64_t size_value(const std::string& what) {
    if (binary_) {
      mark_binary(8, what);
      const std::uint64_t v = bin_.load(pos_, 8);
      pos_ += 8;
      return v;
    }
    const std::int64_t v = ascii_integer(what);
    if (v < 0) fail(what + " is negative: " + std::to_string(v));
    return static_cast<std::uint64_t>(v);
  }

  // A count that must fit a 32-bit index; in binary, `item_bytes` per item must be left.
  std::uint64_t count_value(const std::string& what, std::uint64_t item_bytes, bool ascii = false) {
    const std::uint64_t n = ascii ? ascii_count(what) : size_value(what);
    if (n > std::numeric_limits<std::uint32_t>::max()) fail(what + " " + std::to_string(n) + " exceeds the 32-bit index range");
    if (binary_) {
      const std::uint64_t left = bytes_.size() - pos_;
      if (item_bytes != 0 && n > left / item_bytes) {
        fail(what + " " + std::to_string(n) + " needs " + std::to_string(item_bytes) + " bytes each, but the file has " +
             std::to_string(left) + " left (truncated?)");
      }
    }
    return n;
  }

  std::uint64_t ascii_count(const std::string& what) {
    const std::int64_t v = ascii_integer(what);
    if (v < 0) fail(what + " is negative: " + std::to_string(v));
    return static_cast<std::uint64_t>(v);
  }

  double real_value(const std::string& what) {
    if (binary_) {
      mark_binary(8, what);
      const double v = bin_.real(pos_, 8);
      pos_ += 8;
      if (!std::isfinite(v)) fail(what + " is not finite");
      return v;
    }
    const std::string_view t = token();
    if (t.empty()) fail("file ends in " + what + " (truncated?)");
    if (t.front() == '$') fail("expected " + what + ", found " + quote(t) + " (fewer entries than the count?)");
    double v = 0.0;
    if (const std::string problem = io::parse_real(t, v); !problem.empty()) fail(what + problem);
    return v;
  }

  // A binary int read where the ASCII parts of a binary file hold one ($MeshFormat's "1").
  std::uint64_t raw_word(std::size_t n, const std::string& what) {
    mark_binary(n, what);
    const std::uint64_t v = bin_.load(pos_, n);
    pos_ += n;
    return v;
  }

  void expect_end(std::string_view section) {
    const std::string want = "$End" + std::string(section);
    const std::string_view t = token();
    if (t.empty()) fail("file ends before " + want + " (truncated?)");
    if (t != want) fail("expected " + want + ", found " + quote(t) + " (more entries than the count?)");
  }

  // Moves past "$End<section>" at the start of a line.
  void skip_section(std::string_view section) {
    const std::string want = "\n$End" + std::string(section);
    const std::size_t at = bytes_.find(want, pos_ == 0 ? 0 : pos_ - 1);
    if (at == std::string_view::npos) fail("section $" + std::string(section) + " has no $End" + std::string(section));
    line_ += static_cast<std::uint64_t>(std::count(bytes_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                   bytes_.begin() + static_cast<std::ptrdiff_t>(at + 1), '\n'));
    pos_ = at + want.size();
  }

  // At the last value read (its line in ASCII, its byte in binary).
  [[noreturn]] void fail(const std::string& reason) const {
    if (binary_) bin_.fail(loc_byte_, reason);
    throw ParseError(file_, std::max<std::uint64_t>(loc_line_, 1), reason);
  }
  [[noreturn]] void fail_here(const std::string& reason) const {
    if (binary_) bin_.fail(pos_, reason);
    throw ParseError(file_, line_, reason);
  }

 private:
  void mark_binary(std::size_t n, const std::string& what) {
    loc_byte_ = pos_;
    bin_.need(pos_, n, what);
  }

  io::BinaryInput bin_;
  std::string_view bytes_;
  const std::string& file_;
  bool binary_ = false;
  std::size_t pos_ = 0;
  std::uint64_t line_ = 1;
  std::uint64_t loc_line_ = 1;
  std::size_t loc_byte_ = 0;
};

// An element as read, sorted by tag before it goes into the mesh.
template <std::size_t N>
struct Tagged {
  std::uint64_t tag;
  std::array<std::uint32_t, N> cell;
  int ref;
};

class GmshReader {
 public:
  GmshReader(std::string_view bytes, const std::string& name, NonPositiveTetrahedra tetrahedra)
      : in_(bytes, name), orientation_(tetrahedra) {}

  GmshMesh read() {
    std::string_view t = in_.token();
    if (t != "$MeshFormat") {
      in_.fail(t.empty() ? "empty file: expected $MeshFormat" : "expected $MeshFormat first, found " + quote(t));
    }
    read_format();
    bool have_nodes = false;
    bool have_elements = false;
    bool have_names = false;
    bool have_entities = false;
    while (!(t = in_.token()).empty()) {
      if (t.front() != '$') in_.fail("expected a section ($Name), found " + quote(t));
      const std::string_view section = t.substr(1);
      auto once = [&](bool& seen) {
        if (seen) in_.fail("second " + std::string(t) + " section");
        seen = true;
      };
      if (section == "MeshFormat") {
        in_.fail("second $MeshFormat section");
      } else if (section == "PhysicalNames") {
        once(have_names);
        read_names();
      } else if (section == "Entities" && v41_) {
        once(have_entities);
        if (have_nodes) in_.fail("$Entities after $Nodes");
        read_entities();
      } else if (section == "Nodes") {
        once(have_nodes);
        if (v41_) {
          read_nodes41();
        } else {
          read_nodes22();
        }
      } else if (section == "Elements") {
        once(have_elements);
        if (!have_nodes) in_.fail("$Elements before $Nodes");
        if (v41_) {
          read_elements41();
        } else {
          read_elements22();
        }
      } else if (section == "PartitionedEntities") {
        in_.fail("$PartitionedEntities: partitioned meshes are not supported (save the mesh unpartitioned)");
      } else if (section.starts_with("End")) {
        in_.fail(quote(t) + " without its section");
      } else {
        in_.skip_section(section);
        out_.notes.push_back("section $" + std::string(section) + " skipped (it carries no mesh)");
        continue;
      }
      in_.expect_end(section);
    }
    if (!have_nodes) in_.fail_here("no $Nodes section");
    assemble();
    return std::move(out_);
  }

 private:
  void read_format() {
    const std::string_view version = in_.token();
    if (version == "4.1") {
      v41_ = true;
    } else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") {
      v41_ = false;
    } else if (version == "4" || version == "4.0") {
      in_.fail("MSH 4.0 is not supported: save the mesh as MSH 4.1 or 2.2");
    } else {
      in_.fail("MSH version " + quote(version) + " is not supported (this reader reads 4.1 and 2.2)");
    }
    const std::int64_t type = in_.ascii_integer("file type");
    if (type != 0 && type != 1) in_.fail("file type " + std::to_string(type) + " is not 0 (ASCII) or 1 (binary)");
    const std::int64_t data_size = in_.ascii_integer("data size");
    if (data_size != 8) in_.fail("data size " + std::to_string(data_size) + " is not 8 (this reader reads 8-byte sizes and doubles)");
    if (type == 1) {
      in_.skip_line_end();
      in_.set_binary(false);
      const std::uint64_t one = in_.raw_word(4, "the byte-order word");
      if (one != 1) {
        in_.set_binary(true);
        if (((one >> 24) & 0xff) != 1 || (one & 0xffffff) != 0) {
          in_.fail("byte-order word " + std::to_string(one) + " is not 1 in either byte order");
        }
      }
    }
    in_.expect_end("MeshFormat");
  }

  void read_names() {
    const std::uint64_t n = in_.ascii_count("$PhysicalNames count");
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string what = "physical name " + std::to_string(i + 1);
      PhysicalName name;
      name.dimension = static_cast<int>(in_.ascii_integer(what + " dimension"));
      if (name.dimension < 0 || name.dimension > 3) in_.fail(what + ": dimension " + std::to_string(name.dimension) + " is not 0 to 3");
      const std::int64_t tag = in_.ascii_integer(what + " tag");
      if (tag < std::numeric_limits<int>::min() || tag > std::numeric_limits<int>::max()) {
        in_.fail(what + ": tag " + std::to_string(tag) + " does not fit an int");
      }
      name.tag = static_cast<int>(tag);
      name.name = in_.quoted(what);
      out_.names.push_back(std::move(name));
    }
  }

  void read_entities() {
    if (in_.binary()) in_.skip_line_end();
    std::uint64_t counts[4];
    for (int d = 0; d < 4; ++d) counts[d] = in_.count_value("$Entities count", 4 + 24 + 8);
    for (int d = 0; d < 4; ++d) {
      for (std::uint64_t i = 0; i < counts[d]; ++i) {
        const std::string what = std::string(kEntityNames[d]) + " " + std::to_string(i + 1);
        const int tag = in_.int_value(what + " tag");
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k) in_.real_value(what + (d == 0 ? " coordinate" : " bounding box"));
        const std::uint64_t np = in_.count_value(what + " number of physical tags", 4);
        std::vector<int> physicals;
        for (std::uint64_t k = 0; k < np; ++k) physicals.push_back(in_.int_value(what + " physical tag"));
        if (d > 0) {
          const std::uint64_t nb = in_.count_value(what + " number of bounding entities", 4);
          for (std::uint64_t k = 0; k < nb; ++k) in_.int_value(what + " bounding entity");
        }
        if (!entities_.emplace(std::pair{d, tag}, physicals).second) {
          in_.fail(what + ": a second " + kEntityNames[d] + " with tag " + std::to_string(tag));
        }
        if (physicals.size() > 1) {
          out_.notes.push_back(std::string(kEntityNames[d]) + " " + std::to_string(tag) + " has " +
                               std::to_string(physicals.size()) + " physical tags; its elements keep the first, " +
                               std::to_string(physicals[0]));
        }
      }
    }
  }

  // The reference of the elements of entity (dim, tag): its first physical tag, 0 without one.
  int physical_of(int dim, int tag) const {
    const auto it = entities_.find({dim, tag});
    return it == entities_.end() || it->second.empty() ? 0 : it->second.front();
  }

  void add_node(std::uint64_t tag, const Vec3& p) {
    if (tag == 0) in_.fail("node tag 0: tags start at 1");
    if (!node_index_.emplace(tag, static_cast<std::uint32_t>(nodes_.size())).second) {
      in_.fail("node tag " + std::to_string(tag) + " is used twice");
    }
    nodes_.push_back({tag, p});
  }

  Vec3 read_point(const std::string& what) {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    double c[3];
    for (int k = 0; k < 3; ++k) {
      c[k] = in_.real_value(what + kAxes[k]);
      if (!coordinate_in_range(c[k])) in_.fail(what + kAxes[k] + " is " + coordinate_problem(c[k]));
    }
    return Vec3{c[0], c[1], c[2]};
  }

  void read_nodes41() {
    if (in_.binary()) in_.skip_line_end();
    const std::uint64_t blocks = in_.count_value("$Nodes number of entity blocks", 20);
    const std::uint64_t n = in_.count_value("$Nodes number of nodes", 32);
    in_.size_value("$Nodes minimum node tag");
    in_.size_value("$Nodes maximum node tag");
    std::vector<std::uint64_t> tags;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::string what = "node block " + std::to_string(b + 1);
      const int dim = in_.int_value(what + " entity dimension");
      if (dim < 0 || dim > 3) in_.fail(what + ": entity dimension " + std::to_string(dim) + " is not 0 to 3");
      in_.int_value(what + " entity tag");
      const int parametric = in_.int_value(what + " parametric flag");
      if (parametric != 0 && parametric != 1) in_.fail(what + ": parametric flag " + std::to_string(parametric) + " is not 0 or 1");
      const std::uint64_t m = in_.count_value(what + " number of nodes", 32);
      if (m > n - std::min<std::uint64_t>(n, nodes_.size())) {
        in_.fail(what + " has " + std::to_string(m) + " nodes, more than the " + std::to_string(n) + " of the header leave");
      }
      tags.resize(m);
      for (std::uint64_t i = 0; i < m; ++i) tags[i] = in_.size_value(what + " node tag");
      for (std::uint64_t i = 0; i < m; ++i) {
        const std::string node = "node " + std::to_string(tags[i]);
        const Vec3 p = read_point(node);
        for (int k = 0; k < (parametric == 1 ? dim : 0); ++k) in_.real_value(node + " parametric coordinate");
        add_node(tags[i], p);
      }
      if (parametric == 1 && m > 0 && !parametric_noted_) {
        out_.notes.push_back("parametric coordinates of nodes not kept");
        parametric_noted_ = true;
      }
    }
    if (nodes_.size() != n) {
      in_.fail("$Nodes header counts " + std::to_string(n) + " nodes, the blocks hold " + std::to_string(nodes_.size()));
    }
    index_nodes();
  }

  void read_nodes22() {
    const std::uint64_t n = in_.count_value("$Nodes count", 28, true);
    if (in_.binary()) in_.skip_line_end();
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t tag = in_.binary() ? static_cast<std::uint64_t>(in_.int_value("node number"))
                                              : in_.size_value("node number");
      add_node(tag, read_point("node " + std::to_string(tag)));
    }
    index_nodes();
  }

  // Nodes in the order of their tags; node_index_ maps a tag to its vertex.
  void index_nodes() {
    std::stable_sort(nodes_.begin(), nodes_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    out_.mesh.vertices.reserve(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      node_index_[nodes_[i].first] = static_cast<std::uint32_t>(i);
      out_.mesh.vertices.push_back(nodes_[i].second);
    }
    out_.mesh.vertex_refs.assign(nodes_.size(), 0);
    nodes_.clear();
  }

  std::uint32_t node(std::uint64_t tag, std::uint64_t element) const {
    const auto it = node_index_.find(tag);
    if (it == node_index_.end()) {
      in_.fail("element " + std::to_string(element) + ": node " + std::to_string(tag) + " is not in $Nodes");
    }
    return it->second;
  }

  // One element of a supported type: its nodes (read by `next_node`), checked, stored by kind.
  template <class NextNode>
  void add_element(int type, std::uint64_t tag, int ref, NextNode&& next_node) {
    std::array<std::uint32_t, 4> v{};
    const int k = nodes_of(type);
    for (int i = 0; i < k; ++i) v[static_cast<std::size_t>(i)] = node(next_node(), tag);
    switch (type) {
      case kPoint: {
        int& r = out_.mesh.vertex_refs[v[0]];
        if (r != 0 && r != ref && !point_conflict_noted_) {
          out_.notes.push_back("a node in several point groups keeps the reference of the last one");
          point_conflict_noted_ = true;
        }
        r = ref;
        break;
      }
      case kLine: edges_.push_back({tag, {v[0], v[1]}, ref}); break;
      case kTriangle: triangles_.push_back({tag, {v[0], v[1], v[2]}, ref}); break;
      default: {
        const auto& p = out_.mesh.vertices;
        const Sign s = orientation_ == NonPositiveTetrahedra::Keep
                           ? Sign::Positive
                           : uncounted::orient3d(p[v[0]], p[v[1]], p[v[2]], p[v[3]]);
        if (s == Sign::Negative) {
          in_.fail("tetrahedron " + std::to_string(tag) + " is negatively oriented (Gmsh's tetrahedra have orient3d > 0)");
        }
        if (s == Sign::Zero) in_.fail("tetrahedron " + std::to_string(tag) + " is flat: its four nodes are coplanar");
        tetrahedra_.push_back({tag, v, ref});
      }
    }
  }

  void read_elements41() {
    if (in_.binary()) in_.skip_line_end();
    const std::uint64_t blocks = in_.count_value("$Elements number of entity blocks", 20);
    const std::uint64_t n = in_.count_value("$Elements number of elements", 16);
    in_.size_value("$Elements minimum element tag");
    in_.size_value("$Elements maximum element tag");
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::string what = "element block " + std::to_string(b + 1);
      const int dim = in_.int_value(what + " entity dimension");
      const int entity = in_.int_value(what + " entity tag");
      const int type = in_.int_value(what + " element type");
      const std::uint64_t m = in_.count_value(what + " number of elements", 16);
      if (m > n - seen) {
        in_.fail(what + " has " + std::to_string(m) + " elements, more than the " + std::to_string(n) + " of the header leave");
      }
      seen += m;
      if (m == 0) continue;
      if (nodes_of(type) == 0) in_.fail(type_problem(in_.size_value("element tag"), type));
      if (dimension_of(type) != dim) {
        in_.fail(what + ": " + type_name(type) + " elements on an entity of dimension " + std::to_string(dim));
      }
      const int ref = physical_of(dim, entity);
      for (std::uint64_t i = 0; i < m; ++i) {
        const std::uint64_t tag = in_.size_value("element tag");
        add_element(type, tag, ref, [&] { return in_.size_value("element " + std::to_string(tag) + " node tag"); });
      }
    }
    if (seen != n) in_.fail("$Elements header counts " + std::to_string(n) + " elements, the blocks hold " + std::to_string(seen));
  }

  void read_elements22() {
    const std::uint64_t n = in_.count_value("$Elements count", 12, true);
    if (!in_.binary()) {
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::uint64_t tag = in_.size_value("element number");
        const std::string what = "element " + std::to_string(tag);
        const int type = in_.int_value(what + " type");
        if (nodes_of(type) == 0) in_.fail(type_problem(tag, type));
        const std::uint64_t ntags = in_.count_value(what + " number of tags", 0);
        int ref = 0;
        for (std::uint64_t k = 0; k < ntags; ++k) {
          const int t = in_.int_value(what + " tag");
          if (k == 0) ref = t;
        }
        add_element(type, tag, ref, [&] { return in_.size_value(what + " node number"); });
      }
      return;
    }
    in_.skip_line_end();
    std::uint64_t seen = 0;
    while (seen < n) {
      const int type = in_.int_value("element block type");
      const std::int64_t m = in_.int_value("element block count");
      const std::int64_t ntags = in_.int_value("element block number of tags");
      if (m <= 0 || static_cast<std::uint64_t>(m) > n - seen) {
        in_.fail("element block count " + std::to_string(m) + " is not 1 to the " + std::to_string(n - seen) + " elements left");
      }
      if (ntags < 0) in_.fail("element block number of tags " + std::to_string(ntags) + " is negative");
      const std::uint64_t tag0 = static_cast<std::uint64_t>(in_.int_value("element number"));
      if (nodes_of(type) == 0) in_.fail(type_problem(tag0, type));
      for (std::int64_t i = 0; i < m; ++i) {
        const std::uint64_t tag = i == 0 ? tag0 : static_cast<std::uint64_t>(in_.int_value("element number"));
        const std::string what = "element " + std::to_string(tag);
        int ref = 0;
        for (std::int64_t k = 0; k < ntags; ++k) {
          const int t = in_.int_value(what + " tag");
          if (k == 0) ref = t;
        }
        add_element(type, tag, ref, [&] { return static_cast<std::uint64_t>(in_.int_value(what + " node number")); });
      }
      seen += static_cast<std::uint64_t>(m);
    }
  }

  template <std::size_t N>
  static void take(std::vector<Tagged<N>>& from, std::vector<std::array<std::uint32_t, N>>& cells, std::vector<int>& refs) {
    std::stable_sort(from.begin(), from.end(), [](const auto& a, const auto& b) { return a.tag < b.tag; });
    for (const auto& e : from) {
      cells.push_back(e.cell);
      refs.push_back(e.ref);
    }
  }

  void assemble() {
    take(edges_, out_.mesh.edges, out_.mesh.edge_refs);
    take(triangles_, out_.mesh.triangles, out_.mesh.triangle_refs);
    take(tetrahedra_, out_.mesh.tetrahedra, out_.mesh.tetrahedron_refs);
  }

  static constexpr const char* kEntityNames[4] = {"point", "curve", "surface", "volume"};

  MshInput in_;
  NonPositiveTetrahedra orientation_;
  bool v41_ = true;
  bool parametric_noted_ = false;
  bool point_conflict_noted_ = false;
  std::map<std::pair<int, int>, std::vector<int>> entities_;
  std::vector<std::pair<std::uint64_t, Vec3>> nodes_;
  std::unordered_map<std::uint64_t, std::uint32_t> node_index_;
  std::vector<Tagged<2>> edges_;
  std::vector<Tagged<3>> triangles_;
  std::vector<Tagged<4>> tetrahedra_;
  GmshMesh out_;
};

// --- Writer -------------------------------------------------------------------------------------

// Values in the file's encoding: ints, size_ts and doubles as text or little-endian words.
class MshOutput {
 public:
  explicit MshOutput(bool binary) : binary_(binary) {}

  void text(std::string_view s) { out_ += s; }
  void integer(std::int64_t v) {
    if (binary_) {
      io::store_le(out_, static_cast<std::uint64_t>(v), 4);
    } else {
      separate();
      io::append_integer(out_, v);
    }
  }
  void size(std::uint64_t v) {
    if (binary_) {
      io::store_le(out_, v, 8);
    } else {
      separate();
      io::append_integer(out_, static_cast<std::int64_t>(v));
    }
  }
  void real(double v) {
    if (binary_) {
      io::store_le_real(out_, v);
    } else {
      separate();
      io::append_real(out_, v);
    }
  }
  void end_line() {
    if (!binary_) out_ += '\n';
  }
  // Ends a section: in binary, the newline Gmsh puts after the binary data.
  void end_section(std::string_view name) {
    if (binary_) out_ += '\n';
    out_ += "$End";
    out_ += name;
    out_ += '\n';
  }
  const std::string& str() const noexcept { return out_; }

 private:
  void separate() {
    if (!out_.empty() && out_.back() != '\n') out_ += ' ';
  }

  bool binary_;
  std::string out_;
};

template <std::size_t N>
std::vector<int> distinct_refs(const std::vector<std::array<std::uint32_t, N>>& cells, const std::vector<int>& refs) {
  std::vector<int> d;
  if (cells.empty()) return d;
  if (refs.empty()) return {0};
  d = refs;
  std::sort(d.begin(), d.end());
  d.erase(std::unique(d.begin(), d.end()), d.end());
  return d;
}

void check_positive_refs(const std::vector<int>& refs, const char* noun) {
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (refs[i] < 0) {
      throw InputError(std::string(noun) + " " + std::to_string(i) + ": reference " + std::to_string(refs[i]) +
                           " is negative, and Gmsh's physical tags are positive",
                       {i});
    }
  }
}

}  // namespace

GmshMesh read_gmsh(std::istream& in, const std::string& file_name, NonPositiveTetrahedra tetrahedra) {
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ParseError(file_name, 0, "read error");
  return GmshReader(bytes, file_name, tetrahedra).read();
}

GmshMesh read_gmsh(const std::string& path, NonPositiveTetrahedra tetrahedra) {
  std::ifstream in = io::open_for_reading(path);
  return read_gmsh(in, path, tetrahedra);
}

void write_gmsh(std::ostream& out, const MeshData3& mesh, std::span<const PhysicalName> names, GmshEncoding encoding) {
  const std::size_t nv = mesh.vertices.size();
  io::check_refs(mesh.vertex_refs, nv, "vertex");
  io::check_cells(mesh.edges, mesh.edge_refs, nv, "edge");
  io::check_cells(mesh.triangles, mesh.triangle_refs, nv, "triangle");
  io::check_cells(mesh.tetrahedra, mesh.tetrahedron_refs, nv, "tetrahedron");
  check_positive_refs(mesh.vertex_refs, "vertex");
  check_positive_refs(mesh.edge_refs, "edge");
  check_positive_refs(mesh.triangle_refs, "triangle");
  check_positive_refs(mesh.tetrahedron_refs, "tetrahedron");
  for (const PhysicalName& n : names) {
    if (n.name.find_first_of("\"\n\r") != std::string::npos) {
      throw InputError("physical name " + quote(n.name) + " holds a quote or a line break, which MSH cannot hold");
    }
  }
  const bool binary = encoding == GmshEncoding::Binary;

  // Entities: curves, surfaces and volumes, one per distinct reference; points, one per vertex
  // with a reference.
  const std::vector<int> refs1 = distinct_refs(mesh.edges, mesh.edge_refs);
  std::vector<int> refs2 = distinct_refs(mesh.triangles, mesh.triangle_refs);
  const std::vector<int> refs3 = distinct_refs(mesh.tetrahedra, mesh.tetrahedron_refs);
  std::vector<std::uint32_t> points;
  for (std::size_t i = 0; i < mesh.vertex_refs.size(); ++i) {
    if (mesh.vertex_refs[i] != 0) points.push_back(static_cast<std::uint32_t>(i));
  }
  // Nodes need an entity to sit on: a surface without elements if there is none.
  if (nv > 0 && refs1.empty() && refs2.empty() && refs3.empty() && points.empty()) refs2.push_back(0);
  int node_dim = 0;
  if (!refs1.empty()) node_dim = 1;
  if (!refs2.empty()) node_dim = 2;
  if (!refs3.empty()) node_dim = 3;

  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3& p = mesh.vertices[i];
    if (i == 0) lo = hi = p;
    lo = Vec3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = Vec3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }

  MshOutput o(binary);
  o.text(binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
  if (binary) {
    o.integer(1);
    o.text("\n");
  }
  o.text("$EndMeshFormat\n");
  if (!names.empty()) {
    std::string s = "$PhysicalNames\n";
    io::append_integer(s, static_cast<std::int64_t>(names.size()));
    s += '\n';
    for (const PhysicalName& n : names) {
      io::append_integer(s, n.dimension);
      s += ' ';
      io::append_integer(s, n.tag);
      s += " \"" + n.name + "\"\n";
    }
    s += "$EndPhysicalNames\n";
    o.text(s);
  }

  o.text("$Entities\n");
  o.size(points.size());
  o.size(refs1.size());
  o.size(refs2.size());
  o.size(refs3.size());
  o.end_line();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = mesh.vertices[points[i]];
    o.integer(static_cast<std::int64_t>(i + 1));
    o.real(p.x);
    o.real(p.y);
    o.real(p.z);
    o.size(1);
    o.integer(mesh.vertex_refs[points[i]]);
    o.end_line();
  }
  for (const std::vector<int>* refs : std::initializer_list<const std::vector<int>*>{&refs1, &refs2, &refs3}) {
    for (std::size_t i = 0; i < refs->size(); ++i) {
      o.integer(static_cast<std::int64_t>(i + 1));
      for (double c : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) o.real(c);
      const int r = (*refs)[i];
      o.size(r != 0 ? 1 : 0);
      if (r != 0) o.integer(r);
      o.size(0);
      o.end_line();
    }
  }
  o.end_section("Entities");

  o.text("$Nodes\n");
  o.size(nv > 0 ? 1 : 0);
  o.size(nv);
  o.size(nv > 0 ? 1 : 0);
  o.size(nv);
  o.end_line();
  if (nv > 0) {
    o.integer(node_dim);
    o.integer(1);
    o.integer(0);
    o.size(nv);
    o.end_line();
    for (std::size_t i = 0; i < nv; ++i) {
      o.size(i + 1);
      o.end_line();
    }
    for (const Vec3& p : mesh.vertices) {
      o.real(p.x);
      o.real(p.y);
      o.real(p.z);
      o.end_line();
    }
  }
  o.end_section("Nodes");

  // Element blocks: one per entity and type; tags number edges, triangles, tetrahedra, then
  // the points, each kind in its order.
  const std::size_t total = mesh.edges.size() + mesh.triangles.size() + mesh.tetrahedra.size() + points.size();
  std::size_t blocks = points.size();
  for (const std::vector<int>* refs : std::initializer_list<const std::vector<int>*>{&refs1, &refs2, &refs3}) blocks += refs->size();
  if (!refs2.empty() && mesh.triangles.empty()) blocks -= refs2.size();  // the bare node surface
  o.text("$Elements\n");
  o.size(blocks);
  o.size(total);
  o.size(total > 0 ? 1 : 0);
  o.size(total);
  o.end_line();
  std::size_t base = 0;
  auto write_kind = [&](int dim, int type, const auto& cells, const std::vector<int>& refs, const std::vector<int>& entity_refs) {
    for (std::size_t e = 0; e < entity_refs.size() && !cells.empty(); ++e) {
      const int r = entity_refs[e];
      std::size_t m = 0;
      for (std::size_t i = 0; i < cells.size(); ++i) m += (refs.empty() ? 0 : refs[i]) == r;
      o.integer(dim);
      o.integer(static_cast<std::int64_t>(e + 1));
      o.integer(type);
      o.size(m);
      o.end_line();
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if ((refs.empty() ? 0 : refs[i]) != r) continue;
        o.size(base + i + 1);
        for (std::uint32_t v : cells[i]) o.size(static_cast<std::uint64_t>(v) + 1);
        o.end_line();
      }
    }
    base += cells.size();
  };
  write_kind(1, kLine, mesh.edges, mesh.edge_refs, refs1);
  write_kind(2, kTriangle, mesh.triangles, mesh.triangle_refs, refs2);
  write_kind(3, kTetrahedron, mesh.tetrahedra, mesh.tetrahedron_refs, refs3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    o.integer(0);
    o.integer(static_cast<std::int64_t>(i + 1));
    o.integer(kPoint);
    o.size(1);
    o.end_line();
    o.size(base + i + 1);
    o.size(static_cast<std::uint64_t>(points[i]) + 1);
    o.end_line();
  }
  o.end_section("Elements");
  out.write(o.str().data(), static_cast<std::streamsize>(o.str().size()));
}

void write_gmsh(const std::string& path, const MeshData3& mesh, std::span<const PhysicalName> names,
                GmshEncoding encoding) {
  std::ofstream out = io::open_for_writing(path);
  write_gmsh(out, mesh, names, encoding);
  out.flush();
  io::check_written(out, path);
}

}  // namespace dtlab
