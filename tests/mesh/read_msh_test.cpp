// Reading a user's Gmsh .msh file with physical groups.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

// The unit square as two triangles (one clockwise on purpose), regions "rock" and "seam",
// physical curves "left" and "right"; bottom and top edges have no group.
const char* kSquare = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
4
1 1 "left"
1 2 "right"
2 10 "rock"
2 11 "seam"
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
4 2 2 11 2 1 4 3
$EndElements
)";

TEST(ReadMsh, ReadsRegionsAndBoundariesFromPhysicalGroups) {
  const std::string path = write_temp("hydrodda_read_msh_square.msh", kSquare);
  const TriangleMesh m = read_msh(path);
  std::remove(path.c_str());
  ASSERT_EQ(m.node_count(), 4);
  ASSERT_EQ(m.triangle_count(), 2);
  validate(m);  // both triangles counter-clockwise now
  EXPECT_EQ(m.region_names[m.region[0]], "rock");
  EXPECT_EQ(m.region_names[m.region[1]], "seam");
  int left = 0, right = 0, unnamed = 0;
  for (const BoundaryEdge& e : m.boundary_edges) {
    if (e.boundary < 0) ++unnamed;
    else if (m.boundary_names[e.boundary] == "left") ++left;
    else if (m.boundary_names[e.boundary] == "right") ++right;
  }
  EXPECT_EQ(left, 1);
  EXPECT_EQ(right, 1);
  EXPECT_EQ(unnamed, 2);
}

TEST(ReadMsh, ErrorsNameTheFile) {
  const std::string missing = "no_such_dir/mesh.msh";
  try {
    read_msh(missing);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::string path = write_temp("hydrodda_read_msh_bad.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0\n");
  try {
    read_msh(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace hydrodda::mesh
