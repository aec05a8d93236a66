// Fractures closed one after the other by shortening, through the real program on
// scenarios/verification/coupled_shortening_conductivity.toml (docs/coupling.md,
// "Verification"). Reference: the parallel-plate (cubic) law summed over the open fractures,
//   K = ρ_w g / μ × (k_m + Σ w_i³ / (12 W)),   k_m = d_g² φ_m³ / (180 (1 − φ_m)²)
// (Witherspoon et al. 1980; Kozeny–Carman for the matrix). Tolerance: 2% for each shortening,
// and the conductivity falls strictly.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "coupled_runs.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::read_vtu_array;
using hydrodda::testing::run_program;
using namespace hydrodda::testing::coupled;

namespace {

TEST(CoupledVerification, ShorteningLowersTheConductivityStrictly) {
  // Three fractures of w = 1.2 mm; the right side moved left by d closes them one after the
  // other: for d = 0, 1, 2, 3 mm the apertures are (1.2, 1.2, 1.2), (1.2, 1.2, 0.2),
  // (1.2, 0.4, 0) and (0.6, 0, 0) mm, and the region "set" (W = 3.99 m wide) has
  //   K = rho_w g / mu * (k_m + sum(w_i^3) / (12 W)),  k_m = d_g^2 phi^3 / (180 (1 - phi)^2),
  // which must fall strictly with d, each value within 2% (the cubic law's accuracy on the
  // mesh, tests/coupling/cubic_law_test.cpp). The four cases run as one sweep, and every one
  // converges (with d = 0 only the middle blocks creep, 2e-8 m a pass, see the scenario file).
  const fs::path out = fs::temp_directory_path() / "hydrodda-coupled-verification-shortening";
  fs::remove_all(out);
  const auto result = run_program("sweep " + (kVerification / "coupled_shortening_conductivity.toml").string() +
                                  " --set 'mechanics.displacement[1].value[0]=0,-0.001,-0.002,-0.003'"
                                  " --column flow.regions.set.effective_conductivity --jobs 2 -o " +
                                  out.string());
  // Every case converges, so the sweep exits with 0 and says so.
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("all 4 case(s) converged"), std::string::npos) << result.output;
  const auto rows = read_csv(out / "sweep.csv");
  fs::remove_all(out);
  ASSERT_EQ(rows.size(), 5u);
  const int status = column_of(rows[0], "status");
  const int conductivity = column_of(rows[0], "flow.regions.set.effective_conductivity");
  const int converged = column_of(rows[0], "converged");
  ASSERT_GE(status, 0);
  ASSERT_GE(converged, 0);
  ASSERT_GE(conductivity, 0);

  const double per_k = kRhoWater * kG / 1.0e-3;
  const double phi = 0.1, grain = 1.2e-5;
  const double k_matrix = grain * grain * phi * phi * phi / (180.0 * (1.0 - phi) * (1.0 - phi));
  const std::vector<std::vector<double>> apertures{
      {1.2e-3, 1.2e-3, 1.2e-3}, {1.2e-3, 1.2e-3, 0.2e-3}, {1.2e-3, 0.4e-3, 0.0}, {0.6e-3, 0.0, 0.0}};
  double previous = INFINITY;
  for (std::size_t c = 0; c < apertures.size(); ++c) {
    const auto& row = rows[c + 1];
    ASSERT_EQ(row[status], "ok") << "d = " << c << " mm";
    EXPECT_EQ(row[converged], "true") << "d = " << c << " mm";
    const double k_eff = std::stod(row[conductivity]);
    double cubes = 0.0;
    for (double w : apertures[c]) cubes += w * w * w;
    const double expected = per_k * (k_matrix + cubes / (12.0 * 3.99));
    EXPECT_NEAR(k_eff, expected, 0.02 * expected) << "d = " << c << " mm";
    EXPECT_LT(k_eff, previous) << "d = " << c << " mm: the conductivity must fall";
    previous = k_eff;
  }
}

}  // namespace
