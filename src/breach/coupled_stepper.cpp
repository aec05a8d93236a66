#include "breach/coupled_stepper.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <utility>

#include "coupling/pass_loop.hpp"
#include "output/summary_reading.hpp"
#include "run/coupled_messages.hpp"
#include "run/fracture_output.hpp"
#include "run/model_building.hpp"
#include "run/scenario_fractures.hpp"
#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::breach {

namespace {

const std::regex& flow_key() {
  static const std::regex key(R"(flow\.boundary\[\d+\]\.(head|pressure|flux))");
  return key;
}

// Asks the program's stop request before every pass; records nothing (the search records steps).
class StepObserver final : public coupling::PassObserver {
 public:
  explicit StepObserver(const std::function<bool()>& stop_requested) : stop_requested_(stop_requested) {}
  bool stop_requested() override { return stop_requested_ && stop_requested_(); }
  void after_pass(const coupling::PassReport& r) override {
    spdlog::debug("coupling iteration {}: head change {:.3e}, displacement change {:.3e}, largest opening {:.3e} m{}",
                  r.iteration, r.head_change, r.displacement_change, r.largest_opening, r.converged ? ", converged" : "");
  }

 private:
  const std::function<bool()>& stop_requested_;
};

std::string describe_blocks(const std::vector<coupling::EscapingBlock>& escaping) {
  std::string text;
  for (std::size_t i = 0; i < escaping.size() && i < 5; ++i)
    text += fmt::format("{}block {} (moved {:.3g} m, size {:.3g} m)", i ? ", " : "", escaping[i].block,
                        escaping[i].distance, escaping[i].size);
  if (escaping.size() > 5) text += fmt::format(" and {} more", escaping.size() - 5);
  return text;
}

}  // namespace

bool is_load_key(const std::string& key) {
  static const std::regex traction_key(R"(mechanics\.traction\[\d+\]\.(normal|shear))");
  return std::regex_match(key, flow_key()) || std::regex_match(key, traction_key);
}

scenario::Scenario scenario_at(const std::string& text, const std::filesystem::path& file,
                               const std::vector<std::string>& keys, double value) {
  std::vector<scenario::Override> overrides;
  for (const std::string& key : keys) overrides.push_back({key, fmt::format("{:.17g}", value)});
  return scenario::parse_scenario(scenario::apply_overrides(text, file, overrides), file);
}

Limit parse_limit(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw std::invalid_argument(
        fmt::format("--limit '{}': give PATH=VALUE, e.g. flow.regions.seal.normalised_conductivity=100", text));
  const std::string number = text.substr(equals + 1);
  std::size_t used = 0;
  double most = 0.0;
  try {
    most = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != number.size())
    throw std::invalid_argument(fmt::format("--limit '{}': '{}' is not a number", text, number));
  return Limit{text.substr(0, equals), most};
}

CoupledStepper::CoupledStepper(std::string text, std::filesystem::path file, std::vector<std::string> keys,
                               double first_load,
                               std::optional<Limit> limit, std::function<bool()> stop_requested)
    : text_(std::move(text)),
      file_(std::move(file)),
      keys_(std::move(keys)),
      limit_(std::move(limit)),
      stop_requested_(std::move(stop_requested)),
      kept_load_(first_load),
      last_load_(first_load) {
  if (keys_.empty()) throw std::invalid_argument("--vary: give the key of the load to raise");
  for (const std::string& key : keys_)
    if (!is_load_key(key))
      throw std::invalid_argument(fmt::format(
          "--vary {}: a loading path varies a boundary's head, pressure or flux (flow.boundary[i].head, ...) or a "
          "traction (mechanics.traction[i].normal or .shear)", key));
  const scenario::Scenario first = scenario_at(text_, file_, keys_, first_load);
  if (!first.flow || !first.mechanics)
    throw std::invalid_argument(fmt::format("{}: the breach search takes a coupled scenario ([flow] and [mechanics])",
                                            file_.string()));
  model_ = std::make_unique<run::CoupledModel>(first);
  model_->set_stop_request(stop_requested_);
  kept_ = model_->export_state();
  meter_ = run::make_fracture_meter(model_->scenario());
  if (meter_) flow_zones_ = meter_->flow_zones(model_->mesh());
  if (meter_) joint_laws_ = run::make_joint_aperture_laws(model_->scenario(), meter_->layout().traces);
}

