// The breach named as such (run/no_equilibrium.hpp): the load a scenario drives its blocks with,
// as its keys spell it, and the message that names the load, the escaping blocks at their
// centroids and the fractures open in the last state that held. The message is a contract:
// its text is checked whole.

#include <gtest/gtest.h>

#include <filesystem>

#include "run/no_equilibrium.hpp"

namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;
namespace fs = std::filesystem;
using hydrodda::geometry::Point;
using hydrodda::hydro::BoundaryKind;

namespace {

scenario::Scenario seal_under_pressure() {
  scenario::Scenario s;
  scenario::FlowDefinition flow;
  flow.boundaries = {{"top", BoundaryKind::pressure, 6e6}, {"left", BoundaryKind::flux, 1e-6},
                     {"bottom", BoundaryKind::pressure, 1.1e7}};
  s.flow = flow;
  return s;
}

TEST(NoEquilibrium, TheLoadIsNamedAsTheScenarioSpellsIt) {
  // The highest pressure drives, against the rest; a flux boundary is no load.
  EXPECT_EQ(run::describe_driving_load(seal_under_pressure()),
            "flow.boundary \"bottom\" pressure = 1.1e+07 Pa, against \"top\" pressure = 6e+06 Pa");
  // Two mouths at one head both drive; a head and a pressure are ranked by their pressure head.
  scenario::Scenario jack;
  scenario::FlowDefinition flow;
  flow.boundaries = {{"mouth_left", BoundaryKind::head, 2.75}, {"top", BoundaryKind::head, 0.0},
                     {"mouth_right", BoundaryKind::head, 2.75}};
  jack.flow = flow;
  EXPECT_EQ(run::describe_driving_load(jack), "flow.boundary \"mouth_left\" head = 2.75 m and \"mouth_right\" head = "
                                              "2.75 m, against \"top\" head = 0 m");
  // Mechanical loads after the fluid's.
  scenario::MechanicsDefinition m;
  m.tractions = {{"top", -1e7, -1e7, 0.0, 0.0}, {"side", -1e6, -2e6, 0.0, 1e5}};
  const std::vector<double> force{8648.7, 0.0};
  m.loads = {{Point{1.5, 1.5}, hydrodda::numerics::TimeTable::constant(force)}};
  scenario::Scenario loaded;
  loaded.mechanics = m;
  EXPECT_EQ(run::describe_driving_load(loaded),
            "mechanics.traction \"top\" normal = -1e+07 Pa, shear = 0 Pa, mechanics.traction \"side\" normal = -1e+06 "
            "to -2e+06 Pa, shear = 0 to 1e+05 Pa, mechanics.load at (1.5, 1.5) force = [8649, 0] N/m");
  EXPECT_EQ(run::describe_driving_load(scenario::Scenario{}), "gravity alone");
}

TEST(NoEquilibrium, TheMessageNamesTheLoadTheBlocksAndTheOpenFractures) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-no-equilibrium-test";
  fs::remove_all(dir);
  const hydrodda::output::RunFolder folder(dir, hydrodda::output::ExistingFolder::Refuse);
  const std::vector<run::EscapedBlock> blocks{{{13, 11.4, 1.0}, Point{8.52, 13.4}}, {{2, 10.8, 1.0}, Point{4.5, 12.9}}};
  run::HeldState held;
  held.name = "coupling iteration 1";
  held.step = 1;
  held.fractures_known = true;
  held.open_fractures = {3, 7};
  EXPECT_EQ(run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "coupling iteration 2", &folder),
            "no mechanical equilibrium under flow.boundary \"bottom\" pressure = 1.1e+07 Pa, against \"top\" pressure = "
            "6e+06 Pa: 2 block(s) moved farther than their own size (the square root of their area) and the load still "
            "moves them: block 13 at (8.52, 13.4) (moved 11.4 m, size 1 m), block 2 at (4.5, 12.9) (moved 10.8 m, "
            "size 1 m); in the last state that held (coupling iteration 1) fractures 3, 7 were open; the load exceeds "
            "what the blocks' weight, their contacts and the supports can hold (summary.json, history.csv and the "
            "figures are of coupling iteration 2)");
  held = run::HeldState{};
  held.fractures_known = true;
  const std::string none = run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "DDA step 300", &folder);
  EXPECT_NE(none.find("; in the last state that held (the blocks as built) no fracture was open;"), std::string::npos)
      << none;
  held.fractures_known = false;
  const std::string unknown = run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "DDA step 300", &folder);
  EXPECT_EQ(unknown.find("fracture"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find("held"), std::string::npos) << unknown;
  // A model with bonds: how many had broken by then, with or without traces to measure.
  held.name = "DDA step 28";
  held.broken_bonds = 1;
  const std::string one = run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "DDA step 29", &folder);
  EXPECT_NE(one.find("; in the last state that held (DDA step 28) 1 bond had broken (fractures.csv's bond rows to "
                     "then); the load"),
            std::string::npos)
      << one;
  held.broken_bonds_later = 3;
  const std::string later = run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "DDA step 29", &folder);
  EXPECT_NE(later.find("(DDA step 28) 1 bond had broken (fractures.csv's bond rows to then; 3 more after it); the"),
            std::string::npos)
      << later;
  held.fractures_known = true;
  held.open_fractures = {4};
  held.broken_bonds = 0;
  held.broken_bonds_later = 0;
  const std::string both = run::describe_no_equilibrium(seal_under_pressure(), blocks, held, "DDA step 29", &folder);
  EXPECT_NE(both.find("; in the last state that held (DDA step 28) fracture 4 was open and no bond had broken; the load"),
            std::string::npos)
      << both;
  // summary.json's last_held says the same: no open_fractures where none were measured.
  const hydrodda::output::LastHeldSummary summary = run::summarise_held_state(held);
  EXPECT_EQ(summary.state, "DDA step 28");
  ASSERT_TRUE(summary.open_fractures.has_value());
  EXPECT_EQ(*summary.open_fractures, std::vector<int>{4});
  EXPECT_EQ(summary.broken_bonds, 0);
  held.fractures_known = false;
  EXPECT_FALSE(run::summarise_held_state(held).open_fractures.has_value());
  fs::remove_all(dir);
}

}  // namespace
