// SVG and JSON writers of SvgCanvas (svg_canvas.hpp).
#include "apps/svg_canvas.hpp"

#include <cstdio>
#include <utility>

namespace dtlab::cli {

namespace {

// Two decimals: a hundredth of a pixel; -0.00 printed as 0.00 so that the bytes do not depend
// on the sign of a rounded zero.
std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  if (s == "-0.00") s = "0.00";
  // Trailing zeros dropped: "12.50" -> "12.5", "3.00" -> "3".
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string json_escape(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

void SvgCanvas::begin_polygons(const std::string& stroke, double stroke_width) {
  items_.push_back({Item::Kind::Group, {}, "", stroke, stroke_width, "", "", false});
}

void SvgCanvas::polygon(const std::vector<CanvasPoint>& points, const std::string& fill) {
  items_.push_back({Item::Kind::Polygon, points, fill, "", 0.0, "", "", false});
}

void SvgCanvas::segments(const std::vector<std::pair<CanvasPoint, CanvasPoint>>& lines, const std::string& stroke,
                         double width) {
  Item item{Item::Kind::Segments, {}, "none", stroke, width, "", "", false};
  for (const auto& [a, b] : lines) {
    item.points.push_back(a);
    item.points.push_back(b);
  }
  items_.push_back(std::move(item));
}

void SvgCanvas::rect(double x, double y, double w, double h, const std::string& fill, const std::string& stroke) {
  items_.push_back({Item::Kind::Rect, {{x, y}, {w, h}}, fill, stroke, 1.0, "", "", false});
}

void SvgCanvas::text(double x, double y, const std::string& text, double size, const std::string& anchor, bool bold) {
  items_.push_back({Item::Kind::Text, {{x, y}}, "#000", "", size, text, anchor, bold});
}

std::string SvgCanvas::svg() const {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(width_) + "\" height=\"" +
         num(height_) + "\" viewBox=\"0 0 " + num(width_) + " " + num(height_) +
         "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + num(width_) + "\" height=\"" + num(height_) + "\" fill=\"#fff\"/>\n";
  bool in_group = false;
  for (const Item& it : items_) {
    if (it.kind != Item::Kind::Polygon && in_group) {
      out += "</g>\n";
      in_group = false;
    }
    switch (it.kind) {
      case Item::Kind::Group:
        out += "<g stroke=\"" + it.stroke + "\" stroke-width=\"" + num(it.width) + "\" stroke-linejoin=\"round\">\n";
        in_group = true;
        break;
      case Item::Kind::Polygon: {
        out += "<polygon points=\"";
        for (std::size_t i = 0; i < it.points.size(); ++i) {
          if (i) out += ' ';
          out += num(it.points[i].x) + "," + num(it.points[i].y);
        }
        out += "\" fill=\"" + it.fill + "\"/>\n";
        break;
      }
      case Item::Kind::Segments: {
        if (it.points.empty()) break;
        out += "<path fill=\"none\" stroke=\"" + it.stroke + "\" stroke-width=\"" + num(it.width) +
               "\" stroke-linecap=\"round\" d=\"";
        for (std::size_t i = 0; i + 1 < it.points.size(); i += 2)
          out += 'M' + num(it.points[i].x) + ' ' + num(it.points[i].y) + 'L' + num(it.points[i + 1].x) + ' ' +
                 num(it.points[i + 1].y);
        out += "\"/>\n";
        break;
      }
      case Item::Kind::Rect:
        out += "<rect x=\"" + num(it.points[0].x) + "\" y=\"" + num(it.points[0].y) + "\" width=\"" +
               num(it.points[1].x) + "\" height=\"" + num(it.points[1].y) + "\" fill=\"" + it.fill + "\"" +
               (it.stroke != "none" ? " stroke=\"" + it.stroke + "\" stroke-width=\"1\"" : std::string()) + "/>\n";
        break;
      case Item::Kind::Text:
        out += "<text x=\"" + num(it.points[0].x) + "\" y=\"" + num(it.points[0].y) + "\" font-size=\"" +
               num(it.width) + "\"" + (it.anchor != "start" ? " text-anchor=\"" + it.anchor + "\"" : std::string()) +
               (it.bold ? " font-weight=\"bold\"" : "") + ">" + xml_escape(it.text) + "</text>\n";
        break;
    }
  }
  if (in_group) out += "</g>\n";
  return out + "</svg>\n";
}

// {"width":W,"height":H,"items":[{"kind":"group","stroke":..,"width":..}, {"kind":"polygon",
// "points":[x,y,...],"fill":..}, {"kind":"segments","points":[...],"stroke":..,"width":..},
// {"kind":"rect","x":..,"y":..,"w":..,"h":..,"fill":..,"stroke":..}, {"kind":"text","x":..,
// "y":..,"text":..,"size":..,"anchor":..,"bold":..}]}
std::string SvgCanvas::json() const {
  std::string out = "{\"width\":" + num(width_) + ",\"height\":" + num(height_) + ",\"items\":[\n";
  auto points = [](const std::vector<CanvasPoint>& p) {
    std::string s = "[";
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i) s += ',';
      s += num(p[i].x) + "," + num(p[i].y);
    }
    return s + "]";
  };
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    if (i) out += ",\n";
    switch (it.kind) {
      case Item::Kind::Group:
        out += "{\"kind\":\"group\",\"stroke\":" + json_escape(it.stroke) + ",\"width\":" + num(it.width) + "}";
        break;
      case Item::Kind::Polygon:
        out += "{\"kind\":\"polygon\",\"points\":" + points(it.points) + ",\"fill\":" + json_escape(it.fill) + "}";
        break;
      case Item::Kind::Segments:
        out += "{\"kind\":\"segments\",\"points\":" + points(it.points) + ",\"stroke\":" + json_escape(it.stroke) +
               ",\"width\":" + num(it.width) + "}";
        break;
      case Item::Kind::Rect:
        out += "{\"kind\":\"rect\",\"x\":" + num(it.points[0].x) + ",\"y\":" + num(it.points[0].y) +
               ",\"w\":" + num(it.points[1].x) + ",\"h\":" + num(it.points[1].y) + ",\"fill\":" +
               json_escape(it.fill) + ",\"stroke\":" + json_escape(it.stroke) + "}";
        break;
      case Item::Kind::Text:
        out += "{\"kind\":\"text\",\"x\":" + num(it.points[0].x) + ",\"y\":" + num(it.points[0].y) +
               ",\"text\":" + json_escape(it.text) + ",\"size\":" + num(it.width) + ",\"anchor\":" +
               json_escape(it.anchor) + ",\"bold\":" + (it.bold ? "true" : "false") + "}";
        break;
    }
  }
  return out + "\n]}\n";
}

}  // namespace dtlab::cli
