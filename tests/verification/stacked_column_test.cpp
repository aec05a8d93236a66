// A column of ten blocks under its own weight, through the program on
// scenarios/verification/stacked_column.toml (the engine-level test is
// tests/dda/verification_test.cpp). Reference: the lithostatic stress σyy = −ρ g × depth of
// each block's centroid. Tolerance: 1%.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../cli/run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

nlohmann::json run_and_read(const std::string& name) {
  return hydrodda::testing::run_scenario_and_read("scenarios/verification/" + name + ".toml");
}

TEST(MechanicsVerification, StackedColumnCarriesItsWeight) {
  // Block k from the bottom (k = 1..10 above the fixed base): σyy = −ρ g (10 − (k − 1) − ½), 1%.
  const auto s = run_and_read("stacked_column");
  ASSERT_EQ(s["blocks"].size(), 11u);
  for (int k = 1; k <= 10; ++k) {
    const double expected = -2500.0 * 9.81 * (10.0 - (k - 1) - 0.5);
    const double syy = s["blocks"][k]["stress"][1];
    EXPECT_NEAR(syy, expected, 0.01 * std::abs(expected)) << "block " << k;
  }
}

}  // namespace
