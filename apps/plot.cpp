// `dtlab plot MESH -o OUT.svg|png [--color quality|reference] [--metric M.sol [--background B.mesh]]
// [--histogram]`: a 2D mesh with its triangles filled by Q_K (kernel/quality.hpp, in the vertex
// metrics when given) or by reference, boundary and constrained edges drawn heavier, a colour bar
// or legend; or (--histogram, and always for a 3D mesh) the histogram of Q_K in the book's bins
// [1,2], ]2,3], ]3,10], > 10 (mesh/mesh_quality.hpp, the figures of `dtlab quality`) beside a
// finer one. SVG is written here; PNG by scripts/plot_png.py (matplotlib) from the same layout.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/mesh2d/control_space.hpp"
#include "apps/cli_util.hpp"
#include "mesh/io/any_format.hpp"
#include "mesh/io/staged_outputs.hpp"
#include "apps/subcommands.hpp"
#include "apps/svg_canvas.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quality.hpp"
#include "mesh/io/medit_sol.hpp"
#include "mesh/mesh_quality.hpp"

extern char** environ;

namespace dtlab::cli {

namespace {

struct PlotArgs {
  std::string mesh;
  std::string out;
  std::string color = "quality";
  std::string metric;
  std::string background;
  bool histogram = false;
};

std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// The vertex metrics of a 2D mesh: none, a .sol at its vertices, or a .sol on a background
// mesh interpolated at the vertices the triangles use (as `dtlab quality` does).
std::vector<Metric2> metrics2(const PlotArgs& args, const MeshData2& mesh) {
  if (args.metric.empty()) return {};
  if (args.background.empty()) return read_metrics<Metric2>(args.metric, mesh.vertices.size());
  const MeshData2 background = read_mesh2(args.background);
  std::vector<Metric2> at_background;
  try {
    at_background = read_metrics<Metric2>(args.metric, background.vertices.size());
  } catch (const InputError& e) {
    throw InputError("--background " + args.background + ": " + e.what(), e.items());
  }
  ControlSpace2 control(background, std::move(at_background));
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v < used.size()) used[v] = 1;
  std::vector<Metric2> metrics(mesh.vertices.size(), Metric2{});
  std::uint32_t hint = ControlSpace2::kNoHint;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (used[v]) metrics[v] = control.metric_at(mesh.vertices[v], hint);
  return metrics;
}

// ---- colours ----------------------------------------------------------------------------

std::string hex(double r, double g, double b) {
  char buf[8];
  auto c = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 255.0))); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c(r), c(g), c(b));
  return buf;
}

// ColorBrewer's YlOrRd, 9 classes: pale yellow for Q = 1, dark red for the top of the scale.
std::string quality_colour(double t) {
  static constexpr std::array<std::array<double, 3>, 9> kStops{{{255, 255, 204},
                                                               {255, 237, 160},
                                                               {254, 217, 118},
                                                               {254, 178, 76},
                                                               {253, 141, 60},
                                                               {252, 78, 42},
                                                               {227, 26, 28},
                                                               {189, 0, 38},
                                                               {128, 0, 38}}};
  if (!(t >= 0.0)) t = 0.0;  // NaN too
  t = std::min(t, 1.0) * (kStops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), kStops.size() - 2);
  const double f = t - static_cast<double>(i);
  const auto& a = kStops[i];
  const auto& b = kStops[i + 1];
  return hex(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
}

// Matplotlib's tab20, for references: the first ten strong, the next ten light.
std::string reference_colour(std::size_t i) {
  static constexpr std::array<const char*, 20> kPalette{
      "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
      "#aec7e8", "#ffbb78", "#98df8a", "#ff9896", "#c5b0d5", "#c49c94", "#f7b6d2", "#c7c7c7", "#dbdb8d", "#9edae5"};
  return kPalette[i % kPalette.size()];
}

constexpr const char* kInvertedColour = "#2b83ba";

// The top of the quality scale: the first of these at or above Q_M (10 when Q_M is larger:
// the values above are drawn in the top colour and counted in a last bin).
double scale_top(double worst) {
  for (double top : {1.1, 1.2, 1.3, 1.4, 1.5, 1.75, 2.0, 2.5, 3.0, 4.0, 5.0, 7.5, 10.0})
    if (worst <= top) return top;
  return 10.0;
}

double scale_position(double q, double top) { return (q - 1.0) / (top - 1.0); }

