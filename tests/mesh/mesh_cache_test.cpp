// The folder of shared meshes (mesh_cache.hpp): a stored mesh reads back exactly, is used only
// for its own request, and a changed mesh key meshes anew.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "mesh/mesh_cache.hpp"

namespace hydrodda::mesh {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

MeshRequest fractured_square() {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.boundaries = {{"inlet", {0.0, 0.2}, {0.0, 0.4}}};
  request.refinement_lines = {{{0.1, 0.1}, {0.9, 0.8}}};
  request.regions = {{"core", {{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}}};
  request.size = 0.1;
  request.fracture_size = 0.02;
  request.refine_distance = 0.1;
  return request;
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    ASSERT_EQ(a.nodes[i].x, b.nodes[i].x) << i;  // exactly: the same bits
    ASSERT_EQ(a.nodes[i].y, b.nodes[i].y) << i;
  }
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.region, b.region);
  EXPECT_EQ(a.region_names, b.region_names);
  EXPECT_EQ(a.boundary_names, b.boundary_names);
  ASSERT_EQ(a.boundary_edges.size(), b.boundary_edges.size());
  for (std::size_t i = 0; i < a.boundary_edges.size(); ++i) {
    EXPECT_EQ(a.boundary_edges[i].nodes, b.boundary_edges[i].nodes);
    EXPECT_EQ(a.boundary_edges[i].boundary, b.boundary_edges[i].boundary);
  }
}

// Every field that shapes the mesh is in the key; a change of the last bit of a size too.
TEST(MeshCache, KeyHoldsEveryFieldThatShapesTheMesh) {
  const MeshRequest base = fractured_square();
  const std::string key = canonical_request_text(base);
  EXPECT_EQ(canonical_request_text(fractured_square()), key);
  std::vector<MeshRequest> changed(10, base);
  changed[0].size = std::nextafter(base.size, 1.0);
  changed[1].fracture_size = 0.03;
  changed[2].refine_distance = 0.2;
  changed[3].refinement_lines[0].to.x = 0.85;
  changed[4].boundaries[0].name = "outlet";
  changed[5].regions[0].polygon[2].y = 0.65;
  changed[6].domain[2].x = 1.1;
  changed[7].algorithm = 6;
  changed[8].refinement_points = {{{0.5, 0.5}, 0.001, 0.1}};
  changed[9].refinement_points = {{{0.5, 0.5}, 0.001, std::nextafter(0.1, 1.0)}};
  for (std::size_t i = 0; i < changed.size(); ++i) EXPECT_NE(canonical_request_text(changed[i]), key) << i;
  EXPECT_NE(canonical_request_text(changed[8]), canonical_request_text(changed[9]));  // a point's radius too
  MeshRequest verbose = base;
  verbose.verbose = true;  // only what Gmsh prints
  EXPECT_EQ(canonical_request_text(verbose), key);
}

TEST(MeshCache, StoredMeshReadsBackExactlyAndOnlyForItsKey) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-file");
  fs::create_directories(dir);
  const MeshRequest request = fractured_square();
  const TriangleMesh mesh = generate_mesh(request);
  const std::string key = canonical_request_text(request);
  save_cached_mesh(dir / "a.mesh", mesh, key);
  const auto back = load_cached_mesh(dir / "a.mesh", key);
  ASSERT_TRUE(back);
  expect_same_mesh(*back, mesh);
  EXPECT_FALSE(load_cached_mesh(dir / "a.mesh", key + " "));
  EXPECT_FALSE(load_cached_mesh(dir / "missing.mesh", key));
  // A file cut short is an error, not a smaller mesh.
  fs::resize_file(dir / "a.mesh", fs::file_size(dir / "a.mesh") / 2);
  EXPECT_THROW(load_cached_mesh(dir / "a.mesh", key), std::runtime_error);
  fs::remove_all(dir);
}

TEST(MeshCache, SameRequestMeshesOnceAndAChangedKeyMeshesAnew) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-folder");
  const MeshRequest request = fractured_square();
  const CachedMesh first = generate_or_reuse_mesh(request, dir);
  EXPECT_FALSE(first.reused);
  const CachedMesh second = generate_or_reuse_mesh(request, dir);
  EXPECT_TRUE(second.reused);
  EXPECT_EQ(second.file, first.file);
  expect_same_mesh(second.mesh, first.mesh);
  expect_same_mesh(second.mesh, generate_mesh(request));  // what meshing anew gives
  MeshRequest finer = request;
  finer.fracture_size = 0.01;
  const CachedMesh third = generate_or_reuse_mesh(finer, dir);
  EXPECT_FALSE(third.reused);
  EXPECT_NE(third.file, first.file);
  EXPECT_GT(third.mesh.triangle_count(), first.mesh.triangle_count());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hydrodda::mesh
