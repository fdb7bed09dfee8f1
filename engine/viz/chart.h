// Line charts as SVG (training curves like the paper's Fig. 3).
#pragma once

#include <string>
#include <vector>

#include "viz/svg.h"

namespace squawk::viz {

struct Series {
  std::string label;
  std::vector<double> x, y;  // equal length; non-finite points are skipped
  std::string colour = "#1f77b4";
};

struct Panel {
  std::string title, xlabel, ylabel;
  std::vector<Series> series;
  bool fixed_y = false;  // use [ymin, ymax] instead of the data range
  double ymin = 0, ymax = 1;
};

// Round tick values covering [lo, hi], about `target` of them (1-2-5 steps).
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

// An axis: [lo, hi] widened by `pad` x the range on each side (so that no
// point lies on the frame), then out to the enclosing round ticks, so both
// ends carry a labelled tick.
struct Axis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
};
Axis axis(double lo, double hi, double pad, int target = 5);

// Draws `panel` into the rectangle (x0, y0, w, h) of `svg`, axes and ticks
// included. x runs from 0 (or lower data) to 2 % past the last point; y is
// padded (fixed_y: 4 % around [ymin, ymax]) and ends on labelled ticks, so
// curves stay off the frame.
void draw_panel(Svg& svg, const Panel& panel, double x0, double y0, double w, double h);

// One SVG with the panels side by side, each panel_w x panel_h pixels.
std::string panels_svg(const std::vector<Panel>& panels, double panel_w = 460, double panel_h = 340);

}  // namespace squawk::viz
