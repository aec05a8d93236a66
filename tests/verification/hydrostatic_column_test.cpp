// A block column in still water, through the real program on
// scenarios/verification/coupled_hydrostatic_column.toml (docs/coupling.md, "Verification").
// References: Archimedes' buoyancy, each interface carrying the effective weight above it,
// N = (ρ_r − ρ_w) g (3 m − y) × 1 m (within 1%); no flow under equal heads (|Q| < 1e-15 m²/s);
// the elastic settlement of a column under its own weight, s_dry(y) = ρ_r g (H y − y²/2) / E′
// (plane strain), bounded below by its effective-stress share; with Biot α = 1, Terzaghi's
// effective stress: the column settles as a dry column of density ρ_r − ρ_w, 0.6 of the dry
// settlement within 0.5%.

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

TEST(CoupledVerification, HydrostaticColumnFloatsOnItsContacts) {
  // Equal heads (3 m) on the bottom and the top: the head is 3 m everywhere, no flow; |flow|
  // under 1e-15 m2/s on both boundaries (a 1 mm head difference would drive 3e-12).
  // The water presses on every face, the contact faces too: each block takes Archimedes'
  // buoyancy, and an interface carries the effective weight of the blocks above it,
  //   N = (rho_r - rho_w) g * (3 m - y) * 1 m   (14,715 N at y = 2 m, 29,430 N at y = 1 m),
  // within 1%: the faces integrate the P1 pressure, exact for this linear one (with each vertex
  // taking its element centroid's pressure the contacts carried 530-545 N more, the pressure
  // the top corners took from 5.5 cm down). Every contact stays locked (none opens or slides),
  // no contact opens by more than 1e-9 m in any pass, horizontal displacement under 1e-7 m
  // (1% of the top's settlement).
  // Settlement, elastic only: with the dry column (H = 3 m, plane strain, E' = E / (1 - nu^2))
  //   s_dry(y) = rho_r g (H y - y^2 / 2) / E',
  // each block's lies between the effective-stress value (rho_r - rho_w) / rho_r * s_dry and
  // s_dry + n * 1.5e-6 m (n contacts below it, each allowed to penetrate 1e-4 of the allowed
  // step displacement, 0.01 * 1.5 m). The scenario's blocks are solid (Biot coefficient 0):
  // the water acts on their faces only and they carry the total stress.
  const RunResult r = run_and_read(kVerification / "coupled_hydrostatic_column.toml", "hydrostatic");
  const auto& s = r.summary;
  ASSERT_TRUE(s.contains("flow"));
  EXPECT_EQ(s["converged"], true);
  for (const char* boundary : {"bottom", "top"})
    EXPECT_LE(std::abs(s["flow"]["boundaries"][boundary].get<double>()), 1e-15) << boundary;

  const std::array<double, 3> interface_force = sum_interface_forces(r.contacts, true);
  for (int y = 1; y <= 2; ++y) {
    const double expected = (kRhoRock - kRhoWater) * kG * (3.0 - y) * 1.0;
    EXPECT_NEAR(interface_force[y], expected, 0.01 * expected) << "interface y = " << y << " m";
  }

  const double young = 1.0e10, poisson = 0.25, height = 3.0;
  const double e_plane = young / (1.0 - poisson * poisson);
  const auto s_dry = [&](double y) { return kRhoRock * kG * (height * y - 0.5 * y * y) / e_plane; };
  const double effective = (kRhoRock - kRhoWater) / kRhoRock;
  const double penetration = 1e-4 * 0.01 * 0.5 * height;
  ASSERT_EQ(s["blocks"].size(), 3u);
  for (int k = 0; k < 3; ++k) {  // bottom to top; block k has k contacts below it
    const auto& u = s["blocks"][k]["displacement"];
    const double settlement = -u[1].get<double>(), y = k + 0.5;
    EXPECT_LT(std::abs(u[0].get<double>()), 1e-7) << "block " << k;
    EXPECT_GE(settlement, effective * s_dry(y)) << "block " << k;
    EXPECT_LE(settlement, s_dry(y) + k * penetration) << "block " << k;
  }
  const double top = -s["measure"]["top"]["displacement"][1].get<double>();
  EXPECT_GE(top, effective * s_dry(height));
  EXPECT_LE(top, s_dry(height) + 2 * penetration);

  ASSERT_GE(r.history.size(), 2u);
  const int opening = column_of(r.history[0], "largest_opening");
  ASSERT_GE(opening, 0);
  for (std::size_t row = 1; row < r.history.size(); ++row)
    EXPECT_LE(std::stod(r.history[row][opening]), 1e-9) << "iteration " << r.history[row][0];
}

TEST(CoupledVerification, HydrostaticColumnOfBiotOneSettlesAsABuoyantDryColumn) {
  // The column with Biot coefficient 1: its skeleton feels the seepage force, here -grad p =
  // rho_w g upward, and no pressure on its faces, so it is a dry column of density
  // rho_r - rho_w: its interfaces carry the same effective weight as at alpha = 0 (within 1%)
  // and every block settles by (rho_r - rho_w) / rho_r = 0.6 of what it does dry (the same
  // file with a fluid of density 1e-6 kg/m3), within 0.5% (the contacts' penetration, 1e-4 of
  // the allowed step, scales with their forces too).
  const std::string text = read_text(kVerification / "coupled_hydrostatic_column.toml");
  int count = 0;
  const std::string effective = replace_all(text, "biot_coefficient = 0.0", "biot_coefficient = 1.0", count);
  ASSERT_EQ(count, 1);
  const std::string dry = replace_all(effective, "density = 1000.0", "density = 1.0e-6", count);
  ASSERT_EQ(count, 1);
  std::vector<std::vector<double>> settlements;
  std::array<double, 3> interface_force{};
  for (const auto& [name, scenario] : {std::pair{"column-biot-1", effective}, std::pair{"column-dry", dry}}) {
    const RunResult r = run_text_and_read(scenario, name);
    EXPECT_EQ(r.summary["converged"], true) << name;
    ASSERT_EQ(r.summary["blocks"].size(), 3u) << name;
    std::vector<double> settlement;
    for (int k = 0; k < 3; ++k) settlement.push_back(-r.summary["blocks"][k]["displacement"][1].get<double>());
    settlement.push_back(-r.summary["measure"]["top"]["displacement"][1].get<double>());
    settlements.push_back(settlement);
    if (settlements.size() == 1) interface_force = sum_interface_forces(r.contacts, true);
  }
  for (int y = 1; y <= 2; ++y) {
    const double expected = (kRhoRock - kRhoWater) * kG * (3.0 - y) * 1.0;
    EXPECT_NEAR(interface_force[y], expected, 0.01 * expected) << "interface y = " << y << " m";
  }
  const double ratio = (kRhoRock - kRhoWater) / kRhoRock;
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_GT(settlements[1][k], 1e-6) << "point " << k << ": the dry column settles";
    EXPECT_NEAR(settlements[0][k], ratio * settlements[1][k], 0.005 * ratio * settlements[1][k]) << "point " << k;
  }
}

}  // namespace
