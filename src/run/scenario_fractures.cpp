#include "run/scenario_fractures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "output/item_list.hpp"
#include "run/model_geometry.hpp"

namespace hydrodda::run {

using fractures::FractureLayout;
using fractures::FractureMeter;
using fractures::WedgeTip;
using fractures::WedgeTipElement;

std::optional<FractureLayout> fracture_layout(const scenario::Scenario& s) {
  if (!s.geometry || s.geometry->domain.empty()) return std::nullopt;
  ModelGeometry model = build_model_geometry(s);
  return FractureLayout{std::move(model.traces), std::move(model.network)};
}

std::optional<std::string> describe_unresolved_wedge_tips(std::span<const WedgeTipElement> tips,
                                                          const scenario::MeshDefinition& mesh,
                                                          const output::RunFolder* folder) {
  const auto unresolved = [](const WedgeTipElement& e) { return !resolves_wedge_tip(e); };
  if (tips.empty() || !unresolved(tips.front())) return std::nullopt;
  const WedgeTipElement& worst = tips.front();
  const WedgeTip& tip = worst.tip;
  const std::string found = fmt::format(
      "fracture {} opens as a wedge from ({:.4g}, {:.4g}) at an angle of {:.3g}: with the cubic law the flow passes "
      "between its tip and the matrix over s* = sqrt(12 k_m / angle^3) = {:.3g} m, and the fluid element there is "
      "{:.2g} m across, more than half of that, so the effective conductivities depend on the mesh "
      "(docs/coupling.md, \"Wedge tips\"): ",
      tip.fracture, tip.point.x, tip.point.y, tip.opening_angle, tip.length, worst.element_size);
  const double quarter = 0.25 * tip.length;
  if (mesh.file)
    return found + fmt::format("refine the mesh file to {:.2g} m (s*/4) around the tip, or check them between two meshes",
                               quarter);
  std::vector<std::string> tables, to_paste;  // in the line; in the file, as TOML to paste
  for (const WedgeTipElement& e : tips)
    if (unresolved(e)) {
      const std::string point = fmt::format("[{:.5g}, {:.5g}]", e.tip.point.x, e.tip.point.y);
      const std::string size = fmt::format("{:.2g}", 0.25 * e.tip.length);
      tables.push_back(fmt::format("[[mesh.refine]] point = {}, size = {}", point, size));
      to_paste.push_back(fmt::format("[[mesh.refine]]\npoint = {}\nsize = {}\n", point, size));
    }
  std::string refine = fmt::format(
      "refine around {} (size s*/4): {}",
      tables.size() == 1 ? "the tip" : fmt::format("the {} unresolved tips", tables.size()),
      output::list_items(tables, folder, "unresolved_tips.toml", "; ", to_paste));
  if (!mesh.refine_tips) refine += "; or give mesh.refine_tips = true, and the run meshes again around them itself";
  if (worst.trace_distance <= mesh.fracture_size)
    return found + fmt::format("give mesh.fracture_size = {:.2g} m (s*/4), or {}", quarter, refine);
  return found + fmt::format(
                     "the blocks have carried the tip {:.2g} m from the fracture's trace, and mesh.fracture_size = {:g} "
                     "m refines the traces only, so a smaller one does not reach it: {}",
                     worst.trace_distance, mesh.fracture_size, refine);
}

std::optional<FractureMeter> make_fracture_meter(const scenario::Scenario& s) {
  std::optional<FractureLayout> layout = fracture_layout(s);
  if (!layout) return std::nullopt;
  const geometry::Box box = geometry::bounding_box(s.geometry->domain);
  return FractureMeter(std::move(*layout), std::max(box.width(), box.height()) / 50.0);
}

std::vector<scenario::MeshRefinePoint> refine_points(const std::vector<fractures::RefinedTip>& tips) {
  std::vector<scenario::MeshRefinePoint> points;
  for (const fractures::RefinedTip& t : tips) points.push_back({{t.x, t.y}, t.size, t.radius});
  return points;
}


std::function<double(double size)> default_refine_radius(const scenario::MeshDefinition& mesh) {
  return [mesh_size = mesh.size](double size) { return scenario::default_refine_radius(mesh_size, size); };
}

}  // namespace hydrodda::run
