#pragma once
// The drawing surface every figure of a run is drawn on: PNG (at twice the resolution, for
// print), SVG or PDF by the file's extension, written under a temporary name and renamed like
// every file of the run folder. Only the figure files of this module include cairo.

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <string>

namespace hydrodda::output {

// Draws a width × height (points) page with `draw` into `path`. Throws std::runtime_error
// naming the path for an unknown extension or when the file cannot be written.
void draw_to_file(const std::filesystem::path& path, double width, double height,
                  const std::function<void(cairo_t*)>& draw);

// Text whose bounding box is placed at (x, y) by fractions of its width and height: (0, 0) puts
// its top-left corner there, (0.5, 0.5) its centre. `angle` rotates it about that point.
void draw_text(cairo_t* cr, const std::string& text, double x, double y, double align_x,
               double align_y, double angle = 0.0);

// Width of `text` in the current font.
double text_width(cairo_t* cr, const std::string& text);

}  // namespace hydrodda::output
