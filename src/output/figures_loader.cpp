// render_field_figure, render_line_plot and render_preview_figure through the figures plugin
// (figures/figures_plugin.cpp), loaded with dlopen the first time a figure is drawn: Cairo
// brings some twenty libraries (fontconfig, freetype, X11's) whose loading and symbol lookup
// took half of the CPU time of a run that draws nothing (docs/performance.md, "Start-up").

#include <mutex>
#include <stdexcept>
#include <string>

#include "base/program_files.hpp"
#include "output/figures/figures_plugin.hpp"

namespace hydrodda::output {
namespace {

struct Plugin {
  decltype(&hydrodda_render_field_figure) field = nullptr;
  decltype(&hydrodda_render_line_plot) line = nullptr;
  decltype(&hydrodda_render_preview_figure) preview = nullptr;
};

// Beside the executable, else where the build made it. Loaded once, never unloaded.
Plugin load_plugin() {
  const base::Plugin library("hydrodda_figures.so", HYDRODDA_FIGURES, "the figure drawing");
  Plugin plugin;
  plugin.field = library.entry<decltype(plugin.field)>("hydrodda_render_field_figure");
  plugin.line = library.entry<decltype(plugin.line)>("hydrodda_render_line_plot");
  plugin.preview = library.entry<decltype(plugin.preview)>("hydrodda_render_preview_figure");
  return plugin;
}

const Plugin& plugin() {
  static const Plugin loaded = load_plugin();
  return loaded;
}

}  // namespace

void render_field_figure(const std::filesystem::path& path, const FieldFigure& figure) { plugin().field(path, figure); }

void render_line_plot(const std::filesystem::path& path, const LinePlotSpec& spec) { plugin().line(path, spec); }

void render_preview_figure(const std::filesystem::path& path, const PreviewFigure& figure) {
  plugin().preview(path, figure);
}

}  // namespace hydrodda::output
