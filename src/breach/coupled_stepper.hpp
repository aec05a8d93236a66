#pragma once
// A coupled model taken along a loading path: one value of the scenario, a boundary's head,
// pressure or flux or a traction, changed between converged states, each step run by the
// coupling loop from the last state that held (breach/load_search.hpp's LoadStepper).

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "breach/load_search.hpp"
#include "breach/pass_trail.hpp"
#include "fractures/fracture_results.hpp"
#include "coupling/joint_aperture_laws.hpp"
#include "coupling/pass_report.hpp"
#include "output/summary.hpp"
#include "run/coupled_model.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::breach {

// The key paths a loading path may vary (those of Simulation.set): flow.boundary[i].head,
// .pressure or .flux, and mechanics.traction[i].normal or .shear.
bool is_load_key(const std::string& key);

// The scenario with every one of `keys` at `value`, read again from its text; throws
// scenario::ScenarioError as reading does.
scenario::Scenario scenario_at(const std::string& text, const std::filesystem::path& file,
                               const std::vector<std::string>& keys, double value);

// What holding means beyond a converged state: a summary.json value (e.g.
// flow.regions.seal.normalised_conductivity) that must stay at or below `most`.
struct Limit {
  std::string path;
  double most = 0.0;
};

// "PATH=VALUE" (--limit) as a Limit; std::invalid_argument naming the text otherwise.
Limit parse_limit(const std::string& text);

class CoupledStepper final : public LoadStepper {
 public:
  // Builds the model of `text` (from `file`) with each of `keys` at `first_load` (they move
  // together: the heads of two inflow boundaries, say). `stop_requested` is asked between
  // passes and DDA steps.
  CoupledStepper(std::string text, std::filesystem::path file, std::vector<std::string> keys, double first_load,
                 std::optional<Limit> limit, std::function<bool()> stop_requested);

  StepResult try_load(double load) override;
  void keep_state() override;

  // The model at the kept state (the last that held), its load set again, so that its fields
  // and summary are that state's.
  void back_to_kept_state();
  // The state the model is in as summary.json would give it (fractures included), with the
  // step's status.
  output::RunSummary summary() const;
  // The fractures as the blocks stand, with their flow; none for a scenario that lists its blocks.
  std::optional<fractures::FractureState> measure_fractures() const;
  // Per flow region, K_eff/K_m's range over the last passes of the state the model is in when
  // it held unsettled (a region without a value: none); empty for any other state.
  const std::vector<std::optional<ValueRange>>& unsettled_ranges() const { return last_ranges_; }
  const run::CoupledModel& model() const { return *model_; }
  const scenario::Scenario& scenario() const { return model_->scenario(); }

 private:
  void set_load(double load);
  StepStatus judge_converged_state(std::string& message) const;
  StepStatus judge_unconverged_state(int passes, std::string& message);
  std::string describe_last_pass(const coupling::PassReport& last) const;
  StepStatus judge_unsettled_limit(std::string& message) const;
  double limited_value() const;  // the --limit path's value in summary()
  std::string describe_not_at_rest(double largest_opening) const;
  void record_pass(const coupling::PassReport& report);

  std::string text_;
  std::filesystem::path file_;
  std::vector<std::string> keys_;
  std::optional<Limit> limit_;
  std::function<bool()> stop_requested_;
  std::unique_ptr<run::CoupledModel> model_;
  run::CoupledState kept_;
  double kept_load_;
  double last_load_;
  PassTrail trail_;  // the passes of the step under way (or the last)
  // How the last try and the kept state ended, and their K_eff/K_m ranges when unsettled.
  StepStatus last_status_ = StepStatus::held, kept_status_ = StepStatus::held;
  bool last_unsettled_ = false, kept_unsettled_ = false;  // held unsettled, beyond the limit or not
  std::vector<std::optional<ValueRange>> last_ranges_, kept_ranges_;
  int last_range_passes_ = 0, kept_range_passes_ = 0;  // the passes those ranges are over
  // What summary() measures the fractures with (none for listed blocks), found once.
  std::optional<fractures::FractureMeter> meter_;
  std::optional<fractures::FractureMeter::FlowZones> flow_zones_;
  coupling::JointApertureLaws joint_laws_;  // by fracture id, the meter's
};

}  // namespace hydrodda::breach
