#include "run/load_stall.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "run/mechanics_rest.hpp"
#include "run/no_equilibrium.hpp"

namespace hydrodda::run {

bool LoadStallWatch::update(const dda::StepReport& step) {
  const double start = step.time - step.time_step;
  const bool short_step = step.time_step < mechanics_.time_step * (1.0 - 1e-9);
  if (!short_step || !loads_change_between(mechanics_, start, step.time)) {
    window_.clear();
    return false;
  }
  window_.push_back(step);
  if (window_.size() > static_cast<std::size_t>(kStalledSteps)) window_.pop_front();
  if (window_.size() < static_cast<std::size_t>(kStalledSteps)) return false;
  const Stall s = stall();
  return s.advanced < mechanics_.time_step && 2 * s.cut >= kStalledSteps && s.most_breaks > 0;
}

LoadStallWatch::Stall LoadStallWatch::stall() const {
  Stall s;
  if (window_.empty()) return s;
  s.from = window_.front().time - window_.front().time_step;
  s.advanced = window_.back().time - s.from;
  s.shortest = window_.front().time_step;
  for (const dda::StepReport& r : window_) {
    s.shortest = std::min(s.shortest, r.time_step);
    if (r.retries > 0) ++s.cut;
    s.most_breaks = std::max(s.most_breaks, r.most_breaks_in_a_cut_try);
  }
  return s;
}

std::string describe_load_stall(const scenario::Scenario& s, const LoadStallWatch::Stall& stall, double t,
                                const std::string& reactions, const StallBreaks& broken) {
  const std::string before =
      broken.bonds > 0 ? fmt::format(" ({} broke where the load stalled before, from t = {:g} s)", broken.bonds,
                                     broken.first)
                       : "";
  return fmt::format(
      "the load could not be raised past t = {:g} s ({}{}): its last {} steps, {} of them kept only after cuts, were "
      "short (to {:.3g} s at the shortest) and together advanced the time from {:g} s by {:.3g} s, against "
      "mechanics.time_step = {:g} s; their cut tries broke up to {} in a try, none of them still whole{}: the "
      "rock holds no more load, and t = {:g} s is the largest load it held (its peak)",
      t, describe_driving_load(s, t), reactions.empty() ? "" : "; reactions " + reactions, kStalledSteps, stall.cut,
      stall.shortest, stall.from, stall.advanced, s.mechanics->time_step,
      stall.most_breaks == 1 ? std::string("1 bond") : fmt::format("{} bonds", stall.most_breaks), before, t);
}

}  // namespace hydrodda::run
