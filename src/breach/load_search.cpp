#include "breach/load_search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace hydrodda::breach {

std::string status_name(StepStatus status) {
  switch (status) {
    case StepStatus::held: return "held";
    case StepStatus::held_unsettled: return "held, unsettled";
    case StepStatus::beyond_limit: return "beyond limit";
    case StepStatus::not_converged: return "not converged";
    case StepStatus::not_at_rest: return "not at rest";
    case StepStatus::no_equilibrium: return "no equilibrium";
    case StepStatus::failed: return "failed";
    case StepStatus::interrupted: return "interrupted";
  }
  return "failed";
}

void check_settings(const SearchSettings& s) {
  if (!std::isfinite(s.from) || !std::isfinite(s.to)) throw std::invalid_argument("--from and --to must be finite numbers");
  if (s.from == s.to) throw std::invalid_argument(fmt::format("--from and --to are both {:g}: nothing to search", s.from));
  if (s.steps < 1) throw std::invalid_argument(fmt::format("--steps must be at least 1, not {}", s.steps));
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0))
    throw std::invalid_argument(fmt::format("--tolerance must be between 0 and 1 (a share of the load), not {:g}", s.tolerance));
}

bool holds(StepStatus status, const SearchSettings& settings) {
  return status == StepStatus::held || (status == StepStatus::held_unsettled && !settings.converged_only);
}

namespace {

class Search {
 public:
  Search(const SearchSettings& settings, LoadStepper& stepper, const std::function<void(const SearchStep&)>& on_step)
      : settings_(settings), stepper_(stepper), on_step_(on_step) {}

  // Tries `load` from the kept state; keeps the state when it held. Whether it held.
  bool attempt(double load, bool bisection) {
    SearchStep step{static_cast<int>(result_.steps.size()), load, bisection, stepper_.try_load(load)};
    if (on_step_) on_step_(step);
    result_.steps.push_back(step);
    const StepStatus status = step.result.status;
    if (status == StepStatus::interrupted) {
      result_.interrupted = true;
      return false;
    }
    if (holds(status, settings_)) {
      stepper_.keep_state();
      result_.held = load;
      if (status == StepStatus::held_unsettled) ++result_.unsettled_held;
      return true;
    }
    result_.broken = load;
    result_.broken_status = status;
    return false;
  }

  SearchResult& result() { return result_; }

 private:
  const SearchSettings& settings_;
  LoadStepper& stepper_;
  const std::function<void(const SearchStep&)>& on_step_;
  SearchResult result_;
};

bool narrow_enough(double held, double broken, double tolerance) {
  return std::abs(broken - held) <= tolerance * std::abs(broken);
}

}  // namespace

SearchResult search_breach(const SearchSettings& settings, LoadStepper& stepper,
                           const std::function<void(const SearchStep&)>& on_step) {
  check_settings(settings);
  Search search(settings, stepper, on_step);
  SearchResult& r = search.result();
  for (int i = 0; i <= settings.steps; ++i) {
    // The last step lands on `to` exactly, whatever the round-off of the sum.
    const double load = i == settings.steps ? settings.to
                                            : settings.from + (settings.to - settings.from) * i / settings.steps;
    if (!search.attempt(load, false)) break;
  }
  if (r.interrupted || !r.held || !r.broken) return std::move(r);
  for (int b = 0; b < settings.max_bisections && !narrow_enough(*r.held, *r.broken, settings.tolerance); ++b) {
    search.attempt(0.5 * (*r.held + *r.broken), true);
    if (r.interrupted) return std::move(r);
  }
  r.narrowed = narrow_enough(*r.held, *r.broken, settings.tolerance);
  return std::move(r);
}

}  // namespace hydrodda::breach
