#include "output/field_figure.hpp"

#include <fmt/format.h>

#include "output/figure_canvas.hpp"
#include "output/map_frame.hpp"
#include "output/plot_axes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <stdexcept>

namespace hydrodda::output {

using geometry::Point;

namespace {


constexpr double kMarginLeft = 70, kMarginRight = 120, kMarginTop = 50, kMarginBottom = 60;
constexpr double kMinColourBarHeight = 120;  // room for a colour bar's ticks under a flat domain
constexpr double kKeyArrowRoom = 45;         // under the colour bar: the key arrow and its value
constexpr double kArrowCells = 30;           // flux arrows: grid cells along the larger side

geometry::Box figure_box(const FieldFigure& f) {
  geometry::Box box;
  for (Point p : f.nodes) box.add(p);
  for (const auto& b : f.blocks)
    for (Point p : b) box.add(p);
  for (const auto& s : f.segments)
    for (Point p : s) box.add(p);
  return box;
}

// Elements with an edge on the mesh's boundary (an edge no other element shares).
std::vector<bool> touches_boundary(std::span<const std::array<int, 3>> triangles) {
  std::map<std::pair<int, int>, int> edge_count;
  const auto edge = [](int a, int b) { return std::pair(std::min(a, b), std::max(a, b)); };
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) ++edge_count[edge(t[i], t[(i + 1) % 3])];
  std::vector<bool> out(triangles.size(), false);
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int i = 0; i < 3; ++i)
      if (edge_count[edge(triangles[k][i], triangles[k][(i + 1) % 3])] == 1) out[k] = true;
  return out;
}

Frame make_frame(const geometry::Box& box, double width, double height) {
  Frame fr;
  fr.scale = std::min((width - kMarginLeft - kMarginRight) / box.width(),
                      (height - kMarginTop - kMarginBottom) / box.height());
  fr.x0 = box.lo.x;
  fr.y0 = box.lo.y;
  // A domain narrower than the page (a tall one) stands in its middle, with its colour bar.
  fr.left = kMarginLeft + 0.5 * std::max(0.0, width - kMarginLeft - kMarginRight - box.width() * fr.scale);
  fr.bottom = kMarginTop + box.height() * fr.scale;
  return fr;
}

// The values painted (log10 of the field's on a log scale) and the colour scale's ends.
struct ColourScale {
  bool per_node = false;    // a node field (else an element field, or lines only)
  bool lines_only = false;  // no field on the mesh: the lines carry the values
  std::vector<double> values;
  double lo = 0.0, hi = 1.0;
  bool clipped_above = false;  // values above `hi` are painted the top colour
  bool colours_nothing = false;  // lines only, none of them coloured: no colour bar to read
  std::optional<double> one_value;  // every value this one (to a millionth): the bar's one tick
  std::array<double, 3> colour(double v) const { return viridis((v - lo) / (hi - lo)); }
};

bool is_set(const std::vector<bool>& flags, std::size_t i) { return i < flags.size() && flags[i]; }

// Whether line i is painted its value's colour: highlighted and not marked (black).
bool is_coloured(const FieldFigure& f, std::size_t i) {
  return is_set(f.segment_highlighted, i) && !is_set(f.segment_marked, i);
}

// The range of lines only: on a log scale, or where it need not start at zero, of the highlighted
// ones only; else from zero.
void range_lines(const FieldFigure& f, ColourScale& s) {
  if (f.logarithmic || !f.lines_scale_from_zero) {
    // The lines drawn grey (e.g. joints without an aperture) or black (marked) set no range.
    double highlighted_lo = std::numeric_limits<double>::infinity(), highlighted_hi = -highlighted_lo;
    for (std::size_t i = 0; i < s.values.size(); ++i)
      if (is_coloured(f, i)) {
        highlighted_lo = std::min(highlighted_lo, s.values[i]);
        highlighted_hi = std::max(highlighted_hi, s.values[i]);
      }
    if (highlighted_lo <= highlighted_hi) {
      s.lo = highlighted_lo;
      s.hi = highlighted_hi;
    }
  } else {
    s.lo = std::min(s.lo, 0.0);  // lines carry sizes (apertures): the scale starts at zero
  }
}

