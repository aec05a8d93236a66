#pragma once
// The frame every map of the model is drawn in (the run's field figures, the preview of
// `check --figure`): world metres to page points, and the axes in metres around the domain.

#include <cairo.h>

#include <string>
#include <vector>

#include "geometry/polygon.hpp"

namespace hydrodda::output {

struct Frame {  // world (m) → page (points)
  double scale = 1.0, x0 = 0.0, y0 = 0.0, left = 0.0, bottom = 0.0;
  double px(double x) const { return left + (x - x0) * scale; }
  double py(double y) const { return bottom - (y - y0) * scale; }
};

// An axis tick's label: the value in its shortest form.
std::string tick_label(double v);

// An axis's ticks, as many as 6 and as few as two, spaced so that their labels stand apart.
std::vector<double> readable_ticks(cairo_t* cr, double lo, double hi, double page_per_metre, bool horizontal);

// The box around `box` with ticks in metres and the axes' names.
void draw_axes(cairo_t* cr, const Frame& fr, const geometry::Box& box);

}  // namespace hydrodda::output
