#include "run/coupled_transient_model.hpp"

#include <stdexcept>

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
}

CoupledTransientStepper::Outcome CoupledTransientModel::step(const std::function<bool()>& stop_requested) {
  model_->set_stop_request(stop_requested);
  struct Unset {
    CoupledModel& model;
    ~Unset() { model.set_stop_request({}); }
  } unset{*model_};
  return stepper_->step(stop_requested);
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
  if (failed()) summary.message = failure();
  return summary;
}

}  // namespace hydrodda::run
