#pragma once
// Permeability per fluid element from its equivalent porosity, by the scenario's law
// (permeability_laws.hpp; each law's computation is its own type in permeability_model.cpp).

#include <span>
#include <vector>

#include "coupling/permeability_laws.hpp"
#include "coupling/porosity.hpp"
#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {

struct PermeabilityModel {
  PermeabilityLaw law = PermeabilityLaw::kozeny_carman;
  double grain_diameter = 0.0;   // m (Kozeny–Carman)
  double cap = 9.869e-11;        // m² (Kozeny–Carman)
  // m²: the cubic law's cap on a fracture's own permeability w²/12 (hydro::cubic_law_permeability).
  double fracture_cap = hydro::kDefaultFracturePermeabilityCap;
  double matrix_porosity = 0.0;
  // Cubic law: the fluid domain (its boundary is a wall where fewer than two blocks are near)
  // and how far from an element walls are looked for.
  geometry::Polygon domain;
  double aperture_reach = 1.0;
  // Per element, where materials differ by region: its matrix porosity and grain diameter (empty:
  // matrix_porosity and grain_diameter everywhere). Read by compute() only.
  std::vector<double> element_matrix_porosity;
  std::vector<double> element_grain_diameter;
  double matrix_porosity_of(std::size_t e) const {
    return e < element_matrix_porosity.size() ? element_matrix_porosity[e] : matrix_porosity;
  }
  double grain_diameter_of(std::size_t e) const {
    return e < element_grain_diameter.size() ? element_grain_diameter[e] : grain_diameter;
  }
  bool by_element() const { return !element_matrix_porosity.empty() || !element_grain_diameter.empty(); }
  // k_m of element e: matrix_permeability() on its own matrix.
  double matrix_permeability_of(std::size_t e) const;
  // Each element's equivalent porosity on its own matrix, φ_e = (A_f/A_e)(1 − φ_m,e) + φ_m,e
  // (a field mapped with matrix_porosity; nothing to do without per-element properties).
  void apply_element_matrix_porosity(PorosityField& porosity, std::span<const double> element_areas) const;

  // k per element. Kozeny–Carman: the paper's eq. 9 on φ_e. Cubic: k_m + (A_f/A_e) w_e²/12
  // with k_m the Kozeny–Carman value of the matrix porosity and w_e the local aperture
  // (local_aperture.hpp; required for the cubic law, ignored otherwise), w_e²/12 capped at
  // fracture_cap. `cap` is the paper's device for Kozeny–Carman and does not apply to the cubic
  // law.
  std::vector<double> compute(const PorosityField& porosity, std::span<const double> element_areas,
                              std::span<const double> apertures = {}) const;
  // k_m: what both laws give an element with no open area (Kozeny–Carman of the matrix porosity;
  // capped under Kozeny–Carman only).
  double matrix_permeability() const;
  // Kozeny–Carman's cap lowers k_m itself: the matrix's own value is above it.
  bool matrix_capped() const;
  // The elements whose fracture permeability compute() capped at fracture_cap (cubic law: an
  // open area and w²/12 above the cap), in order; none under Kozeny–Carman.
  std::vector<int> find_capped_elements(const PorosityField& porosity, std::span<const double> element_areas,
                                        std::span<const double> apertures) const;
  // Whether compute() needs the elements' local apertures.
  bool reads_apertures() const { return describe(law).reads_apertures; }
};

}  // namespace hydrodda::coupling
