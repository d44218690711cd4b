#include "mesh/io/tetgen_poly.hpp"

#include <algorithm>
#include <filesystem>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

using io::LineTokenizer;

enum class PlcFormat { Poly, Smesh };

class PlcReader {
 public:
  PlcReader(std::istream& in, const std::string& name, PlcFormat format) : in_(in, name), format_(format) {}

  // `load_nodes` is called only if the point count is 0.
  template <class LoadNodes>
  Plc3 read(LoadNodes&& load_nodes) {
    const std::uint64_t n = read_point_header();
    if (n == 0) {
      take_nodes(load_nodes());
    } else {
      read_points(n);
    }
    read_facets();
    read_holes();
    read_regions();
    return std::move(plc_);
  }

 private:
  // Moves to a part's header line, which must hold between 1 and `max_fields` fields; a longer
  // line is most likely one entry too many in the part before.
  void next_header(const std::string& header, std::size_t max_fields, const char* previous) {
    const std::uint64_t last = in_.line();
    if (!in_.next_line()) in_.fail_at(std::max<std::uint64_t>(last, 1), "file ends before the " + header);
    if (in_.size() > max_fields) {
      in_.fail("expected the " + header + ", found " + std::to_string(in_.size()) + " fields (more " + previous +
               " than the count says?)");
    }
  }

  bool marker_flag(std::size_t k, const std::string& what) {
    const std::int64_t m = in_.integer(k, what);
    if (m != 0 && m != 1) in_.fail(what + " is " + std::to_string(m) + ", not 0 or 1");
    return m == 1;
  }

  Vec3 point(std::size_t k, const std::string& what) {
    static constexpr const char* kAxes[] = {" x", " y", " z"};
    double c[3];
    for (std::size_t a = 0; a < 3; ++a) {
      c[a] = in_.real(k + a, what + kAxes[a]);
      io::check_coordinate(in_, c[a], what + kAxes[a]);
    }
    return {c[0], c[1], c[2]};
  }

  std::uint64_t read_point_header() {
    if (!in_.next_line()) in_.fail_at(1, "empty file: missing the point list header (<#points> <dimension> ...)");
    if (in_.size() > 4) in_.fail("header: trailing text " + io::quote(in_.token(4)) + " after 4 fields");
    const std::uint64_t n = in_.count(0, "point count");
    if (in_.size() > 1) {
      const std::int64_t dim = in_.integer(1, "dimension");
      if (dim != 3) in_.fail("dimension is " + std::to_string(dim) + "; a TetGen PLC must be 3D");
    }
    attribute_count_ = in_.size() > 2 ? in_.count(2, "attribute count") : 0;
    has_point_markers_ = in_.size() > 3 && marker_flag(3, "boundary marker count");
    return n;
  }

  void take_nodes(const TetGenNodes* nodes) {
    if (nodes == nullptr) return;
    plc_.vertices = nodes->points;
    plc_.vertex_markers = nodes->has_markers ? nodes->markers : std::vector<int>(nodes->points.size(), 0);
    first_index_ = nodes->first_index;
  }

