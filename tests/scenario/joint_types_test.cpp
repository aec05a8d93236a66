// Joint types: [joint.NAME] tables over [joint], and the traces that name them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "parse_errors.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

// A unit square cut by one listed fracture and two typed ones, joints of two types.
const std::string kTyped = R"(title = "joint types"
[geometry]
domain = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
fractures = [[[0.0, 0.5], [1.0, 0.5]]]
[[geometry.fracture]]
trace = [[0.5, 0.0], [0.5, 1.0]]
joint = "fault"
[[geometry.fracture]]
trace = [[0.25, 0.0], [0.25, 1.0]]
[joint]
friction_angle = 35.0
cohesion = 1.0e5
tensile_strength = 1.0e4
[joint.fault]
friction_angle = 20.0
cohesion = 0.0
[joint.clay]
barrier_permeability = 1.0e-20
barrier_width = 0.01
[flow]
[[flow.boundary]]
name = "left"
head = 1.0
[[flow.region]]
name = "rock"
polygon = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
permeability = 1.0e-15
[mesh]
size = 0.1
)";

using test_support::errors_of;

bool has_error(const std::vector<Diagnostic>& errors, const std::string& text) {
  for (const Diagnostic& d : errors)
    if (d.format().find(text) != std::string::npos) return true;
  return false;
}

std::string dump(const std::vector<Diagnostic>& errors) {
  std::string out;
  for (const Diagnostic& d : errors) out += d.format() + "\n";
  return out;
}

TEST(JointTypes, ANamedTypeTakesItsOwnKeysAndTheDefaultsOthers) {
  const Scenario s = parse_scenario(kTyped, "case.toml");
  ASSERT_EQ(s.joint_types.size(), 2u);
  EXPECT_EQ(s.joint_type_index(""), 0);
  // Types are numbered in the order the file's tables are read (by name).
  EXPECT_EQ(s.joint_type_index("clay"), 1);
  EXPECT_EQ(s.joint_type_index("fault"), 2);
  EXPECT_EQ(s.joint_type_index("none"), -1);
  const JointDefinition& fault = s.joint_type(2);
  EXPECT_EQ(fault.name, "fault");
  EXPECT_EQ(fault.friction_angle, 20.0);
  EXPECT_EQ(fault.cohesion, 0.0);
  EXPECT_EQ(fault.tensile_strength, 1.0e4);  // [joint]'s
  EXPECT_FALSE(fault.barrier());
  const JointDefinition& clay = s.joint_type(1);
  EXPECT_EQ(clay.friction_angle, 35.0);
  EXPECT_EQ(clay.cohesion, 1.0e5);
  ASSERT_TRUE(clay.barrier());
  EXPECT_DOUBLE_EQ(clay.barrier_resistance(), 0.01 / 1.0e-20);
  EXPECT_TRUE(s.any_joint_barrier());
  EXPECT_FALSE(s.joint.barrier());
}

TEST(JointTypes, TracesNameTheirTypeInFileOrder) {
  const Scenario s = parse_scenario(kTyped, "case.toml");
  const GeometryDefinition& g = *s.geometry;
  ASSERT_EQ(g.fractures.size(), 3u);
  ASSERT_EQ(g.fracture_joints.size(), 3u);
  EXPECT_EQ(g.fracture_joints[0].name, "");       // the `fractures` list: the default type
  EXPECT_EQ(g.fracture_joints[1].name, "fault");
  EXPECT_EQ(g.fracture_joints[1].line, 7);
  EXPECT_EQ(g.fracture_joints[2].name, "");
  EXPECT_EQ(g.fractures[1].from, (Point{0.5, 0.0}));
}

