// A picture as a list of drawing primitives in pixel coordinates (y down), written as SVG 1.1
// natively, or as JSON for scripts/plot_png.py to rasterise with matplotlib. `dtlab plot` lays
// out its pictures once, on this canvas, for both outputs. Numbers are printed with a fixed
// number of decimals, so the same picture gives the same bytes.
#pragma once

#include <string>
#include <vector>

namespace dtlab::cli {

struct CanvasPoint {
  double x = 0.0;
  double y = 0.0;
};

class SvgCanvas {
 public:
  SvgCanvas(double width, double height) : width_(width), height_(height) {}

  // Filled polygons share one stroke (colour, width) per group: the triangles of a mesh with
  // their edges. A group opens with begin_polygons and holds the polygons added until the next.
  void begin_polygons(const std::string& stroke, double stroke_width);
  void polygon(const std::vector<CanvasPoint>& points, const std::string& fill);
  // Line segments drawn as one path: the boundary and constrained edges.
  void segments(const std::vector<std::pair<CanvasPoint, CanvasPoint>>& lines, const std::string& stroke,
                double width);
  void rect(double x, double y, double w, double h, const std::string& fill, const std::string& stroke = "none");
  // anchor: "start", "middle" or "end"; the baseline at y.
  void text(double x, double y, const std::string& text, double size = 12.0, const std::string& anchor = "start",
            bool bold = false);

  std::string svg() const;
  std::string json() const;

 private:
  struct Item {
    enum class Kind { Group, Polygon, Segments, Rect, Text } kind;
    std::vector<CanvasPoint> points;  // polygon vertices; segment end points in pairs; rect: x,y / w,h
    std::string fill;
    std::string stroke;
    double width = 0.0;  // stroke width, or the text's size
    std::string text;
    std::string anchor;
    bool bold = false;
  };
  double width_;
  double height_;
  std::vector<Item> items_;
};

}  // namespace dtlab::cli
