#include "output/field_figure.hpp"

#include "output/plot_axes.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <fstream>
#include <limits>

namespace hydrodda::output {
namespace {

namespace fs = std::filesystem;
using geometry::Point;

TEST(ContourSegment, LinearFieldContourLiesOnItsLevelLine) {
  // f = 2x + 3y + 1 is exact in P1: every contour point of level c satisfies 2x + 3y + 1 = c
  // to 1e-12.
  const std::array<Point, 3> p{Point{0.1, 0.2}, Point{1.3, 0.4}, Point{0.5, 1.7}};
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) v[i] = 2 * p[i].x + 3 * p[i].y + 1;
  for (double c : {2.0, 3.5, 5.0, 6.5}) {
    const auto seg = contour_segment(p, v, c);
    ASSERT_EQ(seg.size(), 2u) << c;
    for (Point q : seg) EXPECT_NEAR(2 * q.x + 3 * q.y + 1, c, 1e-12);
  }
  EXPECT_TRUE(contour_segment(p, v, 100.0).empty());
}

TEST(FieldFigure, WritesPngSvgAndPdf) {
  const std::vector<Point> nodes{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  FieldFigure f;
  f.title = "test";
  f.field_label = "head (m)";
  f.nodes = nodes;
  f.triangles = triangles;
  f.node_field = {0.0, 1.0, 1.0, 0.0};
  f.blocks = {{{0.1, 0.1}, {0.4, 0.1}, {0.4, 0.4}}};
  f.element_flux = {{-1.0, 0.0}, {-1.0, 0.0}};
  const fs::path dir = fs::temp_directory_path() / "hydrodda-figures";
  fs::create_directories(dir);
  const auto head = [](const fs::path& p, std::size_t n) {
    std::ifstream in(p, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), static_cast<std::streamsize>(n));
    return s;
  };
  render_field_figure(dir / "f.png", f);
  EXPECT_EQ(head(dir / "f.png", 8), std::string("\x89PNG\r\n\x1a\n", 8));
  render_field_figure(dir / "f.pdf", f);
  EXPECT_EQ(head(dir / "f.pdf", 5), "%PDF-");
  render_field_figure(dir / "f.svg", f);
  std::ifstream svg(dir / "f.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("</svg>"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "f.svg.tmp"));
  EXPECT_THROW(render_field_figure(dir / "f.jpg", f), std::runtime_error);
  fs::remove_all(dir);
}

// Pixels of the rectangle [x0, x1) × [y0, y1) of a PNG, in page points (the PNG is at twice the
// page's resolution), whose colour passes `is`.
template <class Is>
int pixels_in(const fs::path& png, int x0, int y0, int x1, int y1, Is&& is) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(image), stride = cairo_image_surface_get_stride(image);
  const int height = cairo_image_surface_get_height(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  int count = 0;
  for (int y = 2 * y0; y < std::min(2 * y1, height); ++y)
    for (int x = 2 * x0; x < std::min(2 * x1, width); ++x) {
      const std::uint32_t pixel = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];  // ARGB32
      count += is((pixel >> 16) & 0xffu, (pixel >> 8) & 0xffu, pixel & 0xffu) ? 1 : 0;
    }
  cairo_surface_destroy(image);
  return count;
}

// Red pixels (the warning's and the flux arrows' colour) in the rows [y0, y1) of a PNG, in page
// points.
int red_pixels_in_rows(const fs::path& png, int y0, int y1) {
  return pixels_in(png, 0, y0, std::numeric_limits<int>::max() / 4, y1,
                   [](unsigned r, unsigned g, unsigned b) { return r > 180 && g < 60 && b < 60; });
}

// Red pixels in the band above the plot, where the title and the line under it are drawn (the
// plot starts 50 points down).
int red_pixels_above_plot(const fs::path& png) { return red_pixels_in_rows(png, 0, 48); }

TEST(FieldFigure, AWarningIsWrittenInRedUnderTheTitle) {
  const std::vector<Point> nodes{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  FieldFigure f;
  f.title = "A case";
  f.subtitle = "Hydraulic head, coupling iteration 2";
  f.field_label = "head (m)";
  f.nodes = nodes;
  f.triangles = triangles;
  f.node_field = {0.0, 1.0, 1.0, 0.0};
  f.element_flux = {{-1.0, 0.0}, {-1.0, 0.0}};
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-figure-warning-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  render_field_figure(dir / "converged.png", f);
  f.warning = "NOT CONVERGED";
  render_field_figure(dir / "unconverged.png", f);
  EXPECT_EQ(red_pixels_above_plot(dir / "converged.png"), 0);
  EXPECT_GT(red_pixels_above_plot(dir / "unconverged.png"), 200);
  fs::remove_all(dir);
}

// A column 1 m wide and 10 m tall: drawn 53 points wide and 530 high (the largest height), on a
// page narrowed to 480 points rather than 760 with the column at one side; its x axis has
// three ticks (0, 0.5, 1) whose labels stand apart, where six (every 0.2 m) printed over one
// another. The tick marks are counted as runs of dark pixels just under the plot's frame
// (at 580 points down: 50 of margin and 530 of plot).
TEST(FieldFigure, ATallDomainHasANarrowPageAndReadableTicks) {
  const std::vector<Point> nodes{{0, 0}, {1, 0}, {1, 10}, {0, 10}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  FieldFigure f;
  f.title = "A column";
  f.field_label = "head (m)";
  f.nodes = nodes;
  f.triangles = triangles;
  f.node_field = {0.0, 0.0, 1.0, 1.0};
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-figure-tall-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path png = dir / "tall.png";
  render_field_figure(png, f);
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), 2 * 480);
  // The row 583 points down (2 × 583 in pixels), across the plot's width
  // (the column stands in the page's middle, from 188.5 to 241.5 points; the y axis's
  // labels end 8 points left of it).
  const int stride = cairo_image_surface_get_stride(image);
  const auto* row = reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(image) + 2 * 583 * stride);
  int ticks = 0;
  bool in_tick = false;
  for (int x = 2 * 185; x < 2 * 245; ++x) {
    const std::uint32_t pixel = row[x];  // ARGB32
    const bool dark = ((pixel >> 16) & 0xffu) < 100 && ((pixel >> 8) & 0xffu) < 100 && (pixel & 0xffu) < 100;
    ticks += dark && !in_tick;
    in_tick = dark;
  }
  cairo_surface_destroy(image);
  EXPECT_EQ(ticks, 3);
  fs::remove_all(dir);
}

