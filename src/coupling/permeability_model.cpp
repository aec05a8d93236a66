#include "coupling/permeability_model.hpp"

#include <stdexcept>

#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {

std::vector<double> PermeabilityModel::compute(const PorosityField& porosity, std::span<const double> element_areas,
                                               std::span<const double> apertures) const {
  std::vector<double> k(porosity.porosity.size());
  if (law == PermeabilityLaw::cubic) {
    if (apertures.size() != k.size() || element_areas.size() != k.size())
      throw std::invalid_argument("cubic law: one aperture and one area per element are needed");
    const double k_matrix = matrix_permeability();
    for (std::size_t e = 0; e < k.size(); ++e)
      k[e] = hydro::cubic_law_permeability(porosity.fracture_area[e] / element_areas[e], apertures[e], k_matrix);
    return k;
  }
  for (std::size_t e = 0; e < k.size(); ++e)
    k[e] = hydro::kozeny_carman_permeability(porosity.porosity[e], grain_diameter, cap);
  return k;
}

double PermeabilityModel::matrix_permeability() const {
  return hydro::kozeny_carman_permeability(matrix_porosity, grain_diameter, cap);
}

}  // namespace hydrodda::coupling
