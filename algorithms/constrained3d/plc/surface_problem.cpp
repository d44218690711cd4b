#include "algorithms/constrained3d/plc/surface_problem.hpp"

#include <sstream>

#include "kernel/error.hpp"

namespace dtlab {

SurfaceProblem read_surface_problem(const std::string& path, FacetTriangulationOptions options) {
  SurfaceProblem p;
  p.path = path;
  p.surface = read_surface(path);
  const SurfaceInput& in = p.surface;
  options.facet_name = [&in](std::size_t f) { return in.facet_name(f); };
  options.first_vertex_number = in.first_vertex_number;
  try {
    p.facets = triangulate_facets(in.plc, options);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what(), e.items());
  }
  p.messages = p.facets.messages;
  for (const PlcRegion3& r : in.plc.regions) {
    const int attribute = static_cast<int>(r.attribute);
    if (static_cast<double>(attribute) != r.attribute) {
      std::ostringstream m;
      m << "region attribute " << r.attribute << " is not an integer; the reference is " << attribute;
      p.messages.push_back(m.str());
    }
    p.regions.push_back({r.point, attribute});
  }
  return p;
}

ConstrainedInput3 SurfaceProblem::input() const {
  return {.points = surface.plc.vertices,
          .triangles = facets.triangles,
          .triangle_refs = facets.triangle_refs,
          .holes = surface.plc.holes,
          .regions = regions,
          .triangle_name = [this](std::uint32_t t) { return triangle_name(t); }};
}

std::string SurfaceProblem::triangle_name(std::uint32_t t) const {
  const auto& of = facets.triangle_facet;
  std::uint32_t first = t, last = t;
  while (first > 0 && of[first - 1] == of[t]) --first;
  while (last + 1 < of.size() && of[last + 1] == of[t]) ++last;
  std::string name = surface.facet_name(of[t]);
  if (last > first)
    name += " (triangle " + std::to_string(t - first + 1) + " of " + std::to_string(last - first + 1) + ")";
  return name;
}

}  // namespace dtlab
