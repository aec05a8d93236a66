// The preview of `check --figure` (output/preview_figure.hpp): written in each format, of the
// page size the domain's shape gives, its blocks painted in their materials' colours.

#include "output/preview_figure.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace hydrodda::output {
namespace {

namespace fs = std::filesystem;

// Two materials side by side on a 20 m × 6 m domain, a trace, a boundary with a condition, a
// region and one point of each kind.
PreviewFigure make_two_material_preview() {
  PreviewFigure f;
  f.title = "two materials";
  f.subtitle = "preview: 1 trace, 2 blocks";
  f.note = "expected fluid mesh: about 5,300 triangles";
  f.domain = {{0, 0}, {20, 0}, {20, 6}, {0, 6}};
  f.blocks = {{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{10, 0}, {20, 0}, {20, 6}, {10, 6}}};
  f.block_material = {0, 1};
  f.block_fixed = {false, true};
  f.materials = {"sandstone", "mudrock"};
  f.traces = {{{10, 0}, {10, 6}, 0, 0}};
  f.joint_types = {"joint"};
  f.boundaries = {{{0, 0}, {20, 0}, "bottom: head = 125 m"}};
  f.flow_regions = {{{{2, 1}, {8, 1}, {8, 5}, {2, 5}}, "core"}};
  f.fixed_points = {{{20, 0}, ""}};
  f.loads = {{{5, 6}, "table"}};
  f.measures = {{{15, 3}, "A"}};
  return f;
}

// Pixels of a PNG whose colour is within 2 of `c` in each channel (0–255).
int count_pixels_of(const fs::path& png, Rgb c, int& width, int& height) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  width = cairo_image_surface_get_width(image);
  height = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const auto near = [](std::uint32_t channel, double want) { return std::abs(static_cast<double>(channel) - 255.0 * want) <= 2.0; };
  int count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint32_t pixel = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];  // ARGB32
      count += near((pixel >> 16) & 0xffu, c.r) && near((pixel >> 8) & 0xffu, c.g) && near(pixel & 0xffu, c.b) ? 1 : 0;
    }
  cairo_surface_destroy(image);
  return count;
}

TEST(PreviewFigure, PaintsEachMaterialInItsColourOnAPageOfTheDomainsShape) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-preview-figure";
  fs::create_directories(dir);
  render_preview_figure(dir / "p.png", make_two_material_preview());
  int width = 0, height = 0;
  const int sandstone = count_pixels_of(dir / "p.png", material_colour(0), width, height);
  const int mudrock = count_pixels_of(dir / "p.png", material_colour(1), width, height);
  // A 20 × 6 m domain: the widest page, 820 points, its plot 560 points wide and 168 high under
  // 50 of titles, 80 of axes and note: 298 points; the PNG at twice that.
  EXPECT_EQ(width, 2 * 820);
  EXPECT_EQ(height, 2 * 298);
  // Each block is 280 × 168 points (1120 × 672 pixels less the outlines, labels and marks on
  // it; the fixed one hatched): the free one mostly its colour, the fixed one a good part.
  EXPECT_GT(sandstone, 100'000);
  EXPECT_GT(mudrock, 20'000);
  EXPECT_NE(material_colour(0).r, material_colour(1).r);
  fs::remove_all(dir);
}

TEST(PreviewFigure, WritesSvgAndPdfAndRefusesAnUnknownFormat) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-preview-formats";
  fs::create_directories(dir);
  const PreviewFigure f = make_two_material_preview();
  render_preview_figure(dir / "p.pdf", f);
  render_preview_figure(dir / "p.svg", f);
  std::ifstream pdf(dir / "p.pdf", std::ios::binary);
  std::string start(5, '\0');
  pdf.read(start.data(), 5);
  EXPECT_EQ(start, "%PDF-");
  std::ifstream svg(dir / "p.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("</svg>"), std::string::npos);
  EXPECT_THROW(render_preview_figure(dir / "p.jpg", f), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hydrodda::output