ColourScale make_colour_scale(const FieldFigure& f) {
  ColourScale s;
  s.per_node = !f.node_field.empty();
  s.lines_only = f.node_field.empty() && f.element_field.empty();
  s.values = s.per_node ? f.node_field : s.lines_only ? f.segment_values : f.element_field;
  if (f.logarithmic)
    for (double& v : s.values) v = std::log10(std::max(v, 1e-300));
  s.lo = s.values.empty() ? 0.0 : *std::min_element(s.values.begin(), s.values.end());
  s.hi = s.values.empty() ? 1.0 : *std::max_element(s.values.begin(), s.values.end());
  if (s.lines_only) {
    range_lines(f, s);
    s.colours_nothing = true;
    for (std::size_t i = 0; i < f.segments.size(); ++i)
      if (is_coloured(f, i)) s.colours_nothing = false;
  }
  // An element field's scale ends at the largest value inside the mesh: elements on its
  // boundary, where the blocks part from the fixed domain edge, hold gaps far wider than the
  // joints' and would leave the joints the colour of intact rock. Values above are painted
  // the top colour, and the colour bar ends in a triangle to say so.
  if (!s.per_node && !s.lines_only) {
    const std::vector<bool> on_boundary = touches_boundary(f.triangles);
    double inside_hi = -std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < s.values.size(); ++t)
      if (!on_boundary[t]) inside_hi = std::max(inside_hi, s.values[t]);
    if (inside_hi > s.lo && inside_hi < s.hi) {
      s.hi = inside_hi;
      s.clipped_above = true;
    }
  }
  // A spread below a millionth of the values is no contrast to paint across the whole bar
  // (the cubic law's permeability over closed joints is uniform to 1e-8): such a field is
  // shown as one of a single value is, in the bar's middle colour, with one tick naming it: a bar
  // that started at the value would paint it the bottom colour, and ticks printed to six figures
  // over a unit of a load of 2.1281e7 Pa would all read alike.
  const double spread_of_one_value =
      f.logarithmic ? std::log10(1.0 + 1e-6) : 1e-6 * std::max(std::abs(s.lo), std::abs(s.hi));
  if (!(s.hi - s.lo > spread_of_one_value)) {
    const double largest = s.values.empty() ? s.hi : *std::max_element(s.values.begin(), s.values.end());
    s.one_value = s.lo;
    const std::array<double, 2> unit = one_value_range(s.lo, f.logarithmic);
    s.lo = unit[0];
    s.hi = unit[1];
    s.clipped_above = largest > s.hi;
  }
  return s;
}

// Elements: flat colour of the element (mean of nodes for a node field), painted from the
// smallest value up, so that the thin, high-valued elements along a joint are not covered
// by their neighbours' seam hairlines.
void paint_elements(cairo_t* cr, const Frame& fr, const FieldFigure& f, const ColourScale& s) {
  const auto element_value = [&](std::size_t t) {
    const auto& tri = f.triangles[t];
    return s.per_node ? (s.values[tri[0]] + s.values[tri[1]] + s.values[tri[2]]) / 3.0 : s.values[t];
  };
  std::vector<std::size_t> paint_order(f.triangles.size());
  for (std::size_t t = 0; t < paint_order.size(); ++t) paint_order[t] = t;
  if (!s.per_node)
    std::stable_sort(paint_order.begin(), paint_order.end(),
                     [&](std::size_t a, std::size_t b) { return element_value(a) < element_value(b); });
  for (std::size_t t : paint_order) {
    const auto& tri = f.triangles[t];
    const auto c = s.colour(element_value(t));
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_move_to(cr, fr.px(f.nodes[tri[0]].x), fr.py(f.nodes[tri[0]].y));
    cairo_line_to(cr, fr.px(f.nodes[tri[1]].x), fr.py(f.nodes[tri[1]].y));
    cairo_line_to(cr, fr.px(f.nodes[tri[2]].x), fr.py(f.nodes[tri[2]].y));
    cairo_close_path(cr);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);  // hairline in the same colour hides anti-aliasing seams
  }
}

