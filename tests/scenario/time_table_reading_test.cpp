// Loads over time in the scenario file (docs/scenario.md, "Loads over time"): tables of
// (time, value) rows beside the constants, and each refusal with its file, line and key.

#include <gtest/gtest.h>

#include "parse_errors.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/load_times.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

// One 1 m block, free (dynamic): lines 1–9 here, the case's keys from line 10 on.
const std::string kHead = R"([geometry]
domain = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
grain_diameter = 1.0e-5
[mechanics]
analysis = "dynamic"
)";

using test_support::errors_of;

TEST(TimeTableReading, ReadsTablesForTractionsPointLoadsAndFlowBoundaries) {
  const Scenario s = parse_scenario(kHead + R"([[mechanics.traction]]
boundary = "top"
normal = [[0.0, 0.0], [10.0, -5.0e6]]
shear = 1.0e5
[[mechanics.load]]
point = [0.5, 0.5]
force = [[0.0, 0.0, 0.0], [5.0, 1.0e3, -2.0e3]]
[flow]
[[flow.boundary]]
name = "bottom"
head = [[0.0, 10.0], [3.0, 20.0], [8.0, 15.0]]
[[flow.boundary]]
name = "top"
head = 0.0
)", "case.toml");
  const Traction& t = s.mechanics->tractions[0];
  EXPECT_EQ(t.normal.rows(), 2u);
  EXPECT_EQ(t.normal.value(5.0), -2.5e6);
  EXPECT_EQ(t.normal_end, t.normal);  // defaults to `normal`, table and all
  EXPECT_TRUE(t.shear.is_constant());
  EXPECT_EQ(t.shear.value(7.0), 1.0e5);
  const numerics::TimeTable& force = s.mechanics->loads[0].force;
  EXPECT_EQ(force.columns(), 2u);
  EXPECT_EQ(force.value(2.5, 0), 500.0);
  EXPECT_EQ(force.value(2.5, 1), -1000.0);
  EXPECT_EQ(s.flow->boundaries[0].value.value(3.0), 20.0);
  EXPECT_EQ(find_load_times(s), (std::vector<double>{0.0, 3.0, 5.0, 8.0, 10.0}));
  EXPECT_EQ(find_final_load_time(s), 10.0);
}

TEST(TimeTableReading, ConstantsStayConstantsAndGiveNoLoadTimes) {
  const Scenario s = parse_scenario(kHead + R"([[mechanics.load]]
point = [0.5, 0.5]
force = [1.0, -2.0]
[[mechanics.traction]]
boundary = "top"
normal = -1.0e6
)", "case.toml");
  EXPECT_TRUE(s.mechanics->loads[0].force.is_constant());
  EXPECT_EQ(s.mechanics->loads[0].force.value(9.0, 1), -2.0);
  EXPECT_TRUE(find_load_times(s).empty());
}

// Each bad table is refused naming the file, the row's (or the key's) line and the key.
TEST(TimeTableReading, RefusesTimesThatDoNotIncreaseOneRowAndRowsOfTheWrongSize) {
  struct Case {
    std::string keys;
    int line;
    std::string key;
    std::string words;
  };
  const std::vector<Case> cases{
      {"[[mechanics.traction]]\nboundary = \"top\"\nnormal = [\n  [0.0, 1.0],\n  [2.0, 3.0],\n  [2.0, 4.0]]\n", 15,
       "mechanics.traction.normal", "row 3 (t = 2) is not later than row 2"},
      {"[[mechanics.traction]]\nboundary = \"top\"\nshear = [[5.0, 1.0], [1.0, 3.0]]\n", 12, "mechanics.traction.shear",
       "must increase"},
      {"[[mechanics.traction]]\nboundary = \"top\"\nnormal = [[0.0, 1.0]]\n", 12, "mechanics.traction.normal",
       "at least two rows"},
      {"[[mechanics.load]]\npoint = [0.5, 0.5]\nforce = [[0.0, 1.0], [1.0, 2.0]]\n", 12, "mechanics.load.force",
       "[t, fx, fy]"},
      {"[flow]\n[[flow.boundary]]\nname = \"top\"\nhead = [[0.0, 1.0], [1.0, \"high\"]]\n", 13, "flow.boundary.head",
       "[t, value]"},
      {"[flow]\n[[flow.boundary]]\nname = \"top\"\npressure = [[1.0, 0.0], [0.5, 1.0]]\n", 13, "flow.boundary.pressure",
       "must increase"},
  };
  for (const Case& c : cases) {
    const std::vector<Diagnostic> errors = errors_of(kHead + c.keys);
    ASSERT_FALSE(errors.empty()) << c.keys;
    const auto found = std::find_if(errors.begin(), errors.end(), [&](const Diagnostic& d) { return d.key == c.key; });
    ASSERT_NE(found, errors.end()) << c.keys << "\n" << errors[0].key << ": " << errors[0].message;
    EXPECT_EQ(found->file, "case.toml");
    EXPECT_EQ(found->line, c.line) << c.keys << "\n" << found->message;
    EXPECT_NE(found->message.find(c.words), std::string::npos) << found->message;
  }
}

}  // namespace
}  // namespace hydrodda::scenario
