#include "run/no_equilibrium_in_time.hpp"

#include <fmt/format.h>

#include "run/coupled_transient.hpp"

namespace hydrodda::run {

HeldState hold_time_step(int step, double time, const dda::System& system, const fractures::FractureState* fractures) {
  HeldState held;
  held.step = step;
  if (step > 0) held.name = fmt::format("time step {}, t = {:g} s", step, time);
  if (system.bond_count() > 0) held.broken_bonds = static_cast<int>(system.bond_breaks().size());
  if (fractures) take_open_fractures(*fractures, held);
  return held;
}

bool failed_without_equilibrium(const CoupledTransientStepper& stepper) {
  return stepper.failed() && !stepper.failed_step().escaped.empty();
}

std::string describe_time_step_without_equilibrium(const scenario::Scenario& s, const CoupledTransientStepper& stepper,
                                                   HeldState held, const dda::System& system,
                                                   const output::RunFolder* folder) {
  const StepFailure& failed = stepper.failed_step();
  if (held.broken_bonds)
    held.broken_bonds_later = static_cast<int>(system.bond_breaks().size()) - *held.broken_bonds;
  const std::string kept =
      stepper.steps() > 0 ? fmt::format("time step {}, t = {:g} s", stepper.steps(), stepper.time()) : "t = 0";
  const double end = failed.time + failed.length;
  return fmt::format("time step {} from t = {:g} s to {:g} s ({} cut(s); half of it would be under the floor of {:g} "
                     "s): ",
                     failed.step, failed.time, end, failed.cuts, make_step_control(s).floor) +
         describe_no_equilibrium(
             s, failed.escaped, held,
             fmt::format("{}; the blocks named are where the last try of time step {} left them", kept, failed.step),
             folder, end);
}

}  // namespace hydrodda::run
