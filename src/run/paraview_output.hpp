#pragma once
// The run's ParaView series: fluid.pvd over the fluid mesh (head, pressure, porosity,
// permeability, flux, region), blocks.pvd over the blocks (displacement, rotation, stress,
// area) and contacts.pvd over the block contacts (state, normal force, penetration, aperture),
// one .vtu of each per output step; only the series the scenario's output.fields names.

#include <optional>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/pvd_series.hpp"
#include "output/run_folder.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A continued run's series: lists `name`, a .vtu an earlier part of the run wrote, at `time` if
// it is still in the folder; one deleted since, or left empty by a power cut, is left out, with
// a warning, so that the .pvd never lists what is not there (the next output step writes its
// own anew).
void list_if_present(output::PvdSeries& series, const output::RunFolder& folder, double time, const std::string& name);

class ParaviewOutput {
 public:
  ParaviewOutput(const output::RunFolder& folder, const scenario::OutputFields& fields);

  // `porosity` may be empty (flow-only runs without blocks).
  void write_fluid(int step, double time, const mesh::TriangleMesh& mesh, const hydro::FlowSolution& flow,
                   const std::vector<double>& porosity, const std::vector<double>& permeability);
  // The blocks and their contacts (blocks_NNNN.vtu, contacts_NNNN.vtu).
  void write_blocks(int step, double time, const dda::System& system);
  // A continued run: lists again the fluid, block and contact files an earlier part of the run wrote
  // at these steps (time = step, as in coupled runs), so the series stay whole.
  void list_written(const std::vector<int>& steps);
  // A continued transient run: lists again fluid_NNNN.vtu at times[NNNN], as it wrote them.
  void list_written_fluid(const std::vector<double>& times);
  // A continued coupled transient run: lists again fluid_NNNN.vtu, blocks_NNNN.vtu and
  // contacts_NNNN.vtu at times[NNNN], as it wrote them.
  void list_written_at(const std::vector<double>& times);

 private:
  const output::RunFolder& folder_;
  scenario::OutputFields fields_;
  std::optional<output::PvdSeries> fluid_;
  std::optional<output::PvdSeries> blocks_;
  std::optional<output::PvdSeries> contacts_;

  void write_contacts(int step, double time, const dda::System& system);
};

}  // namespace hydrodda::run
