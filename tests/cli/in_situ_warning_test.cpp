// `check` compares each block's initial σyy with the weight of the layers above it plus the
// top's traction (run/in_situ_check.hpp) and warns beyond 5%, naming mechanics.initial_stress
// with its line; a model that matches says nothing of it. The layered stress of
// scenarios/verification/three_layer_column.toml matches by construction; shifted by
// 0.1 MPa at its free top, its blocks' σyy miss by 0.1 MPa, more than 5% of the weight above
// any block shallower than ~18 m (ρ g depth ≈ 2 MPa at the base).

#include <gtest/gtest.h>

#include <filesystem>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

const fs::path kColumn = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/three_layer_column.toml";
constexpr const char* kWarning = "differs by more than 5% from the weight of the layers above";

TEST(InSituCheck, ALayeredColumnInItsOwnWeightPassesSilently) {
  const auto result = run_program("check " + kColumn.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find(kWarning), std::string::npos) << result.output;
}

TEST(InSituCheck, AStressAtAFreeTopIsWarnedAboutNamingTheKeyAndLine) {
  const fs::path edited = hydrodda::testing::edited_scenario(
      kColumn, "three_layer_column_stress_at_free_top",
      {{"stress = [0.0, 0.0, 0.0]      # at the top", "stress = [-5.0e4, -1.0e5, 0.0]"}});
  const auto result = run_program("check " + edited.string());
  fs::remove(edited);
  EXPECT_EQ(result.exit_code, 0) << result.output;  // a warning, not an error: the user may mean it
  EXPECT_NE(result.output.find(kWarning), std::string::npos) << result.output;
  EXPECT_NE(result.output.find(edited.string() + ":48: mechanics.initial_stress"), std::string::npos) << result.output;
}

TEST(InSituCheck, ATopTractionThatCarriesTheStressIsNotWarnedAbout) {
  // The same stress at the top, now carried by a traction of −0.1 MPa there: in equilibrium.
  const fs::path edited = hydrodda::testing::edited_scenario(
      kColumn, "three_layer_column_with_overburden",
      {{"stress = [0.0, 0.0, 0.0]      # at the top", "stress = [-5.0e4, -1.0e5, 0.0]"},
       {"[output]", "[[mechanics.traction]]\nboundary = \"top\"\nnormal = -1.0e5\nnormal_end = -1.0e5\n[output]"}});
  const auto result = run_program("check " + edited.string());
  fs::remove(edited);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find(kWarning), std::string::npos) << result.output;
}

}  // namespace
