#include "run/figures.hpp"

#include <fmt/format.h>

#include "output/field_figure.hpp"
#include "output/plot_line.hpp"

namespace hydrodda::run {

void draw_figures(const scenario::Scenario& s, const output::RunFolder& folder, const FlowPicture& p) {
  if (s.output.figures.empty()) return;
  const std::filesystem::path dir = folder.figures();
  for (const std::string& format : s.output.figures) {
    output::FieldFigure head;
    head.title = s.title;
    head.field_label = "hydraulic head (m)";
    head.nodes = p.mesh.nodes;
    head.triangles = p.mesh.triangles;
    head.node_field = p.flow.head;
    head.blocks = p.blocks;
    head.element_flux = p.flow.flux;
    output::render_field_figure(dir / ("head." + format), head);

    output::FieldFigure map;
    map.nodes = p.mesh.nodes;
    map.triangles = p.mesh.triangles;
    map.blocks = p.blocks;
    if (!p.porosity.empty()) {
      map.title = "Equivalent porosity";
      map.field_label = "porosity";
      map.element_field = p.porosity;
      output::render_field_figure(dir / ("porosity." + format), map);
    }
    map.title = "Permeability";
    map.field_label = "permeability (m2, log scale)";
    map.element_field = p.permeability;
    map.logarithmic = true;
    output::render_field_figure(dir / ("permeability." + format), map);
  }
}

void draw_convergence(const scenario::Scenario& s, const output::RunFolder& folder, const ConvergenceHistory& h) {
  if (s.output.figures.empty() || h.iteration.empty()) return;
  output::LinePlotSpec plot;
  plot.title = "Convergence of the coupling loop";
  plot.x_label = "coupling iteration";
  plot.y_label = "relative change between iterations";
  plot.y_log = true;
  plot.series = {{"head", h.iteration, h.head_change}, {"block displacement", h.iteration, h.displacement_change}};
  plot.references = {{fmt::format("tolerance {:g}", h.tolerance), h.tolerance}};
  for (const std::string& format : s.output.figures)
    output::render_line_plot(folder.figures() / ("convergence." + format), plot);
}

}  // namespace hydrodda::run
