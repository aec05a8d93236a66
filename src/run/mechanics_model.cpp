#include "run/mechanics_model.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "run/model_building.hpp"
#include "run/run_summary.hpp"

namespace hydrodda::run {

MechanicsModel::MechanicsModel(const scenario::Scenario& scenario)
    : scenario_(scenario),
      initial_blocks_(build_blocks(scenario_)),
      system_(build_mechanics_model(scenario_, initial_blocks_)),
      end_time_(mechanics_duration(*scenario_.mechanics)) {
  spdlog::info("mechanics: {} blocks, penalty {:.3g} N/m, allowed step displacement {:.3g} m",
               system_.block_count(), system_.penalty(), system_.allowed_step_displacement());
}

bool MechanicsModel::finished() const {
  const scenario::MechanicsDefinition& m = *scenario_.mechanics;
  return m.steps ? steps_ >= *m.steps : system_.time() >= end_time_ * (1.0 - 1e-12);
}

dda::StepReport MechanicsModel::step(const std::function<bool(const dda::StepReport&)>& after_each) {
  const scenario::MechanicsDefinition& m = *scenario_.mechanics;
  dda::StepReport r;
  if (m.steps) {
    r = system_.step();
    if (after_each) after_each(r);
  } else {
    r = system_.run_until(std::min(end_time_, system_.time() + m.time_step), after_each);
  }
  ++steps_;
  return r;
}

void MechanicsModel::set_tractions(std::vector<scenario::Traction> tractions) {
  scenario::Scenario changed = scenario_;
  changed.mechanics->tractions = std::move(tractions);
  system_.set_tractions(build_tractions(changed, initial_blocks_));
  scenario_ = std::move(changed);
}

output::RunSummary MechanicsModel::summary() const {
  output::RunSummary summary = summarise_mechanics(scenario_, system_);
  summary.iterations = static_cast<int>(steps_);
  return summary;
}

}  // namespace hydrodda::run
