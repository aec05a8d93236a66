// The shipped mechanics verification scenarios run through the program, against the analytic
// values their files state (the engine-level tests are in tests/dda).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

nlohmann::json run_and_read(const std::string& name) {
  return hydrodda::testing::run_scenario_and_read("scenarios/verification/" + name + ".toml");
}

TEST(MechanicsVerification, FreeFall) {
  // d(1 s) = ½ g t² = 4.905 m, within 0.1%.
  const auto s = run_and_read("free_fall");
  const double dy = s["measure"]["centre"]["displacement"][1];
  EXPECT_NEAR(dy, -4.905, 0.001 * 4.905);
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
