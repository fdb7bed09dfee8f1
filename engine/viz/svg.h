// Svg: a minimal SVG 1.1 document builder (no dependencies).
//
// Coordinates are SVG user units (pixels, y down). Text is XML-escaped.
// Colours are any SVG colour string ("#1f77b4", "black", "none").
#pragma once

#include <string>
#include <vector>

namespace squawk::viz {

struct Point {
  double x = 0;  // [px]
  double y = 0;  // [px]
};

class Svg {
 public:
  Svg(double width, double height, const std::string& background = "white");

  void line(Point a, Point b, const std::string& stroke, double width = 1.0,
            const std::string& dash = "");
  void polyline(const std::vector<Point>& pts, const std::string& stroke, double width = 1.0,
                const std::string& dash = "");
  void circle(Point c, double r, const std::string& stroke, const std::string& fill = "none",
              double width = 1.0, const std::string& dash = "");
  void polygon(const std::vector<Point>& pts, const std::string& fill,
               const std::string& stroke = "none", double width = 1.0);
  void rect(Point corner, double w, double h, const std::string& fill,
            const std::string& stroke = "none", double width = 1.0);
  // anchor: "start", "middle" or "end"; rotate [deg] about the anchor point.
  void text(Point p, const std::string& s, double size = 12, const std::string& anchor = "start",
            const std::string& fill = "black", double rotate = 0, bool bold = false);

  std::string str() const;
  double width() const { return w_; }
  double height() const { return h_; }

 private:
  double w_, h_;
  std::string body_;
};

std::string xml_escape(const std::string& s);

}  // namespace squawk::viz
