#include "output/plot_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "output/figure_canvas.hpp"
#include "output/legend_placement.hpp"
#include "output/plot_axes.hpp"

namespace hydrodda::output {
namespace {

// Okabe–Ito colours, told apart by colour-blind readers; each series also gets its own marker
// so the plot survives printing in grey.
constexpr double kPalette[][3] = {{0.000, 0.447, 0.698}, {0.835, 0.369, 0.000}, {0.000, 0.620, 0.451},
                                  {0.800, 0.475, 0.655}, {0.902, 0.624, 0.000}, {0.337, 0.706, 0.914},
                                  {0.0, 0.0, 0.0}};
constexpr int kMarkers = 4;  // circle, square, triangle, diamond

bool is_plottable(double v, bool log_axis) { return std::isfinite(v) && (!log_axis || v > 0.0); }

bool is_open(const LineSeries& s, std::size_t i) { return !s.open.empty() && s.open[i]; }

// A capped vertical bar from y_low to y_high (page coordinates) in the current colour.
void draw_range_bar(cairo_t* cr, double x, double y_low, double y_high) {
  const double cap = 3.0;
  cairo_set_line_width(cr, 1.4);
  cairo_move_to(cr, x, y_low);
  cairo_line_to(cr, x, y_high);
  cairo_move_to(cr, x - cap, y_low);
  cairo_line_to(cr, x + cap, y_low);
  cairo_move_to(cr, x - cap, y_high);
  cairo_line_to(cr, x + cap, y_high);
  cairo_stroke(cr);
}

bool has_open_point(const LinePlotSpec& spec) {
  return std::any_of(spec.series.begin(), spec.series.end(), [](const LineSeries& s) {
    return std::find(s.open.begin(), s.open.end(), true) != s.open.end();
  });
}

// One axis: data value → page coordinate, linear or log10.
struct Axis {
  double lo, hi, page_lo, page_hi;
  bool log;
  double to_page(double v) const {
    const double t = log ? std::log10(v / lo) / std::log10(hi / lo) : (v - lo) / (hi - lo);
    return page_lo + t * (page_hi - page_lo);
  }
};

// The axis over the data range (padded_range, plot_axes.hpp) from page_lo to page_hi.
Axis make_axis(double lo, double hi, bool log_axis, double page_lo, double page_hi, bool at_least_zero = false) {
  const std::array<double, 2> range = padded_range(lo, hi, log_axis, at_least_zero);
  return {range[0], range[1], page_lo, page_hi, log_axis};
}

// A filled marker, or (open) a larger hollow one: white inside, outlined in the current colour.
void draw_marker(cairo_t* cr, int kind, double x, double y, bool open = false) {
  const double r = open ? 3.4 : 2.6;
  cairo_new_sub_path(cr);
  switch (kind % kMarkers) {
    case 0: cairo_arc(cr, x, y, r, 0.0, 2.0 * std::numbers::pi); break;
    case 1: cairo_rectangle(cr, x - 0.9 * r, y - 0.9 * r, 1.8 * r, 1.8 * r); break;
    case 2:
      cairo_move_to(cr, x, y - 1.2 * r);
      cairo_line_to(cr, x + 1.1 * r, y + 0.8 * r);
      cairo_line_to(cr, x - 1.1 * r, y + 0.8 * r);
      cairo_close_path(cr);
      break;
    default:
      cairo_move_to(cr, x, y - 1.3 * r);
      cairo_line_to(cr, x + 1.1 * r, y);
      cairo_line_to(cr, x, y + 1.3 * r);
      cairo_line_to(cr, x - 1.1 * r, y);
      cairo_close_path(cr);
  }
  if (!open) {
    cairo_fill(cr);
    return;
  }
  cairo_pattern_t* colour = cairo_get_source(cr);
  cairo_pattern_reference(colour);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_fill_preserve(cr);
  cairo_set_source(cr, colour);
  cairo_pattern_destroy(colour);
  cairo_set_line_width(cr, 1.3);
  cairo_stroke(cr);
}

// A decade label 10^e with a raised exponent; returns its width.
double draw_power_of_ten(cairo_t* cr, int e, double x, double y, double align_x, bool measure_only = false) {
  const std::string base = "10", exponent = fmt::format("{}", e);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  const double size = font.ascent + font.descent;
  const double base_w = text_width(cr, base);
  cairo_matrix_t m;
  cairo_get_font_matrix(cr, &m);
  cairo_set_font_size(cr, 0.7 * m.xx);
  const double exp_w = text_width(cr, exponent);
  const double width = base_w + exp_w + 0.5;
  if (!measure_only) {
    const double left = x - align_x * width;
    draw_text(cr, exponent, left + base_w + 0.5, y - 0.45 * size, 0.0, 0.5);
    cairo_set_font_matrix(cr, &m);
    draw_text(cr, base, left, y, 0.0, 0.5);
  }
  cairo_set_font_matrix(cr, &m);
  return width;
}

// "×10⁻⁸": the factor a linear axis's labels leave out.
std::string format_scale(int exponent) {
  static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = exponent < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return " (×10" + text + ")";
}

// The ticks of one axis and their labels. Linear axes whose values are very large or small
// label v / 10^scale and name the factor in the axis title, so labels stay short.
struct TickLabels {
  std::vector<double> major, minor;
  std::vector<std::string> text;  // per major tick; empty for a power of ten (drawn as 10^e)
  int scale = 0;
};

TickLabels make_tick_labels(const Axis& a) {
  TickLabels t;
  t.major = a.log ? log_ticks(a.lo, a.hi) : nice_ticks(a.lo, a.hi, 6);
  if (a.log && t.major.size() >= 2 && t.major[1] / t.major[0] < 11.0)
    for (double d = t.major[0] / 10.0; d < a.hi; d *= 10.0)
      for (int m = 2; m <= 9; ++m)
        if (m * d > a.lo && m * d < a.hi) t.minor.push_back(m * d);
  const double step = t.major.size() >= 2 ? t.major[1] - t.major[0] : 1.0;
  const double largest = std::max(std::abs(a.lo), std::abs(a.hi));
  if (!a.log && (largest >= 1e5 || largest < 1e-3)) t.scale = static_cast<int>(std::floor(std::log10(largest)));
  const double factor = std::pow(10.0, t.scale);
  if (a.log) {
    t.text = log_tick_labels(t.major);
  } else {
    for (double v : t.major) t.text.push_back(format_tick(v / factor, step / factor));
  }
  return t;
}

// Draws (or only measures) the label of major tick i; returns its width.
double draw_tick_label(cairo_t* cr, const TickLabels& t, std::size_t i, double x, double y, bool horizontal,
                       bool measure_only = false) {
  if (t.text[i].empty()) {
    const int e = static_cast<int>(std::lround(std::log10(t.major[i])));
    return horizontal ? draw_power_of_ten(cr, e, x, y + 5.0, 0.5, measure_only)
                      : draw_power_of_ten(cr, e, x, y, 1.0, measure_only);
  }
  if (!measure_only) {
    if (horizontal)
      draw_text(cr, t.text[i], x, y, 0.5, 0.0);
    else
      draw_text(cr, t.text[i], x, y, 1.0, 0.5);
  }
  return text_width(cr, t.text[i]);
}

double measure_widest_label(cairo_t* cr, const TickLabels& t) {
  double widest = 0.0;
  for (std::size_t i = 0; i < t.major.size(); ++i)
    widest = std::max(widest, draw_tick_label(cr, t, i, 0.0, 0.0, false, true));
  return widest;
}

// Ticks of one axis with their labels and light grid lines.
void draw_ticks(cairo_t* cr, const Axis& a, const TickLabels& t, bool horizontal, double frame_lo, double frame_hi) {
  const auto line = [&](double v, double length) {
    const double p = a.to_page(v);
    if (horizontal) {
      cairo_move_to(cr, p, frame_lo);
      cairo_line_to(cr, p, frame_lo - length);
    } else {
      cairo_move_to(cr, frame_lo, p);
      cairo_line_to(cr, frame_lo + length, p);
    }
  };
  // Grid first, under everything else.
  cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
  cairo_set_line_width(cr, 0.5);
  for (double v : t.major) line(v, std::abs(frame_hi - frame_lo));
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 0.7);
  for (double v : t.major) line(v, 4.0);
  for (double v : t.minor) line(v, 2.0);
  cairo_stroke(cr);
  const double gap = 6.0;
  for (std::size_t i = 0; i < t.major.size(); ++i) {
    const double p = a.to_page(t.major[i]);
    if (horizontal)
      draw_tick_label(cr, t, i, p, frame_lo + gap, true);
    else
      draw_tick_label(cr, t, i, frame_lo - gap, p, false);
  }
}

// A cross of half-width r: a point with no value.
void draw_cross(cairo_t* cr, double x, double y, double r = 3.4) {
  cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
  cairo_set_line_width(cr, 1.6);
  cairo_move_to(cr, x - r, y - r);
  cairo_line_to(cr, x + r, y + r);
  cairo_move_to(cr, x - r, y + r);
  cairo_line_to(cr, x + r, y - r);
  cairo_stroke(cr);
}

// The legend's rows (named series, then the open markers', the range bars' and the crosses'
// entries where shown) and its box's size.
struct LegendSize {
  int rows = 0;
  double w = 0.0, h = 0.0;
  bool open_row = false, range_row = false, marks_row = false;
};
constexpr double kLegendRow = 13.0, kLegendInset = 8.0, kLegendMargin = 4.0;

LegendSize measure_legend(cairo_t* cr, const LinePlotSpec& spec) {
  LegendSize legend;
  double text_w = 0.0;
  const auto add_row = [&](const std::string& text) {
    text_w = std::max(text_w, text_width(cr, text));
    ++legend.rows;
  };
  for (const LineSeries& s : spec.series)
    if (!s.name.empty()) add_row(s.name);
  legend.open_row = !spec.open_label.empty() && has_open_point(spec);
  if (legend.open_row) add_row(spec.open_label);
  legend.range_row = !spec.range_label.empty() && !spec.range_bars.empty();
  if (legend.range_row) add_row(spec.range_label);
  legend.marks_row = !spec.marks_label.empty() && !spec.marks_x.empty();
  if (legend.marks_row) add_row(spec.marks_label);
  legend.w = text_w + 36.0;
  legend.h = kLegendRow * legend.rows + 6.0;
  return legend;
}

// Where the data lie on the page: each point, and each range bar's ends and middle.
std::vector<std::array<double, 2>> data_on_page(const LinePlotSpec& spec, const Axis& x, const Axis& y) {
  std::vector<std::array<double, 2>> points;
  for (const RangeBar& bar : spec.range_bars)
    if (is_plottable(bar.x, x.log) && is_plottable(bar.low, y.log) && is_plottable(bar.high, y.log))
      for (const double v : {bar.low, bar.high, y.log ? std::sqrt(bar.low * bar.high) : 0.5 * (bar.low + bar.high)})
        points.push_back({x.to_page(bar.x), y.to_page(v)});
  for (const LineSeries& s : spec.series)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (is_plottable(s.x[i], x.log) && is_plottable(s.y[i], y.log))
        points.push_back({x.to_page(s.x[i]), y.to_page(s.y[i])});
  return points;
}

// The legend's box: the corner of the frame that hides the fewest data points.
PageBox place_legend(const LinePlotSpec& spec, const LegendSize& legend, const Axis& x, const Axis& y) {
  const PageBox frame{x.page_lo, y.page_hi, x.page_hi - x.page_lo, y.page_lo - y.page_hi};
  const std::array<PageBox, 4> corners = legend_corners(frame, legend.w, legend.h, kLegendInset);
  return corners[choose_legend_corner(corners, data_on_page(spec, x, y), kLegendMargin).corner];
}

bool hides_data(const LinePlotSpec& spec, const PageBox& box, const Axis& x, const Axis& y) {
  for (const std::array<double, 2>& p : data_on_page(spec, x, y))
    if (box.holds(p[0], p[1], kLegendMargin)) return true;
  return false;
}

void draw_legend(cairo_t* cr, const LinePlotSpec& spec, const LegendSize& legend, const PageBox& box) {
  const bool open_row = legend.open_row, range_row = legend.range_row, marks_row = legend.marks_row;
  const double row = kLegendRow, w = legend.w, h = legend.h;
  const double bx = box.x, by = box.y;
  cairo_rectangle(cr, bx, by, w, h);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.92);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
  cairo_set_line_width(cr, 0.5);
  cairo_stroke(cr);
  int r = 0;
  for (std::size_t k = 0; k < spec.series.size(); ++k) {
    if (spec.series[k].name.empty()) continue;
    const double y = by + 3.0 + row * (r++ + 0.5);
    const double* c = kPalette[k % std::size(kPalette)];
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_set_line_width(cr, 1.4);
    cairo_move_to(cr, bx + 6.0, y);
    cairo_line_to(cr, bx + 26.0, y);
    cairo_stroke(cr);
    draw_marker(cr, static_cast<int>(k), bx + 16.0, y);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    draw_text(cr, spec.series[k].name, bx + 31.0, y, 0.0, 0.5);
  }
  if (open_row) {
    const double y = by + 3.0 + row * (r++ + 0.5);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    draw_marker(cr, 0, bx + 16.0, y, true);
    draw_text(cr, spec.open_label, bx + 31.0, y, 0.0, 0.5);
  }
  if (range_row) {
    const double y = by + 3.0 + row * (r++ + 0.5);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    draw_range_bar(cr, bx + 16.0, y + 4.5, y - 4.5);
    draw_text(cr, spec.range_label, bx + 31.0, y, 0.0, 0.5);
  }
  if (marks_row) {
    const double y = by + 3.0 + row * (r + 0.5);
    draw_cross(cr, bx + 16.0, y, 3.0);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    draw_text(cr, spec.marks_label, bx + 31.0, y, 0.0, 0.5);
  }
}

}  // namespace

