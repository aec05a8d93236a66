// Every law of kPermeabilityLaws has its type in the factory, and each computes what its row
// says it needs: a law that reads apertures refuses to go without them, one that does not
// ignores them.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "coupling/permeability_laws.hpp"
#include "coupling/permeability_model.hpp"
#include "hydro/permeability_law.hpp"

namespace hydrodda::coupling {
namespace {

PermeabilityModel model_of(PermeabilityLaw law) {
  PermeabilityModel model;
  model.law = law;
  model.matrix_porosity = 0.1;
  model.grain_diameter = 1.2e-5;
  return model;
}

// Two elements: intact rock, and one half open by a 1 mm aperture.
PorosityField two_elements() {
  PorosityField field;
  field.fracture_area = {0.0, 0.5};
  field.porosity = {0.1, 0.55};
  return field;
}

TEST(PermeabilityLaws, EachLawHasItsRowAndItsOwnName) {
  std::set<std::string_view> names;
  for (const PermeabilityLawInfo& info : kPermeabilityLaws) {
    EXPECT_EQ(&describe(info.law), &info);
    EXPECT_FALSE(info.name.empty());
    names.insert(info.name);
  }
  EXPECT_EQ(names.size(), kPermeabilityLaws.size());
}

TEST(PermeabilityLaws, EachLawIsMadeAndComputesAsItsRowSays) {
  const std::vector<double> areas{1.0, 1.0}, apertures{0.0, 1e-3};
  for (const PermeabilityLawInfo& info : kPermeabilityLaws) {
    SCOPED_TRACE(std::string(info.name));
    const PermeabilityModel model = model_of(info.law);
    EXPECT_EQ(model.reads_apertures(), info.reads_apertures);
    const double k_matrix = model.matrix_permeability();
    EXPECT_TRUE(std::isfinite(k_matrix) && k_matrix > 0.0) << k_matrix;
    const std::vector<double> k = model.compute(two_elements(), areas, apertures);
    ASSERT_EQ(k.size(), 2u);
    EXPECT_EQ(k[0], k_matrix);  // intact rock: the matrix's k under every law
    EXPECT_GT(k[1], k_matrix);  // an open element conducts more
    if (info.reads_apertures)
      EXPECT_THROW(model.compute(two_elements(), areas), std::invalid_argument);
    else
      EXPECT_EQ(model.compute(two_elements(), areas), k);
  }
}

TEST(PermeabilityLaws, TheLawsComputeTheirFormulas) {
  const std::vector<double> areas{1.0, 1.0}, apertures{0.0, 1e-3};
  const PermeabilityModel kozeny_carman = model_of(PermeabilityLaw::kozeny_carman);
  EXPECT_EQ(kozeny_carman.compute(two_elements(), areas)[1],
            hydro::kozeny_carman_permeability(0.55, kozeny_carman.grain_diameter, kozeny_carman.cap));
  const PermeabilityModel cubic = model_of(PermeabilityLaw::cubic);
  EXPECT_EQ(cubic.compute(two_elements(), areas, apertures)[1],
            hydro::cubic_law_permeability(0.5, 1e-3, cubic.matrix_permeability()));
}

// The cubic law caps a fracture's permeability w²/12 at fracture_cap, and names the elements it
// capped: of two half-open elements with gaps of 1 mm and 2 cm, the second (w²/12 = 3.3e-5 m²
// against the default cap's 8.3e-6 m²). Kozeny–Carman has its own cap and names none.
TEST(PermeabilityLaws, TheCubicLawCapsTheFracturePermeabilityAndNamesWhere) {
  const std::vector<double> areas{1.0, 1.0}, apertures{1e-3, 2e-2};
  PorosityField half_open = two_elements();
  half_open.fracture_area = {0.5, 0.5};
  const PermeabilityModel cubic = model_of(PermeabilityLaw::cubic);
  const std::vector<double> k = cubic.compute(half_open, areas, apertures);
  EXPECT_EQ(k[0], hydro::cubic_law_permeability(0.5, 1e-3, cubic.matrix_permeability()));
  EXPECT_EQ(k[1], cubic.matrix_permeability() + 0.5 * hydro::kDefaultFracturePermeabilityCap);
  EXPECT_EQ(cubic.find_capped_elements(half_open, areas, apertures), std::vector<int>{1});
  EXPECT_TRUE(model_of(PermeabilityLaw::kozeny_carman).find_capped_elements(half_open, areas, apertures).empty());
}

}  // namespace
}  // namespace hydrodda::coupling
