#pragma once
// The entry points of the figures plugin (figures_plugin.cpp with the drawing code of
// output/, built as hydrodda_figures.so), which figures_loader.cpp looks up by name. Only
// they are visible outside the plugin. Cairo and the libraries it loads (fontconfig,
// freetype, X11's) are the plugin's alone: a run that draws no figure does not load them.

#include <filesystem>

#include "output/field_figure.hpp"
#include "output/plot_line.hpp"
#include "output/preview_figure.hpp"

extern "C" {
__attribute__((visibility("default"))) void hydrodda_render_field_figure(const std::filesystem::path& path,
                                                                         const hydrodda::output::FieldFigure& figure);
__attribute__((visibility("default"))) void hydrodda_render_line_plot(const std::filesystem::path& path,
                                                                      const hydrodda::output::LinePlotSpec& spec);
__attribute__((visibility("default"))) void hydrodda_render_preview_figure(const std::filesystem::path& path,
                                                                           const hydrodda::output::PreviewFigure& figure);
}
