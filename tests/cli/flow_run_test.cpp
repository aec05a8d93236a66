// Flow-only runs through the real program, on the shipped verification scenarios: the boundary
// flows in summary.json against the exact values their files state.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

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

TEST(FlowRun, LinearHeadIsExact) {
  // h = 3 − x on a 2 m × 1 m rectangle: Q = K × 1 m × 1 m/m, K = 1e-12 m² × ρg/μ.
  const double exact = 1e-12 * kConductivityPerPermeability;
  const auto s = run_and_read("flow_linear_head");
  EXPECT_NEAR(s["flow"]["boundaries"]["left"].get<double>(), -exact, 1e-10 * exact);
  EXPECT_NEAR(s["flow"]["regions"]["rock"]["effective_conductivity"].get<double>(), exact, 1e-10 * exact);
}

}  // namespace