std::string fixed(double v, int digits) {
  if (std::isinf(v)) return "inf";
  if (std::isnan(v)) return "-";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string percent(std::uint64_t part, std::uint64_t whole) {
  return fixed(whole ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0, 1) + " %";
}

std::string summary_line(const QualityReport& r, const char* elements) {
  return std::to_string(r.elements) + " " + elements + ", " + std::to_string(r.vertices) +
         " vertices; Q_M = " + fixed(r.quality_worst, 3) + ", mean Q_K = " + fixed(r.quality_mean, 3) +
         "; Q in [1,2]: " + percent(r.quality_bins[0], r.elements) +
         (r.inverted + r.flat ? "; inverted / flat " + std::to_string(r.inverted) + " / " + std::to_string(r.flat)
                              : std::string()) +
         (r.has_metric ? " (in the metric)" : "");
}

// ---- the mesh picture -------------------------------------------------------------------

constexpr double kMargin = 20.0;
constexpr double kTitle = 56.0;       // two lines of text above the picture
constexpr double kSide = 130.0;       // the colour bar or legend, right of the picture
constexpr double kPictureSide = 760.0;

void title(SvgCanvas& canvas, const std::string& first, const std::string& second) {
  canvas.text(kMargin, 24.0, first, 15.0, "start", true);
  canvas.text(kMargin, 44.0, second, 12.0);
}

// A vertical bar of the quality colours from Q = 1 (bottom) to `top`, ticks on its right.
void colour_bar(SvgCanvas& canvas, double x, double y, double height, double top, bool clipped, bool inverted) {
  constexpr int kSteps = 64;
  const double step = height / kSteps;
  canvas.text(x, y - 10.0, "Q_K", 12.0, "start", true);
  for (int i = 0; i < kSteps; ++i)
    canvas.rect(x, y + height - (i + 1) * step, 18.0, step + 0.3, quality_colour((i + 0.5) / kSteps));
  canvas.rect(x, y, 18.0, height, "none", "#333");
  const int ticks = 5;
  for (int i = 0; i < ticks; ++i) {
    const double q = 1.0 + (top - 1.0) * i / (ticks - 1);
    const double ty = y + height - height * i / (ticks - 1);
    canvas.rect(x + 18.0, ty - 0.5, 5.0, 1.0, "#333");
    std::string label = fixed(q, top <= 2.0 ? 2 : 1);
    if (i == ticks - 1 && clipped) label = ">= " + label;
    canvas.text(x + 27.0, ty + 4.0, label, 11.0);
  }
  if (inverted) {
    canvas.rect(x, y + height + 16.0, 18.0, 12.0, kInvertedColour, "#333");
    canvas.text(x + 24.0, y + height + 26.0, "inverted", 11.0);
  }
}

SvgCanvas mesh_picture(const PlotArgs& args, const MeshData2& mesh, const std::vector<double>& q,
                       const std::vector<char>& inverted, const QualityReport& report) {
  // The box of the vertices the triangles use.
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) {
      const Vec2& p = mesh.vertices[v];
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  const double extent = std::max(x1 - x0, y1 - y0);
  const double scale = extent > 0.0 ? kPictureSide / extent : 1.0;
  const double pw = std::max(1.0, (x1 - x0) * scale), ph = std::max(1.0, (y1 - y0) * scale);
  const double width = kMargin + pw + 24.0 + kSide, height = std::max(kTitle + ph + kMargin, kTitle + 320.0);
  auto at = [&](std::uint32_t v) {
    const Vec2& p = mesh.vertices[v];
    return CanvasPoint{kMargin + (p.x - x0) * scale, kTitle + (y1 - p.y) * scale};
  };

  SvgCanvas canvas(width, height);
  const bool by_quality = args.color == "quality";
  title(canvas, base_name(args.mesh) + (by_quality ? ": triangles coloured by Q_K" : ": triangles coloured by reference"),
        summary_line(report, "triangles"));

  // Edge strokes that scale with the triangles' size on the picture: thin for fine meshes.
  const double typical = std::sqrt(pw * ph / static_cast<double>(mesh.triangles.size()));
  const double edge_width = std::clamp(0.03 * typical, 0.1, 0.5);

  std::map<int, std::size_t> references;  // reference -> colour index, in increasing order
  std::map<int, std::uint64_t> reference_counts;
  for (int r : mesh.triangle_refs) ++reference_counts[r];
  for (const auto& [r, n] : reference_counts) references.emplace(r, references.size());

  const double top = scale_top(report.quality_worst);
  canvas.begin_polygons("#555", edge_width);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    std::string fill;
    if (!by_quality)
      fill = reference_colour(references.at(k < mesh.triangle_refs.size() ? mesh.triangle_refs[k] : 0));
    else if (inverted[k])
      fill = kInvertedColour;
    else
      fill = quality_colour(scale_position(q[k], top));
    canvas.polygon({at(t[0]), at(t[1]), at(t[2])}, fill);
  }

  // Heavier: the edges of the file's Edges section (constrained, with their references) and the
  // boundary of the triangulation (the edges of one triangle only).
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<CanvasPoint, CanvasPoint>> heavy;
  for (const auto& [e, n] : uses)
    if (n == 1) heavy.emplace_back(at(e.first), at(e.second));
  for (const auto& e : mesh.edges) {
    if (e[0] >= mesh.vertices.size() || e[1] >= mesh.vertices.size())
      throw InputError(args.mesh + ": edge " + std::to_string(&e - mesh.edges.data() + 1) +
                       " has a vertex out of range");
    if (uses.count({std::min(e[0], e[1]), std::max(e[0], e[1])}) && uses[{std::min(e[0], e[1]), std::max(e[0], e[1])}] == 1)
      continue;  // drawn already
    heavy.emplace_back(at(e[0]), at(e[1]));
  }
  canvas.segments(heavy, "#111", std::max(1.2, 3.0 * edge_width));

  const double side_x = kMargin + pw + 24.0;
  if (by_quality) {
    colour_bar(canvas, side_x, kTitle + 20.0, 240.0, top, report.quality_worst > top, report.inverted > 0);
  } else {
    canvas.text(side_x, kTitle + 10.0, "reference", 12.0, "start", true);
    std::size_t row = 0;
    for (const auto& [r, n] : reference_counts) {
      if (row == 24) {
        canvas.text(side_x, kTitle + 30.0 + 18.0 * row, "... " + std::to_string(references.size() - row) + " more",
                    11.0);
        break;
      }
      const double y = kTitle + 20.0 + 18.0 * row++;
      canvas.rect(side_x, y, 14.0, 12.0, reference_colour(references.at(r)), "#333");
      canvas.text(side_x + 20.0, y + 10.5, std::to_string(r) + " (" + std::to_string(n) + ")", 11.0);
    }
  }
  return canvas;
}

