// A flow-only run on a user's Gmsh mesh and no block geometry: the rock is intact everywhere, so
// the permeability is the Kozeny–Carman value of the matrix porosity in every element and the
// flow across a unit square with a 1 m head drop is Q = k ρ g / μ (exact for P1).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

namespace fs = std::filesystem;

namespace {

// The unit square as two triangles, physical curves "inlet" (x = 0) and "outlet" (x = 1).
const char* kSquareMesh = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "inlet"
1 2 "outlet"
2 10 "rock"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
4
1 1 2 1 1 4 1
2 1 2 2 2 2 3
3 2 2 10 1 1 2 3
4 2 2 10 1 1 3 4
$EndElements
)";

TEST(MeshFileRun, IntactRockWithoutBlockGeometry) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-mesh-file";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "square.msh") << kSquareMesh;
  std::ofstream(dir / "case.toml") << R"(title = "user mesh"
[material.rock]
matrix_porosity = 0.1
grain_diameter = 1.2e-5
[flow]
pressure = "overpressure"
[[flow.boundary]]
name = "inlet"
head = 1.0
[[flow.boundary]]
name = "outlet"
head = 0.0
[mesh]
file = "square.msh"
[output]
figures = []
)";
  const auto result =
      hydrodda::testing::run_program("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "out" / "summary.json"));
  // k = d² φ³ / (180 (1 − φ)²) at φ = 0.1, d = 1.2e-5 m; Q = k ρ g / μ × 1 m × 1 m/m.
  const double k = 1.44e-10 * 1e-3 / (180.0 * 0.81);
  const double exact = k * 1000.0 * 9.81 / 1.0e-3;
  EXPECT_NEAR(summary["flow"]["boundaries"]["outlet"].get<double>(), exact, 1e-10 * exact);
  fs::remove_all(dir);
}

}  // namespace
