// The default contact distance of a scenario's blocks (mechanics.max_displacement_ratio left
// out): Shi's 2.5 × 0.01 × half the model's height, but at most half the thinnest block's
// width, so that no vertex is sought against the edges across a whole block.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "dda/support.hpp"
#include "dda/system.hpp"
#include "geometry/polygon.hpp"
#include "run/model_building.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace dda = hydrodda::dda;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

// A column 1 m wide and 10 m high cut by flat beds every 0.1 m (100 blocks, joints 1 mm
// open), on a held base, under gravity. Shi's contact distance, 2.5 × 0.01 × 5 m = 0.125 m,
// is wider than a bed.
std::string bedded_column(const std::string& extra_mechanics) {
  return R"(
[geometry]
domain = [[0.0, 0.0], [1.0, 0.0], [1.0, 10.0], [0.0, 10.0]]
initial_aperture = 0.001
[[geometry.joint_set]]
angle = 0.0
spacing = 0.1
offset = 0.1
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint]
friction_angle = 30.0
[mechanics]
steps = 1
)" + extra_mechanics + R"(
[[mechanics.displacement]]
boundary = "bottom"
value = [0.0, 0.0]
)";
}

// The widest gap of any contact the search holds after one step.
double widest_candidate_gap(dda::ModelDefinition model) {
  dda::System system(std::move(model));
  system.step();
  double widest = 0.0;
  for (const dda::ContactInfo& c : system.contacts()) widest = std::max(widest, -c.penetration);
  return widest;
}

TEST(ContactDistance, ThinBedsKeepItWithinHalfABed) {
  const scenario::Scenario s = scenario::parse_scenario(bedded_column(""), "column.toml");
  const std::vector<dda::BlockDefinition> blocks = run::build_blocks(s);
  const dda::ModelDefinition model = run::build_mechanics_model(s, blocks);
  double thinnest = INFINITY;
  for (const dda::BlockDefinition& b : blocks)
    thinnest = std::min(thinnest, hydrodda::geometry::width_across_edges(b.polygon));
  // The beds are 0.1 m less the 1 mm aperture.
  EXPECT_NEAR(thinnest, 0.099, 1e-9);
  // 2.5 r w0 = w_min / 2 exactly (round-off: 1e-12 relative).
  EXPECT_NEAR(dda::initial_contact_distance(blocks, model.settings), 0.5 * thinnest, 1e-12 * thinnest);
  EXPECT_LT(model.settings.max_displacement_ratio, 0.01);
  // No candidate across a bed: the search holds the joints' 1 mm gaps, and nothing as far as
  // the edges a bed further on.
  const double widest = widest_candidate_gap(model);
  EXPECT_GT(widest, 0.0009);
  EXPECT_LE(widest, 0.5 * thinnest);
}

TEST(ContactDistance, AGivenRatioIsKeptAndThenReachesAcrossBeds) {
  const scenario::Scenario s =
      scenario::parse_scenario(bedded_column("max_displacement_ratio = 0.01\n"), "column.toml");
  const std::vector<dda::BlockDefinition> blocks = run::build_blocks(s);
  const dda::ModelDefinition model = run::build_mechanics_model(s, blocks);
  EXPECT_EQ(model.settings.max_displacement_ratio, 0.01);
  EXPECT_NEAR(dda::initial_contact_distance(blocks, model.settings), 0.125, 1e-12);
  // What the default keeps out: a corner sought against the far face of the bed beyond its
  // neighbour, 0.1 m and more away.
  EXPECT_GT(widest_candidate_gap(model), 0.1);
}

TEST(ContactDistance, BlocksWideAgainstTheModelKeepShisRatio) {
  // The same column cut every 2.5 m: half the width, 1.25 m, exceeds 0.125 m.
  std::string text = bedded_column("");
  text.replace(text.find("spacing = 0.1"), 13, "spacing = 2.5");
  text.replace(text.find("offset = 0.1"), 12, "offset = 2.5");
  const scenario::Scenario s = scenario::parse_scenario(text, "column.toml");
  EXPECT_FALSE(s.mechanics->max_displacement_ratio.has_value());
  EXPECT_EQ(run::build_mechanics_model(s, run::build_blocks(s)).settings.max_displacement_ratio, 0.01);
}

// The penetration tolerance where the joints carry a hydraulic aperture: a gap within the
// tolerance counts as closed and takes the closure law's aperture, so the default, 1e-4 of
// the allowed step displacement (1.5e-5 m for this 30 m model), falls to a fiftieth of the
// joints' aperture at zero stress a_r + V_m (5 + 40 µm here: 9e-7 m). A given value is kept;
// without the joint keys the DDA's own default stands.
TEST(PenetrationTolerance, JointsWithAHydraulicApertureSetItBelowTheirAperture) {
  const std::filesystem::path seal = std::filesystem::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/seal_at_depth.toml";
  const scenario::Scenario s = scenario::read_scenario(seal);
  const std::vector<dda::BlockDefinition> blocks = run::build_blocks(s);
  const dda::ModelDefinition model = run::build_mechanics_model(s, blocks);
  EXPECT_NEAR(model.settings.penetration_tolerance, 0.02 * (5e-6 + 4e-5), 1e-18);
  EXPECT_EQ(dda::System(model).penetration_tolerance(), model.settings.penetration_tolerance);

  scenario::Scenario given = s;
  given.mechanics->penetration_tolerance = 3e-6;
  EXPECT_EQ(run::build_mechanics_model(given, blocks).settings.penetration_tolerance, 3e-6);

  scenario::Scenario plain = s;
  plain.joint.residual_aperture.reset();
  plain.joint.normal_stiffness.reset();
  plain.joint.max_closure.reset();
  const dda::ModelDefinition unresolved = run::build_mechanics_model(plain, blocks);
  EXPECT_EQ(unresolved.settings.penetration_tolerance, 0.0);  // the DDA's own: 1e-4 r w0
  EXPECT_NEAR(dda::System(unresolved).penetration_tolerance(), 1e-4 * 0.01 * 15.0, 1e-15);
}

TEST(PenetrationTolerance, AValueNotAboveZeroIsRefused) {
  for (const std::string value : {"0.0", "-1e-6"}) {
    try {
      scenario::parse_scenario(bedded_column("penetration_tolerance = " + value + "\n"), "column.toml");
      ADD_FAILURE() << value << " was accepted";
    } catch (const scenario::ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("mechanics.penetration_tolerance: must be > 0"), std::string::npos) << e.what();
    }
  }
  const scenario::Scenario s = scenario::parse_scenario(bedded_column("penetration_tolerance = 2e-6\n"), "column.toml");
  EXPECT_EQ(s.mechanics->penetration_tolerance, std::optional<double>(2e-6));
}

}  // namespace
