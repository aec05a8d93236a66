#pragma once
// How long each block a static step moved freely takes, at the step's rates, to come to rest
// on something (free_drift.cpp, System::free_drift()).

#include <limits>
#include <vector>

namespace hydrodda::dda {

struct FreeDrift {
  static constexpr double kNever = std::numeric_limits<double>::infinity();
  // Per block, of the last step: its largest vertex displacement (m), and the steps it takes
  // at the step's rates to land: 0 for a block at rest, fixed, or held by closed contacts to
  // one that is; kNever for one that meets nothing.
  std::vector<double> motion;
  std::vector<double> landing_steps;
};

}  // namespace hydrodda::dda
