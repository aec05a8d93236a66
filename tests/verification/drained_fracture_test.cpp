// The uplift of a block over a fracture drained at mid-length, through the real program on
// scenarios/verification/coupled_drained_fracture.toml (docs/coupling.md, "Verification").
// Reference: the block's base contacts carry its weight less the integral of the
// finite-element pressure along its base (vertical equilibrium of a rigid body,
// N = ρ_r g h L − ∫ p dx). Tolerance: 1% of the uplift, at Biot α = 0 and α = 1.

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

TEST(CoupledVerification, DrainedFractureLiftsTheBlockByTheIntegralOfItsPressure) {
  // The fracture under the upper block is fed at H = 3 m at its ends and drained to the top at
  // its middle, so the pressure along the block's base is far from linear between its corners.
  // The block (weight W = rho_r g h L = 24.5 kN per metre) rests on the base, and its base
  // contacts carry W less the uplift, which must be the integral of the finite-element pressure
  // along its base (integrated here from fluid_NNNN.vtu by 4,000 samples): within 1% of it, at
  // alpha = 0 (the faces take the pressure) and at alpha = 1 (the seepage force does). The
  // corners' pressure (rho_w g H at both, the paper's rule) would give 29.4 kN, more than the
  // weight: the test also checks that the case is one where that rule is wrong by over 50%.
  const fs::path file = kVerification / "coupled_drained_fracture.toml";
  const std::string text = read_text(file);
  for (const char* biot : {"0.0", "1.0"}) {
    int count = 0;
    const std::string scenario =
        replace_all(text, "biot_coefficient = 0.0", std::string("biot_coefficient = ") + biot, count);
    ASSERT_EQ(count, 1);
    const std::string name = std::string("drained-") + biot;
    const RunResult r = run_text_and_read(scenario, name);
    ASSERT_TRUE(r.summary.contains("measure")) << "alpha " << biot;
    EXPECT_EQ(r.summary["converged"], true) << "alpha " << biot;
    EXPECT_LT(std::abs(r.summary["measure"]["lift"]["displacement"][1].get<double>()), 1e-4)
        << "alpha " << biot << ": the block must rest on the base";

    // The upper block (block 1, vertices 4 to 7) and its base: its two lowest vertices.
    const auto points = read_vtu_points(r.blocks);
    ASSERT_EQ(points.size(), 8u);
    std::vector<std::array<double, 2>> upper(points.begin() + 4, points.end());
    std::sort(upper.begin(), upper.end(), [](const auto& p, const auto& q) { return p[1] < q[1]; });
    auto a = upper[0], b = upper[1];
    if (a[0] > b[0]) std::swap(a, b);
    // Its base lies on y = 1 m to within the settlement; its ends on the domain's sides, which
    // the samples stay 1e-6 m inside (the mesh ends there).
    const PressureField field(r.fluid);
    ASSERT_FALSE(field.empty());
    const int samples = 4000;
    double uplift = 0.0;
    const double x0 = std::max(a[0], 1e-6), x1 = std::min(b[0], 1.0 - 1e-6);
    for (int k = 0; k < samples; ++k) {
      const double t = (k + 0.5) / samples;
      const double p = field.at(x0 + t * (x1 - x0), a[1] + t * (b[1] - a[1]));
      ASSERT_FALSE(std::isnan(p)) << "alpha " << biot << ": sample " << k << " outside the mesh";
      uplift += p * (x1 - x0) / samples;
    }
    const double corners = 0.5 * (field.at(x0, a[1]) + field.at(x1, b[1])) * (b[0] - a[0]);
    const double weight = kRhoRock * kG * 1.0 * (1.0 - 2.5e-5);
    EXPECT_GT(corners, 1.5 * uplift) << "alpha " << biot << ": the pressure along the base must be far from linear";
    EXPECT_GT(corners, weight) << "alpha " << biot << ": the corners' pressure would throw the block up";

    const auto normal = read_vtu_array(r.contacts, "normal_force");
    const auto block_i = read_vtu_array(r.contacts, "block_i");
    const auto block_j = read_vtu_array(r.contacts, "block_j");
    ASSERT_EQ(block_i.size(), normal.size());
    double carried = 0.0;
    for (std::size_t c = 0; c < normal.size(); ++c)
      if (block_i[c] + block_j[c] == 1.0) carried += normal[c];
    EXPECT_NEAR(weight - carried, uplift, 0.01 * uplift) << "alpha " << biot;
  }
}

}  // namespace
