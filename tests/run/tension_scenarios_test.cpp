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

// The tensile strength of a contact's joint type: that of the edge its vertex touches.
double tensile_strength_of(const dda::ModelDefinition& model, const dda::ContactKey& key) {
  const std::vector<int>& edges = model.blocks[static_cast<std::size_t>(key.block_j)].edge_joints;
  const int type = edges.empty() ? 0 : edges[static_cast<std::size_t>(key.edge)];
  return type == 0 ? model.joint.tensile_strength : model.joint_types[static_cast<std::size_t>(type - 1)].tensile_strength;
}

// The largest tension a closed joint contact without tensile strength reports, as a fraction of
// the largest normal force any contact reports (0 when none pulls). A contact on an intact bond
// is intact rock, and one of a joint type with a tensile strength (Mandel's strips held together)
// may pull up to it: their own tests check those (BondVerification.*, Bonds.*, the joint types').
double find_tension_fraction(const dda::System& system, const dda::ModelDefinition& model) {
  double largest = 0.0;
  double tension = 0.0;
  for (const dda::ContactInfo& c : system.contacts()) {
    largest = std::max(largest, std::abs(c.normal_force));
    const int bond = system.bond_of_contact(c.key);
    const bool intact_rock = bond >= 0 && !system.is_bond_broken(bond);
    const bool may_pull = tensile_strength_of(model, c.key) > 0.0;
    if (c.state != dda::ContactState::open && !intact_rock && !may_pull) tension = std::max(tension, -c.normal_force);
  }
  return largest > 0.0 ? tension / largest : 0.0;
}

// With T = 0 (every shipped scenario's default joint), tension beyond round-off (1e-9 of the largest contact
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
    const dda::ModelDefinition model = run::build_mechanics_model(s, run::build_blocks(s));
    dda::System system(model);
    for (int k = 0; k < 20; ++k) {
      system.step();
      ASSERT_LE(find_tension_fraction(system, model), 1e-9) << entry.path() << ", step " << k;
    }
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

}  // namespace
