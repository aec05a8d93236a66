#include "numerics/aitken.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace hydrodda::numerics {

double aitken_relaxation(double relaxation, std::span<const double> previous_update, std::span<const double> update) {
  if (previous_update.size() != update.size())
    throw std::invalid_argument("Aitken relaxation: the two updates differ in size");
  double numerator = 0.0, denominator = 0.0;
  for (std::size_t i = 0; i < update.size(); ++i) {
    const double change = update[i] - previous_update[i];
    numerator += previous_update[i] * change;
    denominator += change * change;
  }
  if (!(denominator > 0.0)) return relaxation;
  return std::clamp(-relaxation * numerator / denominator, kMinAitkenRelaxation, 1.0);
}

}  // namespace hydrodda::numerics
