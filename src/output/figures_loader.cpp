// render_field_figure, render_line_plot and render_preview_figure through the figures plugin
// (figures/figures_plugin.cpp), loaded with dlopen the first time a figure is drawn: Cairo
// brings some twenty libraries (fontconfig, freetype, X11's) whose loading and symbol lookup
// took half of the CPU time of a run that draws nothing (docs/performance.md, "Start-up").
#include <dlfcn.h>

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
  const std::filesystem::path path = base::find_beside_program("hydrodda_figures.so", HYDRODDA_FIGURES);
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    throw std::runtime_error("cannot load the figure drawing '" + path.string() + "': " + (why ? why : "unknown error"));
  }
  Plugin plugin;
  plugin.field = reinterpret_cast<decltype(plugin.field)>(::dlsym(handle, "hydrodda_render_field_figure"));
  plugin.line = reinterpret_cast<decltype(plugin.line)>(::dlsym(handle, "hydrodda_render_line_plot"));
  plugin.preview = reinterpret_cast<decltype(plugin.preview)>(::dlsym(handle, "hydrodda_render_preview_figure"));
  if (!plugin.field || !plugin.line || !plugin.preview)
    throw std::runtime_error("the figure drawing '" + path.string() + "' lacks its entry points");
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