// ---- the histogram ----------------------------------------------------------------------

SvgCanvas histogram_picture(const PlotArgs& args, const std::vector<double>& q, const QualityReport& report,
                            const char* elements) {
  constexpr double kWidth = 900.0, kHeight = 440.0, kPlotTop = kTitle + 64.0, kPlotHeight = 240.0;
  const double base = kPlotTop + kPlotHeight;
  SvgCanvas canvas(kWidth, kHeight);
  title(canvas, base_name(args.mesh) + ": Q_K of its " + elements, summary_line(report, elements));

  // Left: the book's bins, the share of the elements and their count on each bar.
  const std::array<const char*, 4> labels{"[1,2]", "]2,3]", "]3,10]", "> 10"};
  const std::array<double, 4> colour_at{1.5, 2.5, 6.5, 11.0};
  const double left = 60.0, bar = 50.0, gap = 18.0;
  canvas.text(left, kTitle + 24.0, "the book's bins (share of elements)", 12.0, "start", true);
  for (std::size_t i = 0; i < 4; ++i) {
    const double share = report.elements ? static_cast<double>(report.quality_bins[i]) / report.elements : 0.0;
    const double x = left + i * (bar + gap), h = share * kPlotHeight;
    canvas.rect(x, base - h, bar, h, quality_colour(scale_position(colour_at[i], 10.0)), "#333");
    canvas.text(x + bar / 2, base - h - 18.0, percent(report.quality_bins[i], report.elements), 10.0, "middle");
    canvas.text(x + bar / 2, base - h - 6.0, "(" + std::to_string(report.quality_bins[i]) + ")", 10.0, "middle");
    canvas.text(x + bar / 2, base + 16.0, labels[i], 11.0, "middle");
  }
  canvas.rect(left - 6.0, base, 4 * (bar + gap) - gap + 12.0, 1.0, "#333");

  // Right: 25 bins over [1, top] (the scale of the mesh picture) and the values above it.
  const double top = scale_top(report.quality_worst);
  constexpr int kBins = 25;
  std::vector<std::uint64_t> counts(kBins + 1, 0);
  for (double v : q) {
    if (!(v <= top)) {
      ++counts[kBins];  // above the scale, or flat (+infinity)
      continue;
    }
    const int b = static_cast<int>(std::floor(scale_position(v, top) * kBins));
    ++counts[std::clamp(b, 0, kBins - 1)];
  }
  const bool overflow = counts[kBins] > 0;
  const std::uint64_t most = *std::max_element(counts.begin(), counts.end());
  const double right = 380.0, plot_w = 480.0, slot = plot_w / (kBins + (overflow ? 1.5 : 0.0));
  canvas.text(right, kTitle + 24.0, "Q_K, " + std::to_string(kBins) + " bins over [1, " + fixed(top, 2) + "]",
              12.0, "start", true);
  for (int b = 0; b <= kBins; ++b) {
    if (b == kBins && !overflow) break;
    const double h = most ? kPlotHeight * static_cast<double>(counts[b]) / static_cast<double>(most) : 0.0;
    const double x = right + (b == kBins ? (kBins + 0.5) * slot : b * slot);
    canvas.rect(x, base - h, slot, h, quality_colour(b == kBins ? 1.0 : (b + 0.5) / kBins), "#333");
  }
  canvas.rect(right - 4.0, base, plot_w + 8.0, 1.0, "#333");
  for (int i = 0; i <= 5; ++i) {
    const double x = right + kBins * slot * i / 5.0;
    canvas.rect(x - 0.5, base, 1.0, 5.0, "#333");
    canvas.text(x, base + 18.0, fixed(1.0 + (top - 1.0) * i / 5.0, top <= 2.0 ? 2 : 1), 11.0, "middle");
  }
  if (overflow) canvas.text(right + (kBins + 1.0) * slot, base + 18.0, "> " + fixed(top, 0), 11.0, "middle");
  canvas.text(right - 8.0, kPlotTop + 4.0, std::to_string(most), 10.0, "end");
  canvas.text(right - 8.0, base, "0", 10.0, "end");
  canvas.text(right + plot_w / 2, base + 40.0, "elements per bin (the tallest bar: " + std::to_string(most) + ")",
              11.0, "middle");
  return canvas;
}

