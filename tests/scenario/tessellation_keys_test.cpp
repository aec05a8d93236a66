// [[geometry.tessellate]] and its bonds' joint type (scenario/tessellations.hpp): every key
// read, and each bad input named by file, line and key.

#include <gtest/gtest.h>

#include <string>

#include "parse_errors.hpp"
#include "scenario/reader.hpp"
#include "scenario/tessellations.hpp"

namespace hydrodda::scenario {
namespace {

using test_support::errors_of;

const std::string kHead = R"(
[geometry]
domain = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]
[material.rock]
density = 2500.0
young = 1e10
poisson = 0.25
[joint.bond]
tensile_strength = 1.0e6
cohesion = 2.0e6
friction_angle = 35.0
[mechanics]
[[mechanics.fixed]]
point = [1.0, 0.0]
)";

bool has_error(const std::vector<Diagnostic>& errors, const std::string& formatted) {
  for (const Diagnostic& d : errors)
    if (d.format().find(formatted) != std::string::npos) return true;
  return false;
}

std::string dump(const std::vector<Diagnostic>& errors) {
  std::string out;
  for (const Diagnostic& d : errors) out += d.format() + "\n";
  return out;
}

TEST(TessellationKeys, ReadsEveryKey) {
  const Scenario s = parse_scenario(kHead + R"(
[[geometry.tessellate]]
kind = "triangles"
size = 0.5
region = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
seed = 9
joint = "bond"
[[geometry.tessellate]]
size = 0.25
)", "case.toml");
  ASSERT_EQ(s.geometry->tessellations.size(), 2u);
  const TessellationDefinition& a = s.geometry->tessellations[0];
  EXPECT_EQ(a.kind, geometry::TessellationKind::triangles);
  EXPECT_DOUBLE_EQ(a.size, 0.5);
  EXPECT_EQ(a.region.size(), 4u);
  EXPECT_EQ(a.seed, 9u);
  EXPECT_EQ(a.joint.name, "bond");
  const TessellationDefinition& b = s.geometry->tessellations[1];
  EXPECT_EQ(b.kind, geometry::TessellationKind::voronoi);
  EXPECT_TRUE(b.region.empty());
  EXPECT_EQ(b.seed, 0u);
  EXPECT_TRUE(b.joint.name.empty());  // [joint]
}

// Line numbers count from the text's first line: kHead ends at line 14, the tables start at 16.
TEST(TessellationKeys, BadInputIsNamedByFileLineAndKey) {
  const auto errors = errors_of(kHead + R"(
[[geometry.tessellate]]
size = 5.0
joint = "rock"
[[geometry.tessellate]]
size = -1.0
region = [[10.0, 10.0], [12.0, 10.0], [12.0, 12.0]]
[[geometry.tessellate]]
kind = "hexagons"
)");
  EXPECT_TRUE(has_error(errors, "case.toml:17: geometry.tessellate.size: 5 m is larger than the region it tessellates (2 m across"))
      << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:18: geometry.tessellate.joint: joint type \"rock\" is not defined (the types are bond)"))
      << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:20: geometry.tessellate.size: must be > 0")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:21: geometry.tessellate.region: the region lies wholly outside geometry.domain"))
      << dump(errors);
  EXPECT_TRUE(has_error(errors, "geometry.tessellate.kind")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:22: geometry.tessellate.size: required key is missing")) << dump(errors);
}

TEST(TessellationKeys, NegativeStrengthsAndFractureEnergyAreRefused) {
  std::string text = kHead + R"(
[joint.weak]
tensile_strength = -1.0
cohesion = -2.0
fracture_energy = -5.0
[[geometry.tessellate]]
size = 0.5
joint = "weak"
)";
  const auto errors = errors_of(text);
  EXPECT_TRUE(has_error(errors, "case.toml:17: joint.weak.tensile_strength: must be >= 0")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:18: joint.weak.cohesion: must be >= 0")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:19: joint.weak.fracture_energy: must be >= 0")) << dump(errors);
}

TEST(TessellationKeys, ASofteningBondNeedsATensileStrength) {
  // w_c = 2 G_f / T: a fracture energy on bonds of no tensile strength has no softening law.
  auto errors = errors_of(kHead + R"(
[joint.soft]
fracture_energy = 50.0
[[geometry.tessellate]]
size = 0.5
joint = "soft"
)");
  EXPECT_TRUE(has_error(errors, "case.toml:17: joint.soft.fracture_energy: a softening bond (geometry.tessellate, line 18) "
                                "softens from its tensile_strength"))
      << dump(errors);
  // With one, it is a softening bond (docs/dda.md, "Bonds").
  errors = errors_of(kHead + R"(
[joint.soft]
tensile_strength = 1.0e6
fracture_energy = 50.0
[[geometry.tessellate]]
size = 0.5
joint = "soft"
)");
  EXPECT_TRUE(errors.empty()) << dump(errors);
}

TEST(TessellationKeys, ACoupledRunWithBondedSubBlocksIsAccepted) {
  // Broken bonds conduct and take the fluid's pressure (docs/dda.md, "Bonds").
  const auto errors = errors_of(kHead + R"(
[[geometry.tessellate]]
size = 0.5
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
[mesh]
size = 0.5
)");
  for (const auto& e : errors) EXPECT_EQ(e.key.find("geometry.tessellate"), std::string::npos) << dump(errors);
}

TEST(TessellationKeys, CracksAreReadAndABadOneIsRefusedByName) {
  auto errors = errors_of(kHead + R"(
[[geometry.tessellate]]
size = 0.2
region = [[0.5, 0.5], [3.5, 0.5], [3.5, 1.5], [0.5, 1.5]]
cracks = [[[1.0, 1.0], [3.0, 1.0]], [[1.0, 0.8], [1.3, 0.8]], [[1.0, 1.2], [3.9, 1.2]], [[1.0, 1.0]]]
)");
  EXPECT_TRUE(has_error(errors, "case.toml:19: geometry.tessellate.cracks: a crack 0.3 m long is shorter than two "
                                "sub-blocks (2 size = 0.4 m)"))
      << dump(errors);
  EXPECT_TRUE(has_error(errors, "geometry.tessellate.cracks: a crack must lie inside the tessellation's region")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "geometry.tessellate.cracks: a crack is a straight segment")) << dump(errors);
  EXPECT_EQ(errors.size(), 3u) << dump(errors);  // the first crack is good
}

TEST(TessellationKeys, TooManySubBlocksAreRefusedNamingTheKeysThatSetThem) {
  const auto errors = errors_of(kHead + R"(
[[geometry.tessellate]]
size = 0.005
)");
  // 8 m² / 0.005² = 320,000 cells, zoned into some 1.92 million triangles.
  EXPECT_TRUE(has_error(errors, "geometry.tessellate.size: the tessellations would make some 1.92e+06 sub-blocks"))
      << dump(errors);
  TessellationDefinition t;
  t.size = 0.5;
  const Polygon domain{{0.0, 0.0}, {4.0, 0.0}, {4.0, 2.0}, {0.0, 2.0}};
  EXPECT_DOUBLE_EQ(estimate_sub_blocks(t, domain), 192.0);  // Voronoi cells, zoned
  t.kind = geometry::TessellationKind::triangles;
  EXPECT_DOUBLE_EQ(estimate_sub_blocks(t, domain), 192.0);
}

}  // namespace
}  // namespace hydrodda::scenario