void render_line_plot(const std::filesystem::path& path, const LinePlotSpec& spec) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const LineSeries& s : spec.series) {
    if (s.x.size() != s.y.size() || (!s.open.empty() && s.open.size() != s.x.size()))
      throw std::invalid_argument(fmt::format("line plot {}: series '{}' has {} x, {} y and {} open values",
                                              path.string(), s.name, s.x.size(), s.y.size(), s.open.size()));
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!is_plottable(s.x[i], spec.x_log) || !is_plottable(s.y[i], spec.y_log)) continue;
      xlo = std::min(xlo, s.x[i]);
      xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, s.y[i]);
      yhi = std::max(yhi, s.y[i]);
    }
  }
  for (double mark : spec.marks_x)
    if (is_plottable(mark, spec.x_log)) {
      xlo = std::min(xlo, mark);
      xhi = std::max(xhi, mark);
    }
  for (const RangeBar& bar : spec.range_bars) {
    if (bar.series >= spec.series.size())
      throw std::invalid_argument(fmt::format("line plot {}: a range bar of series {} of {}", path.string(), bar.series,
                                              spec.series.size()));
    if (!is_plottable(bar.x, spec.x_log) || !is_plottable(bar.low, spec.y_log) || !is_plottable(bar.high, spec.y_log))
      continue;
    xlo = std::min(xlo, bar.x);
    xhi = std::max(xhi, bar.x);
    ylo = std::min(ylo, bar.low);
    yhi = std::max(yhi, bar.high);
  }
  if (!(xlo <= xhi)) throw std::invalid_argument(fmt::format("line plot {}: nothing to plot", path.string()));
  if (!(ylo <= yhi)) ylo = spec.y_log ? 0.1 : 0.0, yhi = 1.0;  // crosses alone
  for (const ReferenceLine& r : spec.references)
    if (is_plottable(r.y, spec.y_log)) {
      ylo = std::min(ylo, r.y);
      yhi = std::max(yhi, r.y);
    }

  draw_to_file(path, spec.width, spec.height, [&](cairo_t* cr) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 9.5);
    const double top = (spec.title.empty() ? 14.0 : 32.0) + (spec.warning.empty() ? 0.0 : 14.0);
    const double bottom = spec.height - 42.0;
    // The left margin holds the widest y label and the y title beside it, so the x axis
    // follows the y axis.
    const double right = spec.width - 18.0;
    const auto x_axis_beside = [&](const Axis& y_axis, double& widest_label) {
      widest_label = measure_widest_label(cr, make_tick_labels(y_axis));
      return make_axis(xlo, xhi, spec.x_log, std::max(48.0, widest_label + 32.0), right);
    };
    double widest = 0.0;
    Axis y = make_axis(ylo, yhi, spec.y_log, bottom, top, spec.y_at_least_zero);
    Axis x = x_axis_beside(y, widest);
    // A legend that would hide data in every corner gets a band above the data instead.
    const LegendSize legend = measure_legend(cr, spec);
    PageBox legend_box = legend.rows > 0 ? place_legend(spec, legend, x, y) : PageBox{};
    const double band = (legend.h + kLegendInset + 2.0 * kLegendMargin) / (bottom - top);
    if (legend.rows > 0 && band < 0.5 && hides_data(spec, legend_box, x, y)) {
      y.hi = raise_axis_top(y.lo, yhi, band, spec.y_log);
      x = x_axis_beside(y, widest);
      legend_box = place_legend(spec, legend, x, y);
    }
    const double left = x.page_lo;
    const TickLabels y_ticks = make_tick_labels(y);
    const TickLabels x_ticks = make_tick_labels(x);
    draw_ticks(cr, x, x_ticks, true, bottom, top);
    draw_ticks(cr, y, y_ticks, false, left, right);

    // Series and reference lines, clipped to the frame.
    cairo_save(cr);
    cairo_rectangle(cr, left, top, right - left, bottom - top);
    cairo_clip(cr);
    const double dash[] = {5.0, 3.0};
    for (const ReferenceLine& r : spec.references) {
      if (!is_plottable(r.y, spec.y_log)) continue;
      cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
      cairo_set_line_width(cr, 1.0);
      cairo_set_dash(cr, dash, 2, 0.0);
      cairo_move_to(cr, left, y.to_page(r.y));
      cairo_line_to(cr, right, y.to_page(r.y));
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0.0);
      draw_text(cr, r.name, right - 6.0, y.to_page(r.y) - 3.0, 1.0, 1.0);
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (std::size_t k = 0; k < spec.series.size(); ++k) {
      const LineSeries& s = spec.series[k];
      const double* c = kPalette[k % std::size(kPalette)];
      cairo_set_source_rgb(cr, c[0], c[1], c[2]);
      cairo_set_line_width(cr, 1.4);
      bool pen_down = false;
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (is_open(s, i)) continue;  // off the line, which joins its neighbours
        const bool ok = is_plottable(s.x[i], spec.x_log) && is_plottable(s.y[i], spec.y_log);
        if (ok && pen_down) cairo_line_to(cr, x.to_page(s.x[i]), y.to_page(s.y[i]));
        if (ok && !pen_down) cairo_move_to(cr, x.to_page(s.x[i]), y.to_page(s.y[i]));
        pen_down = ok;
      }
      cairo_stroke(cr);
      for (std::size_t i = 0; i < s.x.size(); ++i)
        if (is_plottable(s.x[i], spec.x_log) && is_plottable(s.y[i], spec.y_log))
          draw_marker(cr, static_cast<int>(k), x.to_page(s.x[i]), y.to_page(s.y[i]), is_open(s, i));
    }
    for (const RangeBar& bar : spec.range_bars) {
      if (!is_plottable(bar.x, spec.x_log) || !is_plottable(bar.low, spec.y_log) || !is_plottable(bar.high, spec.y_log))
        continue;
      const double* c = kPalette[bar.series % std::size(kPalette)];
      cairo_set_source_rgb(cr, c[0], c[1], c[2]);
      draw_range_bar(cr, x.to_page(bar.x), y.to_page(bar.low), y.to_page(bar.high));
    }
    cairo_restore(cr);

    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 0.8);
    cairo_rectangle(cr, left, top, right - left, bottom - top);
    cairo_stroke(cr);
    for (double mark : spec.marks_x)
      if (is_plottable(mark, spec.x_log)) draw_cross(cr, x.to_page(mark), bottom);
    if (legend.rows > 0) draw_legend(cr, spec, legend, legend_box);

    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_font_size(cr, 10.5);
    const std::string x_title = spec.x_label + (x_ticks.scale ? format_scale(x_ticks.scale) : "");
    const std::string y_title = spec.y_label + (y_ticks.scale ? format_scale(y_ticks.scale) : "");
    draw_text(cr, x_title, 0.5 * (left + right), bottom + 24.0, 0.5, 0.0);
    draw_text(cr, y_title, left - widest - 12.0, 0.5 * (top + bottom), 0.5, 1.0, -std::numbers::pi / 2);
    if (!spec.title.empty()) {
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
      cairo_set_font_size(cr, 11.5);
      const double title_width = text_width(cr, spec.title);
      // 4% to spare: the hinted glyphs drawn at the PNG's resolution run wider than measured.
      const double room = 0.96 * (spec.width - 16.0);
      if (title_width > room) cairo_set_font_size(cr, 11.5 * room / title_width);
      draw_text(cr, spec.title, 0.5 * spec.width, 10.0, 0.5, 0.0);
    }
    if (!spec.warning.empty()) {
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
      cairo_set_font_size(cr, 10.0);
      // A run's status may be long: shrunk to the page, as the title is.
      const double warning_width = text_width(cr, spec.warning), room = 0.96 * (spec.width - 16.0);
      if (warning_width > room) cairo_set_font_size(cr, 10.0 * room / warning_width);
      cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
      draw_text(cr, spec.warning, 0.5 * spec.width, spec.title.empty() ? 10.0 : 26.0, 0.5, 0.0);
    }
  });
}

}  // namespace hydrodda::output