TEST(JointTypes, ANameThatNamesNoTypeIsAnErrorAtItsLineAndKey) {
  std::string text = kTyped;
  text.replace(text.find("joint = \"fault\""), 15, "joint = \"faul\"");
  const auto errors = errors_of(text);
  EXPECT_TRUE(has_error(errors, "case.toml:7: geometry.fracture.joint: joint type \"faul\" is not defined (the types are "
                                "clay, fault)"))
      << dump(errors);
  text.replace(text.find("[joint]"), 0, "[[geometry.joint_set]]\nangle = 0.0\nspacing = 0.3\njoint = \"shear\"\n");
  EXPECT_TRUE(has_error(errors_of(text), "case.toml:13: geometry.joint_set.joint: joint type \"shear\" is not defined"))
      << dump(errors_of(text));
}

TEST(JointTypes, ABarrierNeedsBothItsKeys) {
  std::string text = kTyped;
  text.replace(text.find("barrier_width = 0.01"), 20, "");
  EXPECT_TRUE(has_error(errors_of(text), "case.toml:18: joint.clay.barrier_width: required with barrier_permeability"))
      << dump(errors_of(text));
  text = kTyped;
  text.replace(text.find("barrier_width = 0.01"), 20, "barrier_width = -1.0");
  EXPECT_TRUE(has_error(errors_of(text), "joint.clay.barrier_width: must lie in (0, 1) m")) << dump(errors_of(text));
}

TEST(JointTypes, AFractureTableNeedsATraceOfTwoPoints) {
  std::string text = kTyped;
  const std::string trace = "trace = [[0.25, 0.0], [0.25, 1.0]]";
  text.replace(text.find(trace), trace.size(), "trace = [[0.25, 0.0]]");
  EXPECT_TRUE(has_error(errors_of(text), "geometry.fracture.trace: a fracture is a straight cut")) << dump(errors_of(text));
}

TEST(JointTypes, AFracturesFileRowNamesItsTypeInAFifthColumn) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-joint-types-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "dfn.csv") << "x1,y1,x2,y2,joint\n0.0,0.75,1.0,0.75,fault\n0.75,0.0,0.75,1.0\n0.1,0.0,0.1,1.0,slip\n";
  std::string text = kTyped;
  text.replace(text.find("[[geometry.fracture]]"), 0, "fractures_file = \"dfn.csv\"\n");
  std::ofstream(dir / "case.toml") << text;
  std::vector<Diagnostic> errors;
  try {
    read_scenario(dir / "case.toml");
  } catch (const ScenarioError& e) {
    errors = e.diagnostics();
  }
  fs::remove_all(dir);
  ASSERT_EQ(errors.size(), 1u) << dump(errors);
  EXPECT_TRUE(has_error(errors, "dfn.csv:4: geometry.fractures_file: joint type \"slip\" is not defined")) << dump(errors);
}

}  // namespace
}  // namespace hydrodda::scenario

