// The figures plugin's entry points: the drawing functions of output/ (field_figure.cpp,
// plot_line.cpp, preview_figure.cpp over figure_canvas.cpp and map_frame.cpp), compiled into
// hydrodda_figures.so with Cairo.
#include "output/figures/figures_plugin.hpp"

void hydrodda_render_field_figure(const std::filesystem::path& path, const hydrodda::output::FieldFigure& figure) {
  hydrodda::output::render_field_figure(path, figure);
}

void hydrodda_render_line_plot(const std::filesystem::path& path, const hydrodda::output::LinePlotSpec& spec) {
  hydrodda::output::render_line_plot(path, spec);
}

void hydrodda_render_preview_figure(const std::filesystem::path& path, const hydrodda::output::PreviewFigure& figure) {
  hydrodda::output::render_preview_figure(path, figure);
}
