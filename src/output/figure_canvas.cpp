#include "output/figure_canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <fmt/format.h>

#include <stdexcept>

namespace hydrodda::output {

void draw_to_file(const std::filesystem::path& path, double width, double height,
                  const std::function<void(cairo_t*)>& draw) {
  const std::string ext = path.extension().string();
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  cairo_surface_t* surface = nullptr;
  if (ext == ".png")
    surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(width * 2), static_cast<int>(height * 2));
  else if (ext == ".svg")
    surface = cairo_svg_surface_create(temporary.c_str(), width, height);
  else if (ext == ".pdf")
    surface = cairo_pdf_surface_create(temporary.c_str(), width, height);
  else
    throw std::runtime_error(fmt::format("cannot draw {}: use .png, .svg or .pdf", path.string()));
  cairo_t* cr = cairo_create(surface);
  if (ext == ".png") cairo_scale(cr, 2.0, 2.0);  // 2× resolution for print
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw(cr);
  cairo_destroy(cr);
  cairo_status_t status = cairo_surface_status(surface);
  if (status == CAIRO_STATUS_SUCCESS && ext == ".png") status = cairo_surface_write_to_png(surface, temporary.c_str());
  cairo_surface_finish(surface);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), cairo_status_to_string(status)));
  }
  std::filesystem::rename(temporary, path);
}

void draw_text(cairo_t* cr, const std::string& text, double x, double y, double align_x, double align_y,
               double angle) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle);
  cairo_move_to(cr, -align_x * e.width - e.x_bearing, -align_y * e.height - e.y_bearing);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

}  // namespace hydrodda::output
