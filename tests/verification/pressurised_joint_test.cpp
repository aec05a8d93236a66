// A joint under uniform pore pressure, through the real program on
// scenarios/verification/coupled_pressurised_joint.toml (docs/coupling.md, "Verification").
// Reference: Biot's effective stress (Biot 1941). At α = 1 a uniform p loads the skeleton with
// nothing and the joint stays shut (< 1e-7 m); at α = 0 each block is a confined (oedometric)
// elastic block under σ_x = −p, and the joint opens by 2 p L (1 + ν)(1 − 2ν) / ((1 − ν) E)
// = 1.667 mm. Tolerance: 1%.

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

TEST(CoupledVerification, UniformPorePressureOpensAJointOnlyUnderTotalStress) {
  // Two blocks of L = 1 m, each held by the corners of its outer side, touching along a closed
  // joint; p = 10 MPa everywhere (the same pressure on every side), no gravity.
  // alpha = 1: uniform p loads the skeleton with nothing; the joint stays shut, < 1e-7 m.
  // alpha = 0: p on the faces only. Each block's held side keeps epsilon_y = 0 (plane strain:
  // epsilon_z = 0 too) and its joint face carries sigma_x = -p, so
  //   epsilon_x = -p (1 + nu)(1 - 2 nu) / ((1 - nu) E)
  // (the constrained modulus), each block shortens by p L times that, and the joint opens by
  //   2 p L (1 + nu)(1 - 2 nu) / ((1 - nu) E) = 1.6667 mm   (E = 10 GPa, nu = 0.25),
  // within 1% (measured 1.6649 mm: the corner pins are stiff springs, not rigid).
  const std::string text = read_text(kVerification / "coupled_pressurised_joint.toml");
  const double p = 1.0e7, length = 1.0, young = 1.0e10, nu = 0.25;
  const double expected = 2.0 * p * length * (1.0 + nu) * (1.0 - 2.0 * nu) / ((1.0 - nu) * young);
  for (const char* biot : {"1.0", "0.0"}) {
    int count = 0;
    const std::string scenario = replace_all(text, "biot_coefficient = 1.0", std::string("biot_coefficient = ") + biot, count);
    ASSERT_EQ(count, 1);
    const std::string name = std::string("pressurised-joint-") + biot;
    const RunResult r = run_text_and_read(scenario, name);
    EXPECT_EQ(r.summary["converged"], true) << "alpha " << biot;
    ASSERT_GE(r.history.size(), 2u) << "alpha " << biot;
    const int opening = column_of(r.history[0], "largest_opening");
    ASSERT_GE(opening, 0);
    const double widest = std::stod(r.history.back()[opening]);
    if (std::string(biot) == "1.0") EXPECT_LT(widest, 1e-7) << "the joint must stay shut";
    else EXPECT_NEAR(widest, expected, 0.01 * expected);
  }
}

}  // namespace
