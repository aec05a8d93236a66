#include "coupling/settling_watch.hpp"

#include <cmath>

namespace hydrodda::coupling {

bool SettlingWatch::slows_to_rest(double u_before, double u_now, double at_rest, int steps_left) {
  if (u_now <= at_rest) return true;
  if (!(u_now < u_before)) return false;  // steady or faster
  // u_{k+n} = u_k r^n ≤ at_rest  ⇔  n ≥ ln(at_rest/u_k) / ln r  (both logarithms negative)
  const double steps_to_rest = std::log(at_rest / u_now) / std::log(u_now / u_before);
  return steps_to_rest <= static_cast<double>(steps_left);
}

void SettlingWatch::observe(const dda::FreeDrift& drift, int steps_left) {
  const auto left = static_cast<double>(steps_left);
  drifting_block_ = -1;
  bool adrift = false;  // a block meets nothing and does not slow into a rest
  double latest = 0.0;
  for (std::size_t b = 0; b < drift.landing_steps.size() && !adrift; ++b) {
    const double lands = drift.landing_steps[b];
    if (lands <= left) continue;  // at rest, or lands in time
    if (b < last_motion_.size() && slows_to_rest(last_motion_[b], drift.motion[b], at_rest_, steps_left)) continue;
    if (!(lands < dda::FreeDrift::kNever)) {
      adrift = true;
    } else if (lands > latest) {
      latest = lands;
      drifting_block_ = static_cast<int>(b);
    }
  }
  if (adrift) drifting_block_ = -1;
  drifting_steps_ = drifting_block_ >= 0 ? drifting_steps_ + 1 : 0;
  last_motion_ = drift.motion;
}

}  // namespace hydrodda::coupling
