#include "run/no_equilibrium_in_time.hpp"

#include <fmt/format.h>

#include <exception>

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

namespace {

// Where the blocks a failed step names were left, and by what.
std::string where_named(const StepFailure& failed) {
  if (failed.steady_pass == 0) return fmt::format("the last try of time step {} left them", failed.step);
  return fmt::format("steady passes from that state under these loads left them in their pass {} (the last try of "
                     "time step {} threw blocks in its iteration {}, after the first held them)",
                     failed.steady_pass, failed.step, failed.escaped_in);
}

}  // namespace

bool failed_without_equilibrium(const CoupledTransientStepper& stepper) {
  return stepper.failed() && !stepper.failed_step().escaped.empty();
}

SteadyCheck check_steady_equilibrium(CoupledModel& model, double time, coupling::PassObserver& observer) {
  const int most = model.scenario().coupling.max_iterations;
  const std::string asked = fmt::format("steady passes from the last step's end under the loads at t = {:g} s", time);
  model.begin_steady_at(time);
  const int before = model.iterations();
  coupling::LoopResult result;
  try {
    result = model.run({before + most, std::nullopt}, observer);
  } catch (const coupling::PassInterrupted&) {
    return {.interrupted = true};
  } catch (const std::exception& e) {
    // A DDA step or flow solve that fails while blocks fly off is their escape, as in a steady run.
    std::vector<EscapedBlock> escaped =
        locate_escaping_blocks(model.loop().blocks_beyond_their_size(), model.block_polygons());
    const int pass = model.iterations() + 1 - before;
    model.abandon_pass();
    if (escaped.empty()) return {.ended = fmt::format("{} failed in their pass {} ({})", asked, pass, e.what())};
    return {.escaped = std::move(escaped), .pass = pass};
  }
  const int passes = model.iterations() - before;
  switch (result.end) {
    case coupling::LoopEnd::escaping:
      return {.escaped = locate_escaping_blocks(result.last_pass->escaping, model.block_polygons()),
              .pass = result.last_pass->iteration - before};
    case coupling::LoopEnd::stop_requested: return {.interrupted = true};
    case coupling::LoopEnd::converged:
      return {.ended = fmt::format("{} held the blocks (converged in {} passes)", asked, passes)};
    case coupling::LoopEnd::diverging:
      return {.ended = fmt::format("{} diverged in {} passes, no block thrown", asked, passes)};
    default:
      return {.ended = fmt::format("{} threw no block in {} (coupling.max_iterations), nor converged", asked, most)};
  }
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
             fmt::format("{}; the blocks named are where {}", kept, where_named(failed)),
             folder, end);
}

}  // namespace hydrodda::run
