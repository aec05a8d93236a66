#include "breach/coupled_stepper.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <utility>

#include "coupling/pass_loop.hpp"
#include "numerics/distinct_digits.hpp"
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

// Asks the program's stop request before every pass, and ends a step whose blocks came to rest
// in none of kPassesNotAtRest passes in a row (with settling passes: without them no pass
// tests for rest), unless the last of them is getting through the chatter that cut its DDA
// steps short, still moving the blocks past the loop's tolerance (pass_trail.hpp); tells
// `record` after every pass. Records nothing else (the search records steps).
class StepObserver final : public coupling::PassObserver {
 public:
  StepObserver(const std::function<bool()>& stop_requested, bool settling, const PassTrail& trail,
               std::function<void(const coupling::PassReport&)> record)
      : stop_requested_(stop_requested), settling_(settling), trail_(trail), record_(std::move(record)) {}
  bool stop_requested() override { return user_stop() || not_at_rest(); }
  bool user_stop() const { return stop_requested_ && stop_requested_(); }
  bool not_at_rest() const {
    return settling_ && trail_.passes_not_at_rest() >= kPassesNotAtRest && !trail_.getting_through();
  }
  void after_pass(const coupling::PassReport& r) override {
    spdlog::debug("coupling iteration {}: head change {:.3e}, displacement change {:.3e}, largest opening {:.3e} m, "
                  "{}, last step {}, {} step cuts, {} crossings switched{}",
                  r.iteration, r.head_change, r.displacement_change, r.largest_opening,
                  r.at_rest ? "at rest" : "not at rest", r.full_time_step ? "at the full time step" : "cut short",
                  r.step_cuts, r.joint_crossings_switched, r.converged ? ", converged" : "");
    record_(r);
  }

 private:
  const std::function<bool()>& stop_requested_;
  bool settling_;
  const PassTrail& trail_;
  std::function<void(const coupling::PassReport&)> record_;
};

std::string describe_blocks(const std::vector<coupling::EscapingBlock>& escaping) {
  std::string text;
  for (std::size_t i = 0; i < escaping.size() && i < 5; ++i)
    text += fmt::format("{}block {} (moved {:.3g} m, size {:.3g} m)", i ? ", " : "", escaping[i].block,
                        escaping[i].distance, escaping[i].size);
  if (escaping.size() > 5) text += fmt::format(" and {} more", escaping.size() - 5);
  return text;
}

