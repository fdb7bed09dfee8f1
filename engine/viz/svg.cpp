#include "viz/svg.h"

#include <cstdio>

namespace squawk::viz {

namespace {
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}
std::string stroke_attrs(const std::string& stroke, double width, const std::string& dash) {
  std::string s = " stroke=\"" + stroke + "\" stroke-width=\"" + num(width) + "\"";
  if (!dash.empty()) s += " stroke-dasharray=\"" + dash + "\"";
  return s;
}
std::string points_attr(const std::vector<Point>& pts) {
  std::string s;
  for (const auto& p : pts) s += num(p.x) + "," + num(p.y) + " ";
  return s;
}
}  // namespace

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      default: r += c;
    }
  }
  return r;
}

Svg::Svg(double width, double height, const std::string& background) : w_(width), h_(height) {
  rect({0, 0}, width, height, background);
}

void Svg::line(Point a, Point b, const std::string& stroke, double width, const std::string& dash) {
  body_ += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" +
           num(b.y) + "\"" + stroke_attrs(stroke, width, dash) + "/>\n";
}

void Svg::polyline(const std::vector<Point>& pts, const std::string& stroke, double width,
                   const std::string& dash) {
  if (pts.size() < 2) return;
  body_ += "<polyline fill=\"none\" points=\"" + points_attr(pts) + "\"" +
           stroke_attrs(stroke, width, dash) + " stroke-linejoin=\"round\"/>\n";
}

void Svg::circle(Point c, double r, const std::string& stroke, const std::string& fill, double width,
                 const std::string& dash) {
  body_ += "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\" fill=\"" +
           fill + "\"" + stroke_attrs(stroke, width, dash) + "/>\n";
}

void Svg::polygon(const std::vector<Point>& pts, const std::string& fill, const std::string& stroke,
                  double width) {
  body_ += "<polygon points=\"" + points_attr(pts) + "\" fill=\"" + fill + "\"" +
           stroke_attrs(stroke, width, "") + "/>\n";
}

void Svg::rect(Point corner, double w, double h, const std::string& fill, const std::string& stroke,
               double width) {
  body_ += "<rect x=\"" + num(corner.x) + "\" y=\"" + num(corner.y) + "\" width=\"" + num(w) +
           "\" height=\"" + num(h) + "\" fill=\"" + fill + "\"" + stroke_attrs(stroke, width, "") +
           "/>\n";
}

void Svg::text(Point p, const std::string& s, double size, const std::string& anchor,
               const std::string& fill, double rotate, bool bold) {
  body_ += "<text x=\"" + num(p.x) + "\" y=\"" + num(p.y) + "\" font-size=\"" + num(size) +
           "\" font-family=\"DejaVu Sans, Arial, sans-serif\" text-anchor=\"" + anchor + "\" fill=\"" +
           fill + "\"";
  if (bold) body_ += " font-weight=\"bold\"";
  if (rotate != 0)
    body_ += " transform=\"rotate(" + num(rotate) + " " + num(p.x) + " " + num(p.y) + ")\"";
  body_ += ">" + xml_escape(s) + "</text>\n";
}

std::string Svg::str() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "width=\"" + num(w_) + "\" height=\"" + num(h_) + "\" viewBox=\"0 0 " + num(w_) + " " +
         num(h_) + "\">\n" + body_ + "</svg>\n";
}

}  // namespace squawk::viz
