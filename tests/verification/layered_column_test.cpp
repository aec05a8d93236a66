// A column of three materials by region on rollers under gravity, through the program on
// scenarios/verification/three_layer_column.toml. References: the lithostatic stress of a
// layered column, σyy(y) = −g ∫_y^H ρ(η) dη, and the oedometric settlement of a point at height
// y with no initial stress, u(y) = ∫_0^y |σyy(η)| / M(η) dη, M = E(1 − ν)/((1 + ν)(1 − 2ν))
// (plane strain). Started in the layered stress (vertical = "layers"), the column stays put:
// no block moves by more than 1e-6 of the settlement S = u(H) it has without it. Started
// without it, its top block settles by u(y_c) (1%: the blocks' uniform strain and the contact
// springs' compliance).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../cli/run_program.hpp"

namespace fs = std::filesystem;

namespace {

struct Layer {
  double bottom, top, density, young, poisson;
  double oedometric_modulus() const { return young * (1.0 - poisson) / ((1.0 + poisson) * (1.0 - 2.0 * poisson)); }
};
// As the scenario file gives them.
const Layer kLayers[] = {{0.0, 10.0, 2300.0, 1.5e10, 0.2}, {10.0, 20.0, 2500.0, 1.0e10, 0.3}, {20.0, 30.0, 2200.0, 8.0e9, 0.25}};
constexpr double kG = 9.81;

// |σyy| at y: the weight of the layers above.
double vertical_stress(double y) {
  double sum = 0.0;
  for (const Layer& l : kLayers)
    if (l.top > y) sum += (l.top - std::max(l.bottom, y)) * l.density * kG;
  return sum;
}

// ∫_0^y |σyy| / M: exact, as |σyy| is linear in each layer (the trapezium rule per piece).
double settlement_at(double y) {
  double u = 0.0;
  for (const Layer& l : kLayers) {
    const double top = std::min(l.top, y);
    if (top <= l.bottom) continue;
    u += 0.5 * (vertical_stress(l.bottom) + vertical_stress(top)) * (top - l.bottom) / l.oedometric_modulus();
  }
  return u;
}

std::string material_at(double y) { return y < 10.0 ? "sandstone" : (y < 20.0 ? "mudstone" : "siltstone"); }

TEST(MechanicsVerification, ThreeLayerColumnStartsInItsLayeredStressAndStaysPut) {
  const double settlement = settlement_at(30.0);  // 7.0815e-4 m
  ASSERT_NEAR(settlement, 7.0815e-4, 1e-7);
  const auto s = hydrodda::testing::run_scenario_and_read("scenarios/verification/three_layer_column.toml");
  ASSERT_EQ(s["blocks"].size(), 15u);
  for (const auto& b : s["blocks"]) {
    const double y = b["centroid"][1];
    EXPECT_EQ(b["material"], material_at(y)) << "block at y = " << y;
    // Motion: under 1e-6 of S.
    EXPECT_LE(std::hypot(double(b["displacement"][0]), double(b["displacement"][1])), 1e-6 * settlement)
        << "block at y = " << y;
    // Stress: the layered lithostatic one, σxx = 0.5 σyy, within 1e-6 of the column's base stress.
    const double tolerance = 1e-6 * vertical_stress(0.0);
    EXPECT_NEAR(double(b["stress"][1]), -vertical_stress(y), tolerance) << "block at y = " << y;
    EXPECT_NEAR(double(b["stress"][0]), -0.5 * vertical_stress(y), tolerance) << "block at y = " << y;
  }
}

TEST(MechanicsVerification, ThreeLayerColumnWithoutItsInSituStressSettles) {
  // The same column started unstressed: its top block (centroid at 29 m) settles by u(29 m), 1%.
  const fs::path edited = hydrodda::testing::edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/three_layer_column.toml", "three_layer_column_unstressed",
      {{"[mechanics.initial_stress]\n", ""},
       {"stress = [0.0, 0.0, 0.0]      # at the top\n", ""},
       {"reference_y = 30.0\n", ""},
       {"vertical = \"layers\"           # dσyy/dy = ρ g in each layer\n", ""},
       {"horizontal_ratio = 0.5        # σxx = 0.5 σyy\n", ""}});
  const fs::path out = fs::temp_directory_path() / ("hydrodda-unstressed-column-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = hydrodda::testing::run_program("run " + edited.string() + " -o " + out.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  fs::remove_all(out);
  fs::remove(edited);
  double top_settlement = 0.0;
  for (const auto& b : s["blocks"])
    if (double(b["centroid"][1]) > 28.0) top_settlement = -double(b["displacement"][1]);
  const double expected = settlement_at(29.0);
  EXPECT_NEAR(top_settlement, expected, 0.01 * expected);
}

}  // namespace
