// A column on rollers, through the program on scenarios/verification/roller_oedometer.toml and
// in_situ_column.toml. References: the oedometer (uniaxial strain) of linear elasticity,
// σxx/σyy = ν/(1 − ν) and a settlement of ρ g H² / (2M), M = E(1 − ν)/((1 + ν)(1 − 2ν)) the
// constrained modulus (1%); a column started in its in-situ stress σyy = −ρ g (H − y),
// σxx = 0.6 σyy is in equilibrium (moves under 1e-6 H, stresses within 1e-6 ρ g H).

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

TEST(MechanicsVerification, RollerColumnIsAnOedometer) {
  // σxx/σyy = ν/(1−ν) = 1/3 in every block and σyy = −ρ g (H − y_c), 1%; the top settles by
  // ρ g H² / (2M) = 1.0219e-4 m, M = E(1−ν)/((1+ν)(1−2ν)), 1% (measured +0.01%).
  const auto s = run_and_read("roller_oedometer");
  ASSERT_EQ(s["blocks"].size(), 10u);
  for (int k = 0; k < 10; ++k) {
    const double sxx = s["blocks"][k]["stress"][0], syy = s["blocks"][k]["stress"][1];
    const double expected = -2500.0 * 9.81 * (10.0 - (k + 0.5));
    EXPECT_NEAR(syy, expected, 0.01 * std::abs(expected)) << "block " << k;
    EXPECT_NEAR(sxx / syy, 1.0 / 3.0, 0.01 / 3.0) << "block " << k;
  }
  const double modulus = 1.0e10 * 0.75 / (1.25 * 0.5);
  const double settlement = 2500.0 * 9.81 * 100.0 / (2.0 * modulus);
  const double dy = s["measure"]["top"]["displacement"][1];
  EXPECT_NEAR(-dy, settlement, 0.01 * settlement);
}

TEST(MechanicsVerification, InSituColumnStartsInEquilibrium) {
  // Starting in σyy = −ρ g (H − y), σxx = 0.6 σyy on rollers: no block moves by more than
  // 1e-6 H = 1e-5 m over 100 steps, and every stress stays within 1e-6 ρ g H of its start.
  const auto s = run_and_read("in_situ_column");
  ASSERT_EQ(s["blocks"].size(), 10u);
  const double rho_g = 2500.0 * 9.81;
  for (int k = 0; k < 10; ++k) {
    const auto& b = s["blocks"][k];
    EXPECT_LE(std::hypot(double(b["displacement"][0]), double(b["displacement"][1])), 1e-5) << "block " << k;
    const double syy = -rho_g * (10.0 - (k + 0.5));
    EXPECT_NEAR(double(b["stress"][1]), syy, 1e-6 * rho_g * 10.0) << "block " << k;
    EXPECT_NEAR(double(b["stress"][0]), 0.6 * syy, 1e-6 * rho_g * 10.0) << "block " << k;
  }
}

}  // namespace
