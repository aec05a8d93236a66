#pragma once
// The fractures of a coupled transient run in time: measured at every step (fractures.csv a row
// per fracture per step, with the step's number and time), their counts in history.csv, their
// traces in fractures.pvd at the output times, and figures/fractures.* (how many are open
// against time: their open length) beside figures/flows.* (each boundary's outward flow and the rate of storage
// against time). What a seal does as its reservoir fills shows there: the joints opening as
// the pressure nears their effective normal stress, the flow through the seal rising with them
// (docs/tutorial_seal_in_time.md).

#include <optional>
#include <string>
#include <vector>

#include "fractures/fracture_results.hpp"
#include "output/plot_line.hpp"
#include "run/coupled_model.hpp"
#include "run/fracture_output.hpp"
#include "run/runs.hpp"

namespace hydrodda::run {

// One step's counts of its fractures, as history.csv gives them.
struct FractureCounts {
  int open = 0;                    // open over at least 9/10 of their length (fractures.csv's `open`)
  int partly_open = 0;             // open somewhere (open_length > 0)
  double open_length = 0.0;        // m, summed over all fractures
  double largest_opening = 0.0;    // m, the widest mechanical opening (max_aperture)
  double largest_hydraulic = 0.0;  // m, the largest of the fractures' mean hydraulic apertures
};

// The counts of a measured state.
FractureCounts count_fractures(const fractures::FractureState& state);

// history.csv's columns for them, after the run's own, and one step's cells.
std::vector<std::string> fracture_count_columns();
std::vector<std::string> fracture_count_cells(const FractureCounts& counts);

// figures/fractures.*: the fractures' open length, summed, against `times` (a count of open
// fractures jumps as a joint opens by a few centimetres at one step and not the next; the
// length follows the opening). Throws std::invalid_argument when the sizes differ.
output::LinePlotSpec plot_open_fractures(const std::vector<double>& times, const std::vector<FractureCounts>& counts);

// The fractures of a coupled transient run (none without a [geometry] domain to cut).
class FracturesInTime {
 public:
  FracturesInTime(const RunContext& context, const CoupledModel& model);
  bool measured() const { return meter_.has_value(); }
  // Measures the fractures as the model is now and adds their rows to fractures.csv.
  void record(long long step, double time);
  // fractures_NNNN.vtu in fractures.pvd at `time` (output.fields.fractures).
  void write_series(int written, double time);
  // A continued run after step `steps`: fractures.csv's rows up to it kept (its broken bonds'
  // too: call list_broken_bonds first), fractures_NNNN.vtu
  // listed again at `written_times`[NNNN], the counts so far taken up and the fractures measured
  // again as the model stands (the state that step left).
  void resume(int steps, const std::vector<double>& written_times, std::vector<FractureCounts> counts);
  const std::vector<FractureCounts>& counts() const { return counts_; }
  // A model with bonds: fractures.csv lists its breaks too, as BondOutput adds them to output()
  // (call before any row).
  void list_broken_bonds() { output_.list_broken_bonds(); }
  FractureOutput& output() { return output_; }
  const std::optional<fractures::FractureState>& state() const { return state_; }

 private:
  const RunContext& context_;
  const CoupledModel& model_;
  std::optional<fractures::FractureMeter> meter_;
  coupling::JointApertureLaws joint_laws_;
  fractures::FractureMeter::FlowZones flow_zones_;
  FractureOutput output_;
  std::optional<fractures::FractureState> state_;
  std::vector<FractureCounts> counts_;
};

}  // namespace hydrodda::run