// Head contours: white lines at `contour_levels` levels evenly between the scale's ends.
void draw_contours(cairo_t* cr, const Frame& fr, const FieldFigure& f, const ColourScale& s) {
  if (!s.per_node || f.contour_levels <= 0 || f.logarithmic) return;
  cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
  cairo_set_line_width(cr, 0.8);
  for (int k = 1; k <= f.contour_levels; ++k) {
    const double level = s.lo + (s.hi - s.lo) * k / (f.contour_levels + 1);
    for (const auto& tri : f.triangles) {
      const auto seg = contour_segment({f.nodes[tri[0]], f.nodes[tri[1]], f.nodes[tri[2]]},
                                       {f.node_field[tri[0]], f.node_field[tri[1]], f.node_field[tri[2]]}, level);
      if (seg.empty()) continue;
      cairo_move_to(cr, fr.px(seg[0].x), fr.py(seg[0].y));
      cairo_line_to(cr, fr.px(seg[1].x), fr.py(seg[1].y));
    }
    cairo_stroke(cr);
  }
}

// Blocks: filled light grey under coloured lines, so that the lines stand out; outlined.
void draw_blocks(cairo_t* cr, const Frame& fr, const FieldFigure& f) {
  if (!f.segments.empty()) {
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    for (const auto& b : f.blocks) {
      for (std::size_t i = 0; i < b.size(); ++i) cairo_line_to(cr, fr.px(b[i].x), fr.py(b[i].y));
      cairo_close_path(cr);
      cairo_fill(cr);
    }
  }
  if (f.faint_blocks) {
    cairo_set_source_rgba(cr, 0.6, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 0.4);
  } else {
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, f.segments.empty() ? 1.2 : 0.4);
  }
  for (const auto& b : f.blocks) {
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (i == 0) cairo_move_to(cr, fr.px(b[i].x), fr.py(b[i].y));
      else cairo_line_to(cr, fr.px(b[i].x), fr.py(b[i].y));
    }
    cairo_close_path(cr);
    cairo_stroke(cr);
  }
}

