#pragma once
// A coupled transient run ([mechanics], [flow] and [flow.transient]): time steps by the
// fixed-stress split (coupling/fixed_stress_step.hpp), each iterated to convergence of both
// the heads and the blocks, then advanced (docs/coupling.md, "Coupled transient runs"). The
// step control here is plain arithmetic, tested alone; the run is run_coupled_transient.

#include <vector>

#include "scenario/scenario.hpp"

namespace hydrodda::run {

// How the steps' lengths follow the iterations they need:
//   - a step that converged in at most `few_iterations` passes makes the next kTimeStepGrowth
//     (1.2) times longer, up to max_step; one that needed more keeps its length;
//   - a step whose passes do not converge in coupling.max_iterations (or whose DDA or flow
//     solve fails, or whose loop diverges) is cut to half and tried again from the state the
//     last step left, down to `floor`: a step that fails at the floor ends the run, not
//     converged, saying at which time and why;
//   - a step ends on each output time and on the end time (and on the boundary tables' rows),
//     shortened to land there exactly (within a millionth of itself, as plan_step_times).
struct StepControl {
  double first_step = 0.0;
  double max_step = 0.0;
  double floor = 0.0;       // first_step / 2^kMostCuts
  int few_iterations = 0;   // max(3, coupling.max_iterations / 4)
};
inline constexpr int kMostCuts = 10;

StepControl make_step_control(const scenario::Scenario& scenario);

// The times a step must end on after 0: the output times, the load tables' rows and the end,
// sorted, once each.
std::vector<double> find_step_stops(const scenario::Scenario& scenario);

// The next step's length from `time` with the nominal `step`: shortened to land on `stop`
// (the first stop after `time`) when it would reach it or fall a millionth of itself short.
double land_on_stop(double time, double step, double stop);

// The nominal step after one that converged in `passes` passes.
double grow_step(const StepControl& control, double step, int passes);

}  // namespace hydrodda::run
