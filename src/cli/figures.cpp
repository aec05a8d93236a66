#include "cli/figures.hpp"

#include "output/field_figure.hpp"

namespace hydrodda::cli {

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

}  // namespace hydrodda::cli