// ---- output -----------------------------------------------------------------------------

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw InputError("cannot write '" + path + "'");
}

std::string png_script() {
  if (const char* env = std::getenv("DTLAB_PLOT_PNG_SCRIPT")) return env;
#ifdef DTLAB_PLOT_PNG_SCRIPT
  return DTLAB_PLOT_PNG_SCRIPT;
#else
  return "scripts/plot_png.py";
#endif
}

// Runs `python script json png` and returns its exit status (127: the interpreter not found).
int run_python(const std::string& python, const std::string& script, const std::string& json, const std::string& png) {
  std::vector<std::string> words{python, script, json, png};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return 127;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// PNG through matplotlib: the canvas as JSON beside the output, rasterised by scripts/plot_png.py
// with the first interpreter that has matplotlib ($DTLAB_PYTHON, python3, /usr/bin/python3).
void write_png(const std::string& path, const SvgCanvas& canvas) {
  const std::string script = png_script();
  if (!std::filesystem::exists(script))
    throw InputError("cannot write '" + path + "': the PNG writer " + script +
                     " is missing (set DTLAB_PLOT_PNG_SCRIPT, or write .svg)");
  const std::string json = path + ".canvas.json";
  write_text(json, canvas.json());
  std::vector<std::string> pythons;
  if (const char* env = std::getenv("DTLAB_PYTHON")) pythons.emplace_back(env);
  pythons.emplace_back("python3");
  pythons.emplace_back("/usr/bin/python3");
  setenv("DTLAB_PLOT_PNG_QUIET", "1", 1);  // an interpreter without matplotlib exits 3 without a message
  int status = 127;
  for (const std::string& python : pythons) {
    status = run_python(python, script, json, path);
    if (status != 127 && status != 3) break;  // 3: that interpreter has no matplotlib
  }
  std::filesystem::remove(json);
  if (status == 3 || status == 127)
    throw InputError("cannot write '" + path +
                     "': PNG needs Python 3 with matplotlib (Debian: apt-get install python3-matplotlib); "
                     "write .svg instead");
  if (status != 0) throw InputError("cannot write '" + path + "': " + script + " exited with status " + std::to_string(status));
}

void write_picture(const std::string& target, const SvgCanvas& canvas) {
  StagedOutputs outputs;
  outputs.write(target, [&](const std::string& path) {
    if (extension_of(path) == "svg")
      write_text(path, canvas.svg());
    else
      write_png(path, canvas);
  });
  outputs.commit();
}

// ---- the command ------------------------------------------------------------------------

int run_plot(const PlotArgs& args) {
  const std::string out_ext = extension_of(args.out);
  if (out_ext != "svg" && out_ext != "png")
    throw InputError("-o " + args.out + ": give an .svg or .png output");
  check_output_target(args.out);
  if (args.color != "quality" && args.color != "reference")
    throw InputError("--color " + args.color + ": give quality or reference");
  if (!args.background.empty() && args.metric.empty())
    throw InputError("--background " + args.background + " needs --metric, the metric at its vertices");
  const std::string path = mesh_input_path(args.mesh, "plot");

  if (input_dimension(path) == 3) {
    if (args.color == "reference")
      throw InputError("--color reference: " + path + " is 3D; its tetrahedra are coloured by quality only");
    if (!args.background.empty())
      throw InputError("--background " + args.background + ": a background mesh is supported for 2D meshes only, and " +
                       path + " is 3D (give --metric at its vertices)");
    const MeshData3 mesh = read_mesh3(path);
    if (mesh.tetrahedra.empty()) throw InputError("nothing to plot: " + path + " has no tetrahedra");
    const std::vector<Metric3> metrics =
        args.metric.empty() ? std::vector<Metric3>{} : read_metrics<Metric3>(args.metric, mesh.vertices.size());
    const QualityReport report = measure_quality(mesh.vertices, mesh.tetrahedra, metrics);  // checks the input
    std::vector<double> q;
    q.reserve(mesh.tetrahedra.size());
    for (const auto& t : mesh.tetrahedra) {
      const auto& p = mesh.vertices;
      q.push_back(metrics.empty() ? shape_quality(p[t[0]], p[t[1]], p[t[2]], p[t[3]])
                                  : shape_quality(p[t[0]], p[t[1]], p[t[2]], p[t[3]], metrics[t[0]], metrics[t[1]],
                                                  metrics[t[2]], metrics[t[3]]));
    }
    write_picture(args.out, histogram_picture(args, q, report, "tetrahedra"));
    return 0;
  }

  const MeshData2 mesh = read_mesh2(path);
  if (mesh.triangles.empty()) throw InputError("nothing to plot: " + path + " has no triangles");
  const std::vector<Metric2> metrics = metrics2(args, mesh);
  const QualityReport report = measure_quality(mesh.vertices, mesh.triangles, metrics);  // checks the input
  std::vector<double> q;
  std::vector<char> inverted;
  q.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const auto& p = mesh.vertices;
    q.push_back(metrics.empty() ? shape_quality(p[t[0]], p[t[1]], p[t[2]])
                                : shape_quality(p[t[0]], p[t[1]], p[t[2]], metrics[t[0]], metrics[t[1]], metrics[t[2]]));
    inverted.push_back(orient2d(p[t[0]], p[t[1]], p[t[2]]) == Sign::Negative);
  }
  if (args.histogram)
    write_picture(args.out, histogram_picture(args, q, report, "triangles"));
  else
    write_picture(args.out, mesh_picture(args, mesh, q, inverted, report));
  return 0;
}

}  // namespace

void add_plot(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw a 2D mesh (triangles coloured by quality Q_K or by reference, boundary and constrained edges heavier, "
      "a colour bar or legend) or the histogram of Q_K of any mesh, as SVG (or PNG through matplotlib)");
  cmd->add_option("mesh", args->mesh, "The mesh: Medit .mesh/.meshb, Gmsh .msh, Triangle/TetGen .ele (or base name)")
      ->required();
  cmd->add_option("-o,--output", args->out, "The picture: .svg (written natively) or .png (scripts/plot_png.py)")
      ->required();
  cmd->add_option("--color", args->color, "quality (Q_K, the default) or reference");
  cmd->add_option("--metric", args->metric, "Medit .sol with the metric at the mesh's (or the background's) vertices");
  cmd->add_option("--background", args->background, "2D: the background mesh of --metric");
  cmd->add_flag("--histogram", args->histogram,
                "The histogram of Q_K (the book's bins [1,2], ]2,3], ]3,10], > 10 and a finer one) instead of the "
                "mesh; always so for a 3D mesh");
  cmd->callback([args] { exit_code() = run_plot(*args); });
}

}  // namespace dtlab::cli
