#include "output/preview_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "output/figure_canvas.hpp"
#include "output/map_frame.hpp"

namespace hydrodda::output {

using geometry::Point;

namespace {

constexpr double kMarginLeft = 70, kMarginRight = 190, kMarginTop = 50, kMarginBottom = 80;
constexpr double kLegendHeight = 230;  // the tallest legend of a few materials and joint types
constexpr Rgb kBoundaryColour{0.0, 0.3, 0.75};

void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

geometry::Box preview_box(const PreviewFigure& f) {
  geometry::Box box;
  for (Point p : f.domain) box.add(p);
  for (const geometry::Polygon& b : f.blocks)
    for (Point p : b) box.add(p);
  return box;
}

Frame make_preview_frame(const geometry::Box& box, double width, double height) {
  Frame fr;
  fr.scale = std::min((width - kMarginLeft - kMarginRight) / box.width(), (height - kMarginTop - kMarginBottom) / box.height());
  fr.x0 = box.lo.x;
  fr.y0 = box.lo.y;
  fr.left = kMarginLeft + 0.5 * std::max(0.0, width - kMarginLeft - kMarginRight - box.width() * fr.scale);
  fr.bottom = kMarginTop + box.height() * fr.scale;
  return fr;
}

void trace_polygon(cairo_t* cr, const Frame& fr, const geometry::Polygon& p) {
  for (std::size_t i = 0; i < p.size(); ++i) cairo_line_to(cr, fr.px(p[i].x), fr.py(p[i].y));
  cairo_close_path(cr);
}

// Each block filled with its material's colour, a fixed one hatched, all outlined thin.
void draw_blocks(cairo_t* cr, const Frame& fr, const PreviewFigure& f) {
  for (std::size_t b = 0; b < f.blocks.size(); ++b) {
    set_colour(cr, material_colour(f.block_material[b]));
    trace_polygon(cr, fr, f.blocks[b]);
    cairo_fill(cr);
    if (!f.block_fixed.empty() && f.block_fixed[b]) {  // hatched: it never moves
      cairo_save(cr);
      trace_polygon(cr, fr, f.blocks[b]);
      cairo_clip(cr);
      double x0, y0, x1, y1;
      cairo_clip_extents(cr, &x0, &y0, &x1, &y1);
      cairo_set_source_rgba(cr, 0.2, 0.2, 0.2, 0.6);
      cairo_set_line_width(cr, 0.6);
      for (double x = x0 - (y1 - y0); x < x1; x += 6) {
        cairo_move_to(cr, x, y1);
        cairo_line_to(cr, x + (y1 - y0), y0);
      }
      cairo_stroke(cr);
      cairo_restore(cr);
    }
  }
  cairo_set_source_rgba(cr, 0.25, 0.25, 0.25, 0.8);
  cairo_set_line_width(cr, 0.4);
  for (const geometry::Polygon& b : f.blocks) {
    cairo_new_path(cr);
    trace_polygon(cr, fr, b);
    cairo_stroke(cr);
  }
  if (!f.domain.empty()) {
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.0);
    cairo_new_path(cr);
    trace_polygon(cr, fr, f.domain);
    cairo_stroke(cr);
  }
}

// A label on a white ground at (x, y): its middle there, or with align_x 0 (1) its left (right)
// end, turned by `angle`.
void draw_label(cairo_t* cr, const std::string& text, double x, double y, Rgb colour, double angle = 0.0,
                double align_x = 0.5) {
  const double w = text_width(cr, text) + 4, h = 11;
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
  cairo_rectangle(cr, -align_x * w, -0.5 * h, w, h);
  cairo_fill(cr);
  set_colour(cr, colour);
  draw_text(cr, text, (0.5 - align_x) * w, 0, 0.5, 0.5);
  cairo_restore(cr);
}

// The traces by joint type, and each fracture's id at the middle of its longest piece.
void draw_traces(cairo_t* cr, const Frame& fr, const PreviewFigure& f) {
  cairo_set_line_width(cr, 1.6);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  std::map<int, const PreviewFigure::Trace*> longest;  // by fracture id: ordered, so labels are drawn alike every time
  for (const PreviewFigure::Trace& t : f.traces) {
    set_colour(cr, joint_type_colour(t.joint_type));
    cairo_move_to(cr, fr.px(t.from.x), fr.py(t.from.y));
    cairo_line_to(cr, fr.px(t.to.x), fr.py(t.to.y));
    cairo_stroke(cr);
    const PreviewFigure::Trace*& held = longest[t.fracture];
    if (!held || geometry::distance(t.from, t.to) > geometry::distance(held->from, held->to)) held = &t;
  }
  cairo_set_font_size(cr, 8);
  for (const auto& [id, t] : longest) {
    const Point mid = 0.5 * (t->from + t->to);
    draw_label(cr, fmt::format("{}", id), fr.px(mid.x), fr.py(mid.y), joint_type_colour(t->joint_type));
  }
}

// Each boundary with a condition: a thick line along it, and its conditions in words just
// inside it (turned along a boundary that runs up or down the page).
void draw_boundaries(cairo_t* cr, const Frame& fr, const geometry::Box& box, const PreviewFigure& f) {
  cairo_set_font_size(cr, 9);
  for (const PreviewFigure::Boundary& b : f.boundaries) {
    set_colour(cr, kBoundaryColour, 0.8);
    cairo_set_line_width(cr, 3.5);
    cairo_move_to(cr, fr.px(b.from.x), fr.py(b.from.y));
    cairo_line_to(cr, fr.px(b.to.x), fr.py(b.to.y));
    cairo_stroke(cr);
    const Point mid = 0.5 * (b.from + b.to);
    const Point along = b.to - b.from;
    const bool upright = std::abs(along.y) > std::abs(along.x);
    // Inward: towards the box's centre, by half a line and a bit.
    const Point centre = 0.5 * (box.lo + box.hi);
    const double x = fr.px(mid.x), y = fr.py(mid.y);
    if (upright && text_width(cr, b.label) + 8 > std::abs(along.y) * fr.scale) {
      // Longer than the boundary is tall: across it, from its inner side.
      const bool left_side = centre.x > mid.x;
      draw_label(cr, b.label, x + (left_side ? 6.0 : -6.0), y, kBoundaryColour, 0.0, left_side ? 0.0 : 1.0);
      continue;
    }
    const double inward_x = upright ? (centre.x > mid.x ? 12.0 : -12.0) : 0.0;
    const double inward_y = upright ? 0.0 : (centre.y > mid.y ? -12.0 : 12.0);
    draw_label(cr, b.label, x + inward_x, y + inward_y, kBoundaryColour, upright ? -M_PI / 2 : 0.0);
  }
}

void draw_regions(cairo_t* cr, const Frame& fr, const PreviewFigure& f) {
  const double dashes[] = {5.0, 3.0};
  cairo_set_font_size(cr, 9);
  for (const PreviewFigure::Region& r : f.flow_regions) {
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.2);
    cairo_set_dash(cr, dashes, 2, 0.0);
    cairo_new_path(cr);
    trace_polygon(cr, fr, r.polygon);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    // At the region's top right corner, inside: the boundaries' labels stand at their middles.
    const geometry::Box b = geometry::bounding_box(r.polygon);
    draw_label(cr, "region " + r.name, fr.px(b.hi.x) - 30, fr.py(b.hi.y) + 10, {0.1, 0.1, 0.1}, 0.0, 1.0);
  }
}

