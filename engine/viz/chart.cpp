#include "viz/chart.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/text.h"
#include "viz/layout.h"

namespace squawk::viz {

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  const double raw = (hi - lo) / std::max(1, target);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

Axis axis(double lo, double hi, double pad, int target) {
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  const double margin = pad * (hi - lo);
  lo -= margin;
  hi += margin;
  const auto t = nice_ticks(lo, hi, target);
  const double step = t.size() > 1 ? t[1] - t[0] : hi - lo;
  Axis a;
  a.lo = std::floor(lo / step + 1e-9) * step;
  a.hi = std::ceil(hi / step - 1e-9) * step;
  for (double v = a.lo; v <= a.hi + 1e-9 * step; v += step) a.ticks.push_back(std::fabs(v) < 1e-12 * step ? 0.0 : v);
  return a;
}

void draw_panel(Svg& svg, const Panel& panel, double x0, double y0, double w, double h) {
  const double left = x0 + 62, right = x0 + w - 34, top = y0 + 30, bottom = y0 + h - 46;
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& s : panel.series)
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      xlo = std::min(xlo, s.x[i]);
      xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, s.y[i]);
      yhi = std::max(yhi, s.y[i]);
    }
  if (!std::isfinite(xlo)) xlo = 0, xhi = 1, ylo = 0, yhi = 1;
  if (xlo > 0) xlo = 0;  // x counts from 0 (episodes trained)
  if (!(xhi > xlo)) xhi = xlo + 1;
  // x ends 2 % past the last point, ticks inside; y ends on labelled ticks.
  const Axis ax{xlo, xhi + 0.02 * (xhi - xlo), nice_ticks(xlo, xhi + 0.02 * (xhi - xlo), 5)};
  const Axis ay = panel.fixed_y ? Axis{panel.ymin - 0.04 * (panel.ymax - panel.ymin),
                                       panel.ymax + 0.04 * (panel.ymax - panel.ymin),
                                       nice_ticks(panel.ymin, panel.ymax, 5)}
                                : axis(ylo, yhi, 0.04, 5);
  xlo = ax.lo, xhi = ax.hi, ylo = ay.lo, yhi = ay.hi;
  const auto& xt = ax.ticks;
  const auto& yt = ay.ticks;
  auto px = [&](double x) { return left + (x - xlo) / (xhi - xlo) * (right - left); };
  auto py = [&](double y) { return bottom - (y - ylo) / (yhi - ylo) * (bottom - top); };

  for (double t : yt) {
    svg.line({left, py(t)}, {right, py(t)}, "#dddddd", 1);
    svg.text({left - 6, py(t) + 4}, text::fmt_double(t, 3), 11, "end");
  }
  for (double t : xt) {
    svg.line({px(t), top}, {px(t), bottom}, "#eeeeee", 1);
    svg.text({px(t), bottom + 16}, text::fmt_double(t, 3), 11, "middle");
  }
  svg.rect({left, top}, right - left, bottom - top, "none", "black", 1);
  svg.text({(left + right) / 2, y0 + 18}, panel.title, 14, "middle", "black", 0, true);
  svg.text({(left + right) / 2, bottom + 36}, panel.xlabel, 12, "middle");
  svg.text({x0 + 16, (top + bottom) / 2}, panel.ylabel, 12, "middle", "black", -90);

  double ly = bottom - 10 - 16.0 * static_cast<double>(panel.series.size() - 1);  // legend, bottom right
  double legend_w = 0;
  for (const auto& s : panel.series) legend_w = std::max(legend_w, text_width(s.label, 11));
  const double lx = right - 10 - legend_w - 25;
  for (const auto& s : panel.series) {
    std::vector<Point> pts;
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) pts.push_back({px(s.x[i]), py(s.y[i])});
    svg.polyline(pts, s.colour, 2);
    if (pts.size() == 1) svg.circle(pts[0], 3, s.colour, s.colour);
    if (!s.label.empty()) {
      svg.line({lx, ly - 4}, {lx + 20, ly - 4}, s.colour, 2);
      svg.text({lx + 25, ly}, s.label, 11);
      ly += 16;
    }
  }
}

std::string panels_svg(const std::vector<Panel>& panels, double panel_w, double panel_h) {
  Svg svg(panel_w * static_cast<double>(std::max<size_t>(1, panels.size())), panel_h);
  for (size_t i = 0; i < panels.size(); ++i)
    draw_panel(svg, panels[i], panel_w * static_cast<double>(i), 0, panel_w, panel_h);
  return svg.str();
}

}  // namespace squawk::viz
