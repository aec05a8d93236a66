// The coupled transient run's steps (coupled_transient_stepper.hpp): each tried, cut by half
// from the last step's end while it fails, to the floor.

#include "run/coupled_transient_stepper.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

#include "coupling/staggered_loop.hpp"
#include "run/no_equilibrium_in_time.hpp"

namespace hydrodda::run {

namespace {

// Counts a step's passes and keeps its last; stops at the stop request.
class StepObserver final : public coupling::PassObserver {
 public:
  explicit StepObserver(const std::function<bool()>& stop_requested) : stop_requested_(stop_requested) {}
  bool stop_requested() override { return stop_requested_ && stop_requested_(); }
  void after_pass(const coupling::PassReport& report) override {
    ++passes;
    last = report;
  }
  int passes = 0;
  coupling::PassReport last;

 private:
  const std::function<bool()>& stop_requested_;
};

// How one attempt at a step ended: converged, or why not; the blocks it threw farther than
// their own size, where it left them, and in which of its iterations (1: the first).
struct Attempt {
  bool converged = false;
  bool interrupted = false;
  std::string why{};
  std::vector<EscapedBlock> escaped{};
  int escaped_in = 0;
};

// Blocks thrown in iteration `iteration` of a try. Only the first iteration's heads are the
// step's loads on the blocks as the last step left them; a later one's carry the blocks' own
// change of volume fed back (a gap the first iteration closed, its water squeezed undrained),
// which can throw blocks that a converged step holds: the jacked block of jacking_in_time.toml
// at 0.96 H* on steps of 1 s is pulled down 5e-5 m, closing its gap, in iteration 1 and thrown
// up 4.4 m in iteration 2 (docs/studies/2026-11-30-escape-in-time.md).
Attempt escaped_attempt(std::vector<EscapedBlock> escaped, int iteration, const std::string& then) {
  std::string why = iteration == 1 ? "blocks escaped beyond their own size in its first iteration"
                                   : fmt::format("blocks escaped beyond their own size in its iteration {}, after the "
                                                 "first held them (the heads of a later iteration carry the blocks' "
                                                 "own change of volume fed back)",
                                                 iteration);
  if (!then.empty()) why += fmt::format(" (and then: {})", then);
  return {.why = std::move(why), .escaped = std::move(escaped), .escaped_in = iteration};
}

Attempt try_step(CoupledModel& model, StepObserver& observer, double time, double length) {
  const scenario::Scenario& s = model.scenario();
  model.begin_time_step(time, length);
  const int before = model.iterations();
  coupling::LoopResult result;
  try {
    result = model.run({before + s.coupling.max_iterations, std::nullopt}, observer);
  } catch (const coupling::PassInterrupted&) {
    return {.interrupted = true};
  } catch (const std::exception& e) {
    // A DDA step or flow solve that fails while blocks fly off is their escape, as in a steady
    // run (the step cut 40 times as they fly, the flow of a layer lifted off its base).
    std::vector<EscapedBlock> escaped =
        locate_escaping_blocks(model.loop().blocks_beyond_their_size(), model.block_polygons());
    if (escaped.empty()) {
      model.abandon_pass();
      return {.why = e.what()};
    }
    Attempt attempt = escaped_attempt(std::move(escaped), model.iterations() + 1 - before, e.what());
    model.abandon_pass();
    return attempt;
  }
  switch (result.end) {
    case coupling::LoopEnd::converged: return {.converged = true};
    case coupling::LoopEnd::stop_requested: return {.interrupted = true};
    case coupling::LoopEnd::diverging: return {.why = "its iterations diverged"};
    case coupling::LoopEnd::escaping:
      return escaped_attempt(locate_escaping_blocks(result.last_pass->escaping, model.block_polygons()),
                             result.last_pass->iteration - before, "");
    default: {
      const coupling::PassReport& r = observer.last;
      return {.why = fmt::format("its iterations did not converge in {} (coupling.max_iterations; head change {:.3e}, "
                                 "displacement change {:.3e}, tolerance {:g})",
                                 s.coupling.max_iterations, r.head_change, r.displacement_change,
                                 s.coupling.tolerance)};
    }
  }
}

}  // namespace

CoupledTransientStepper::CoupledTransientStepper(CoupledModel& model)
    : model_(model),
      control_(make_step_control(model.scenario())),
      stops_(find_step_stops(model.scenario())),
      end_time_(model.scenario().flow->transient->end_time),
      position_{0, 0.0, control_.first_step, 0},
      saved_(model.export_state()) {}

void CoupledTransientStepper::resume_at(const StepPosition& position) {
  if (position.steps < 0 || position.next_stop < 0 || position.next_stop >= static_cast<int>(stops_.size()) + 1 ||
      !(position.nominal > 0.0))
    throw std::invalid_argument("the step position does not fit this scenario's steps");
  position_ = position;
  record_ = StepRecord{position.steps, position.time, 0.0, 0, 0, {}};
  saved_ = model_.export_state();
}

CoupledTransientStepper::Outcome CoupledTransientStepper::step(const std::function<bool()>& stop_requested) {
  if (finished()) throw std::logic_error("CoupledTransientStepper::step: the run has ended");
  const double time = position_.time;
  const double stop = stops_[static_cast<std::size_t>(position_.next_stop)];
  StepObserver observer(stop_requested);
  int cuts = 0;
  double length = land_on_stop(time, position_.nominal, stop);
  Attempt attempt;
  for (;;) {
    attempt = try_step(model_, observer, time, length);
    if (attempt.converged || attempt.interrupted) break;
    model_.import_state(saved_);  // back to the last step's end
    if (length / 2.0 < control_.floor) break;
    spdlog::info("t = {:g} s: the step of {:g} s failed ({}); cut to {:g} s", time, length, attempt.why, length / 2);
    length /= 2.0;
    ++cuts;
  }
  // Blocks the step's own load throws, in its first iteration, have no equilibrium under it.
  // Thrown later, by heads the iterations fed back, they may be the iterations' doing: the load
  // is asked by the steady loop's own criterion, from the last step's end.
  int steady_pass = 0;
  if (!attempt.converged && !attempt.interrupted && attempt.escaped_in > 1) {
    StepObserver check_observer(stop_requested);
    SteadyCheck check = check_steady_equilibrium(model_, time + length, check_observer);
    model_.import_state(saved_);
    attempt.interrupted = check.interrupted;
    attempt.escaped = std::move(check.escaped);
    steady_pass = check.pass;
    if (attempt.escaped.empty()) attempt.why += "; " + check.ended;
  }
  if (attempt.interrupted) {
    model_.import_state(saved_);
    return Outcome::interrupted;
  }
  if (!attempt.converged) {
    failed_ = true;
    failed_step_ = {position_.steps + 1, time, length, cuts, attempt.why, std::move(attempt.escaped),
                    attempt.escaped_in, steady_pass};
    failure_ = fmt::format("not converged at t = {:g} s: the step from there failed at {:g} s after {} cut(s), and "
                           "half of it would be under the floor of {:g} s (flow.transient.time_step / 2^{}); the "
                           "last try: {}",
                           time, length, cuts, control_.floor, kMostCuts, attempt.why);
    return Outcome::failed;
  }
  const bool landed = length == stop - time;
  position_.time = landed ? stop : time + length;
  if (landed) ++position_.next_stop;
  ++position_.steps;
  saved_ = model_.export_state();
  record_ = {position_.steps, position_.time, length, observer.passes, cuts, observer.last};
  // A cut step's length is where the next starts from; a full one grows when it came easily.
  const double nominal = position_.nominal;
  position_.nominal =
      cuts > 0 ? length : (landed && length < nominal ? nominal : grow_step(control_, length, observer.passes));
  return Outcome::stepped;
}

}  // namespace hydrodda::run
