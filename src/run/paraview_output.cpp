#include "run/paraview_output.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>

#include "geometry/polygon.hpp"

#include "output/vtk_writer.hpp"

namespace hydrodda::run {

using output::DataArray;

void list_if_present(output::PvdSeries& series, const output::RunFolder& folder, double time, const std::string& name) {
  std::error_code ec;
  const std::filesystem::path file = folder.file(name);
  const std::string series_name = series.path().filename().string();
  if (!std::filesystem::is_regular_file(file, ec))
    spdlog::warn("{} is missing from {}: left out of {}", name, folder.path().string(), series_name);
  else if (std::filesystem::file_size(file, ec) == 0 && !ec)
    // What a power cut can leave of a field renamed into place before its bytes reached the
    // disk (docs/output.md, "Durability"); a .vtu the program wrote is never empty.
    spdlog::warn("{} in {} is empty (a power cut before it reached the disk?): left out of {}", name,
                 folder.path().string(), series_name);
  else
    series.add(time, name);
}

ParaviewOutput::ParaviewOutput(const output::RunFolder& folder, const scenario::OutputFields& fields)
    : folder_(folder), fields_(fields) {}

void ParaviewOutput::write_fluid(int step, double time, const mesh::TriangleMesh& mesh,
                                 const hydro::FlowSolution& flow, const std::vector<double>& porosity,
                                 const std::vector<double>& permeability) {
  if (!fields_.fluid) return;
  // The fields the run keeps are written in place, not copied: at a million triangles each
  // copy is megabytes.
  std::vector<DataArray> points{DataArray::view("head", 1, flow.head), DataArray::view("pressure", 1, flow.pressure)};
  std::vector<DataArray> cells{DataArray::view("permeability", 1, permeability)};
  if (!porosity.empty()) cells.push_back(DataArray::view("porosity", 1, porosity));
  DataArray flux{"flux", 2, {}};
  flux.values.reserve(2 * flow.flux.size());
  for (const geometry::Point& q : flow.flux) flux.values.insert(flux.values.end(), {q.x, q.y});
  cells.push_back(std::move(flux));
  cells.push_back({"region", 1, std::vector<double>(mesh.region.begin(), mesh.region.end())});
  const std::string name = fmt::format("fluid_{:04d}.vtu", step);
  output::write_vtu_triangles(folder_.file(name), mesh.nodes, mesh.triangles, points, cells);
  if (!fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  fluid_->add(time, name);
}

void ParaviewOutput::list_written(const std::vector<int>& steps) {
  if (fields_.fluid && !fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  if (fields_.blocks && !blocks_) blocks_.emplace(folder_.file("blocks.pvd"));
  if (fields_.contacts && !contacts_) contacts_.emplace(folder_.file("contacts.pvd"));
  const auto add_existing = [&](std::optional<output::PvdSeries>& series, int step, const std::string& name) {
    if (series) list_if_present(*series, folder_, step, name);
  };
  for (int step : steps) {
    add_existing(fluid_, step, fmt::format("fluid_{:04d}.vtu", step));
    add_existing(blocks_, step, fmt::format("blocks_{:04d}.vtu", step));
    add_existing(contacts_, step, fmt::format("contacts_{:04d}.vtu", step));
  }
}

void ParaviewOutput::list_written_fluid(const std::vector<double>& times) {
  if (!fields_.fluid) return;
  if (!fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  for (std::size_t i = 0; i < times.size(); ++i)
    list_if_present(*fluid_, folder_, times[i], fmt::format("fluid_{:04d}.vtu", i));
}

void ParaviewOutput::list_written_at(const std::vector<double>& times) {
  if (fields_.fluid && !fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  if (fields_.blocks && !blocks_) blocks_.emplace(folder_.file("blocks.pvd"));
  if (fields_.contacts && !contacts_) contacts_.emplace(folder_.file("contacts.pvd"));
  for (std::size_t i = 0; i < times.size(); ++i)
    for (auto [series, name] : {std::pair{&fluid_, "fluid"}, std::pair{&blocks_, "blocks"}, std::pair{&contacts_, "contacts"}})
      if (*series) list_if_present(**series, folder_, times[i], fmt::format("{}_{:04d}.vtu", name, i));
}

void ParaviewOutput::write_blocks(int step, double time, const dda::System& system) {
  if (fields_.contacts) write_contacts(step, time, system);
  if (!fields_.blocks) return;
  std::vector<std::vector<geometry::Point>> polygons;
  DataArray id{"block", 1, {}}, displacement{"displacement", 2, {}}, rotation{"rotation", 1, {}},
      stress{"stress", 3, {}}, area{"area", 1, {}}, material{"material", 1, {}};
  for (int b = 0; b < system.block_count(); ++b) {
    polygons.push_back(system.polygon(b));
    id.values.push_back(b);
    const geometry::Point u = system.displacement(b);
    displacement.values.insert(displacement.values.end(), {u.x, u.y});
    rotation.values.push_back(system.rotation(b));
    const auto s = system.stress(b);
    stress.values.insert(stress.values.end(), s.begin(), s.end());
    area.values.push_back(system.area(b));
    material.values.push_back(system.material(b));
  }
  std::vector<DataArray> cells{id, displacement, rotation, stress, area};
  // The material's index (in the scenario's order) where there are several to tell apart.
  if (system.material_count() > 1) cells.push_back(material);
  const std::string name = fmt::format("blocks_{:04d}.vtu", step);
  output::write_vtu_polygons(folder_.file(name), polygons, cells);
  if (!blocks_) blocks_.emplace(folder_.file("blocks.pvd"));
  blocks_->add(time, name);
}

static_assert(static_cast<int>(dda::ContactState::open) == 0 && static_cast<int>(dda::ContactState::sliding) == 1 &&
              static_cast<int>(dda::ContactState::locked) == 2);

// Each contact as a line from block_i's vertex to the nearest point of block_j's edge: its
// length shows the gap (or overlap) the contact measures.
void ParaviewOutput::write_contacts(int step, double time, const dda::System& system) {
  std::vector<std::array<geometry::Point, 2>> segments;
  DataArray state{"state", 1, {}}, normal_force{"normal_force", 1, {}}, penetration{"penetration", 1, {}},
      aperture{"aperture", 1, {}}, block_i{"block_i", 1, {}}, block_j{"block_j", 1, {}};
  for (const dda::ContactInfo& c : system.contacts()) {
    const geometry::Polygon vertex_block = system.polygon(c.key.block_i);
    const geometry::Polygon edge_block = system.polygon(c.key.block_j);
    const geometry::Point p = vertex_block[c.key.vertex];
    const geometry::Point a = edge_block[c.key.edge];
    const geometry::Point b = edge_block[(c.key.edge + 1) % edge_block.size()];
    segments.push_back({p, geometry::closest_point_on_segment(p, a, b)});
    state.values.push_back(static_cast<double>(c.state));  // 0 open, 1 sliding, 2 locked
    normal_force.values.push_back(c.normal_force);
    penetration.values.push_back(c.penetration);
    aperture.values.push_back(std::max(0.0, -c.penetration));
    block_i.values.push_back(c.key.block_i);
    block_j.values.push_back(c.key.block_j);
  }
  const std::vector<DataArray> cells{state, normal_force, penetration, aperture, block_i, block_j};
  const std::string name = fmt::format("contacts_{:04d}.vtu", step);
  output::write_vtu_segments(folder_.file(name), segments, cells);
  if (!contacts_) contacts_.emplace(folder_.file("contacts.pvd"));
  contacts_->add(time, name);
}

}  // namespace hydrodda::run