namespace hydrodda::scenario {
namespace {

// kTyped as a coupled model: the joint hydraulic keys need a [mechanics] section.
std::string with_mechanics(std::string text) {
  return text + "[material.rock]\ndensity = 2500.0\nyoung = 1.0e10\npoisson = 0.25\ngrain_diameter = 1.0e-4\n"
                "[mechanics]\n[[mechanics.fixed]]\npoint = [0.1, 0.1]\n";
}

// Each type's own hydraulic aperture law: [joint.fault]'s keys over [joint]'s, a type that gives
// none takes [joint]'s (clay here), and none at all is a = 0 (a closed joint carries nothing).
TEST(JointTypes, ATypeHasItsOwnHydraulicApertureLawOverTheDefaults) {
  std::string text = with_mechanics(kTyped);
  text.replace(text.find("tensile_strength = 1.0e4\n"), 0, "residual_aperture = 1.0e-5\nnormal_stiffness = 2.0e11\nmax_closure = 1.0e-4\n");
  text.replace(text.find("cohesion = 0.0\n"), 0, "residual_aperture = 5.0e-5\n");
  ASSERT_TRUE(errors_of(text).empty()) << dump(errors_of(text));
  const Scenario s = parse_scenario(text, "case.toml");
  const JointDefinition& fault = s.joint_type(s.joint_type_index("fault"));
  const JointDefinition& clay = s.joint_type(s.joint_type_index("clay"));
  EXPECT_EQ(fault.residual_aperture, 5.0e-5);
  EXPECT_EQ(fault.normal_stiffness, 2.0e11);  // inherited
  EXPECT_EQ(fault.max_closure, 1.0e-4);
  EXPECT_EQ(clay.residual_aperture, 1.0e-5);
  EXPECT_EQ(clay.max_closure, 1.0e-4);
  EXPECT_TRUE(s.any_joint_hydraulic());

  // Only the fault conducts by a law of its own; [joint] gives none.
  std::string fault_only = with_mechanics(kTyped);
  fault_only.replace(fault_only.find("cohesion = 0.0\n"), 0, "residual_aperture = 5.0e-5\n");
  const Scenario f = parse_scenario(fault_only, "case.toml");
  EXPECT_FALSE(f.joint.hydraulic());
  EXPECT_EQ(f.joint_type(f.joint_type_index("fault")).residual_aperture, 5.0e-5);
  EXPECT_TRUE(f.any_joint_hydraulic());
}

// Bad values of a type's own law are named by file, line and key.
TEST(JointTypes, ATypesBadApertureLawIsNamedByFileLineAndKey) {
  std::string text = with_mechanics(kTyped);
  text.replace(text.find("cohesion = 0.0\n"), 0, "residual_aperture = -1.0e-5\n");
  EXPECT_TRUE(has_error(errors_of(text), "case.toml:16: joint.fault.residual_aperture: must lie in [0, 1) m"))
      << dump(errors_of(text));
  std::string closure = with_mechanics(kTyped);
  closure.replace(closure.find("cohesion = 0.0\n"), 0, "max_closure = 1.0e-4\n");
  EXPECT_TRUE(has_error(errors_of(closure), "case.toml:16: joint.fault.normal_stiffness: required with joint.fault.max_closure"))
      << dump(errors_of(closure));
  // Without [mechanics] a type's law has no contacts to be measured on.
  std::string flow_only = kTyped;
  flow_only.replace(flow_only.find("cohesion = 0.0\n"), 0, "residual_aperture = 5.0e-5\n");
  EXPECT_TRUE(has_error(errors_of(flow_only), "case.toml:16: joint.fault.residual_aperture: joint hydraulic apertures "
                                              "are measured on the blocks' contacts"))
      << dump(errors_of(flow_only));
}


// Where a face is open to the flow, `hydraulic_opening`: "face" by default, a type's own over
// [joint]'s, and a value of neither spelling named by file, line and key.
TEST(JointTypes, ATypeSaysWhereItsFacesOpenToTheFlow) {
  std::string text = with_mechanics(kTyped);
  text.replace(text.find("tensile_strength = 1.0e4\n"), 0, "residual_aperture = 1.0e-5\nhydraulic_opening = \"local\"\n");
  text.replace(text.find("cohesion = 0.0\n"), 0, "hydraulic_opening = \"face\"\n");
  ASSERT_TRUE(errors_of(text).empty()) << dump(errors_of(text));
  const Scenario s = parse_scenario(text, "case.toml");
  EXPECT_EQ(s.joint.hydraulic_opening, hydro::HydraulicOpening::local);
  EXPECT_EQ(s.joint_type(s.joint_type_index("fault")).hydraulic_opening, hydro::HydraulicOpening::face);
  EXPECT_EQ(s.joint_type(s.joint_type_index("clay")).hydraulic_opening, hydro::HydraulicOpening::local);  // inherited
  EXPECT_EQ(parse_scenario(with_mechanics(kTyped), "case.toml").joint.hydraulic_opening, hydro::HydraulicOpening::face);

  std::string bad = with_mechanics(kTyped);
  bad.replace(bad.find("cohesion = 0.0\n"), 0, "hydraulic_opening = \"gap\"\n");
  EXPECT_TRUE(has_error(errors_of(bad), "case.toml:16: joint.fault.hydraulic_opening:")) << dump(errors_of(bad));
}

}  // namespace
}  // namespace hydrodda::scenario