enum class MarkerShape { triangle, circle, cross };

void draw_marker(cairo_t* cr, double x, double y, MarkerShape shape) {
  cairo_set_line_width(cr, 1.4);
  switch (shape) {
    case MarkerShape::triangle:
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_move_to(cr, x, y - 5);
      cairo_line_to(cr, x + 5, y + 4);
      cairo_line_to(cr, x - 5, y + 4);
      cairo_close_path(cr);
      cairo_fill(cr);
      break;
    case MarkerShape::circle:
      cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
      cairo_new_sub_path(cr);
      cairo_arc(cr, x, y, 4, 0, 2 * M_PI);
      cairo_fill(cr);
      break;
    case MarkerShape::cross:
      cairo_set_source_rgb(cr, 0.0, 0.45, 0.2);
      cairo_move_to(cr, x - 4, y - 4);
      cairo_line_to(cr, x + 4, y + 4);
      cairo_move_to(cr, x - 4, y + 4);
      cairo_line_to(cr, x + 4, y - 4);
      cairo_stroke(cr);
      break;
  }
}

void draw_markers(cairo_t* cr, const Frame& fr, const PreviewFigure& f) {
  cairo_set_font_size(cr, 9);
  const auto draw_all = [&](const std::vector<PreviewFigure::Marker>& markers, MarkerShape shape) {
    for (const PreviewFigure::Marker& m : markers) {
      const double x = fr.px(m.point.x), y = fr.py(m.point.y);
      draw_marker(cr, x, y, shape);
      if (m.name.empty()) continue;
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      draw_text(cr, m.name, x + 7, y - 7, 0.0, 0.5);
    }
  };
  draw_all(f.fixed_points, MarkerShape::triangle);
  draw_all(f.loads, MarkerShape::circle);
  draw_all(f.measures, MarkerShape::cross);
}