// A 20 m × 2 m strip of 40 × 4 squares, each cut in two triangles: drawn 570 points wide and
// 57 high, from 70 points in and 50 down.
void make_flat_strip(std::vector<Point>& nodes, std::vector<std::array<int, 3>>& triangles) {
  const int nx = 40, ny = 4;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) nodes.push_back({20.0 * i / nx, 2.0 * j / ny});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
}

// A flat layer (20 m × 2 m, the shape of a seal) with a uniform upward flux: the arrows stay
// inside the plot (none reach the title band above it, where 8% of the width drew them 1.6 m
// long over a 2 m layer), and the key arrow under the colour bar is on the page (it fell off
// a page this flat).
TEST(FieldFigure, FluxArrowsStayInAFlatPlotAndTheKeyArrowIsOnThePage) {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  make_flat_strip(nodes, triangles);
  FieldFigure f;
  f.title = "A flat layer";
  f.field_label = "head (m)";
  f.nodes = nodes;
  f.triangles = triangles;
  for (Point p : nodes) f.node_field.push_back(2.0 - p.y);
  f.element_flux.assign(triangles.size(), Point{0.0, 1e-6});
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-figure-arrows-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  render_field_figure(dir / "flat.png", f);
  cairo_surface_t* image = cairo_image_surface_create_from_png((dir / "flat.png").c_str());
  const int page_height = cairo_image_surface_get_height(image) / 2;
  cairo_surface_destroy(image);
  // The plot is 570 points wide for 20 m: 57 points high, from 50 points down.
  EXPECT_EQ(red_pixels_in_rows(dir / "flat.png", 0, 48), 0);
  EXPECT_GT(red_pixels_in_rows(dir / "flat.png", 50, 107), 100);
  // The key arrow: under the 120-point colour bar that starts at the plot's top.
  EXPECT_GT(red_pixels_in_rows(dir / "flat.png", 50 + 120, page_height), 10);
  fs::remove_all(dir);
}