// "K_eff/K_m of region 'seal' from 966 to 1044 (7.5%)", over the regions with a range.
std::string describe_ranges(const std::vector<std::optional<ValueRange>>& ranges,
                            const std::vector<scenario::FlowRegion>& regions) {
  std::string text;
  for (std::size_t r = 0; r < ranges.size() && r < regions.size(); ++r)
    if (ranges[r] && ranges[r]->spread() > 1e-9) {  // a region whose answer did not move is no news
      const std::array<std::string, 2> ends = numerics::format_apart(ranges[r]->least, ranges[r]->largest, 4);
      text += fmt::format("{}K_eff/K_m of region '{}' from {} to {} ({:.2g}%)", text.empty() ? "" : ", ",
                          regions[r].name, ends[0], ends[1], 100.0 * ranges[r]->spread());
    }
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
  trail_.clear();
  last_ranges_.clear();
  last_unsettled_ = false;
  StepResult result;
  const int before = model_->iterations();
  StepObserver observer(stop_requested_, model_->scenario().coupling.settle, trail_,
                        [this](const coupling::PassReport& r) { record_pass(r); });
  try {
    const coupling::LoopLimits limits{before + model_->scenario().coupling.max_iterations, std::nullopt};
    coupling::LoopResult loop = model_->run(limits, observer);
    result.passes = loop.passes_run;
    // A step begun from a converged state starts with a change far under the tolerance; a loop
    // that then swings grows tenfold within five passes and reads as diverging. While every pass
    // so far left the blocks at rest, the step runs its passes out to show whether the swing is
    // bounded (held, unsettled) or still growing at its last pass (not converged).
    while (loop.end == coupling::LoopEnd::diverging && model_->iterations() < limits.max_passes &&
           model_->scenario().coupling.settle && trail_.rested_in_last(trail_.passes())) {
      loop = model_->run(limits, observer);
      result.passes += loop.passes_run;
    }
    switch (loop.end) {
      case coupling::LoopEnd::converged: result.status = judge_converged_state(result.message); break;
      case coupling::LoopEnd::stop_requested:
        if (observer.user_stop() || !observer.not_at_rest()) {
          result.status = StepStatus::interrupted;
          break;
        }
        result.status = StepStatus::not_at_rest;
        result.message = describe_not_at_rest(loop.last_pass->largest_opening);
        break;
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
        result.status = judge_unconverged_state(loop.passes_run, result.message);
        if (loop.last_pass) result.message += describe_last_pass(*loop.last_pass);
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
  last_status_ = result.status;
  return result;
}

void CoupledStepper::record_pass(const coupling::PassReport& r) {
  std::vector<std::optional<double>> conductivity;
  for (const std::optional<output::RegionSummary>& region : model_->region_flows())
    conductivity.push_back(region ? region->normalised_conductivity : std::nullopt);
  trail_.add(r.at_rest, r.full_time_step, r.displacement_change > model_->scenario().coupling.tolerance,
             std::move(conductivity));
}

// Why a step whose blocks came to rest in none of kPassesNotAtRest passes in a row ended: its
// last pass moving at the full time step, or stalled on steps cut short that no longer moved
// the blocks past the loop's tolerance (neither moving nor passing the at-rest test: whether
// they would rest is unknown).
std::string CoupledStepper::describe_not_at_rest(double largest_opening) const {
  const int passes = trail_.passes_not_at_rest();
  const int cut = trail_.passes_cut_short(passes);
  std::string how;
  if (cut == 0)
    how = ", still moving at the full time step";
  else if (trail_.passes_cut_short(1) == 0)
    how = fmt::format(" ({} of them ended on DDA steps cut short; the last still moved the blocks at the full time "
                      "step)", cut);
  else
    how = fmt::format(" ({} of them ended on DDA steps cut short, the last without moving the blocks by the loop's "
                      "tolerance: they stall, barely moving, and do not pass the at-rest test)", cut);
  return fmt::format("the blocks came to rest in none of {} passes in a row, each with its settling steps{}; the largest "
                     "opening {:.3g} m", passes, how, largest_opening);
}

// "; at its last pass the head change 6.2e-05 and the displacement change 0.0038 (tolerance
// 0.0001)", and where the displacement change is above the tolerance the blocks that moved
// most in that pass: which norm holds the loop open, and whether a few pieces hold it.
std::string CoupledStepper::describe_last_pass(const coupling::PassReport& last) const {
  const double tolerance = model_->scenario().coupling.tolerance;
  std::string text = fmt::format("; at its last pass the head change {:.2g} and the displacement change {:.2g} "
                                 "(tolerance {:g})", last.head_change, last.displacement_change, tolerance);
  if (last.displacement_change >= tolerance)
    if (const std::string movers = run::describe_last_pass_movers(model_->loop().last_pass_motion(), model_->mechanics());
        !movers.empty())
      text += "; " + movers;
  return text;
}

// A loop that ran its passes out: held, unsettled when settling passes brought the blocks to
// rest in each of its last kUnsettledPasses (or all, if fewer); else not converged.
StepStatus CoupledStepper::judge_unconverged_state(int passes, std::string& message) {
  const bool settling = model_->scenario().coupling.settle;
  if (!settling) {
    message = fmt::format("the coupling loop did not converge in {} passes (without coupling.settle no pass tests the "
                          "blocks for rest)", passes);
    return StepStatus::not_converged;
  }
  if (!trail_.rested_in_last(kUnsettledPasses)) {
    const int over = std::min(kUnsettledPasses, trail_.passes());
    const int cut = trail_.passes_cut_short(kUnsettledPasses);
    message = fmt::format("the coupling loop did not converge in {} passes, and its blocks did not come to rest in each "
                          "of the last {}{}", passes, over,
                          cut > 0 ? fmt::format(" ({} of them ended on a DDA step cut short, whose at-rest test "
                                                "proves nothing)", cut)
                                  : "");
    return StepStatus::not_converged;
  }
  last_ranges_ = trail_.ranges_over_last(kUnsettledPasses);
  const int over = std::min(kUnsettledPasses, trail_.passes());
  last_range_passes_ = over;
  const std::string ranges = describe_ranges(last_ranges_, model_->scenario().flow->regions);
  message = fmt::format("the coupling loop did not converge in {} passes; the blocks came to rest in each of the last "
                        "{}{}", passes, over, ranges.empty() ? "" : ", over which " + ranges);
  last_unsettled_ = true;
  return judge_unsettled_limit(message);
}

// A state that held unsettled is beyond the limit where the limited value passed its bound in
// any of its last passes: a region's K_eff/K_m by the largest of its range, any other value by
// the last pass's (summary.json's).
StepStatus CoupledStepper::judge_unsettled_limit(std::string& message) const {
  if (!limit_) return StepStatus::held_unsettled;
  std::optional<double> largest;
  const std::vector<scenario::FlowRegion>& regions = scenario().flow->regions;
  for (std::size_t r = 0; r < last_ranges_.size() && r < regions.size(); ++r)
    if (last_ranges_[r] && limit_->path == "flow.regions." + regions[r].name + ".normalised_conductivity")
      largest = last_ranges_[r]->largest;
  const double value = largest ? *largest : limited_value();
  if (value <= limit_->most) return StepStatus::held_unsettled;
  message = fmt::format("{} up to {:.4g} over its last passes is above the limit {:.4g}; {}", limit_->path, value,
                        limit_->most, message);
  return StepStatus::beyond_limit;
}

double CoupledStepper::limited_value() const {
  const std::optional<std::string> value = output::summary_values(output::format_summary(summary()), {limit_->path})[0];
  if (!value) throw std::invalid_argument(fmt::format("--limit {}: summary.json has no value there", limit_->path));
  try {
    return std::stod(*value);
  } catch (const std::exception&) {
    throw std::invalid_argument(fmt::format("--limit {}: summary.json holds '{}' there, not a number", limit_->path, *value));
  }
}

StepStatus CoupledStepper::judge_converged_state(std::string& message) const {
  if (!limit_) return StepStatus::held;
  const double number = limited_value();
  if (number <= limit_->most) return StepStatus::held;
  message = fmt::format("{} = {:.4g} is above the limit {:.4g}", limit_->path, number, limit_->most);
  return StepStatus::beyond_limit;
}

void CoupledStepper::keep_state() {
  kept_ = model_->export_state();
  kept_load_ = last_load_;
  kept_status_ = last_status_;
  kept_unsettled_ = last_unsettled_;
  kept_ranges_ = last_ranges_;
  kept_range_passes_ = last_range_passes_;
}

void CoupledStepper::back_to_kept_state() {
  model_->import_state(kept_);
  set_load(kept_load_);
  last_load_ = kept_load_;
  last_status_ = kept_status_;
  last_unsettled_ = kept_unsettled_;
  last_ranges_ = kept_ranges_;
  last_range_passes_ = kept_range_passes_;
}

output::RunSummary CoupledStepper::summary() const {
  output::RunSummary summary = model_->summary();
  // An unsettled state is the last pass's of a loop that did not converge: each region's answer
  // is the range over its last passes, not one number.
  summary.converged = !last_unsettled_;
  const std::vector<scenario::FlowRegion>& regions = scenario().flow->regions;
  if (summary.flow)
    for (output::RegionSummary& region : summary.flow->regions)
      for (std::size_t r = 0; r < last_ranges_.size() && r < regions.size(); ++r)
        if (last_ranges_[r] && regions[r].name == region.name)
          region.last_passes = output::RegionSummary::PassRange{last_range_passes_, last_ranges_[r]->least,
                                                                last_ranges_[r]->largest};
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