// The legend beside the plot: materials, joint types, the markers in use.
void draw_legend(cairo_t* cr, double x, double top, const PreviewFigure& f) {
  double y = top;
  const auto heading = [&](const std::string& text) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 10);
    draw_text(cr, text, x, y, 0.0, 0.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    y += 16;
  };
  const auto entry = [&](const std::string& text) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    draw_text(cr, text, x + 22, y + 5, 0.0, 0.5);
    y += 15;
  };
  heading("materials");
  for (std::size_t m = 0; m < f.materials.size(); ++m) {
    set_colour(cr, material_colour(static_cast<int>(m)));
    cairo_rectangle(cr, x, y, 16, 10);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_set_line_width(cr, 0.4);
    cairo_stroke(cr);
    entry(f.materials[m]);
  }
  if (std::find(f.block_fixed.begin(), f.block_fixed.end(), true) != f.block_fixed.end()) entry("(hatched: fixed)");
  if (!f.traces.empty()) {
    y += 6;
    heading("joint types");
    for (std::size_t j = 0; j < f.joint_types.size(); ++j) {
      set_colour(cr, joint_type_colour(static_cast<int>(j)));
      cairo_set_line_width(cr, 2.0);
      cairo_move_to(cr, x, y + 5);
      cairo_line_to(cr, x + 16, y + 5);
      cairo_stroke(cr);
      entry(f.joint_types[j]);
    }
  }
  const std::vector<std::pair<MarkerShape, std::string>> markers{
      {MarkerShape::triangle, f.fixed_points.empty() ? "" : "fixed point"},
      {MarkerShape::circle, f.loads.empty() ? "" : "point load"},
      {MarkerShape::cross, f.measures.empty() ? "" : "measured point"}};
  bool first = true;
  for (const auto& [shape, text] : markers) {
    if (text.empty()) continue;
    if (first) y += 6, heading("points"), first = false;
    draw_marker(cr, x + 8, y + 5, shape);
    entry(text);
  }
  if (!f.boundaries.empty()) {
    y += 6;
    heading("boundaries");
    set_colour(cr, kBoundaryColour, 0.8);
    cairo_set_line_width(cr, 3.5);
    cairo_move_to(cr, x, y + 5);
    cairo_line_to(cr, x + 16, y + 5);
    cairo_stroke(cr);
    entry("with a condition");
  }
}

void draw_titles(cairo_t* cr, double width, const PreviewFigure& f) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 14);
  const double title_width = text_width(cr, f.title);
  if (title_width > width - 20) cairo_set_font_size(cr, 14 * (width - 20) / title_width);
  draw_text(cr, f.title, 0.5 * width, 8, 0.5, 0.0);
  cairo_set_font_size(cr, 11);
  const double subtitle_width = text_width(cr, f.subtitle);
  if (subtitle_width > width - 20) cairo_set_font_size(cr, 11 * (width - 20) / subtitle_width);
  draw_text(cr, f.subtitle, 0.5 * width, 28, 0.5, 0.0);
}

void draw_preview(cairo_t* cr, double width, double height, const PreviewFigure& f) {
  const geometry::Box box = preview_box(f);
  const Frame fr = make_preview_frame(box, width, height);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  draw_blocks(cr, fr, f);
  draw_traces(cr, fr, f);
  draw_regions(cr, fr, f);
  draw_boundaries(cr, fr, box, f);
  draw_markers(cr, fr, f);
  draw_axes(cr, fr, box);
  draw_titles(cr, width, f);
  draw_legend(cr, fr.px(box.hi.x) + 25, fr.py(box.hi.y), f);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_font_size(cr, 10);
  draw_text(cr, f.note, fr.px(0.5 * (box.lo.x + box.hi.x)), fr.py(box.lo.y) + 50, 0.5, 0.0);
}

}  // namespace

void render_preview_figure(const std::filesystem::path& path, const PreviewFigure& figure) {
  // The page follows the domain's shape as the field figures' does.
  const double largest_width = 820, narrowest_width = 560, largest_height = 660;
  const geometry::Box box = preview_box(figure);
  const double largest_plot_height = largest_height - kMarginTop - kMarginBottom;
  const double tall_plot_width = box.height() > 0 ? largest_plot_height * box.width() / box.height() : largest_width;
  const double width = std::clamp(kMarginLeft + kMarginRight + tall_plot_width, narrowest_width, largest_width);
  const double plot_width = width - kMarginLeft - kMarginRight;
  const double plot_height = box.width() > 0 ? plot_width * box.height() / box.width() : plot_width;
  const double height = std::min(largest_height, kMarginTop + std::max(plot_height + kMarginBottom, kLegendHeight));
  draw_to_file(path, width, height, [&](cairo_t* cr) { draw_preview(cr, width, height, figure); });
}

}  // namespace hydrodda::output
