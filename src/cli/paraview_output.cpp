#include "cli/paraview_output.hpp"

#include <fmt/format.h>

#include "output/vtk_writer.hpp"

namespace hydrodda::cli {

using output::DataArray;

ParaviewOutput::ParaviewOutput(const output::RunFolder& folder) : folder_(folder) {}

void ParaviewOutput::write_fluid(int step, double time, const mesh::TriangleMesh& mesh,
                                 const hydro::FlowSolution& flow, const std::vector<double>& porosity,
                                 const std::vector<double>& permeability) {
  std::vector<DataArray> points{{"head", 1, flow.head}, {"pressure", 1, flow.pressure}};
  std::vector<DataArray> cells{{"permeability", 1, permeability}};
  if (!porosity.empty()) cells.push_back({"porosity", 1, porosity});
  DataArray flux{"flux", 2, {}};
  for (const geometry::Point& q : flow.flux) flux.values.insert(flux.values.end(), {q.x, q.y});
  cells.push_back(std::move(flux));
  cells.push_back({"region", 1, std::vector<double>(mesh.region.begin(), mesh.region.end())});
  const std::string name = fmt::format("fluid_{:04d}.vtu", step);
  output::write_vtu_triangles(folder_.file(name), mesh.nodes, mesh.triangles, points, cells);
  if (!fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  fluid_->add(time, name);
}

void ParaviewOutput::list_written(const std::vector<int>& steps) {
  if (!fluid_) fluid_.emplace(folder_.file("fluid.pvd"));
  if (!blocks_) blocks_.emplace(folder_.file("blocks.pvd"));
  for (int step : steps) {
    fluid_->add(step, fmt::format("fluid_{:04d}.vtu", step));
    blocks_->add(step, fmt::format("blocks_{:04d}.vtu", step));
  }
}

void ParaviewOutput::write_blocks(int step, double time, const dda::System& system) {
  std::vector<std::vector<geometry::Point>> polygons;
  DataArray id{"block", 1, {}}, displacement{"displacement", 2, {}}, rotation{"rotation", 1, {}},
      stress{"stress", 3, {}}, area{"area", 1, {}};
  for (int b = 0; b < system.block_count(); ++b) {
    polygons.push_back(system.polygon(b));
    id.values.push_back(b);
    const geometry::Point u = system.displacement(b);
    displacement.values.insert(displacement.values.end(), {u.x, u.y});
    rotation.values.push_back(system.rotation(b));
    const auto s = system.stress(b);
    stress.values.insert(stress.values.end(), s.begin(), s.end());
    area.values.push_back(system.area(b));
  }
  const std::vector<DataArray> cells{id, displacement, rotation, stress, area};
  const std::string name = fmt::format("blocks_{:04d}.vtu", step);
  output::write_vtu_polygons(folder_.file(name), polygons, cells);
  if (!blocks_) blocks_.emplace(folder_.file("blocks.pvd"));
  blocks_->add(time, name);
}

}  // namespace hydrodda::cli
