// Which capped fluid elements a run warns about (run/permeability_cap.hpp): only those whose
// permeability is the cubic law's. An element whose permeability the scenario gives (a material's
// `permeability`, a flow region's) takes that value instead, so the cap changes no flow there.
// Exact: a filter, no arithmetic.

#include "run/permeability_cap.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

namespace hydrodda::run {
namespace {

TEST(CappedByTheLaw, ElementsWhosePermeabilityTheScenarioGivesAreLeftOut) {
  const std::vector<int> capped{3, 5, 8};
  std::vector<std::optional<double>> given(10);
  given[5] = 1e-20;  // a mudstone of given permeability
  EXPECT_EQ(capped_by_the_law(capped, given), (std::vector<int>{3, 8}));
  EXPECT_EQ(capped_by_the_law(capped, {}), capped) << "nothing given: every capped element is the law's";
  given.assign(10, 1e-20);
  EXPECT_TRUE(capped_by_the_law(capped, given).empty());
}

}  // namespace
}  // namespace hydrodda::run
