#include "coupling/load_ramp.hpp"

#include <algorithm>
#include <stdexcept>

namespace hydrodda::coupling {

double ramp_factor(int pass, int ramp_passes) {
  return std::min(1.0, static_cast<double>(pass) / ramp_passes);
}

void ramp_fluid_forces(std::vector<std::vector<geometry::Point>>& forces,
                       const std::vector<std::vector<geometry::Point>>& still, double factor) {
  if (factor >= 1.0) return;
  if (still.empty()) {
    for (std::vector<geometry::Point>& block : forces)
      for (geometry::Point& f : block) f = factor * f;
    return;
  }
  if (still.size() != forces.size())
    throw std::invalid_argument("load ramp: the still water's forces are for another number of blocks");
  for (std::size_t b = 0; b < forces.size(); ++b) {
    if (still[b].size() != forces[b].size())
      throw std::invalid_argument("load ramp: the still water's forces are for another number of vertices");
    for (std::size_t v = 0; v < forces[b].size(); ++v)
      forces[b][v] = still[b][v] + factor * (forces[b][v] - still[b][v]);
  }
}

}  // namespace hydrodda::coupling