// Coloured lines: the highlighted ones thick over the others, and the marked ones thick in black
// over both.
void draw_segments(cairo_t* cr, const Frame& fr, const FieldFigure& f, const ColourScale& s) {
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (int pass = 0; pass < 3; ++pass)
    for (std::size_t i = 0; i < f.segments.size(); ++i) {
      const bool marked = is_set(f.segment_marked, i);
      const bool highlighted = is_coloured(f, i);
      if (pass != (marked ? 2 : highlighted ? 1 : 0)) continue;
      const auto c = s.colour(s.lines_only ? s.values[i] : f.segment_values[i]);
      if (marked) cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
      else if (highlighted) cairo_set_source_rgb(cr, c[0], c[1], c[2]);
      else cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
      cairo_set_line_width(cr, marked || highlighted ? 3.0 : 1.0);
      cairo_move_to(cr, fr.px(f.segments[i][0].x), fr.py(f.segments[i][0].y));
      cairo_line_to(cr, fr.px(f.segments[i][1].x), fr.py(f.segments[i][1].y));
      cairo_stroke(cr);
    }
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

// An arrow of page length `len` centred on (xc, yc), along the flux q.
void draw_arrow(cairo_t* cr, double xc, double yc, Point q, double len) {
  const double m = geometry::norm(q);
  const double ux = q.x / m, uy = -q.y / m;  // page y points down
  const double x0 = xc - 0.5 * len * ux, y0 = yc - 0.5 * len * uy;
  const double x1 = x0 + len * ux, y1 = y0 + len * uy;
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  const double head = std::min(6.0, 0.35 * len);
  cairo_move_to(cr, x1, y1);
  cairo_line_to(cr, x1 - head * (ux * 0.87 - uy * 0.5), y1 - head * (uy * 0.87 + ux * 0.5));
  cairo_move_to(cr, x1, y1);
  cairo_line_to(cr, x1 - head * (ux * 0.87 + uy * 0.5), y1 - head * (uy * 0.87 - ux * 0.5));
  cairo_stroke(cr);
}

// The flux arrows' key: the largest flux and the page length of its arrow (0 without fluxes).
struct ArrowKey {
  double q_max = 0.0;
  double full = 0.0;
};

// Flux arrows: length ∝ |q|; under 1% of the largest hidden, as the paper's Fig. 6. The
// arrows are thinned to one per cell of a square grid, kArrowCells cells along the domain's
// larger side, each cell showing its largest flux; the largest arrow is 0.9 of a cell, so
// that neighbours do not overlap on a flat layer (8% of the width drew 1.6 m arrows over a
// 6 m seal). They are clipped to the plot.
ArrowKey draw_flux_arrows(cairo_t* cr, const Frame& fr, const geometry::Box& box, const FieldFigure& f) {
  ArrowKey key;
  const double cell = std::max(box.width(), box.height()) / kArrowCells;
  key.full = 0.9 * cell * fr.scale;
  if (f.element_flux.empty()) return key;
  for (Point q : f.element_flux) key.q_max = std::max(key.q_max, geometry::norm(q));
  const int nx = static_cast<int>(box.width() / cell) + 1, ny = static_cast<int>(box.height() / cell) + 1;
  std::vector<long> largest(static_cast<std::size_t>(nx) * ny, -1);
  const auto centroid = [&](std::size_t t) {
    const auto& tri = f.triangles[t];
    return (f.nodes[tri[0]] + f.nodes[tri[1]] + f.nodes[tri[2]]) / 3.0;
  };
  for (std::size_t t = 0; t < f.triangles.size() && key.q_max > 0.0; ++t) {
    if (geometry::norm(f.element_flux[t]) < 0.01 * key.q_max) continue;
    const Point c = centroid(t);
    const int gx = std::clamp(static_cast<int>((c.x - box.lo.x) / cell), 0, nx - 1);
    const int gy = std::clamp(static_cast<int>((c.y - box.lo.y) / cell), 0, ny - 1);
    long& slot = largest[static_cast<std::size_t>(gy) * nx + gx];
    if (slot < 0 || geometry::norm(f.element_flux[t]) > geometry::norm(f.element_flux[slot])) slot = static_cast<long>(t);
  }
  cairo_save(cr);
  cairo_rectangle(cr, fr.px(box.lo.x), fr.py(box.hi.y), box.width() * fr.scale, box.height() * fr.scale);
  cairo_clip(cr);
  cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
  cairo_set_line_width(cr, 1.1);
  for (long t : largest) {
    if (t < 0) continue;
    const Point c = centroid(static_cast<std::size_t>(t));
    draw_arrow(cr, fr.px(c.x), fr.py(c.y), f.element_flux[t], key.full * geometry::norm(f.element_flux[t]) / key.q_max);
  }
  cairo_restore(cr);
  return key;
}

// One line centred at height y in a font of `size`, shrunk to the page when it is longer (a
// run's status in a subtitle may be long).
void draw_line_within(cairo_t* cr, const std::string& line, double width, double size, double y) {
  cairo_set_font_size(cr, size);
  const double line_width = text_width(cr, line);
  if (line_width > width - 20) cairo_set_font_size(cr, size * (width - 20) / line_width);
  draw_text(cr, line, 0.5 * width, y, 0.5, 0.0);
  cairo_set_font_size(cr, 11);
}

// Title, then the quantity, or a warning in red: each shrunk to the page when long.
void draw_titles(cairo_t* cr, double width, const FieldFigure& f) {
  draw_line_within(cr, f.title, width, 14, 8);
  if (!f.warning.empty()) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_source_rgb(cr, 0.8, 0.0, 0.0);
    draw_line_within(cr, f.subtitle.empty() ? f.warning : f.subtitle + ": " + f.warning, width, 11, 28);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  } else if (!f.subtitle.empty()) {
    draw_line_within(cr, f.subtitle, width, 11, 28);
  }
}

// Where the colour bar stands on the page.
struct ColourBar {
  double x = 0.0, top = 0.0, height = 0.0;
};

// The bar's 200 bands, its frame, and the triangle atop it when values go beyond its top.
void paint_colour_bar(cairo_t* cr, const ColourBar& bar, bool clipped_above) {
  for (int i = 0; i < 200; ++i) {
    const auto c = viridis(1.0 - i / 199.0);
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_rectangle(cr, bar.x, bar.top + bar.height * i / 200.0, 16, bar.height / 200.0 + 0.6);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, bar.x, bar.top, 16, bar.height);
  cairo_stroke(cr);
  if (clipped_above) {  // values above the bar's top: a triangle in the top colour
    const auto c = viridis(1.0);
    cairo_move_to(cr, bar.x, bar.top);
    cairo_line_to(cr, bar.x + 8, bar.top - 12);
    cairo_line_to(cr, bar.x + 16, bar.top);
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_stroke(cr);
  }
}