  void read_points(std::uint64_t n) {
    const std::size_t fields = 4 + attribute_count_ + (has_point_markers_ ? 1 : 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "points");
      const std::string what = "point " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(fields, what);
      first_index_ = io::list_entry_number(in_, i, first_index_, what);
      plc_.vertices.push_back(point(1, what));
      for (std::size_t a = 0; a < attribute_count_; ++a) in_.real(4 + a, what + " attribute " + std::to_string(a + 1));
      plc_.vertex_markers.push_back(has_point_markers_ ? io::int_field(in_, fields - 1, what + " boundary marker") : 0);
    }
  }

  // The index of the next token, moving on to the following lines when the current one is used
  // up: TetGen lets a corner list continue over several lines.
  std::size_t take(std::size_t& k, const std::string& what) {
    while (k >= in_.size()) {
      const std::uint64_t last = in_.line();
      if (!in_.next_line()) in_.fail_at(last, "file ends in " + what + " (truncated?)");
      k = 0;
    }
    return k++;
  }

  // A corner list from token k of the current line: <#corners> <corner 1> ... <corner n>.
  std::vector<std::uint32_t> read_polygon(std::size_t& k, const std::string& what) {
    const std::uint64_t corners = in_.count(take(k, what), what + " corner count");
    if (corners == 0) in_.fail(what + " has no corner");
    std::vector<std::uint32_t> polygon;
    for (std::uint64_t c = 0; c < corners; ++c) {
      polygon.push_back(io::vertex_number(in_, take(k, what), first_index_, plc_.vertices.size(), what));
    }
    return polygon;
  }

  void expect_line_end(std::size_t k, const std::string& what) {
    if (k < in_.size()) in_.fail(what + ": trailing text " + io::quote(in_.token(k)));
  }

  void read_facets() {
    next_header("facet list header (<#facets> [<#boundary markers>])", 2, "points");
    const std::uint64_t n = in_.count(0, "facet count");
    has_facet_markers_ = in_.size() > 1 && marker_flag(1, "facet boundary marker count");
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "facets");
      const std::string what = "facet " + std::to_string(i + 1) + " of " + std::to_string(n);
      plc_.facets.push_back(format_ == PlcFormat::Poly ? read_poly_facet(what) : read_smesh_facet(what));
    }
  }

  PlcFacet3 read_smesh_facet(const std::string& what) {
    PlcFacet3 facet;
    std::size_t k = 0;
    facet.polygons.push_back(read_polygon(k, what));
    // The marker ends the corner list's last line (a continuation line would be the next facet).
    if (has_facet_markers_) {
      if (k >= in_.size()) in_.fail(what + ": missing boundary marker (the facet list header announces one per facet)");
      facet.marker = io::int_field(in_, k++, what + " boundary marker");
    }
    expect_line_end(k, what);
    return facet;
  }

  PlcFacet3 read_poly_facet(const std::string& what) {
    if (has_facet_markers_) {
      in_.expect_tokens(3, what + " (<#polygons> <#holes> <boundary marker>)");
    } else if (in_.size() > 2) {
      in_.fail(what + ": trailing text " + io::quote(in_.token(2)) +
               " after <#polygons> <#holes> (the facet list header says there are no boundary markers)");
    }
    PlcFacet3 facet;
    const std::uint64_t polygons = in_.count(0, what + " polygon count");
    if (polygons == 0) in_.fail(what + " has no polygon");
    const std::uint64_t holes = in_.size() > 1 ? in_.count(1, what + " hole count") : 0;
    if (has_facet_markers_) facet.marker = io::int_field(in_, 2, what + " boundary marker");
    for (std::uint64_t p = 0; p < polygons; ++p) {
      const std::string polygon = "polygon " + std::to_string(p + 1) + " of " + what;
      io::next_counted_entry(in_, p, polygons, "polygons of " + what);
      std::size_t k = 0;
      facet.polygons.push_back(read_polygon(k, polygon));
      expect_line_end(k, polygon);
    }
    int first = 0;
    for (std::uint64_t h = 0; h < holes; ++h) {
      const std::string hole = "hole " + std::to_string(h + 1) + " of " + what;
      io::next_counted_entry(in_, h, holes, "holes of " + what);
      in_.expect_tokens(4, hole + " (<hole #> <x> <y> <z>)");
      first = io::list_entry_number(in_, h, first, hole);
      facet.holes.push_back(point(1, hole));
    }
    return facet;
  }

  void read_holes() {
    next_header("volume hole count (<#holes>)", 1, "facets");
    const std::uint64_t n = in_.count(0, "hole count");
    int first = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "holes");
      const std::string what = "hole " + std::to_string(i + 1) + " of " + std::to_string(n);
      in_.expect_tokens(4, what + " (<hole #> <x> <y> <z>)");
      first = io::list_entry_number(in_, i, first, what);
      plc_.holes.push_back(point(1, what));
    }
  }

  // The region part is optional: the file may end after the holes.
  void read_regions() {
    if (!in_.next_line()) return;
    if (in_.size() > 1) {
      in_.fail("expected the optional region count (<#regions>) alone on its line, found " +
               std::to_string(in_.size()) + " fields (more holes than the count says?)");
    }
    const std::uint64_t n = in_.count(0, "region count");
    int first = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      io::next_counted_entry(in_, i, n, "regions");
      const std::string what = "region " + std::to_string(i + 1) + " of " + std::to_string(n);
      if (in_.size() != 5) in_.expect_tokens(6, what + " (<region #> <x> <y> <z> <attribute> [<maximum volume>])");
      first = io::list_entry_number(in_, i, first, what);
      PlcRegion3 r;
      r.point = point(1, what);
      r.attribute = in_.real(4, what + " attribute");
      if (in_.size() == 6) r.max_volume = in_.real(5, what + " maximum volume");
      plc_.regions.push_back(r);
    }
    if (in_.next_line()) {
      in_.fail("text after the last region (more regions than the count says?): " + io::quote(in_.token(0)));
    }
  }

  LineTokenizer in_;
  PlcFormat format_;
  Plc3 plc_;
  int first_index_ = 1;
  std::size_t attribute_count_ = 0;
  bool has_point_markers_ = false;
  bool has_facet_markers_ = false;
};

