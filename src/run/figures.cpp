#include "run/figures.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "output/field_figure.hpp"
#include "output/plot_line.hpp"

namespace hydrodda::run {

namespace {

// "coupling iteration 4" or nothing (flow-only run).
std::string state_of(const FlowPicture& p) {
  return p.iterations > 0 ? fmt::format(", coupling iteration {}", p.iterations) : std::string();
}

}  // namespace

void draw_figures(const scenario::Scenario& s, const output::RunFolder& folder, const FlowPicture& p) {
  if (s.output.figures.empty()) return;
  const std::filesystem::path dir = folder.figures();
  spdlog::debug("figures: drawing in {}", dir.string());
  const auto stop = [&p] { return p.stop_requested && p.stop_requested(); };
  for (const std::string& format : s.output.figures) {
    if (stop()) return;
    output::FieldFigure head;
    head.title = s.title;
    head.subtitle = "Hydraulic head and Darcy flux" + state_of(p);
    head.warning = p.status;
    head.field_label = "hydraulic head (m)";
    head.nodes = p.mesh.nodes;
    head.triangles = p.mesh.triangles;
    head.node_field = p.flow.head;
    head.blocks = p.blocks;
    head.element_flux = p.flow.flux;
    output::render_field_figure(dir / ("head." + format), head);

    output::FieldFigure map;
    map.title = s.title;
    map.warning = head.warning;
    map.nodes = p.mesh.nodes;
    map.triangles = p.mesh.triangles;
    map.blocks = p.blocks;
    map.faint_blocks = true;
    map.logarithmic = true;
    if (!p.porosity.empty() && !stop()) {
      map.subtitle = "Equivalent porosity" + state_of(p);
      map.field_label = "porosity (log scale)";
      map.element_field = p.porosity;
      output::render_field_figure(dir / ("porosity." + format), map);
    }
    map.subtitle = "Permeability" + state_of(p);
    map.field_label = "permeability (m², log scale)";
    map.element_field = p.permeability;
    if (stop()) return;
    output::render_field_figure(dir / ("permeability." + format), map);
  }
}

std::string describe_status_for_figures(const std::string& head, const std::string& message) {
  constexpr std::size_t kLine = 70;
  if (message.empty()) return head;
  std::string what = message.substr(0, message.find_first_of(":;"));
  if (what.size() > kLine) what = what.substr(0, kLine - 3) + "...";
  return head + ": " + what;
}

void draw_convergence(const scenario::Scenario& s, const output::RunFolder& folder, const ConvergenceHistory& h) {
  if (s.output.figures.empty() || h.iteration.empty()) return;
  output::LinePlotSpec plot;
  plot.title = s.title;
  plot.warning = h.status;
  plot.x_label = "coupling iteration";
  plot.y_label = "relative change between coupling iterations";
  plot.y_log = true;
  plot.series = {{"head", h.iteration, h.head_change, {}},
                 {"block displacement", h.iteration, h.displacement_change, {}}};
  plot.references = {{fmt::format("tolerance {:g}", h.tolerance), h.tolerance}};
  for (const std::string& format : s.output.figures)
    output::render_line_plot(folder.figures() / ("convergence." + format), plot);
}

}  // namespace hydrodda::run