// The bar's ticks and labels, then the field's label just beside the tick labels.
void label_colour_bar(cairo_t* cr, const ColourBar& bar, const FieldFigure& f, const ColourScale& s) {
  cairo_set_font_size(cr, 10);
  double widest_tick = 0.0;
  // A log bar is ticked at values (decades, or 1, 2, 5 times them over a short range), placed
  // at their log10, and labelled with the value itself.
  std::vector<double> ticks = f.whole_numbers ? whole_number_ticks(s.lo, s.hi, 6) : nice_ticks(s.lo, s.hi, 6);
  if (f.logarithmic) {
    ticks.clear();
    for (double v : log_ticks(std::pow(10.0, s.lo), std::pow(10.0, s.hi))) ticks.push_back(std::log10(v));
  }
  if (s.one_value) ticks = {*s.one_value};
  for (double v : ticks) {
    const double y = bar.top + bar.height * (1.0 - (v - s.lo) / (s.hi - s.lo));
    if (y < bar.top - 0.5 || y > bar.top + bar.height + 0.5) continue;
    cairo_move_to(cr, bar.x + 16, y);
    cairo_line_to(cr, bar.x + 20, y);
    cairo_stroke(cr);
    const std::string label = f.logarithmic ? fmt::format("{:.3g}", std::pow(10.0, v)) : tick_label(v);
    widest_tick = std::max(widest_tick, text_width(cr, label));
    draw_text(cr, label, bar.x + 23, y, 0.0, 0.5);
  }
  cairo_set_font_size(cr, 11);
  draw_text(cr, f.field_label, bar.x + 23 + widest_tick + 6, bar.top + 0.5 * bar.height, 0.5, 0.0, -M_PI / 2);
}

// The key arrow under the colour bar: the largest flux's length, and its value.
void draw_arrow_key(cairo_t* cr, const ColourBar& bar, const ArrowKey& key, const std::string& unit) {
  if (!(key.q_max > 0.0)) return;
  const double key_y = bar.top + bar.height + 28;
  cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
  cairo_set_line_width(cr, 1.1);
  draw_arrow(cr, bar.x + 0.5 * key.full, key_y, {1.0, 0.0}, key.full);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 10);
  draw_text(cr, fmt::format("{:.3g} {}", key.q_max, unit), bar.x, key_y + 8, 0.0, 0.0);
}

void draw_figure(cairo_t* cr, double width, double height, const FieldFigure& f) {
  const geometry::Box box = figure_box(f);
  const Frame fr = make_frame(box, width, height);
  const ColourScale scale = make_colour_scale(f);
  paint_elements(cr, fr, f, scale);
  draw_contours(cr, fr, f, scale);
  draw_blocks(cr, fr, f);
  draw_segments(cr, fr, f, scale);
  const ArrowKey key = draw_flux_arrows(cr, fr, box, f);
  draw_axes(cr, fr, box);
  draw_titles(cr, width, f);
  const ColourBar bar{fr.px(box.hi.x) + 25, fr.py(box.hi.y), std::max(box.height() * fr.scale, kMinColourBarHeight)};
  if (!scale.colours_nothing) {
    paint_colour_bar(cr, bar, scale.clipped_above);
    label_colour_bar(cr, bar, f, scale);
  }
  draw_arrow_key(cr, bar, key, f.flux_unit);
}

}  // namespace

void render_field_figure(const std::filesystem::path& path, const FieldFigure& figure) {
  // The page follows the domain's shape: a wide, flat layer gets a short page rather than a
  // strip above a blank one; a tall domain is held to the largest height, on a narrower page
  // (down to one that holds a title) rather than beside a blank one.
  const double largest_width = 760, narrowest_width = 480, largest_height = 640;
  const geometry::Box box = figure_box(figure);
  const double largest_plot_height = largest_height - kMarginTop - kMarginBottom;
  const double tall_plot_width =
      box.height() > 0 ? largest_plot_height * box.width() / box.height() : largest_width;
  const double width =
      std::clamp(kMarginLeft + kMarginRight + tall_plot_width, narrowest_width, largest_width);
  const double plot_width = width - kMarginLeft - kMarginRight;
  const double plot_height = box.width() > 0 ? plot_width * box.height() / box.width() : plot_width;
  const double height = std::min(
      largest_height, kMarginTop + std::max(plot_height + kMarginBottom,
                                            kMinColourBarHeight + 15 + (figure.element_flux.empty() ? 0 : kKeyArrowRoom)));
  draw_to_file(path, width, height, [&](cairo_t* cr) { draw_figure(cr, width, height, figure); });
}

}  // namespace hydrodda::output
