#include "run/mechanics_model.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "run/model_building.hpp"
#include "run/run_summary.hpp"

namespace hydrodda::run {

MechanicsModel::MechanicsModel(const scenario::Scenario& scenario)
    : scenario_(scenario),
      system_(build_mechanics_model(scenario_, build_blocks(scenario_))),
      end_time_(mechanics_duration(*scenario_.mechanics)) {
  spdlog::info("mechanics: {} blocks, penalty {:.3g} N/m, allowed step displacement {:.3g} m",
               system_.block_count(), system_.penalty(), system_.allowed_step_displacement());
}

bool MechanicsModel::finished() const {
  const scenario::MechanicsDefinition& m = *scenario_.mechanics;
  return m.steps ? steps_ >= *m.steps : system_.time() >= end_time_ * (1.0 - 1e-12);
}

dda::StepReport MechanicsModel::step() {
  const scenario::MechanicsDefinition& m = *scenario_.mechanics;
  const dda::StepReport r =
      m.steps ? system_.step() : system_.run_until(std::min(end_time_, system_.time() + m.time_step));
  ++steps_;
  return r;
}

output::RunSummary MechanicsModel::summary() const {
  output::RunSummary summary = summarise_mechanics(scenario_, system_);
  summary.iterations = static_cast<int>(steps_);
  return summary;
}

}  // namespace hydrodda::run
