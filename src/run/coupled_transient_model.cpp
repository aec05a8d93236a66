#include "run/coupled_transient_model.hpp"

#include <stdexcept>

#include "run/model_building.hpp"
#include "run/no_equilibrium_in_time.hpp"
#include "run/scenario_fractures.hpp"

namespace hydrodda::run {

namespace {

const scenario::Scenario& checked(const scenario::Scenario& s) {
  if (!s.mechanics || !s.flow || !s.flow->transient)
    throw std::invalid_argument("CoupledTransientModel: the scenario needs [mechanics], [flow] and [flow.transient]");
  return s;
}

}  // namespace

CoupledTransientModel::CoupledTransientModel(const scenario::Scenario& scenario)
    : model_(std::make_unique<CoupledModel>(checked(scenario))) {
  model_->start_in_time();
  stepper_ = std::make_unique<CoupledTransientStepper>(*model_);
  sites_ = locate_probes(model_->scenario(), model_->mesh());
  if (model_->mechanics().bond_count() > 0)
    trace_count_ = static_cast<int>(fracture_type_names(model_->scenario()).size());
  meter_ = make_fracture_meter(model_->scenario());
  if (meter_) joint_laws_ = make_joint_aperture_laws(model_->scenario(), meter_->layout().traces);
  hold_if_held();
}

CoupledTransientStepper::Outcome CoupledTransientModel::step(const std::function<bool()>& stop_requested) {
  model_->set_stop_request(stop_requested);
  struct Unset {
    CoupledModel& model;
    ~Unset() { model.set_stop_request({}); }
  } unset{*model_};
  const CoupledTransientStepper::Outcome outcome = stepper_->step(stop_requested);
  if (outcome == CoupledTransientStepper::Outcome::stepped) {
    record_breaks();
    hold_if_held();
  }
  return outcome;
}

// The breaks the system lists beyond those recorded: the step just taken's (a step cut and
// tried again starts again from the last step's state, its breaks with it).
void CoupledTransientModel::record_breaks() {
  const dda::System& system = model_->mechanics();
  const std::vector<dda::BondBreak>& breaks = system.bond_breaks();
  for (std::size_t k = broken_bonds_.size(); k < breaks.size(); ++k)
    broken_bonds_.push_back({steps(), broken_bond_row(model_->scenario(), system, breaks[k], trace_count_, time())});
}

void CoupledTransientModel::hold_if_held() {
  const dda::System& system = model_->mechanics();
  if (!find_escaping_blocks(system).empty()) return;
  std::optional<fractures::FractureState> state;
  if (meter_)
    state = meter_->measure(model_->block_polygons(), system.penetration_tolerance(), system.contacts(), joint_laws_);
  held_ = hold_time_step(steps(), time(), system, state ? &*state : nullptr);
}

std::vector<ProbeReading> CoupledTransientModel::read_probes() const {
  const hydro::FlowSolution& flow = model_->loop().flow();
  std::vector<ProbeReading> readings;
  for (const ProbeSite& site : sites_)
    readings.push_back({site.name, value_at(site, model_->mesh(), flow.head), value_at(site, model_->mesh(), flow.pressure)});
  return readings;
}

output::RunSummary CoupledTransientModel::summary() const {
  output::RunSummary summary = summarise_coupled_transient(*model_, time(), steps());
  summary.converged = finished() && !failed();
  if (failed_without_equilibrium(*stepper_)) {
    summary.status = "no equilibrium";
    summary.message =
        describe_time_step_without_equilibrium(model_->scenario(), *stepper_, held_, model_->mechanics(), nullptr);
    summary.last_held = summarise_held_state(held_);
  } else if (failed()) {
    summary.message = failure();
  }
  return summary;
}

}  // namespace hydrodda::run
