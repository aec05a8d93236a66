#pragma once
// A coupled transient run whose time step, cut to the floor, threw blocks beyond their own size
// in its first iteration ends with no equilibrium under the loads at the step's end
// (docs/output.md, "A run that found no equilibrium"): the last time step that held, and the
// words of that end, the same for the program's run and for a model stepped by hand (Python's
// Simulation).

#include <string>

#include "dda/system.hpp"
#include "fractures/fracture_results.hpp"
#include "output/run_folder.hpp"
#include "run/coupled_transient_stepper.hpp"
#include "run/no_equilibrium.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Time step `step`, ending at `time` (0: the blocks as built), as the last state that held: the
// bonds `system` has broken by then (a system with bonds) and the fractures open in `fractures`,
// measured then (none: a scenario without traces to measure).
HeldState hold_time_step(int step, double time, const dda::System& system, const fractures::FractureState* fractures);

// The stepper failed so: a step at the floor threw blocks in its first iteration.
bool failed_without_equilibrium(const CoupledTransientStepper& stepper);

// The message of that end: the step, its loads at its end, the blocks where its last try left
// them, `held` (with the bonds `system`, at the stepper's last step, broke after it) and that
// last step as the state kept. Long lists of blocks go whole to escaping_blocks.txt in `folder`
// where there is one.
std::string describe_time_step_without_equilibrium(const scenario::Scenario& s, const CoupledTransientStepper& stepper,
                                                   HeldState held, const dda::System& system,
                                                   const output::RunFolder* folder);

}  // namespace hydrodda::run
