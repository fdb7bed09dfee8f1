#include "viz/layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace squawk::viz {

double text_width(const std::string& s, double size, bool bold) {
  size_t chars = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++chars;  // count UTF-8 code points
  return static_cast<double>(chars) * size * (bold ? 0.68 : 0.62);
}

double fit_text(std::string& s, double width, double size, double min_size) {
  const double w = text_width(s, size);
  if (w <= width) return size;
  const double fitted = std::max(min_size, size * width / w);
  if (text_width(s, fitted) <= width) return fitted;
  while (!s.empty() && text_width(s + "...", fitted) > width) s.pop_back();
  s += "...";
  return fitted;
}

double LabelLayout::cost(const Box& b) const {
  double c = b.inside(area_) ? 0.0 : 1e6;
  for (const auto& t : taken_) {
    if (!b.overlaps(t)) continue;
    c += (std::min(b.x1, t.x1) - std::max(b.x0, t.x0)) * (std::min(b.y1, t.y1) - std::max(b.y0, t.y0));
  }
  return c;
}

std::optional<Point> LabelLayout::place(Point a, double w, double h, double gap, bool required) {
  Point best{a.x + gap, a.y - h / 2};
  double best_cost = std::numeric_limits<double>::infinity();
  // Two rings of eight positions of the top-left corner, nearest first.
  for (double g : {gap, 2.5 * gap + 6}) {
    const double d = g * 0.75;
    const Point corners[] = {
        {a.x + g, a.y - h / 2},     {a.x + d, a.y - d - h},       {a.x - w / 2, a.y - g - h},
        {a.x - d - w, a.y - d - h}, {a.x - g - w, a.y - h / 2},   {a.x - d - w, a.y + d},
        {a.x - w / 2, a.y + g},     {a.x + d, a.y + d},
    };
    for (const Point& c : corners) {
      const double k = cost({c.x, c.y, c.x + w, c.y + h});
      if (k < best_cost) best_cost = k, best = c;
      if (k == 0) break;
    }
    if (best_cost == 0) break;
  }
  if (best_cost > 0 && !required) return std::nullopt;
  taken_.push_back({best.x, best.y, best.x + w, best.y + h});
  return best;
}

}  // namespace squawk::viz
