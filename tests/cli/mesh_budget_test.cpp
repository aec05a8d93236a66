// No surprise meshes through the real program: `check` prints the triangles the mesh is
// expected to have, and a mesh beyond the machine's memory is refused by check, run and sweep
// (exit 2), naming the keys that set it, before anything is meshed.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::fresh_dir;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;
const fs::path kFractures = kSource / "scenarios/verification/flow_three_fractures.toml";

// The three-fracture square with its [mesh] replaced.
fs::path with_mesh(const fs::path& dir, const std::string& mesh) {
  std::string text = hydrodda::testing::read_file(kFractures);
  text = text.substr(0, text.find("[mesh]")) + "[mesh]\n" + mesh + "\n";
  fs::create_directories(dir);
  const fs::path file = dir / "scenario.toml";
  std::ofstream(file) << text;
  return file;
}

double physical_memory_gb() {
  return static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / 1e9;
}

}  // namespace

// check's estimate against the mesh the run makes: within the documented factor 1.5.
TEST(MeshBudget, CheckPrintsTheExpectedTriangles) {
  const auto folder = fresh_dir("hydrodda-mesh-budget-check");
  const fs::path& dir = folder.path;
  const auto check = run_program("check " + kFractures.string());
  ASSERT_EQ(check.exit_code, 0) << check.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(check.output, m, std::regex("mesh of about ([0-9]+) triangles \\(([0-9]+) within "
                                                            "mesh.refine_distance = 0.1 m")))
      << check.output;
  const double estimate = std::stod(m[1]);
  const auto run = run_program("run " + kFractures.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_TRUE(std::regex_search(run.output, m, std::regex("mesh: [0-9]+ nodes, ([0-9]+) triangles"))) << run.output;
  const double actual = std::stod(m[1]);
  EXPECT_LT(estimate, 1.5 * actual) << check.output << run.output;
  EXPECT_GT(estimate, actual / 1.5) << check.output << run.output;
}

// fracture_size 1e-8 m along three 1 m fractures: about 10^10 triangles, terabytes.
TEST(MeshBudget, AMeshBeyondTheMachinesMemoryIsRefused) {
  const auto folder = fresh_dir("hydrodda-mesh-budget-refused");
  const fs::path& dir = folder.path;
  const fs::path file = with_mesh(dir, "size = 0.04\nfracture_size = 1e-8\nrefine_distance = 0.1");
  for (const std::string& command : {"check " + file.string(), "run " + file.string() + " -o " + (dir / "out").string()}) {
    const auto result = run_program(command);
    EXPECT_EQ(result.exit_code, 2) << command << "\n" << result.output;
    EXPECT_NE(result.output.find("mesh: the mesh would have about"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("at mesh.fracture_size = 1e-08 m"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("more than this machine's"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("make mesh.fracture_size larger or mesh.refine_distance smaller"), std::string::npos)
        << result.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  const auto sweep = run_program("sweep " + kFractures.string() + " --set mesh.fracture_size=0.002,1e-8 -o " +
                                 (dir / "sweep").string());
  EXPECT_EQ(sweep.exit_code, 2) << sweep.output;
  EXPECT_NE(sweep.output.find("case_001 (mesh.fracture_size=1e-8)"), std::string::npos) << sweep.output;
  EXPECT_FALSE(fs::exists(dir / "sweep"));
}

// A mesh of about three quarters of what the machine's memory holds (N × 1,200 B): warned
// about with its cost (memory and seconds of meshing), said before it starts (check only:
// nothing is meshed). A uniform size h gives about 4.14 million triangles at h = 0.0008 m
// on this square, and N grows as 1/h².
TEST(MeshBudget, ALargeMeshIsWarnedAbout) {
  const double triangles = 0.75 * physical_memory_gb() * 1e9 / 1200.0;
  const double size = 0.0008 * std::sqrt(4.14e6 / triangles);
  const auto folder = fresh_dir("hydrodda-mesh-budget-warned");
  const fs::path& dir = folder.path;
  const std::string h = std::to_string(size);
  const fs::path file = with_mesh(dir, "size = " + h + "\nfracture_size = " + h + "\nrefine_distance = 0.1");
  const auto result = run_program("check " + file.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("warning: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("s of meshing"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("make mesh.size larger"), std::string::npos) << result.output;
}
