#pragma once
// Whether a static mechanics-only run ended at rest: what its `converged` says. A run of a fixed
// number of steps (or to an end time) that stops with its blocks still moving has not found the
// equilibrium a static analysis asks for, and says so rather than "converged".

#include <string>

#include "dda/system.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Empty when the run's last step left the blocks at rest: it ran at the full time_step (to 1e-9
// of it) and either moved no vertex by more than dda::System::at_rest_displacement (1e-9 of
// half the model's height) or left no block an unbalanced force above 1e-5 of the forces on it
// (StepReport::unbalanced_force_ratio, Itasca's limit). The force test is what tells blocks that
// follow a load rising every step, each step ending in equilibrium after moving by the load's
// increment over their stiffness, from blocks that move unheld; the displacement test passes
// blocks that no longer move at all. Also empty when the scenario's loads changed over the last
// step (a load table, a prescribed displacement still ramping): the blocks then follow a load
// path, moving by its increment each step, and rest is not what the run asks at its end. Else
// why not: how far the last step moved a vertex and the force it left, or how short it was, the
// blocks that moved most (ids and centroids, largest first, five named), and what to raise.
// `last`: the report of the run's last step; `steps`: how many it took.
std::string describe_motion_at_end(const scenario::Scenario& scenario, const dda::System& system,
                                   const dda::StepReport& last, long long steps);

// Whether a [mechanics] load changes between times t0 and t1: a traction's or point load's
// table, or a prescribed displacement still ramping (over ramp_time, or the run's duration).
bool loads_change_between(const scenario::MechanicsDefinition& mechanics, double t0, double t1);

}  // namespace hydrodda::run