Plc3 read_plc_file(const std::string& path, PlcFormat format) {
  std::ifstream in = io::open_for_reading(path);
  TetGenNodes nodes;
  return PlcReader(in, path, format).read([&] {
    nodes = read_tetgen_node(std::filesystem::path(path).replace_extension(".node").string());
    return &nodes;
  });
}

// --- Writers ---------------------------------------------------------------------------------

void check_plc(const Plc3& plc) {
  if (!plc.vertex_markers.empty() && plc.vertex_markers.size() != plc.vertices.size()) {
    throw InputError("Plc3::vertex_markers: " + std::to_string(plc.vertex_markers.size()) + " values, expected " +
                     std::to_string(plc.vertices.size()));
  }
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    for (std::size_t p = 0; p < plc.facets[f].polygons.size(); ++p) {
      const auto& polygon = plc.facets[f].polygons[p];
      if (polygon.empty()) throw InputError("facet " + std::to_string(f) + ", polygon " + std::to_string(p) + " has no corner", {f});
      for (std::uint32_t v : polygon) {
        if (v >= plc.vertices.size()) {
          throw InputError("facet " + std::to_string(f) + ", polygon " + std::to_string(p) + ": vertex " +
                               std::to_string(v) + " out of range (" + std::to_string(plc.vertices.size()) + " vertices)",
                           {f});
        }
      }
    }
  }
}

void append_point(std::string& text, const Vec3& p) {
  for (double c : {p.x, p.y, p.z}) {
    text += ' ';
    io::append_real(text, c);
  }
}

void append_polygon(std::string& text, const std::vector<std::uint32_t>& polygon) {
  io::append_integer(text, static_cast<std::int64_t>(polygon.size()));
  for (std::uint32_t v : polygon) {
    text += ' ';
    io::append_integer(text, static_cast<std::int64_t>(v) + 1);
  }
}

void append_numbered_points(std::string& text, const std::vector<Vec3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + 1);
    append_point(text, points[i]);
    text += '\n';
  }
}

