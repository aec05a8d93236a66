#include "coupling/permeability_model.hpp"

#include <limits>
#include <stdexcept>

#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {

namespace {

// A_f/A_e for the cubic law. The open area is the element's area less the blocks' over it, so
// an element that blocks cover has a round-off remainder (up to 1e-13 of its area), which the
// local aperture, measured between walls that may be far apart, would turn into a fracture's
// share (1e-13 × (0.3 m)²/12 is 0.8 k_m of the paper's rock). A fraction below 1e-9 (a 1 nm gap
// across a 1 m element, transmissivity < 1e-27 m³) is taken as none.
double compute_open_fraction(double fracture_area, double element_area) {
  constexpr double kRoundOff = 1e-9;
  const double fraction = fracture_area / element_area;
  return fraction < kRoundOff ? 0.0 : fraction;
}

}  // namespace

std::vector<double> PermeabilityModel::compute(const PorosityField& porosity, std::span<const double> element_areas,
                                               std::span<const double> apertures) const {
  std::vector<double> k(porosity.porosity.size());
  if (law == PermeabilityLaw::cubic) {
    if (apertures.size() != k.size() || element_areas.size() != k.size())
      throw std::invalid_argument("cubic law: one aperture and one area per element are needed");
    const double k_matrix = matrix_permeability();
    for (std::size_t e = 0; e < k.size(); ++e)
      k[e] = hydro::cubic_law_permeability(compute_open_fraction(porosity.fracture_area[e], element_areas[e]),
                                           apertures[e], k_matrix);
    return k;
  }
  for (std::size_t e = 0; e < k.size(); ++e)
    k[e] = hydro::kozeny_carman_permeability(porosity.porosity[e], grain_diameter, cap);
  return k;
}

double PermeabilityModel::matrix_permeability() const {
  // The cap keeps Kozeny–Carman finite as φ → 1; the cubic law's k_m is the rock's as given.
  const double bound = law == PermeabilityLaw::cubic ? std::numeric_limits<double>::infinity() : cap;
  return hydro::kozeny_carman_permeability(matrix_porosity, grain_diameter, bound);
}

bool PermeabilityModel::matrix_capped() const {
  return law == PermeabilityLaw::kozeny_carman &&
         hydro::kozeny_carman_permeability(matrix_porosity, grain_diameter, std::numeric_limits<double>::infinity()) > cap;
}

}  // namespace hydrodda::coupling
