#include "coupling/permeability_model.hpp"

#include <stdexcept>

#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {

std::vector<double> PermeabilityModel::compute(const PorosityField& porosity, std::span<const double>) const {
  if (law == PermeabilityLaw::cubic)
    throw std::runtime_error("flow.permeability_law = \"cubic\" is not available yet: the local aperture per "
                             "element is not computed yet; use \"kozeny-carman\"");
  std::vector<double> k(porosity.porosity.size());
  for (std::size_t e = 0; e < k.size(); ++e)
    k[e] = hydro::kozeny_carman_permeability(porosity.porosity[e], grain_diameter, cap);
  return k;
}

}  // namespace hydrodda::coupling
