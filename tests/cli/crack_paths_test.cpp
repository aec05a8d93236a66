// geometry.tessellate.paths (docs/scenario.md): a straight line the sub-blocks' faces follow,
// their bonds intact; a crack lying on a path takes the path's faces, its broken bonds those
// whose middle lies on it. On a path 2 m long of `size` 0.05 (40 pairs of seeds, spacing
// 0.05 m), a crack 1 m long from the path's start is exactly 20 faces: `check` reports 20 bonds
// broken (exact). Without the path, the crack's own seeds give it 20 faces as well (its
// spacing 1 m / 20); with a crack off the path (crossing it) the crack keeps its own seeds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

std::string plate(const std::string& keys) {
  return R"(title = "paths"
[geometry]
domain = [[0.0, -1.0], [3.0, -1.0], [3.0, 1.0], [0.0, 1.0]]
[[geometry.tessellate]]
size = 0.05
region = [[0.0, -0.2], [2.5, -0.2], [2.5, 0.2], [0.0, 0.2]]
kind = "triangles"
joint = "bond"
)" + keys + R"(
[[geometry.tessellate]]
size = 0.3
kind = "triangles"
joint = "bond"
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint.bond]
tensile_strength = 1.0e6
cohesion = 1.0e6
fracture_energy = 10.0
[mechanics]
analysis = "static"
gravity = [0.0, 0.0]
time_step = 1.0
steps = 1
[[mechanics.roller]]
boundary = "bottom"
)";
}

std::string check(const std::string& text, const std::string& name) {
  const fs::path file = fs::temp_directory_path() / ("hydrodda-paths-" + name + "-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << text;
  const auto result = run_program("check " + file.string());
  fs::remove(file);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return result.output;
}

TEST(CrackPaths, ACrackOnAPathTakesThePathsFaces) {
  const std::string on_path = check(plate("cracks = [[[0.0, 0.0], [1.0, 0.0]]]\npaths = [[[0.0, 0.0], [2.0, 0.0]]]"), "on");
  EXPECT_NE(on_path.find("20 bonds start broken along the cracks"), std::string::npos) << on_path;
  const std::string alone = check(plate("cracks = [[[0.0, 0.0], [1.0, 0.0]]]"), "alone");
  EXPECT_NE(alone.find("20 bonds start broken along the cracks"), std::string::npos) << alone;
}

TEST(CrackPaths, APathNeedsTwoSubBlocksAndItsRegion) {
  const fs::path file = fs::temp_directory_path() / ("hydrodda-paths-bad-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << plate("paths = [[[0.0, 0.0], [0.08, 0.0]], [[0.0, 0.0], [2.9, 0.0]]]");
  const auto result = run_program("check " + file.string());
  fs::remove(file);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("geometry.tessellate.paths: a path 0.08 m long is shorter than two sub-blocks"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("geometry.tessellate.paths: a path must lie inside the tessellation's region"),
            std::string::npos)
      << result.output;
}

}  // namespace
