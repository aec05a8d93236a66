#include "scenario/fracture_sources.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

namespace fs = std::filesystem;

const char* kHead = R"(
[geometry]
domain = [[0.0, 0.0], [10.0, 0.0], [10.0, 5.0], [0.0, 5.0]]
)";
const char* kTail = R"(
[material.rock]
density = 2500.0
young = 1e10
poisson = 0.25
[mechanics]
[[mechanics.fixed]]
point = [1.0, 0.0]
)";

std::vector<Diagnostic> errors_of(const std::string& text, const fs::path& file = "case.toml") {
  try {
    parse_scenario(text, file);
  } catch (const ScenarioError& e) {
    return e.diagnostics();
  }
  return {};
}

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

TEST(JointSetKeys, ReadsEveryKeyAndRecordsTheSeedDefault) {
  const Scenario s = parse_scenario(std::string(kHead) + R"(
[[geometry.joint_set]]
angle = 85.0
spacing = 2.0
angle_spread = 3.0
spacing_spread = 0.5
length = 4.0
length_spread = 1.0
gap = 2.0
gap_spread = 0.5
offset = 0.3
region = [[0.0, 0.0], [5.0, 0.0], [5.0, 5.0], [0.0, 5.0]]
seed = 7
[[geometry.joint_set]]
angle = 0.0
spacing = 1.0
)" + kTail, "case.toml");
  ASSERT_EQ(s.geometry->joint_sets.size(), 2u);
  const JointSetDefinition& a = s.geometry->joint_sets[0];
  EXPECT_EQ(a.angle, 85.0);
  EXPECT_EQ(a.spacing, 2.0);
  EXPECT_EQ(a.angle_spread, 3.0);
  EXPECT_EQ(a.spacing_spread, 0.5);
  EXPECT_EQ(a.length, 4.0);
  EXPECT_EQ(a.length_spread, 1.0);
  EXPECT_EQ(a.gap, 2.0);
  EXPECT_EQ(a.gap_spread, 0.5);
  EXPECT_EQ(a.offset, 0.3);
  EXPECT_EQ(a.region.size(), 4u);
  EXPECT_EQ(a.seed, 7u);
  const JointSetDefinition& b = s.geometry->joint_sets[1];
  EXPECT_FALSE(b.length);
  EXPECT_FALSE(b.offset);
  EXPECT_TRUE(b.region.empty());
  EXPECT_EQ(b.seed, 0u);
  bool seed_default = false;
  for (const DefaultUsed& d : s.defaults_used) seed_default = seed_default || d.key == "geometry.joint_set[1].seed";
  EXPECT_TRUE(seed_default);
}

TEST(JointSetKeys, BadValuesNameTheirLineAndKey) {
  const auto errors = errors_of(std::string(kHead) + R"(
[[geometry.joint_set]]
angle = 85.0
spacing = -2.0
length_spread = 1.0
[[geometry.joint_set]]
spacing = 1.0e-6
)" + kTail);
  EXPECT_TRUE(has_error(errors, "case.toml:7: geometry.joint_set.spacing: must be > 0")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:8: geometry.joint_set.length_spread: applies to traces of a given length")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:9: geometry.joint_set.angle: required key is missing")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "case.toml:10: geometry.joint_set.spacing: the set would make some")) << dump(errors);
  EXPECT_EQ(errors.size(), 4u) << dump(errors);
}

TEST(JointSetKeys, SetsNeedADomain) {
  const auto errors = errors_of(R"(
[geometry]
[[geometry.block]]
vertices = [[0, 0], [1, 0], [1, 1], [0, 1]]
[[geometry.joint_set]]
angle = 0.0
spacing = 0.5
)" + std::string(kTail));
  EXPECT_TRUE(has_error(errors, "geometry.domain: fractures, joint sets and welded regions need a domain")) << dump(errors);
}

TEST(FracturesFile, RowsHeaderCommentsAndBlankLines) {
  std::vector<Diagnostic> errors;
  const auto rows = parse_fracture_rows("x1,y1,x2,y2\n1,2,3,4\n\n# a comment\n 5.5 , -1e-1, 7,8 \r\n", "dfn.csv",
                                        "geometry.fractures_file", errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].segment.from, (Point{1, 2}));
  EXPECT_EQ(rows[0].line, 2);
  EXPECT_EQ(rows[1].segment.from, (Point{5.5, -0.1}));
  EXPECT_EQ(rows[1].segment.to, (Point{7, 8}));
  EXPECT_EQ(rows[1].line, 5);
}

TEST(FracturesFile, BadRowsNameTheFileAndLine) {
  std::vector<Diagnostic> errors;
  const auto rows = parse_fracture_rows("1,2,3,4\nx1,y1,x2,y2\n1,2,3\n4,4,4,4\n1,2,3,nan\n", "dfn.csv",
                                        "geometry.fractures_file", errors);
  EXPECT_EQ(rows.size(), 1u);
  EXPECT_TRUE(has_error(errors, "dfn.csv:2: geometry.fractures_file: expected four numbers")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "dfn.csv:3: geometry.fractures_file: expected four numbers")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "dfn.csv:4: geometry.fractures_file: the trace's two end points coincide")) << dump(errors);
  EXPECT_TRUE(has_error(errors, "dfn.csv:5: geometry.fractures_file: expected four numbers")) << dump(errors);
  EXPECT_EQ(errors.size(), 4u);
}

TEST(FracturesFile, ReadAgainstTheScenariosFolder) {
  const fs::path folder = fs::temp_directory_path() / "hydrodda-fractures-file";
  fs::remove_all(folder);
  fs::create_directories(folder / "dfn");
  std::ofstream(folder / "dfn" / "traces.csv") << "x1,y1,x2,y2\n1,0,2,5\n3,0,4,5\n";
  const std::string text = std::string(kHead) + "fractures_file = \"dfn/traces.csv\"\n" + kTail;
  const Scenario s = parse_scenario(text, folder / "case.toml");
  ASSERT_EQ(s.geometry->file_fractures.size(), 2u);
  EXPECT_EQ(s.geometry->file_fractures[1].segment.to, (Point{4, 5}));
  EXPECT_EQ(s.geometry->file_fractures[1].line, 3);
  EXPECT_EQ(*s.geometry->fractures_file, folder / "dfn" / "traces.csv");
  // A missing file is an error on the key's line.
  const auto errors = errors_of(std::string(kHead) + "fractures_file = \"none.csv\"\n" + kTail, folder / "case.toml");
  EXPECT_TRUE(has_error(errors, "case.toml:4: geometry.fractures_file: cannot read")) << dump(errors);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace hydrodda::scenario
