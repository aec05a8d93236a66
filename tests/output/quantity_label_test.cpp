// A scenario key or summary.json path as an axis title (output/quantity_label.hpp). Exact text.

#include "output/quantity_label.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace hydrodda::output {
namespace {

// Axis titles name the quantity, what it belongs to and its unit; a path the table does not
// know stays as it is.
TEST(QuantityLabel, NamesTheQuantityAndItsUnit) {
  const std::vector<std::string> boundaries{"base", "top"};
  EXPECT_EQ(quantity_label("flow.boundary[0].head", boundaries), "head at base (m)");
  EXPECT_EQ(quantity_label("flow.boundary[1].pressure", boundaries), "pressure at top (Pa)");
  EXPECT_EQ(quantity_label("flow.regions.fractured.normalised_conductivity"), "K_eff / K_matrix of fractured");
  EXPECT_EQ(quantity_label("flow.boundaries.top"), "flow out of top (m²/s)");
  EXPECT_EQ(quantity_label("flow.regions.core.effective_conductivity"), "K_eff of core (m/s)");
  EXPECT_EQ(quantity_label("measure.top.displacement.1"), "y displacement of top (m)");
  EXPECT_EQ(quantity_label("mechanics.traction[0].normal_end"), "normal traction at the end (Pa)");
  EXPECT_EQ(quantity_label("material.rock.density"), "density (kg/m³)");
  EXPECT_EQ(quantity_label("output.every"), "output.every");
}

}  // namespace
}  // namespace hydrodda::output
