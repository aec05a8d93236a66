#pragma once
// A coupled transient run whose time step, cut to the floor, threw blocks beyond their own size
// ends with no equilibrium under the loads at the step's end (docs/output.md, "A run that found
// no equilibrium") when its first iteration threw them, or when a later one did and steady
// passes from the last step's end under those loads throw blocks too: the last time step that
// held, and the words of that end, the same for the program's run and for a model stepped by
// hand (Python's Simulation).

#include <string>
#include <vector>

#include "dda/system.hpp"
#include "fractures/fracture_results.hpp"
#include "output/run_folder.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient_stepper.hpp"
#include "run/no_equilibrium.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Time step `step`, ending at `time` (0: the blocks as built), as the last state that held: the
// bonds `system` has broken by then (a system with bonds) and the fractures open in `fractures`,
// measured then (none: a scenario without traces to measure).
HeldState hold_time_step(int step, double time, const dda::System& system, const fractures::FractureState* fractures);

// The stepper failed so: a step at the floor threw blocks, and they have no equilibrium under
// its loads (StepFailure::escaped).
bool failed_without_equilibrium(const CoupledTransientStepper& stepper);

// Whether the loads at `time` hold the blocks of `model`'s state now, by the steady loop's own
// criterion (a steady run's "no equilibrium"): up to coupling.max_iterations steady passes from
// that state under them. `escaped`: the blocks one of them threw farther than their own size,
// farthest first, where pass `pass` (1: the first) left them; none, and `ended` how the passes
// ended, when they threw none; `interrupted` when the stop request (`observer`'s, or the
// model's before a DDA step) ended them first, which answers nothing. The model is left where
// the passes took it, out of its time step: import the state wanted after.
struct SteadyCheck {
  std::vector<EscapedBlock> escaped{};
  int pass = 0;
  std::string ended{};
  bool interrupted = false;
};
SteadyCheck check_steady_equilibrium(CoupledModel& model, double time, coupling::PassObserver& observer);

// The message of that end: the step, its loads at its end, the blocks where its last try left
// them, `held` (with the bonds `system`, at the stepper's last step, broke after it) and that
// last step as the state kept. Long lists of blocks go whole to escaping_blocks.txt in `folder`
// where there is one.
std::string describe_time_step_without_equilibrium(const scenario::Scenario& s, const CoupledTransientStepper& stepper,
                                                   HeldState held, const dda::System& system,
                                                   const output::RunFolder* folder);

}  // namespace hydrodda::run