void CoupledStepper::set_load(double load) {
  const scenario::Scenario at = scenario_at(text_, file_, keys_, load);
  const bool flow = std::any_of(keys_.begin(), keys_.end(), [](const std::string& k) { return std::regex_match(k, flow_key()); });
  const bool tractions = std::any_of(keys_.begin(), keys_.end(), [](const std::string& k) { return !std::regex_match(k, flow_key()); });
  if (flow) model_->set_flow_boundaries(at.flow->boundaries);
  if (tractions) model_->set_tractions(at.mechanics->tractions);
}

StepResult CoupledStepper::try_load(double load) {
  model_->import_state(kept_);
  set_load(load);
  last_load_ = load;
  StepResult result;
  const int before = model_->iterations();
  StepObserver observer(stop_requested_);
  try {
    const coupling::LoopResult loop =
        model_->run({before + model_->scenario().coupling.max_iterations, std::nullopt}, observer);
    result.passes = loop.passes_run;
    switch (loop.end) {
      case coupling::LoopEnd::converged: result.status = judge_converged_state(result.message); break;
      case coupling::LoopEnd::stop_requested: result.status = StepStatus::interrupted; break;
      case coupling::LoopEnd::escaping:
        result.status = StepStatus::no_equilibrium;
        result.message = "blocks escape: " + describe_blocks(loop.last_pass->escaping);
        break;
      case coupling::LoopEnd::diverging:
        result.status = StepStatus::not_converged;
        result.message = fmt::format("the coupling loop diverges ({} passes of growing change)",
                                     loop.last_pass->growing_passes);
        break;
      default:
        result.status = StepStatus::not_converged;
        result.message = fmt::format("the coupling loop did not converge in {} passes", loop.passes_run);
    }
  } catch (const coupling::PassInterrupted&) {
    model_->abandon_pass();
    result.status = StepStatus::interrupted;
  } catch (const std::exception& e) {
    const std::vector<coupling::EscapingBlock> escaping = model_->loop().blocks_beyond_their_size();
    model_->abandon_pass();
    result.passes = model_->iterations() - before + 1;
    result.status = escaping.empty() ? StepStatus::failed : StepStatus::no_equilibrium;
    result.message = escaping.empty() ? e.what() : "blocks escape: " + describe_blocks(escaping);
  }
  return result;
}

StepStatus CoupledStepper::judge_converged_state(std::string& message) const {
  if (!limit_) return StepStatus::held;
  const std::optional<std::string> value = output::summary_values(output::format_summary(summary()), {limit_->path})[0];
  if (!value) throw std::invalid_argument(fmt::format("--limit {}: summary.json has no value there", limit_->path));
  double number = 0.0;
  try {
    number = std::stod(*value);
  } catch (const std::exception&) {
    throw std::invalid_argument(fmt::format("--limit {}: summary.json holds '{}' there, not a number", limit_->path, *value));
  }
  if (number <= limit_->most) return StepStatus::held;
  message = fmt::format("{} = {:.4g} is above the limit {:.4g}", limit_->path, number, limit_->most);
  return StepStatus::beyond_limit;
}

void CoupledStepper::keep_state() {
  kept_ = model_->export_state();
  kept_load_ = last_load_;
}

void CoupledStepper::back_to_kept_state() {
  model_->import_state(kept_);
  set_load(kept_load_);
  last_load_ = kept_load_;
}

output::RunSummary CoupledStepper::summary() const {
  output::RunSummary summary = model_->summary();
  summary.converged = true;
  if (const std::optional<fractures::FractureState> state = measure_fractures())
    summary.fractures = run::summarise_fractures(*state, run::fracture_type_names(scenario()));
  return summary;
}

std::optional<fractures::FractureState> CoupledStepper::measure_fractures() const {
  if (!meter_) return std::nullopt;
  const dda::System& blocks = model_->mechanics();
  fractures::FractureState state =
      meter_->measure(model_->block_polygons(), blocks.penetration_tolerance(), blocks.contacts(), joint_laws_);
  if (model_->loop().has_flow()) meter_->add_flow(state, *flow_zones_, model_->mesh(), model_->loop().flow());
  return state;
}

}  // namespace hydrodda::breach
