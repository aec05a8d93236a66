#pragma once
// Where a line plot's legend goes: in the corner of the frame whose box hides the fewest data
// points, and, when each corner's hides some, over a band the y axis is raised to leave free
// above the data: a legend never covers a value (the breach figure's last load, its range bar
// in the top right-hand corner, lay under it).

#include <array>
#include <cstddef>
#include <span>

namespace hydrodda::output {

// A box on the page, points; y grows downwards.
struct PageBox {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  // Inside the box grown by `margin` on every side.
  bool holds(double px, double py, double margin) const {
    return px > x - margin && px < x + w + margin && py > y - margin && py < y + h + margin;
  }
};

// The frame's inner corners for a w × h box set `inset` in from its edges, in the order tried:
// top right, top left, bottom right, bottom left.
std::array<PageBox, 4> legend_corners(const PageBox& frame, double w, double h, double inset);

// The first of the corners whose box (grown by `margin`) holds the fewest of the points, and
// how many it holds.
struct LegendCorner {
  std::size_t corner = 0;
  std::size_t hidden = 0;
};
LegendCorner choose_legend_corner(const std::array<PageBox, 4>& corners, std::span<const std::array<double, 2>> points,
                                  double margin);

// The top of a y axis from `lo` raised so that values up to `data_top` lie in its lowest
// 1 − `band` of the frame's height: data_top = lo + (1 − band)(hi − lo), on log10 of the
// values for a log axis. `band` in [0, 1).
double raise_axis_top(double lo, double data_top, double band, bool log_axis);

}  // namespace hydrodda::output
