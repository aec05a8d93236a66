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

// A bad first row was taken for a header and skipped, where the same row on line 2 was an
// error: a header is a row with no number in it.
TEST(FracturesFile, AFirstRowWithANumberInItIsReadAsARow) {
  for (const std::string bad : {"x,0,1,5", "nan,0,1,5", "1,inf,1,5", "1,0,1e400,5", "1 0 1 5", "1,0,1,5,x,y"}) {
    SCOPED_TRACE(bad);
    std::vector<Diagnostic> first, second;
    EXPECT_EQ(parse_fracture_rows(bad + "\n2,0,2,5\n", "dfn.csv", "geometry.fractures_file", first).size(), 1u);
    EXPECT_EQ(parse_fracture_rows("2,0,2,5\n" + bad + "\n", "dfn.csv", "geometry.fractures_file", second).size(), 1u);
    ASSERT_EQ(first.size(), 1u) << dump(first);
    ASSERT_EQ(second.size(), 1u) << dump(second);
    EXPECT_EQ(first[0].format(), "dfn.csv:1: geometry.fractures_file: " + second[0].message);
  }
  std::vector<Diagnostic> errors;
  parse_fracture_rows("nan,0,1,5\n2,0,2,5\n", "dfn.csv", "geometry.fractures_file", errors);
  EXPECT_TRUE(has_error(errors, "dfn.csv:1: geometry.fractures_file: expected four numbers x1,y1,x2,y2, got "
                                "\"nan,0,1,5\": x1 = nan is not a finite number"))
      << dump(errors);
  errors.clear();
  parse_fracture_rows("1,0,1e400,5\n", "dfn.csv", "geometry.fractures_file", errors);
  EXPECT_TRUE(has_error(errors, "x2 = 1e400 is beyond the range of a number")) << dump(errors);
  // A header still has no number in it, whatever its words.
  for (const std::string header : {"x1,y1,x2,y2", "start x, start y, end x, end y", "trace"}) {
    errors.clear();
    EXPECT_EQ(parse_fracture_rows(header + "\n2,0,2,5\n", "dfn.csv", "geometry.fractures_file", errors).size(), 1u);
    EXPECT_TRUE(errors.empty()) << header << "\n" << dump(errors);
  }
}

// Traces wholly outside the domain were cut into nothing and the run went on on intact rock.
TEST(FracturesFile, ATraceWhollyOutsideTheDomainIsAnErrorAtItsRow) {
  const fs::path folder = fs::temp_directory_path() / "hydrodda-fractures-outside";
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::ofstream traces(folder / "traces.csv");
  traces << "x1,y1,x2,y2\n1,0,2,5\n-5,-5,20,20\n20,0,20,5\n";  // inside, across, outside
  for (int i = 0; i < 25; ++i) traces << "30," << i << ",31," << i << "\n";
  traces.close();
  const auto errors = errors_of(std::string(kHead) + "fractures_file = \"traces.csv\"\n" + kTail, folder / "case.toml");
  const std::string file = (folder / "traces.csv").string();
  EXPECT_TRUE(has_error(errors, file + ":4: geometry.fractures_file: the trace lies wholly outside geometry.domain"))
      << dump(errors);
  EXPECT_FALSE(has_error(errors, file + ":2:")) << dump(errors);
  EXPECT_FALSE(has_error(errors, file + ":3:")) << dump(errors);
  // The first 20 are named, then how many there are.
  EXPECT_EQ(errors.size(), 21u) << dump(errors);
  EXPECT_TRUE(has_error(errors, "26 of its 28 traces lie wholly outside geometry.domain")) << dump(errors);
  fs::remove_all(folder);
}

TEST(JointSetKeys, ARegionWhollyOutsideTheDomainIsAnError) {
  const auto errors = errors_of(std::string(kHead) + R"([[geometry.joint_set]]
angle = 90.0
spacing = 1.0
region = [[20.0, 0.0], [30.0, 0.0], [30.0, 5.0], [20.0, 5.0]]
)" + kTail);
  EXPECT_TRUE(has_error(errors, "case.toml:7: geometry.joint_set.region: the set's region lies wholly outside geometry.domain"))
      << dump(errors);
  EXPECT_EQ(errors.size(), 1u) << dump(errors);
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
  EXPECT_TRUE(has_error(errors, "case.toml:4: geometry.fractures_file: no such file")) << dump(errors);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace hydrodda::scenario
