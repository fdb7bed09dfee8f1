// Layout helpers for pictures: text size estimates, fitting a text to a
// width, and placing labels so they overlap neither each other nor marked
// obstacles.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "viz/svg.h"

namespace squawk::viz {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [px] x0 <= x1, y0 <= y1 (y down)
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool inside(const Box& o) const { return x0 >= o.x0 && x1 <= o.x1 && y0 >= o.y0 && y1 <= o.y1; }
};

// Width [px] of `s` at font size `size` in DejaVu Sans (an upper estimate:
// 0.62 em per character, 0.68 bold).
double text_width(const std::string& s, double size, bool bold = false);

// The largest font size in [min_size, size] at which `s` fits `width`; at
// min_size a text still too wide is cut and ends in "...". Returns the size
// and replaces `s` by what fits.
double fit_text(std::string& s, double width, double size, double min_size);

// Greedy label placement: each label goes to the first of eight positions
// around its anchor (right, upper right, above, ...), at the given gap and
// then farther out, that lies inside the area and overlaps no obstacle and
// no earlier label; when none is free, to the one with the least overlap,
// or, when not `required`, nowhere.
class LabelLayout {
 public:
  explicit LabelLayout(Box area) : area_(area) {}
  void block(const Box& b) { taken_.push_back(b); }
  // Top-left corner of a w x h label around `anchor` at distance `gap` [px];
  // nullopt when not `required` and no position is free.
  std::optional<Point> place(Point anchor, double w, double h, double gap, bool required = true);

 private:
  double cost(const Box& b) const;
  Box area_;
  std::vector<Box> taken_;
};

}  // namespace squawk::viz
