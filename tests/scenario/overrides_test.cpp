#include "scenario/overrides.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

const std::filesystem::path kSixBlock =
    std::filesystem::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_lr_rl.toml";

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The message of the ScenarioError that applying `overrides` throws, or "" if none.
std::string error_of(const std::vector<Override>& overrides) {
  try {
    apply_overrides(read_text(kSixBlock), kSixBlock, overrides);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioOverrides, SetsValuesInTablesAndArraysOfTables) {
  const std::string text = apply_overrides(read_text(kSixBlock), kSixBlock,
                                           {{"coupling.relaxation", "0.5"},
                                            {"flow.boundary[0].head", "5"},
                                            {"mechanics.contact", "penalty"},
                                            {"mechanics.gravity", "[0.0, -10.0]"},
                                            {"mechanics.displacement[1].value[0]", "-0.002"},
                                            {"title", "\"case 1\""}});
  const Scenario s = parse_scenario(text, "case.toml");
  EXPECT_EQ(s.coupling.relaxation, 0.5);
  ASSERT_EQ(s.flow->boundaries.size(), 2u);
  EXPECT_EQ(s.flow->boundaries[0].name, "right");
  EXPECT_EQ(s.flow->boundaries[0].value.value(0.0), 5.0);
  EXPECT_EQ(s.flow->boundaries[1].value.value(0.0), 0.0);  // the other boundary untouched
  EXPECT_EQ(s.mechanics->contact, dda::ContactMethod::penalty);
  EXPECT_EQ(s.mechanics->gravity, (Point{0.0, -10.0}));
  EXPECT_EQ(s.title, "case 1");
  // A whole number replacing a decimal stays a decimal in the file.
  EXPECT_NE(text.find("head = 5.0"), std::string::npos) << text;
  // Everything else reads back as in the original file.
  const Scenario original = read_scenario(kSixBlock);
  EXPECT_EQ(s.geometry->fractures.size(), original.geometry->fractures.size());
  EXPECT_EQ(s.mesh->size, original.mesh->size);
  EXPECT_EQ(s.coupling.tolerance, original.coupling.tolerance);
}

TEST(ScenarioOverrides, AddsAValueMissingFromAnExistingTable) {
  // coupling.relaxation is in the file; mechanics.max_displacement_ratio is not.
  const std::string text = apply_overrides(read_text(kSixBlock), kSixBlock,
                                           {{"mechanics.max_displacement_ratio", "0.005"}});
  EXPECT_EQ(parse_scenario(text, "case.toml").mechanics->max_displacement_ratio, std::optional<double>(0.005));
}

// `text` without its table `[name]`: from its header to the next header or the end.
std::string without_table(std::string text, const std::string& name) {
  const std::size_t from = text.find("\n[" + name + "]\n");
  EXPECT_NE(from, std::string::npos) << name;
  if (from == std::string::npos) return text;
  const std::size_t next = text.find("\n[", from + 1);
  return text.erase(from, next == std::string::npos ? std::string::npos : next - from);
}

// [coupling], [output], [mesh] and [joint] hold settings only and may be left out of a file:
// an override of one of their keys makes the table. A table that says what is run
// ([mechanics] of a flow-only scenario) is not made.
TEST(ScenarioOverrides, MakesAMissingTableOfSettings) {
  const std::string text = without_table(without_table(read_text(kSixBlock), "coupling"), "output");
  const Scenario s = parse_scenario(
      apply_overrides(text, kSixBlock, {{"coupling.acceleration", "aitken"}, {"output.figures", "[]"}}), "case.toml");
  EXPECT_EQ(s.coupling.acceleration, coupling::Acceleration::aitken);
  EXPECT_EQ(s.coupling.max_iterations, Scenario{}.coupling.max_iterations);  // the rest the defaults
  EXPECT_TRUE(s.output.figures.empty());
  try {
    apply_overrides("[flow]\n", kSixBlock, {{"mechanics.steps", "10"}});
    FAIL() << "a [mechanics] table was made";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("the scenario has no 'mechanics'"), std::string::npos) << e.what();
  }
}

