#include "output/legend_placement.hpp"

#include <cmath>
#include <limits>

namespace hydrodda::output {

std::array<PageBox, 4> legend_corners(const PageBox& frame, double w, double h, double inset) {
  const double right = frame.x + frame.w - w - inset, left = frame.x + inset;
  const double top = frame.y + inset, bottom = frame.y + frame.h - h - inset;
  return {{{right, top, w, h}, {left, top, w, h}, {right, bottom, w, h}, {left, bottom, w, h}}};
}

LegendCorner choose_legend_corner(const std::array<PageBox, 4>& corners, std::span<const std::array<double, 2>> points,
                                  double margin) {
  LegendCorner best{0, std::numeric_limits<std::size_t>::max()};
  for (std::size_t c = 0; c < corners.size(); ++c) {
    std::size_t hidden = 0;
    for (const std::array<double, 2>& p : points) hidden += corners[c].holds(p[0], p[1], margin);
    if (hidden < best.hidden) best = {c, hidden};
  }
  return best;
}

double raise_axis_top(double lo, double data_top, double band, bool log_axis) {
  const double share = 1.0 - band;
  if (log_axis) return lo * std::pow(data_top / lo, 1.0 / share);
  return lo + (data_top - lo) / share;
}

}  // namespace hydrodda::output
