#include "hydro/permeability_law.hpp"

#include <algorithm>
#include <stdexcept>

namespace hydrodda::hydro {

double kozeny_carman_permeability(double porosity, double grain_diameter, double cap) {
  if (!(porosity >= 0.0 && porosity <= 1.0))
    throw std::invalid_argument("Kozeny-Carman: porosity must lie in [0, 1]");
  if (porosity >= 1.0) return cap;
  const double one_minus = 1.0 - porosity;
  const double k = grain_diameter * grain_diameter * porosity * porosity * porosity / (180.0 * one_minus * one_minus);
  return std::min(k, cap);
}

double cubic_law_permeability(double fracture_fraction, double aperture, double matrix_permeability) {
  if (!(fracture_fraction >= 0.0 && fracture_fraction <= 1.0))
    throw std::invalid_argument("cubic law: the fracture fraction must lie in [0, 1]");
  return matrix_permeability + fracture_fraction * aperture * aperture / 12.0;
}

}  // namespace hydrodda::hydro
