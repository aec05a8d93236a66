// Warnings are read by a person: a warning names at most five items, and where there is a run
// folder writes them all to a file in it that it names. Listed fractures of which a piece
// separates no blocks (and is dropped) are named in one warning, not in a warning each; the
// fractures along which the cubic law reached its permeability cap, in a file beside.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "output/run_folder.hpp"
#include "run/model_geometry.hpp"
#include "run/permeability_cap.hpp"
#include "scenario/reader.hpp"

namespace fs = std::filesystem;
namespace output = hydrodda::output;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

// A 10 m × 2 m domain cut in two by fracture 0 at x = 5, and `loose` short fractures inside its
// left block, touching nothing (fractures 1, 2, ...: the ids of fractures.csv and the
// preview): each separates no blocks.
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

TEST(WarningLists, OneLooseFractureIsNamedByItsId) {
  const scenario::Scenario s = scenario::parse_scenario(domain_with_loose_fractures(1), "loose.toml");
  const run::ModelGeometry model = run::build_model_geometry(s);
  std::string warning;
  ASSERT_EQ(count_dropped_warnings(model, warning), 1);
  EXPECT_NE(warning.find("geometry.fractures: fracture 1: a piece of it separates no blocks"), std::string::npos)
      << warning;
}

TEST(WarningLists, ManyLooseFracturesAreNamedInOneWarningOfFive) {
  const scenario::Scenario s = scenario::parse_scenario(domain_with_loose_fractures(8), "loose.toml");
  const run::ModelGeometry model = run::build_model_geometry(s);
  std::string warning;
  ASSERT_EQ(count_dropped_warnings(model, warning), 1);
  EXPECT_NE(warning.find("geometry.fractures: fractures 1, 2, 3, 4, 5 and 3 more: a piece of each separates no blocks"),
            std::string::npos)
      << warning;
}

// 40 fluid elements capped, each in the flow zone of its own fracture (ids 0, 10, 20, ...,
// 390): the warning names five and "35 more", and capped_fractures.txt in the run folder holds
// all 40, one a line.
TEST(WarningLists, CappedFracturesPastFiveAreWrittenToAFileTheWarningNames) {
  hydrodda::mesh::TriangleMesh mesh;
  std::vector<int> capped, element_fractures;
  for (int e = 0; e < 40; ++e) {
    const double x = e;
    mesh.nodes.push_back({x, 0.0});
    mesh.nodes.push_back({x + 1.0, 0.0});
    mesh.nodes.push_back({x, 1.0});
    mesh.triangles.push_back({3 * e, 3 * e + 1, 3 * e + 2});
    capped.push_back(e);
    element_fractures.push_back(10 * e);
  }
  const fs::path dir = fs::temp_directory_path() / "hydrodda-capped-fractures";
  fs::remove_all(dir);
  const output::RunFolder folder(dir, output::ExistingFolder::Refuse);
  const std::optional<std::string> text = run::describe_capped_fractures(capped, mesh, element_fractures, 1e-6, &folder);
  ASSERT_TRUE(text.has_value());
  EXPECT_NE(text->find("in 40 fluid elements, along fractures 0, 10, 20, 30, 40 and 35 more (all 40 in " +
                       (dir / "capped_fractures.txt").string() + ")"),
            std::string::npos)
      << *text;
  std::ifstream in(dir / "capped_fractures.txt");
  std::stringstream all;
  all << in.rdbuf();
  std::string expected;
  for (int e = 0; e < 40; ++e) expected += std::to_string(10 * e) + "\n";
  EXPECT_EQ(all.str(), expected);
  fs::remove_all(dir);
}

}  // namespace