// An element field whose halves differ by a hundred-millionth (the cubic law's permeability
// over closed joints) is painted in one colour, as a uniform one is: the bar's bottom colour
// (viridis' dark purple) over the whole plot, none of its top colour (yellow). The same field
// with halves 1% apart paints the right half yellow, so the count does see a contrast.
TEST(FieldFigure, ASpreadOfRoundOffIsNotPaintedAsContrast) {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;
  make_flat_strip(nodes, triangles);
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-figure-spread-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto paint = [&](double relative_step, bool logarithmic) {
    FieldFigure f;
    f.title = "A uniform layer";
    f.field_label = "permeability (m²)";
    f.nodes = nodes;
    f.triangles = triangles;
    f.logarithmic = logarithmic;
    for (const auto& t : triangles) {
      const bool right = nodes[t[0]].x + nodes[t[1]].x + nodes[t[2]].x > 30.0;
      f.element_field.push_back(6.8587e-18 * (right ? 1.0 + relative_step : 1.0));
    }
    const fs::path png = dir / "spread.png";
    render_field_figure(png, f);
    // The plot is 570 points wide from 70 points in, 57 high from 50 down; its inside only.
    const auto yellow = [](unsigned r, unsigned g, unsigned b) { return r > 180 && g > 180 && b < 120; };
    // A field of one value is painted the middle of its bar, viridis(0.5), to ±6 of 255 a channel.
    const std::array<double, 3> middle = viridis(0.5);
    const auto teal = [&](unsigned r, unsigned g, unsigned b) {
      const auto near = [](unsigned got, double want) { return std::abs(static_cast<double>(got) - 255 * want) <= 6; };
      return near(r, middle[0]) && near(g, middle[1]) && near(b, middle[2]);
    };
    return std::pair{pixels_in(png, 72, 52, 638, 105, yellow), pixels_in(png, 72, 52, 638, 105, teal)};
  };
  for (bool logarithmic : {true, false}) {
    const auto [yellow, teal] = paint(1e-8, logarithmic);
    EXPECT_EQ(yellow, 0) << (logarithmic ? "log" : "linear");
    EXPECT_GT(teal, 100000) << (logarithmic ? "log" : "linear");
    EXPECT_GT(paint(1e-2, logarithmic).first, 50000) << (logarithmic ? "log" : "linear");
  }
  fs::remove_all(dir);
}

// Lines marked (cracks broken from the start, on a figure coloured by the load each bond broke
// at) are drawn black and set no part of the scale, which spans the highlighted lines' own values
// when it need not start at zero: the first crack of 1,100 and 1,200 is painted the bar's bottom
// colour (viridis' dark purple), where a scale from zero paints it a yellow-green (1100/1200 of
// the way up). Each count is the difference from the same figure unmarked, scaled from zero:
// the axes' text and the colour bar are the same in both.
TEST(FieldFigure, MarkedLinesAreBlackAndTheScaleSpansTheHighlightedOnes) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-figure-marked-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  FieldFigure f;
  f.title = "Cracks";
  f.field_label = "broke at the load";
  f.blocks = {{{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}}};
  f.segments = {{Point{1.0, 1.0}, Point{1.0, 9.0}}, {Point{4.0, 1.0}, Point{4.0, 9.0}}, {Point{7.0, 1.0}, Point{7.0, 9.0}}};
  f.segment_values = {0.0, 1100.0, 1200.0};
  f.segment_highlighted = {false, true, true};
  f.segment_marked = {true, false, false};
  f.lines_scale_from_zero = false;
  FieldFigure plain = f;
  plain.segment_marked.clear();
  plain.lines_scale_from_zero = true;
  render_field_figure(dir / "marked.png", f);
  render_field_figure(dir / "plain.png", plain);
  const auto black = [](unsigned r, unsigned g, unsigned b) { return r < 40 && g < 40 && b < 40; };
  const auto purple = [](unsigned r, unsigned g, unsigned b) { return r < 100 && g < 40 && b > 60; };
  const auto count = [&](const char* name, const auto& is) {
    return pixels_in(dir / name, 0, 0, std::numeric_limits<int>::max() / 4, std::numeric_limits<int>::max() / 4, is);
  };
  EXPECT_GT(count("marked.png", black) - count("plain.png", black), 1000);
  EXPECT_GT(count("marked.png", purple) - count("plain.png", purple), 1000);
  // With no line coloured (no bond broken after the start) there is no colour bar to read: none
  // of its top colour (viridis' yellow) is on the page, where the figure above has some.
  FieldFigure uncoloured = f;
  uncoloured.segment_highlighted = {false, false, false};
  render_field_figure(dir / "uncoloured.png", uncoloured);
  const auto yellow = [](unsigned r, unsigned g, unsigned b) { return r > 180 && g > 180 && b < 120; };
  EXPECT_GT(count("marked.png", yellow), 100);
  EXPECT_EQ(count("uncoloured.png", yellow), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hydrodda::output
