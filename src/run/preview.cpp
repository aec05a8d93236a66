#include "run/preview.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <vector>

#include "mesh/mesh_estimate.hpp"
#include "run/model_building.hpp"
#include "run/model_geometry.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::run {

namespace {

// A number in its unit, Pa as kPa, MPa or GPa where that reads shorter.
std::string format_in_unit(double v, const std::string& unit) {
  if (unit == "Pa") {
    for (const auto& [scale, name] : {std::pair{1e9, "GPa"}, std::pair{1e6, "MPa"}, std::pair{1e3, "kPa"}})
      if (std::abs(v) >= scale) return fmt::format("{:g} {}", v / scale, name);
  }
  return fmt::format("{:g} {}", v, unit);
}

// The conditions on each named boundary, in words, in the scenario's order.
std::map<std::string, std::vector<std::string>> describe_boundary_conditions(const scenario::Scenario& s) {
  std::map<std::string, std::vector<std::string>> said;
  if (s.flow)
    for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) {
      const std::string unit = bc.kind == hydro::BoundaryKind::head ? "m" : bc.kind == hydro::BoundaryKind::pressure ? "Pa" : "m/s";
      said[bc.name].push_back(fmt::format("{} = {}", scenario::spell(bc.kind), describe_load(bc.value, unit)));
    }
  if (s.mechanics) {
    for (const scenario::RollerDefinition& r : s.mechanics->rollers) said[r.boundary].push_back("roller");
    for (const scenario::Traction& t : s.mechanics->tractions) {
      std::string text = "traction " + describe_load(t.normal, "Pa");
      if (!(t.normal_end == t.normal)) text += " to " + describe_load(t.normal_end, "Pa");
      if (!(t.shear.is_constant() && t.shear.value(0.0) == 0.0 && t.shear_end == t.shear))
        text += ", shear " + describe_load(t.shear, "Pa");
      said[t.boundary].push_back(text);
    }
    for (const scenario::PrescribedDisplacement& d : s.mechanics->displacements)
      if (!d.boundary.empty()) said[d.boundary].push_back(fmt::format("displaced ({:g}, {:g}) m", d.value.x, d.value.y));
  }
  return said;
}

void add_boundaries(const scenario::Scenario& s, output::PreviewFigure& figure) {
  const std::map<std::string, std::vector<std::string>> said = describe_boundary_conditions(s);
  for (const scenario::BoundarySegment& b : s.boundaries) {
    const auto found = said.find(b.name);
    if (found == said.end()) continue;
    std::string label = b.name + ":";
    for (std::size_t i = 0; i < found->second.size(); ++i) label += (i == 0 ? " " : "; ") + found->second[i];
    figure.boundaries.push_back({b.segment.from, b.segment.to, label});
  }
}

void add_points(const scenario::Scenario& s, output::PreviewFigure& figure) {
  if (s.flow)
    for (const scenario::FlowRegion& r : s.flow->regions) figure.flow_regions.push_back({r.polygon, r.name});
  if (!s.mechanics) return;
  for (const scenario::FixedPoint& f : s.mechanics->fixed) figure.fixed_points.push_back({f.point, ""});
  for (const scenario::PointLoad& l : s.mechanics->loads)
    figure.loads.push_back({l.point, l.force.is_constant()
                                         ? fmt::format("({:g}, {:g}) N/m", l.force.value(0, 0), l.force.value(0, 1))
                                         : "table"});
  for (const scenario::MeasurePoint& m : s.mechanics->measures) figure.measures.push_back({m.point, m.name});
}

// The mesh a run would make or read, in words.
std::string describe_expected_mesh(const scenario::Scenario& s) {
  if (!s.flow) return "no [flow]: no fluid mesh";
  if (s.mesh && s.mesh->file) return "fluid mesh: read from " + s.mesh->file->filename().string();
  if (!s.mesh || !s.geometry || s.geometry->domain.empty()) return "";
  const mesh::MeshRequest request = make_mesh_request(s);
  const mesh::TriangleEstimate estimate = mesh::estimate_triangle_count(request);
  // A planar triangulation has about half as many nodes as triangles (Euler's formula).
  const auto rounded = [](double n) {  // two significant digits, thousands apart: "5,300"
    const double step = std::pow(10.0, std::max(0.0, std::floor(std::log10(std::max(n, 1.0))) - 1));
    const std::string digits = fmt::format("{:.0f}", std::round(n / step) * step);
    std::string grouped;
    for (std::size_t i = 0; i < digits.size(); ++i) {
      if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
      grouped += digits[i];
    }
    return grouped;
  };
  return fmt::format("expected fluid mesh: about {} triangles, {} nodes (mesh.size = {:g} m{})",
                     rounded(estimate.total()), rounded(0.5 * estimate.total()), request.size,
                     estimate.near_lines > 0 ? fmt::format(", {:g} m along the fractures", request.fracture_size) : "");
}

}  // namespace

std::string describe_load(const numerics::TimeTable& value, const std::string& unit) {
  if (value.is_constant()) return format_in_unit(value.at(0), unit);
  return fmt::format("{} → {} (table)", format_in_unit(value.at(0), unit), format_in_unit(value.at(value.rows() - 1), unit));
}

output::PreviewFigure build_preview(const scenario::Scenario& s) {
  output::PreviewFigure figure;
  figure.title = s.title.empty() ? s.file.filename().string() : s.title;
  for (const scenario::MaterialDefinition& m : s.materials) figure.materials.push_back(m.name);
  // The joint types as the scenario numbers them: 0 is [joint], i + 1 is [joint.NAME] i.
  figure.joint_types = {"joint"};
  for (const scenario::JointDefinition& type : s.joint_types) figure.joint_types.push_back("joint." + type.name);
  std::vector<dda::BlockDefinition> blocks;
  if (s.geometry && !s.geometry->domain.empty()) {
    const ModelGeometry model = build_model_geometry(s);  // check_model has logged what the cut says
    figure.domain = s.geometry->domain;
    blocks = blocks_of(s, model);
    for (const geometry::FractureFace& face : model.network.faces)
      figure.traces.push_back({face.segment.from, face.segment.to, face.fracture, model.traces.at(face.fracture).joint_type});
    figure.subtitle = "preview: " + model.summary;
  } else {
    blocks = build_blocks(s, GeometryWarnings::already_logged);
    figure.subtitle = fmt::format("preview: {} blocks", blocks.size());
  }
  for (const dda::BlockDefinition& b : blocks) {
    figure.blocks.push_back(b.polygon);
    figure.block_material.push_back(b.material);
    figure.block_fixed.push_back(b.fixed);
  }
  add_boundaries(s, figure);
  add_points(s, figure);
  figure.note = describe_expected_mesh(s);
  return figure;
}

void draw_preview(const scenario::Scenario& s, const std::filesystem::path& path) {
  output::render_preview_figure(path, build_preview(s));
}

std::string find_figure_path_problem(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string extension = path.extension().string();
  if (fs::is_directory(path)) return "is a folder: give a file name ending in .png, .svg or .pdf";
  if (extension != ".png" && extension != ".svg" && extension != ".pdf")
    return "must end in .png, .svg or .pdf (the figure's format)";
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::is_directory(folder)) return "is in a folder that does not exist: " + folder.string();
  return "";
}

}  // namespace hydrodda::run
