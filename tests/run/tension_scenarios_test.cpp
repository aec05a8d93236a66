// Every shipped scenario with a [mechanics] section, as it is (mechanics.tension_cutoff on by
// default): its mechanics as the scenario builds them (blocks, joint, supports and loads; no
// fluid forces), stepped 20 times, end every step with no closed contact pulling.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "dda/system.hpp"
#include "run/model_building.hpp"
#include "scenario/reader.hpp"

namespace fs = std::filesystem;
namespace dda = hydrodda::dda;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

// The largest tension a closed joint contact reports, as a fraction of the largest normal force
// any contact reports (0 when none pulls). A contact on an intact bond is intact rock, not a
// joint: it carries tension up to the bond's strength, which its own tests check
// (BondVerification.*, Bonds.*).
double find_tension_fraction(const dda::System& system) {
  double largest = 0.0;
  double tension = 0.0;
  for (const dda::ContactInfo& c : system.contacts()) {
    largest = std::max(largest, std::abs(c.normal_force));
    const int bond = system.bond_of_contact(c.key);
    const bool intact_rock = bond >= 0 && !system.is_bond_broken(bond);
    if (c.state != dda::ContactState::open && !intact_rock) tension = std::max(tension, -c.normal_force);
  }
  return largest > 0.0 ? tension / largest : 0.0;
}

// With T = 0 (every shipped joint), tension beyond round-off (1e-9 of the largest contact
// force) in a closed contact after any of 20 steps. With tension_cutoff = false the paper's flexures
// end steps with closed contacts pulling up to the largest compression anywhere in them
// (symmetric_flexure_*.toml), the asymmetric ones with 2–6% of it, the brick wall with 19%.
// All of them take well under a second.
TEST(TensionScenarios, NoClosedContactPullsInAShippedScenario) {
  int checked = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios")) {
    if (entry.path().extension() != ".toml") continue;
    const scenario::Scenario s = scenario::read_scenario(entry.path());
    if (!s.mechanics) continue;
    ASSERT_EQ(s.joint.tensile_strength, 0.0) << entry.path();
    dda::System system(run::build_mechanics_model(s, run::build_blocks(s)));
    for (int k = 0; k < 20; ++k) {
      system.step();
      ASSERT_LE(find_tension_fraction(system), 1e-9) << entry.path() << ", step " << k;
    }
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

}  // namespace