void write_plc(std::ostream& out, const Plc3& plc, PlcFormat format) {
  check_plc(plc);
  if (format == PlcFormat::Smesh) {
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
      if (plc.facets[f].polygons.size() != 1 || !plc.facets[f].holes.empty()) {
        throw InputError("facet " + std::to_string(f) + " has " + std::to_string(plc.facets[f].polygons.size()) +
                             " polygons and " + std::to_string(plc.facets[f].holes.size()) +
                             " holes; a .smesh facet is one polygon without holes",
                         {f});
      }
    }
  }
  std::string text;
  io::append_integer(text, static_cast<std::int64_t>(plc.vertices.size()));
  text += " 3 0 1\n";
  for (std::size_t i = 0; i < plc.vertices.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + 1);
    append_point(text, plc.vertices[i]);
    text += ' ';
    io::append_integer(text, plc.vertex_markers.empty() ? 0 : plc.vertex_markers[i]);
    text += '\n';
  }
  io::append_integer(text, static_cast<std::int64_t>(plc.facets.size()));
  text += " 1\n";
  for (const PlcFacet3& facet : plc.facets) {
    if (format == PlcFormat::Smesh) {
      append_polygon(text, facet.polygons[0]);
      text += ' ';
      io::append_integer(text, facet.marker);
      text += '\n';
      continue;
    }
    io::append_integer(text, static_cast<std::int64_t>(facet.polygons.size()));
    text += ' ';
    io::append_integer(text, static_cast<std::int64_t>(facet.holes.size()));
    text += ' ';
    io::append_integer(text, facet.marker);
    text += '\n';
    for (const auto& polygon : facet.polygons) {
      append_polygon(text, polygon);
      text += '\n';
    }
    append_numbered_points(text, facet.holes);
  }
  io::append_integer(text, static_cast<std::int64_t>(plc.holes.size()));
  text += '\n';
  append_numbered_points(text, plc.holes);
  io::append_integer(text, static_cast<std::int64_t>(plc.regions.size()));
  text += '\n';
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    io::append_integer(text, static_cast<std::int64_t>(i) + 1);
    append_point(text, plc.regions[i].point);
    text += ' ';
    io::append_real(text, plc.regions[i].attribute);
    text += ' ';
    io::append_real(text, plc.regions[i].max_volume);
    text += '\n';
  }
  out << text;
}

void write_plc_file(const std::string& path, const Plc3& plc, PlcFormat format) {
  std::ofstream out = io::open_for_writing(path);
  write_plc(out, plc, format);
  out.flush();
  io::check_written(out, path);
}

// --- Facets to triangles -----------------------------------------------------------------------

// The projection that drops coordinate `axis` (0 = x, 1 = y, 2 = z): exact, so orient2d of the
// projected points is the sign of one component of the 3D normal.
Vec2 project(const Vec3& p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// The first axis along which triangle abc projects to a non-flat triangle, or -1 if a, b, c are
// collinear (all three projections flat).
int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  for (int axis = 0; axis < 3; ++axis) {
    if (uncounted::orient2d(project(a, axis), project(b, axis), project(c, axis)) != Sign::Zero) return axis;
  }
  return -1;
}

