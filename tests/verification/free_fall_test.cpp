// Free fall through the program, on scenarios/verification/free_fall.toml (the engine-level
// test is tests/dda/verification_test.cpp). Reference: Galileo's d(t) = ½ g t².
// Tolerance: 0.1% at t = 1 s.

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

TEST(MechanicsVerification, FreeFall) {
  // d(1 s) = ½ g t² = 4.905 m, within 0.1%.
  const auto s = run_and_read("free_fall");
  const double dy = s["measure"]["centre"]["displacement"][1];
  EXPECT_NEAR(dy, -4.905, 0.001 * 4.905);
}

}  // namespace
