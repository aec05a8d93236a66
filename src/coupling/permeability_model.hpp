#pragma once
// Permeability per fluid element from its equivalent porosity, by the scenario's law.

#include <span>
#include <vector>

#include "coupling/porosity.hpp"

namespace hydrodda::coupling {

enum class PermeabilityLaw { kozeny_carman, cubic };

struct PermeabilityModel {
  PermeabilityLaw law = PermeabilityLaw::kozeny_carman;
  double grain_diameter = 0.0;   // m (Kozeny–Carman)
  double cap = 9.869e-11;        // m² (Kozeny–Carman)
  double matrix_porosity = 0.0;

  // k per element. Kozeny–Carman: the paper's eq. 9 on φ_e. Cubic: not available yet (the
  // local aperture per element is not computed yet): throws rather than guess.
  std::vector<double> compute(const PorosityField& porosity, std::span<const double> element_areas) const;
};

}  // namespace hydrodda::coupling
