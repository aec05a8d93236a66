// The layered in-situ stress of a scenario (run/layered_stress.hpp) and the in-situ check
// (run/in_situ_check.hpp), on scenarios built in code. References: σyy(y) = σyy(y_ref) −
// g_y ∫_{y_ref}^{y} ρ' dη with ρ' = ρ − α ρ_w under hydrostatic pore pressure in a coupled run
// (the effective stress in still water), ρ otherwise; σxx = σxx(y_ref) + K0 (σyy − σyy(y_ref)).
// Hand-computed values; tolerance 1e-9 relative (round-off).

#include <gtest/gtest.h>

#include "run/in_situ_check.hpp"
#include "run/layered_stress.hpp"

namespace {

using hydrodda::scenario::MaterialDefinition;
using hydrodda::scenario::Scenario;

// A 4 m × 10 m domain: "sand" below y = 4 (ρ 2000, α 0.5), "mud" above (ρ 2500, α 1), free top at
// y = 10 where σ = (−1e5, −2e5, 0), K0 = 0.5.
Scenario two_layers() {
  Scenario s;
  s.geometry.emplace();
  s.geometry->domain = {{0, 0}, {4, 0}, {4, 10}, {0, 10}};
  MaterialDefinition mud;
  mud.name = "mud";
  mud.density = 2500.0;
  MaterialDefinition sand;
  sand.name = "sand";
  sand.density = 2000.0;
  sand.biot_coefficient = 0.5;
  sand.region = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  s.materials = {mud, sand};
  s.mechanics.emplace();
  s.mechanics->gravity = {0.0, -10.0};
  hydrodda::scenario::InitialStressDefinition stress;
  stress.stress = {-1e5, -2e5, 0.0};
  stress.reference_y = 10.0;
  stress.layers = true;
  stress.horizontal_ratio = 0.5;
  s.mechanics->initial_stress = stress;
  return s;
}

TEST(LayeredStress, IntegratesEachLayersDensityDownFromTheTop) {
  const Scenario s = two_layers();
  const auto field = hydrodda::run::build_initial_stress(s);
  // At y = 4: −2e5 − 10 × 2500 × 6 = −3.5e5; at y = 0: that − 10 × 2000 × 4 = −4.3e5.
  EXPECT_NEAR(field.at(4.0)[1], -3.5e5, 1e-9 * 3.5e5);
  EXPECT_NEAR(field.at(0.0)[1], -4.3e5, 1e-9 * 4.3e5);
  EXPECT_NEAR(field.at(2.0)[1], -3.9e5, 1e-9 * 3.9e5);
  EXPECT_NEAR(field.at(0.0)[0], -1e5 + 0.5 * (-4.3e5 + 2e5), 1e-9 * 2.15e5);
  EXPECT_EQ(field.at(0.0)[2], 0.0);
}

TEST(LayeredStress, CarriesTheBuoyantWeightUnderHydrostaticPorePressure) {
  // Coupled, hydrostatic: ρ' = 2500 − 1000 above, 2000 − 0.5 × 1000 below.
  Scenario s = two_layers();
  s.flow.emplace();
  s.flow->pressure = hydrodda::hydro::PressureConvention::hydrostatic;
  const auto field = hydrodda::run::build_initial_stress(s);
  const double at_border = -2e5 - 10.0 * 1500.0 * 6.0, at_base = at_border - 10.0 * 1500.0 * 4.0;
  EXPECT_NEAR(field.at(4.0)[1], at_border, 1e-9 * std::abs(at_border));
  EXPECT_NEAR(field.at(0.0)[1], at_base, 1e-9 * std::abs(at_base));
}

TEST(LayeredStress, ReadsTheColumnAtColumnXWhereTheLayersStep) {
  // The sand's top steps from y = 4 (x < 2) to y = 6 (x > 2); read at x = 3 the border is at 6.
  Scenario s = two_layers();
  s.materials[1].region = {{0, 0}, {4, 0}, {4, 6}, {2, 6}, {2, 4}, {0, 4}};
  s.mechanics->initial_stress->column_x = 3.0;
  const auto field = hydrodda::run::build_initial_stress(s);
  EXPECT_NEAR(field.at(6.0)[1], -2e5 - 10.0 * 2500.0 * 4.0, 1.0e-4);
  EXPECT_NEAR(field.at(0.0)[1], -2e5 - 10.0 * 2500.0 * 4.0 - 10.0 * 2000.0 * 6.0, 1.0e-4);
}

TEST(InSituCheck, NamesTheBlocksWhoseColumnTheFieldMisses) {
  // The stepped layers read at x = 3, from σ = 0 at the free top. At x = 1 the sand's top is at 4:
  // a block centred at (1, 5) has 5 m of mud over it, −1.25e5 Pa, against the field's 4 m of mud
  // and 1 m of sand, −1.2e5 (4% off: not warned); one at (1, 2) has 6 m of mud and 2 m of sand,
  // −1.9e5, against the field's 4 m and 4 m, −1.8e5 (5.3% off: warned).
  Scenario s = two_layers();
  s.materials[1].region = {{0, 0}, {4, 0}, {4, 6}, {2, 6}, {2, 4}, {0, 4}};
  s.mechanics->initial_stress->column_x = 3.0;
  s.mechanics->initial_stress->stress = {0.0, 0.0, 0.0};
  const auto field = hydrodda::run::build_initial_stress(s);
  const std::vector<hydrodda::dda::BlockDefinition> blocks = {{{{0, 4}, {2, 4}, {2, 6}, {0, 6}}, 0, false},
                                                              {{{0, 1}, {2, 1}, {2, 3}, {0, 3}}, 1, false}};
  const auto mismatches = hydrodda::run::compare_in_situ_stress(s, blocks, field);
  ASSERT_EQ(mismatches.size(), 1u);
  EXPECT_EQ(mismatches[0].block, 1);
  EXPECT_NEAR(mismatches[0].expected, -1.9e5, 1e-9 * 1.9e5);
  EXPECT_NEAR(mismatches[0].initial, -1.8e5, 1e-9 * 1.8e5);
  const auto text = hydrodda::run::describe_in_situ_mismatch(s, mismatches);
  ASSERT_TRUE(text.has_value());
  EXPECT_NE(text->find("mechanics.initial_stress"), std::string::npos);
  EXPECT_NE(text->find("block 1 at (1, 2)"), std::string::npos) << *text;
}

TEST(InSituCheck, AllowsForTheSeepageTheBoundaryHeadsCanDrive) {
  // Coupled, hydrostatic, heads 0 and 10 m on the boundaries: up to α ρ_w g Δh = 1 × 1000 × 10
  // × 10 = 1e5 Pa may come off the still-water weight. A start 0.9e5 lighter than it passes.
  Scenario s = two_layers();
  s.materials.pop_back();  // mud only, α = 1
  s.mechanics->initial_stress->stress = {0.0, 0.0, 0.0};
  s.flow.emplace();
  s.flow->pressure = hydrodda::hydro::PressureConvention::hydrostatic;
  s.flow->boundaries = {{"bottom", hydrodda::hydro::BoundaryKind::head, 10.0, 0},
                        {"top", hydrodda::hydro::BoundaryKind::head, 0.0, 0}};
  auto field = hydrodda::run::build_initial_stress(s);
  for (auto& knot : field.knots) knot.stress[1] += 0.9e5 * (10.0 - knot.y) / 10.0;
  const std::vector<hydrodda::dda::BlockDefinition> blocks = {{{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, 0, false}};
  EXPECT_TRUE(hydrodda::run::compare_in_situ_stress(s, blocks, field).empty());
  s.flow->boundaries[0].value = 1.0;  // Δh = 1 m: 1e4 Pa at most
  EXPECT_EQ(hydrodda::run::compare_in_situ_stress(s, blocks, field).size(), 1u);
}

TEST(InSituCheck, CountsTheFluidsShareOnTheTopsFaceWhereTheBiotCoefficientIsBelowOne) {
  // Mud only at α = 0 (total stress), hydrostatic, the top (y = 10) at a head of 30 m, the base at
  // 40 m: the top's face takes (1 − α) p_top = ρ_w g (30 − 10) = 1000 × 10 × 20 = 2e5 Pa beside
  // its (here zero) traction (docs/coupling.md, "Fluid pressure on the blocks"), so a field of
  // −2e5 Pa at the top, growing by ρ g = 2.5e4 Pa/m, is in equilibrium and passes; the field
  // without the fluid's share (0 at the top), 2e5 Pa off the 2.25e5 expected at y = 9, is warned
  // about, and so is the in-equilibrium field once α = 1 (the face then takes none).
  Scenario s = two_layers();
  s.materials.pop_back();
  s.materials[0].biot_coefficient = 0.0;
  s.mechanics->initial_stress->stress = {0.0, -2e5, 0.0};
  s.flow.emplace();
  s.flow->pressure = hydrodda::hydro::PressureConvention::hydrostatic;
  s.flow->boundaries = {{"bottom", hydrodda::hydro::BoundaryKind::head, 40.0, 0},
                        {"top", hydrodda::hydro::BoundaryKind::head, 30.0, 0}};
  const std::vector<hydrodda::dda::BlockDefinition> blocks = {{{{0, 8}, {4, 8}, {4, 10}, {0, 10}}, 0, false}};
  const auto in_equilibrium = hydrodda::run::build_initial_stress(s);
  EXPECT_TRUE(hydrodda::run::compare_in_situ_stress(s, blocks, in_equilibrium).empty());
  s.mechanics->initial_stress->stress = {0.0, 0.0, 0.0};
  const auto mismatches = hydrodda::run::compare_in_situ_stress(s, blocks, hydrodda::run::build_initial_stress(s));
  ASSERT_EQ(mismatches.size(), 1u);
  EXPECT_NEAR(mismatches[0].expected, -2.25e5, 1e-9 * 2.25e5);
  s.materials[0].biot_coefficient = 1.0;
  EXPECT_EQ(hydrodda::run::compare_in_situ_stress(s, blocks, in_equilibrium).size(), 1u);
}

}  // namespace
