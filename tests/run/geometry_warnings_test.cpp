// The warnings of a scenario's geometry are read by a person: listed fractures of which a piece
// separates no blocks (and is dropped) are named in one warning, at most five of them, not in
// a warning each.

#include <gtest/gtest.h>

#include <string>

#include "run/model_geometry.hpp"
#include "scenario/reader.hpp"

namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

// A 10 m × 2 m domain cut in two by fracture 1 at x = 5, and `loose` short fractures inside its
// left block, touching nothing (fractures 2, 3, ...): each separates no blocks.
std::string domain_with_loose_fractures(int loose) {
  std::string fractures = "[[5.0, 0.0], [5.0, 2.0]]";
  for (int k = 0; k < loose; ++k) {
    const double x = 0.5 + 0.5 * k;
    fractures += ", [[" + std::to_string(x) + ", 0.8], [" + std::to_string(x) + ", 1.2]]";
  }
  return R"(
[geometry]
domain = [[0.0, 0.0], [10.0, 0.0], [10.0, 2.0], [0.0, 2.0]]
fractures = [ )" + fractures + R"( ]
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint]
friction_angle = 30.0
[mechanics]
steps = 1
[[mechanics.displacement]]
boundary = "bottom"
value = [0.0, 0.0]
)";
}

// The warnings that name dropped pieces of listed fractures, and how many there are.
int count_dropped_warnings(const run::ModelGeometry& model, std::string& last) {
  int count = 0;
  for (const std::string& w : model.warnings)
    if (w.find("separates no blocks and is dropped") != std::string::npos) {
      ++count;
      last = w;
    }
  return count;
}

TEST(GeometryWarnings, OneLooseFractureIsNamedAsBefore) {
  const scenario::Scenario s = scenario::parse_scenario(domain_with_loose_fractures(1), "loose.toml");
  const run::ModelGeometry model = run::build_model_geometry(s);
  std::string warning;
  ASSERT_EQ(count_dropped_warnings(model, warning), 1);
  EXPECT_NE(warning.find("geometry.fractures: fracture 2: a piece of it separates no blocks"), std::string::npos)
      << warning;
}

TEST(GeometryWarnings, ManyLooseFracturesAreNamedInOneWarningOfFive) {
  const scenario::Scenario s = scenario::parse_scenario(domain_with_loose_fractures(8), "loose.toml");
  const run::ModelGeometry model = run::build_model_geometry(s);
  std::string warning;
  ASSERT_EQ(count_dropped_warnings(model, warning), 1);
  EXPECT_NE(warning.find("geometry.fractures: fractures 2, 3, 4, 5, 6 and 3 more: a piece of each separates no blocks"),
            std::string::npos)
      << warning;
}

}  // namespace
