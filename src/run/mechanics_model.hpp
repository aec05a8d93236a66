#pragma once

#include <functional>
// A mechanics-only model: the DDA system of the scenario's blocks and loads, stepped until the
// scenario's `steps` or `end_time`. It writes no file; run() drives it into a run folder.

#include <vector>

#include "dda/system.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

class MechanicsModel {
 public:
  // Cuts or reads the blocks and builds the system with every load of [mechanics]. Throws
  // scenario::ScenarioError for what only the blocks show (a fixed point in no block).
  explicit MechanicsModel(const scenario::Scenario& scenario);

  // Whether the run is at its end: `steps` taken, or `end_time` reached.
  bool finished() const;
  // One DDA step: of the current step size under `steps`; under `end_time`, one that does not
  // pass it (time-step control may shorten steps, so such a run takes as many as it needs).
  // `after_each`, when given, is handed each DDA step's report; its true ends the step there.
  dda::StepReport step(const std::function<bool(const dda::StepReport&)>& after_each = {});
  long long steps() const { return steps_; }
  // New [[mechanics.traction]] loads from the next step on, placed on the blocks as built; throws
  // scenario::ScenarioError for a boundary on which no block edge lies.
  void set_tractions(std::vector<scenario::Traction> tractions);

  const scenario::Scenario& scenario() const { return scenario_; }
  const dda::System& system() const { return system_; }
  // At a stall (load_stall.hpp): dda::System::break_bonds_of_last_cut_try.
  int break_bonds_of_last_cut_try() { return system_.break_bonds_of_last_cut_try(); }
  // Asked within each step, between its open–close passes (dda::System::set_interrupt_check):
  // true abandons the step and step() throws dda::StepInterrupted.
  void set_interrupt_check(std::function<bool()> check) { system_.set_interrupt_check(std::move(check)); }
  // summary.json's blocks and measured points, iterations = steps taken; no timings.
  output::RunSummary summary() const;

 private:
  scenario::Scenario scenario_;
  std::vector<dda::BlockDefinition> initial_blocks_;  // where the tractions' edges are found
  dda::System system_;
  double end_time_ = 0.0;
  long long steps_ = 0;
};

}  // namespace hydrodda::run