// Splits a planar, strictly convex polygon of 4 or more corners into a fan from its first corner,
// or throws InputError naming facet f and polygon p. Strict convexity on the projection: every
// turn (v[i-1], v[i], v[i+1]) and every fan triangle (v[0], v[i], v[i+1]) has the sign of the
// first turn; the fan condition rules out polygons that wind more than once (a pentagram).
void split_convex_polygon(const std::vector<Vec3>& v, const std::vector<std::uint32_t>& polygon, std::size_t f,
                          std::size_t p, int marker, MeshData3& out) {
  const std::string what = "facet " + std::to_string(f) + ", polygon " + std::to_string(p) + " (" +
                           std::to_string(polygon.size()) + " corners)";
  const std::size_t n = polygon.size();
  auto corner = [&](std::size_t i) -> const Vec3& { return v[polygon[i % n]]; };
  const int axis = projection_axis(corner(0), corner(1), corner(2));
  if (axis < 0) {
    throw InputError(what + ": corners 0, 1, 2 are collinear; polygons of more than 3 corners are triangulated only "
                            "when strictly convex",
                     {f});
  }
  for (std::size_t i = 3; i < n; ++i) {
    if (uncounted::orient3d(corner(0), corner(1), corner(2), corner(i)) != Sign::Zero) {
      throw InputError(what + ": corner " + std::to_string(i) + " (vertex " + std::to_string(polygon[i]) +
                           ") is not in the plane of corners 0, 1, 2 (decided exactly)",
                       {f});
    }
  }
  auto turn = [&](std::size_t i, std::size_t j, std::size_t k) {
    return uncounted::orient2d(project(corner(i), axis), project(corner(j), axis), project(corner(k), axis));
  };
  const Sign s = turn(0, 1, 2);
  for (std::size_t i = 1; i <= n; ++i) {
    const Sign t = turn(i - 1, i, i + 1);
    if (t == Sign::Zero) {
      throw InputError(what + ": corners " + std::to_string(i - 1) + ", " + std::to_string(i % n) + ", " +
                           std::to_string((i + 1) % n) +
                           " are collinear; polygons of more than 3 corners are triangulated only when strictly convex",
                       {f});
    }
    if (t != s) {
      throw InputError(what + " is not convex (it turns the other way at corner " + std::to_string(i % n) +
                           "); only strictly convex polygons of more than 3 corners are triangulated",
                       {f});
    }
  }
  for (std::size_t i = 2; i + 1 < n; ++i) {
    if (turn(0, i, i + 1) != s) {
      throw InputError(what + " winds around more than once (not a simple convex polygon)", {f});
    }
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    out.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
    out.triangle_refs.push_back(marker);
  }
}

}  // namespace

Plc3 read_tetgen_poly(std::istream& in, const std::string& file_name, const TetGenNodes* separate_nodes) {
  return PlcReader(in, file_name, PlcFormat::Poly).read([&] { return separate_nodes; });
}

Plc3 read_tetgen_poly(const std::string& path) { return read_plc_file(path, PlcFormat::Poly); }

Plc3 read_tetgen_smesh(std::istream& in, const std::string& file_name, const TetGenNodes* separate_nodes) {
  return PlcReader(in, file_name, PlcFormat::Smesh).read([&] { return separate_nodes; });
}

Plc3 read_tetgen_smesh(const std::string& path) { return read_plc_file(path, PlcFormat::Smesh); }

void write_tetgen_poly(std::ostream& out, const Plc3& plc) { write_plc(out, plc, PlcFormat::Poly); }
void write_tetgen_poly(const std::string& path, const Plc3& plc) { write_plc_file(path, plc, PlcFormat::Poly); }
void write_tetgen_smesh(std::ostream& out, const Plc3& plc) { write_plc(out, plc, PlcFormat::Smesh); }
void write_tetgen_smesh(const std::string& path, const Plc3& plc) { write_plc_file(path, plc, PlcFormat::Smesh); }

MeshData3 triangulate_plc_facets(const Plc3& plc) {
  check_plc(plc);
  check_coordinates(plc.vertices, "PLC vertex");
  MeshData3 mesh;
  mesh.vertices = plc.vertices;
  mesh.vertex_refs = plc.vertex_markers.empty() ? std::vector<int>(plc.vertices.size(), 0) : plc.vertex_markers;
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    const PlcFacet3& facet = plc.facets[f];
    if (!facet.holes.empty()) {
      throw InputError("facet " + std::to_string(f) + " has " + std::to_string(facet.holes.size()) +
                           " holes: facet holes are not supported yet",
                       {f});
    }
    for (std::size_t p = 0; p < facet.polygons.size(); ++p) {
      const auto& polygon = facet.polygons[p];
      if (polygon.size() == 2) {
        mesh.edges.push_back({polygon[0], polygon[1]});
        mesh.edge_refs.push_back(facet.marker);
      } else if (polygon.size() == 3) {
        mesh.triangles.push_back({polygon[0], polygon[1], polygon[2]});
        mesh.triangle_refs.push_back(facet.marker);
      } else if (polygon.size() > 3) {
        split_convex_polygon(plc.vertices, polygon, f, p, facet.marker, mesh);
      }
    }
  }
  return mesh;
}

}  // namespace dtlab
