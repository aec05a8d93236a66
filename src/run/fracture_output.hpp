#pragma once
// The run folder's per-fracture files: fractures.csv (one row per fracture per output step),
// fractures.pvd with fractures_NNNN.vtu (each fracture as lines along its deformed faces, cut
// where it opens or closes) and figures/apertures.* (the blocks with every fracture coloured
// by its aperture). What they hold: docs/output.md.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fractures/fracture_results.hpp"
#include "output/csv_table.hpp"
#include "output/pvd_series.hpp"
#include "output/summary.hpp"
#include "output/run_folder.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A bond that broke, as fractures.csv lists it (a new fracture).
struct BrokenBondRow {
  int fracture = 0;  // its id: after the traces' (their count + the bond's id)
  int bond = 0;
  double time = 0.0;  // the end of the step it broke in
  std::string mode;   // "tension" or "shear"
  std::string type;   // its joint type's name
  geometry::Point from, to;
};

class FractureOutput {
 public:
  // `with_flow`: coupled runs, whose rows have the flow along each fracture. `types`: each
  // fracture's joint type by id (fracture_type_names).
  FractureOutput(const output::RunFolder& folder, bool with_flow, std::vector<std::string> types = {});

  // A continued run: keeps the rows fractures.csv has for steps up to `last_step` and lists
  // again the .vtu files an earlier part of the run wrote at `written` (time = step) that are
  // still there.
  void continue_from(int last_step, const std::vector<int>& written);
  // The same for a coupled transient run: fractures_NNNN.vtu listed at `written_times`[NNNN].
  void continue_in_time(int last_step, const std::vector<double>& written_times);
  // One step's rows, written at once.
  void add_rows(long long step, double time, const fractures::FractureState& state);
  // A model with bonds: fractures.csv gets the columns mode, x1, y1, x2, y2 (empty on the
  // traces' rows); call before any row.
  void list_broken_bonds();
  // The bonds broken in step `step`, one row each (origin "bond", number the bond's id, open 1),
  // written at once.
  void add_broken_bonds(long long step, const std::vector<BrokenBondRow>& rows);
  // fractures_NNNN.vtu, listed in fractures.pvd at `time`.
  void write_series(int step, double time, const fractures::FractureState& state);

 private:
  const output::RunFolder& folder_;
  bool with_flow_;
  bool with_bonds_ = false;
  std::vector<std::string> types_;
  output::CsvTable table_;
  std::optional<output::PvdSeries> series_;

  // fractures.csv's rows up to `last_step` (those of later steps, written before the run
  // stopped, left out).
  void keep_rows_up_to(int last_step);
};

// What a figure shows: at which coupling iteration or DDA step, and how the run ended when not
// as asked ("not converged after 40 passes", "failed at pass 6: ...", in red; empty: nothing).
struct FigureState {
  std::string when;  // e.g. "coupling iteration 4", "DDA step 200"
  std::string status{};
};

// Each fracture's joint type by id, as fractures.csv and summary.json name it: the NAME of its
// [joint.NAME], "joint" for the default type [joint].
std::vector<std::string> fracture_type_names(const scenario::Scenario& scenario);

// summary.json's `fractures` section from a step's results (docs/output.md); `types` as
// fracture_type_names gives them.
output::FractureSummary summarise_fractures(const fractures::FractureState& state,
                                            const std::vector<std::string>& types = {});

// figures/apertures.* for each format output.figures asks for: the blocks as they are, each
// fracture piece coloured by its mechanical aperture (mm), closed pieces thin and grey; titled
// with the scenario's title. With the joint keys of a hydraulic aperture (residual_aperture,
// normal_stiffness, max_closure in [joint] or a [joint.NAME]) also figures/hydraulic_apertures.*:
// every piece coloured by the aperture the flow sees (µm, log scale), by its joint type's law.
void draw_aperture_figure(const scenario::Scenario& scenario, const output::RunFolder& folder,
                          std::span<const geometry::Polygon> blocks, const fractures::FractureState& state,
                          const FigureState& shown);

}  // namespace hydrodda::run
