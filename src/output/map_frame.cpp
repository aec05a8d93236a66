#include "output/map_frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "output/figure_canvas.hpp"
#include "output/plot_axes.hpp"

namespace hydrodda::output {

std::string tick_label(double v) { return fmt::format("{:g}", v); }

// An axis's ticks, as many as 6 and as few as two, spaced so that their labels stand apart:
// the width of a 1 m column beside its 10 m height printed six labels over one another.
std::vector<double> readable_ticks(cairo_t* cr, double lo, double hi, double page_per_metre, bool horizontal) {
  constexpr double kGap = 8, kLineHeight = 11;
  std::vector<double> ticks;
  for (int count = 6; count >= 1; --count) {
    ticks = nice_ticks(lo, hi, count);
    if (ticks.size() < 3) return ticks;
    double room = kLineHeight + kGap;
    if (horizontal)
      for (double v : ticks) room = std::max(room, text_width(cr, tick_label(v)) + kGap);
    if ((ticks[1] - ticks[0]) * page_per_metre >= room) return ticks;
  }
  return ticks;
}

// Axes with ticks in metres.
void draw_axes(cairo_t* cr, const Frame& fr, const geometry::Box& box) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, fr.px(box.lo.x), fr.py(box.hi.y), box.width() * fr.scale, box.height() * fr.scale);
  cairo_stroke(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 11);
  // Ticks reach a hair beyond the box, so that a domain whose blocks moved a few microns in from
  // its edge (0.00001 to 5.99999 m) is still ticked at 0 and 6.
  const double reach = 1e-3 * std::max(box.width(), box.height());
  for (double x : readable_ticks(cr, box.lo.x - reach, box.hi.x + reach, fr.scale, true)) {
    cairo_move_to(cr, fr.px(x), fr.py(box.lo.y));
    cairo_line_to(cr, fr.px(x), fr.py(box.lo.y) + 5);
    cairo_stroke(cr);
    draw_text(cr, tick_label(x), fr.px(x), fr.py(box.lo.y) + 8, 0.5, 0.0);
  }
  for (double y : readable_ticks(cr, box.lo.y - reach, box.hi.y + reach, fr.scale, false)) {
    cairo_move_to(cr, fr.px(box.lo.x), fr.py(y));
    cairo_line_to(cr, fr.px(box.lo.x) - 5, fr.py(y));
    cairo_stroke(cr);
    draw_text(cr, tick_label(y), fr.px(box.lo.x) - 8, fr.py(y), 1.0, 0.5);
  }
  draw_text(cr, "x (m)", fr.px(0.5 * (box.lo.x + box.hi.x)), fr.py(box.lo.y) + 28, 0.5, 0.0);
  draw_text(cr, "y (m)", fr.px(box.lo.x) - 48, fr.py(0.5 * (box.lo.y + box.hi.y)), 0.5, 0.5, -M_PI / 2);
}

}  // namespace hydrodda::output
