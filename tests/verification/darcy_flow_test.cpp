// Flow-only runs through the real program, on the shipped verification scenarios: the boundary
// flows in summary.json against the exact values their files state. References: Darcy's law,
// Q = K A Δh / L; layers in series conduct by the harmonic mean of their conductivities and
// layers in parallel by the arithmetic mean (Bear, Dynamics of Fluids in Porous Media, 1972);
// a linear head is exact for P1 elements; the matrix by Kozeny–Carman,
// k = d² φ³ / (180 (1 − φ)²). Tolerances: 1e-8 relative (layers), 1e-10 (linear head), 1e-9
// (Kozeny–Carman matrix): round-off only.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../cli/run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

// ρ g / μ for water at the scenarios' fluid: K = k × 9.81e6 (m/s per m²).
constexpr double kConductivityPerPermeability = 1000.0 * 9.81 / 1.0e-3;

nlohmann::json run_and_read(const std::string& name) {
  return hydrodda::testing::run_scenario_and_read("scenarios/verification/" + name + ".toml");
}

TEST(FlowRun, LayersInSeriesGiveTheHarmonicMean) {
  // Q = Δh / Σ(L_i / K_i) over layers 0.3 m (1e-12), 0.25 m (1e-6), 0.25 m (1e-9), 0.2 m (1e-12).
  const double resistance = (0.3 / 1e-12 + 0.25 / 1e-6 + 0.25 / 1e-9 + 0.2 / 1e-12) / kConductivityPerPermeability;
  const double exact = 1.0 / resistance;
  const auto s = run_and_read("flow_layers_series");
  EXPECT_NEAR(s["flow"]["boundaries"]["left"].get<double>(), -exact, 1e-8 * exact);
  EXPECT_NEAR(s["flow"]["boundaries"]["right"].get<double>(), exact, 1e-8 * exact);
  EXPECT_LE(s["flow"]["balance"].get<double>(), 1e-10);
}

TEST(FlowRun, LayersInParallelGiveTheArithmeticMean) {
  // Q = Δh/L Σ K_i w_i over widths 0.1 (1e-9), 0.3 (1e-12), 0.6 (1e-15).
  const double exact = (0.1 * 1e-9 + 0.3 * 1e-12 + 0.6 * 1e-15) * kConductivityPerPermeability;
  const auto s = run_and_read("flow_layers_parallel");
  EXPECT_NEAR(s["flow"]["boundaries"]["right"].get<double>(), exact, 1e-8 * exact);
  EXPECT_LE(s["flow"]["balance"].get<double>(), 1e-10);
}

TEST(FlowRun, MaterialsByRegionGiveTheirMatricesInSeries) {
  // Sandstone 4 m (its permeability fixed at 1e-13 m²) under mudstone 6 m (Kozeny–Carman of
  // φ = 0.1, d = 1e-5 m: k = d² φ³ / (180 (1 − φ)²)), across the flow from bottom to top, 10 m
  // wide: Q = 10 m × Δh / Σ (L_i / K_i), 1e-8 relative (round-off: the mesh honours the border).
  const double k_mud = 1e-10 * 1e-3 / (180.0 * 0.9 * 0.9);
  const double resistance = (4.0 / 1e-13 + 6.0 / k_mud) / kConductivityPerPermeability;
  const double exact = 10.0 * 1.0 / resistance;
  const auto s = run_and_read("flow_two_materials_series");
  EXPECT_NEAR(s["flow"]["boundaries"]["bottom"].get<double>(), -exact, 1e-8 * exact);
  EXPECT_NEAR(s["flow"]["boundaries"]["top"].get<double>(), exact, 1e-8 * exact);
  EXPECT_LE(s["flow"]["balance"].get<double>(), 1e-10);
}

TEST(FlowRun, LinearHeadIsExact) {
  // h = 3 − x on a 2 m × 1 m rectangle: Q = K × 1 m × 1 m/m, K = 1e-12 m² × ρg/μ.
  const double exact = 1e-12 * kConductivityPerPermeability;
  const auto s = run_and_read("flow_linear_head");
  EXPECT_NEAR(s["flow"]["boundaries"]["left"].get<double>(), -exact, 1e-10 * exact);
  EXPECT_NEAR(s["flow"]["regions"]["rock"]["effective_conductivity"].get<double>(), exact, 1e-10 * exact);
  // The region fixes the permeability everywhere: the unfractured case is the same field, and
  // the ratio is 1 to round-off.
  EXPECT_NEAR(s["flow"]["regions"]["rock"]["matrix_conductivity"].get<double>(), exact, 1e-10 * exact);
  EXPECT_NEAR(s["flow"]["regions"]["rock"]["normalised_conductivity"].get<double>(), 1.0, 1e-12);
}

TEST(FlowRun, FractureAlongTheFlowRaisesTheConductivityAboveTheMatrix) {
  const auto s = hydrodda::testing::run_scenario_and_read("tests/cli/scenarios/fractured_strip.toml");
  const auto& region = s["flow"]["regions"]["slab"];
  // Unfractured: uniform k_m = d² φ³ / (180 (1 − φ)²) (Kozeny–Carman, φ = 0.1, d = 1.2e-5 m)
  // on a rectangle along the flow, so K_eff = k_m ρ g / μ exactly; round-off only, 1e-9.
  const double k_matrix = 1.2e-5 * 1.2e-5 * 1e-3 / (180.0 * 0.9 * 0.9);
  const double matrix = k_matrix * kConductivityPerPermeability;
  EXPECT_NEAR(region["matrix_conductivity"].get<double>(), matrix, 1e-9 * matrix);
  const double effective = region["effective_conductivity"].get<double>();
  EXPECT_NEAR(region["normalised_conductivity"].get<double>(), effective / matrix, 1e-9 * effective / matrix);
  // Kozeny–Carman k grows with φ and the gap only adds porosity, so no element is below k_m and
  // those the gap crosses are above it: the ratio exceeds 1.
  EXPECT_GT(region["normalised_conductivity"].get<double>(), 1.0);
}

}  // namespace
