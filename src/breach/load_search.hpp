#pragma once
// The search for a breach load along one loading path: the load raised in equal steps, each
// from the last state that held, then the first step that did not hold bisected against the
// last that did, until the two are within a tolerance of each other.
//
//   held ← none, broken ← none
//   for L in from, from + Δ, …, to:            (Δ = (to − from) / steps)
//     try L from the kept state
//     holds? keep its state, held ← L; else broken ← L, stop
//   while held and broken and |broken − held| > tolerance · |broken|:
//     try m = (held + broken) / 2 from the state kept at `held`
//     holds? keep its state, held ← m; else broken ← m
// "holds": `held`, or `held_unsettled` unless SearchSettings::converged_only (docs/breach.md).
// A path-following search (the loading path of a limit analysis), as a laboratory raises a load
// on one specimen: every state is reached from the one before, never from the start, so that
// a path-dependent model (friction, contact states) is loaded as it would be.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hydrodda::breach {

// How a step at one load ended. `held`: the loop converged. `held_unsettled`: the loop did not
// converge but the blocks came to rest in every one of its last passes, so the model holds
// mechanically while its answer (K_eff) swings within a range; the search counts it as holding
// unless SearchSettings::converged_only. `beyond_limit` held too but past the limit the user
// set (e.g. a conductivity), which the search treats as the breach. `not_at_rest`: the blocks
// did not come to rest in several passes in a row (no state to hold:
// moving, or stalled on DDA steps cut short).
enum class StepStatus {
  held, held_unsettled, beyond_limit, not_converged, not_at_rest, no_equilibrium, failed, interrupted
};

// As breach.csv writes it: "held", "held, unsettled", "beyond limit", "not converged",
// "not at rest", "no equilibrium", "failed", "interrupted".
std::string status_name(StepStatus status);

struct StepResult {
  StepStatus status = StepStatus::failed;
  int passes = 0;        // coupling passes this step ran
  std::string message;   // why it did not hold; empty when it held
};

// What the search drives: a model that takes a load from its kept state and keeps a state.
class LoadStepper {
 public:
  virtual ~LoadStepper() = default;
  // Brings the model to `load`, starting from the state kept last (as built before any).
  virtual StepResult try_load(double load) = 0;
  // The state the last try_load reached becomes the kept one.
  virtual void keep_state() = 0;
};

struct SearchSettings {
  double from = 0.0, to = 1.0;
  int steps = 10;            // equal steps from `from` to `to`
  double tolerance = 5e-3;   // the bracket's width as a share of the breaking load
  int max_bisections = 30;
  // Only a converged step holds (`held_unsettled` then breaks): the loop's breach rather than the
  // model's mechanical one.
  bool converged_only = false;
};

// Whether the search counts a step that ended so as holding (its state kept, the load raised).
bool holds(StepStatus status, const SearchSettings& settings);

struct SearchStep {
  int index = 0;     // in the order tried
  double load = 0.0;
  bool bisection = false;
  StepResult result;
};

// Where the search ended: the largest load that held and the least that did not (either may be
// none: nothing held from `from` on, or everything held up to `to`).
struct SearchResult {
  std::optional<double> held, broken;
  std::optional<StepStatus> broken_status;
  bool interrupted = false;
  bool narrowed = false;  // the bracket reached the tolerance
  // Steps counted as holding that ended `held_unsettled` (all lie below the breach).
  int unsettled_held = 0;
  std::vector<SearchStep> steps;
};

// Runs the search. `on_step` is told after every step (before the state is kept); a step that
// ends `interrupted` ends the search where it is.
SearchResult search_breach(const SearchSettings& settings, LoadStepper& stepper,
                           const std::function<void(const SearchStep&)>& on_step = {});

// Throws std::invalid_argument naming the setting for settings that cannot be searched.
void check_settings(const SearchSettings& settings);

}  // namespace hydrodda::breach