TEST(ScenarioOverrides, BadKeysAreNamed) {
  EXPECT_NE(error_of({{"nosuch.value", "1"}}).find("nosuch.value: the scenario has no 'nosuch'"), std::string::npos);
  EXPECT_NE(error_of({{"flow.boundary[2].head", "1"}}).find("flow.boundary has 2 element(s); index 2 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of({{"coupling[0].relaxation", "1"}}).find("coupling is not an array"), std::string::npos);
  EXPECT_NE(error_of({{"flow.boundary[x].head", "1"}}).find("'boundary[x]'"), std::string::npos);
  EXPECT_NE(error_of({{"coupling..tolerance", "1"}}).find("expected a key path"), std::string::npos);
  EXPECT_NE(error_of({{"coupling.relaxation.value", "1"}}).find("coupling.relaxation is not a table"),
            std::string::npos);
  // A misspelt last key is set, and the reader then names it with a suggestion.
  const std::string text =
      apply_overrides(read_text(kSixBlock), kSixBlock, {{"coupling.relaxtion", "0.5"}});
  try {
    parse_scenario(text, "case.toml");
    FAIL() << "an unknown key was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling.relaxtion"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("relaxation"), std::string::npos) << e.what();
  }
}

// A number TOML cannot hold was taken for a string, which the reader then called one.
TEST(ScenarioOverrides, ANumberBeyondTomlsRangeIsSaidToBeOutOfRange) {
  for (const std::string value : {"1180591620717411303424", "-9223372036854775809", "3e400", "-3e400", "+3e400"}) {
    SCOPED_TRACE(value);
    EXPECT_NE(error_of({{"coupling.relaxation", value}})
                  .find("--set coupling.relaxation=" + value + ": coupling.relaxation: " + value + " is out of range"),
              std::string::npos)
        << error_of({{"coupling.relaxation", value}});
  }
  // Text that is no number at all is still a string.
  EXPECT_EQ(error_of({{"mechanics.contact", "penalty"}}), "");
}

TEST(ScenarioOverrides, RelativeMeshFileBecomesAbsolute) {
  const std::filesystem::path file = "/data/models/case.toml";
  const std::string text = apply_overrides("[mesh]\nfile = \"meshes/m.msh\"\n", file, {});
  EXPECT_NE(text.find("/data/models/meshes/m.msh"), std::string::npos) << text;
}

}  // namespace
}  // namespace hydrodda::scenario

namespace hydrodda::scenario {
namespace {

// The 1-based line of the first line of `text` after line `after` that starts with `start`
// (indentation aside).
int line_starting(const std::string& text, const std::string& start, int after = 0) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (n > after && line.find_first_not_of(' ') != std::string::npos &&
        line.compare(line.find_first_not_of(' '), start.size(), start) == 0)
      return n;
  return 0;
}

// A case's diagnostics told against what the user wrote (item 18 of the robustness list): the
// value an override set is cited by the override, even in the second of two [[flow.boundary]]
// tables; the first table's value, which no override set, at its own line of the original.
TEST(ScenarioOverrides, DiagnosticsOfACaseCiteTheOverrideOrTheOriginalLine) {
  const std::string original = read_text(kSixBlock);
  const std::vector<Override> overrides{{"flow.boundary[1].head", "-7"}};
  const std::string made = apply_overrides(original, kSixBlock, overrides);
  const std::filesystem::path case_file = "out/case_000/scenario.toml";
  const int made_second = line_starting(made, "head", line_starting(made, "head"));
  const int made_first = line_starting(made, "head");
  ASSERT_GT(made_second, made_first);
  const std::vector<Diagnostic> found{{case_file.string(), made_second, "flow.boundary.head", "as set"},
                                      {case_file.string(), made_first, "flow.boundary.head", "as written"},
                                      {case_file.string(), 0, "coupling.tolerance", "no line"},
                                      {"fractures.csv", 3, "geometry.fractures_file", "another file"}};
  const std::vector<Diagnostic> cited = locate_in_original(found, made, case_file, original, kSixBlock, overrides);
  ASSERT_EQ(cited.size(), 4u);
  EXPECT_EQ(cited[0].format(), "--set flow.boundary[1].head=-7: flow.boundary.head: as set");
  EXPECT_EQ(cited[1].file, kSixBlock.string());
  EXPECT_EQ(cited[1].line, line_starting(original, "head"));
  EXPECT_EQ(cited[2].format(), kSixBlock.string() + ": coupling.tolerance: no line");
  EXPECT_EQ(cited[3].format(), "fractures.csv:3: geometry.fractures_file: another file");
}

}  // namespace
}  // namespace hydrodda::scenario
