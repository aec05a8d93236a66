#pragma once
// A CoupledModel stepped in time by the step control of coupled_transient.hpp, one time step at
// a time: each step's passes its fixed-stress iterations, cut by half from the state the last
// step left when they fail, to the floor. The run (coupled_transient_run.cpp) and Python's
// Simulation both step it; a run continued from its checkpoint takes up its position.

#include <functional>
#include <string>
#include <vector>

#include "coupling/pass_report.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient.hpp"
#include "run/no_equilibrium.hpp"

namespace hydrodda::run {

// Where the steps are: the steps taken, the time they reached, the nominal length of the next
// (before it lands on a stop) and the next of find_step_stops' stops. All a later step reads of
// the step control: a checkpoint holds it.
struct StepPosition {
  int steps = 0;
  double time = 0.0;
  double nominal = 0.0;
  int next_stop = 0;
};

// What one step did: its end, its length, the passes it took (the last try's), the cuts before
// it converged and its last pass's report.
struct StepRecord {
  int step = 0;
  double time = 0.0, length = 0.0;
  int passes = 0, cuts = 0;
  coupling::PassReport last;
};

// A step that failed at the floor: the time step it would have been, where it started, its last
// try's length, the cuts before it and why that try failed; `escaped`, the blocks the step's
// loads have no equilibrium for, farthest first: those the try's first iteration left farther
// than their own size, where it left them, or, thrown in a later iteration (`escaped_in`), those
// the steady passes from the last step's end under the step's end loads threw, where their pass
// `steady_pass` left them (check_steady_equilibrium); none when it failed otherwise, or when
// those steady passes threw none (coupled_transient_stepper.cpp).
struct StepFailure {
  int step = 0;
  double time = 0.0, length = 0.0;
  int cuts = 0;
  std::string why;
  std::vector<EscapedBlock> escaped;
  int escaped_in = 0;
  int steady_pass = 0;
};

class CoupledTransientStepper {
 public:
  // `model` has its heads at t = 0 (CoupledModel::start_in_time) or a checkpoint's state; it
  // must outlive the stepper.
  explicit CoupledTransientStepper(CoupledModel& model);

  // A continued run: the model holds the state of `position`'s step end (import_state).
  void resume_at(const StepPosition& position);

  enum class Outcome {
    stepped,      // the step converged: record() says what it did
    interrupted,  // the stop request abandoned it: the model is back at the last step's end
    failed,       // it failed at the floor: failure() says when and why; the model is at the last step's end
  };
  // One step from time(). `stop_requested` is asked before every DDA step; unset: never.
  // Throws std::logic_error once finished().
  Outcome step(const std::function<bool()>& stop_requested = {});

  // end_time reached, or a step failed at the floor.
  bool finished() const { return failed_ || position_.time >= end_time_; }
  bool failed() const { return failed_; }
  const std::string& failure() const { return failure_; }
  // What failed, once failed(): the step, and the blocks it threw where they escaped.
  const StepFailure& failed_step() const { return failed_step_; }
  const StepPosition& position() const { return position_; }
  double time() const { return position_.time; }
  int steps() const { return position_.steps; }
  double end_time() const { return end_time_; }
  // The stops a step lands on, after 0 (find_step_stops).
  const std::vector<double>& stops() const { return stops_; }
  // The last step that converged (none before the first: step 0 at t = 0).
  const StepRecord& record() const { return record_; }
  // The model's state at the end of the last step (as built, or as resumed, before any).
  const CoupledState& state_at_step_end() const { return saved_; }

 private:
  CoupledModel& model_;
  StepControl control_;
  std::vector<double> stops_;
  double end_time_ = 0.0;
  StepPosition position_;
  StepRecord record_;
  CoupledState saved_;
  bool failed_ = false;
  std::string failure_;
  StepFailure failed_step_;
};

// summary.json's content for a coupled transient model at `time` after `steps` steps: the
// model's summary, its time, the steps as its iterations and the flow's rate of storage; no
// timings, no fractures.
output::RunSummary summarise_coupled_transient(const CoupledModel& model, double time, int steps);

}  // namespace hydrodda::run
