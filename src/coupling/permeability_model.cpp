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

// What a law computes, from the model's parameters: one type per law behind this interface.
class Law {
 public:
  virtual ~Law() = default;
  virtual std::vector<double> compute(const PermeabilityModel& model, const PorosityField& porosity,
                                      std::span<const double> element_areas, std::span<const double> apertures) const = 0;
  // k_m: an element with no open area.
  virtual double matrix_permeability(const PermeabilityModel& model) const = 0;
  // Whether the law's own bound lowers k_m below the matrix's value.
  virtual bool matrix_capped(const PermeabilityModel&) const { return false; }
};

// The paper's eq. 9 on φ_e, capped so that open fractures (φ → 1) stay finite.
class KozenyCarmanLaw final : public Law {
 public:
  std::vector<double> compute(const PermeabilityModel& model, const PorosityField& porosity, std::span<const double>,
                              std::span<const double>) const override {
    std::vector<double> k(porosity.porosity.size());
    for (std::size_t e = 0; e < k.size(); ++e)
      k[e] = hydro::kozeny_carman_permeability(porosity.porosity[e], model.grain_diameter_of(e), model.cap);
    return k;
  }
  double matrix_permeability(const PermeabilityModel& model) const override {
    return hydro::kozeny_carman_permeability(model.matrix_porosity, model.grain_diameter, model.cap);
  }
  bool matrix_capped(const PermeabilityModel& model) const override {
    return hydro::kozeny_carman_permeability(model.matrix_porosity, model.grain_diameter,
                                             std::numeric_limits<double>::infinity()) > model.cap;
  }
};

// k_m + (A_f/A_e) min(w_e²/12, fracture_cap), k_m the Kozeny–Carman value of the matrix
// porosity, uncapped: `cap` is the paper's device for Kozeny–Carman, and the cubic law's k_m is
// the rock's as given.
class CubicLaw final : public Law {
 public:
  std::vector<double> compute(const PermeabilityModel& model, const PorosityField& porosity,
                              std::span<const double> element_areas, std::span<const double> apertures) const override {
    std::vector<double> k(porosity.porosity.size());
    if (apertures.size() != k.size() || element_areas.size() != k.size())
      throw std::invalid_argument("cubic law: one aperture and one area per element are needed");
    const double k_matrix = matrix_permeability(model);
    const bool by_element = model.by_element();
    for (std::size_t e = 0; e < k.size(); ++e)
      k[e] = hydro::cubic_law_permeability(compute_open_fraction(porosity.fracture_area[e], element_areas[e]),
                                           apertures[e], by_element ? model.matrix_permeability_of(e) : k_matrix,
                                           model.fracture_cap);
    return k;
  }
  double matrix_permeability(const PermeabilityModel& model) const override {
    return hydro::kozeny_carman_permeability(model.matrix_porosity, model.grain_diameter,
                                             std::numeric_limits<double>::infinity());
  }
};

// The one factory: the type of the law the scenario named.
const Law& find_law(PermeabilityLaw law) {
  static const KozenyCarmanLaw kozeny_carman;
  static const CubicLaw cubic;
  switch (law) {
    case PermeabilityLaw::kozeny_carman: return kozeny_carman;
    case PermeabilityLaw::cubic: return cubic;
  }
  throw std::logic_error("a permeability law without a type");
}

}  // namespace

std::vector<double> PermeabilityModel::compute(const PorosityField& porosity, std::span<const double> element_areas,
                                               std::span<const double> apertures) const {
  return find_law(law).compute(*this, porosity, element_areas, apertures);
}

std::vector<int> PermeabilityModel::find_capped_elements(const PorosityField& porosity,
                                                         std::span<const double> element_areas,
                                                         std::span<const double> apertures) const {
  std::vector<int> capped;
  if (law != PermeabilityLaw::cubic) return capped;
  for (std::size_t e = 0; e < apertures.size() && e < element_areas.size(); ++e)
    if (compute_open_fraction(porosity.fracture_area[e], element_areas[e]) > 0.0 &&
        hydro::reaches_fracture_cap(apertures[e], fracture_cap))
      capped.push_back(static_cast<int>(e));
  return capped;
}

double PermeabilityModel::matrix_permeability() const { return find_law(law).matrix_permeability(*this); }

double PermeabilityModel::matrix_permeability_of(std::size_t e) const {
  if (!by_element()) return matrix_permeability();
  // Both laws' k_m is Kozeny–Carman's of the matrix, capped under Kozeny–Carman only.
  const double bound = law == PermeabilityLaw::kozeny_carman ? cap : std::numeric_limits<double>::infinity();
  return hydro::kozeny_carman_permeability(matrix_porosity_of(e), grain_diameter_of(e), bound);
}

void PermeabilityModel::apply_element_matrix_porosity(PorosityField& porosity, std::span<const double> element_areas) const {
  for (std::size_t e = 0; e < element_matrix_porosity.size() && e < porosity.porosity.size(); ++e)
    porosity.porosity[e] = equivalent_porosity(porosity.fracture_area[e], element_areas[e], element_matrix_porosity[e]);
}

bool PermeabilityModel::matrix_capped() const { return find_law(law).matrix_capped(*this); }

}  // namespace hydrodda::coupling
