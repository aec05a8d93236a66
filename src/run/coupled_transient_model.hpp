#pragma once
// A coupled transient model stepped by hand (Python's Simulation): the CoupledModel with its
// heads at t = 0, its CoupledTransientStepper and its probes, stepped as the run steps it, so
// that stepped to the end it reads the run's probes.csv rows at every step, digit for digit.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "coupling/joint_aperture_laws.hpp"
#include "fractures/fracture_results.hpp"
#include "output/summary.hpp"
#include "run/bond_output.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient_stepper.hpp"
#include "run/no_equilibrium.hpp"
#include "run/transient_flow.hpp"
#include "run/transient_model.hpp"

namespace hydrodda::run {

// A bond's break as the run records it: at the time step whose iterations broke it, its row of
// fractures.csv at that step (`row.time` the step's end).
struct SteppedBondBreak {
  int step = 0;
  BrokenBondRow row;
};

class CoupledTransientModel {
 public:
  // Builds the model (as CoupledModel does) and takes its heads at t = 0. Throws
  // std::invalid_argument for a scenario without [mechanics], [flow] and [flow.transient].
  explicit CoupledTransientModel(const scenario::Scenario& scenario);

  // One time step (CoupledTransientStepper::step), its DDA steps asking `stop_requested`.
  CoupledTransientStepper::Outcome step(const std::function<bool()>& stop_requested = {});

  double time() const { return stepper_->time(); }
  int steps() const { return stepper_->steps(); }
  // end_time reached, or a step failed at the floor (failed(), failure() says why).
  bool finished() const { return stepper_->finished(); }
  bool failed() const { return stepper_->failed(); }
  const std::string& failure() const { return stepper_->failure(); }
  const CoupledTransientStepper& stepper() const { return *stepper_; }
  const CoupledModel& model() const { return *model_; }

  // The bonds broken so far, by time step (fractures.csv's bond rows: a step cut and tried again
  // keeps only the breaks of the try that converged); empty without bonds.
  const std::vector<SteppedBondBreak>& broken_bonds() const { return broken_bonds_; }

  // probes.csv's rows at time(): each [[flow.probe]]'s head and pressure.
  std::vector<ProbeReading> read_probes() const;
  // summary.json's content for the state now (no timings, no fractures): time, the steps as
  // `iterations`, the rate of storage; `converged` when end_time is reached without a failure,
  // else false with the failure as `message`; a step that threw blocks in its first iteration,
  // status "no equilibrium", the run's message and `last_held` (no_equilibrium_in_time.hpp).
  output::RunSummary summary() const;

 private:
  void record_breaks();
  // The blocks as built, or the step just taken, as the last state that held, where no block is
  // farther than its own size (the run's record, its fractures measured alike).
  void hold_if_held();

  std::unique_ptr<CoupledModel> model_;
  std::unique_ptr<CoupledTransientStepper> stepper_;
  std::vector<ProbeSite> sites_;
  int trace_count_ = 0;  // the fractures the traces number: the broken bonds' ids follow theirs
  std::vector<SteppedBondBreak> broken_bonds_;
  std::optional<fractures::FractureMeter> meter_;  // a scenario with a [geometry] domain
  coupling::JointApertureLaws joint_laws_;
  HeldState held_;
};

}  // namespace hydrodda::run
