// The folder of shared meshes (mesh_cache.hpp): a stored mesh reads back exactly, is used only
// for its own request, and a changed mesh key meshes anew; a damaged entry is discarded and
// meshed again, and a folder that cannot be used is done without.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

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

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// The entry with its first node moved 2 cm in x, every other byte as stored: the node's x is
// the first double after the magic line, the key (length, text) and the node count.
std::string with_first_node_moved(const std::string& entry, const std::string& key) {
  const std::size_t at = std::strlen("hydrodda cached mesh 2\n") + 8 + key.size() + 8;
  double x = 0.0;
  std::memcpy(&x, entry.data() + at, sizeof x);
  x += 0.02;
  std::string moved = entry;
  std::memcpy(moved.data() + at, &x, sizeof x);
  return moved;
}

// A node moved 2 cm reads back as the damage it is, not as a mesh (its boundary flow would be
// 0.3% off and nothing would say so).
TEST(MeshCache, ANodeMovedOnDiskIsRefusedByTheChecksum) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-moved");
  fs::create_directories(dir);
  const MeshRequest request = fractured_square();
  const TriangleMesh mesh = generate_mesh(request);
  const std::string key = canonical_request_text(request);
  save_cached_mesh(dir / "a.mesh", mesh, key);
  const std::string entry = read_bytes(dir / "a.mesh");
  const std::string moved = with_first_node_moved(entry, key);
  ASSERT_NE(moved, entry);
  write_bytes(dir / "a.mesh", moved);
  try {
    load_cached_mesh(dir / "a.mesh", key);
    ADD_FAILURE() << "a moved node was read back";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("checksum does not match"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("a.mesh"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// An entry moved, cut short or overwritten with garbage: discarded with a warning naming it,
// the mesh made again (as generate_mesh makes it) and stored in its place.
TEST(MeshCache, ADamagedEntryIsDiscardedAndMeshedAgain) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-damaged");
  const MeshRequest request = fractured_square();
  const std::string key = canonical_request_text(request);
  const CachedMesh first = generate_or_reuse_mesh(request, dir);
  ASSERT_TRUE(first.stored);
  EXPECT_TRUE(first.warnings.empty());
  const std::string entry = read_bytes(first.file);
  const std::vector<std::pair<std::string, std::string>> damages{
      {"moved", with_first_node_moved(entry, key)},
      {"cut short", entry.substr(0, entry.size() * 2 / 3)},
      {"garbage", std::string(4096, '\x5a')}};
  for (const auto& [what, bytes] : damages) {
    write_bytes(first.file, bytes);
    const CachedMesh again = generate_or_reuse_mesh(request, dir);
    EXPECT_FALSE(again.reused) << what;
    EXPECT_TRUE(again.stored) << what;
    ASSERT_EQ(again.warnings.size(), 1u) << what;
    EXPECT_NE(again.warnings[0].find(first.file.string()), std::string::npos) << again.warnings[0];
    EXPECT_NE(again.warnings[0].find("discarded"), std::string::npos) << again.warnings[0];
    expect_same_mesh(again.mesh, first.mesh);
    EXPECT_EQ(read_bytes(first.file), entry) << what;  // stored again, whole
    EXPECT_TRUE(generate_or_reuse_mesh(request, dir).reused) << what;
  }
  fs::remove_all(dir);
}

// A folder that cannot be made (a file where it should be) or an entry that cannot be written
// (a folder in the way of its temporary file, as a full disk would refuse it): the mesh is made
// and used all the same, and the warnings say why it was not cached. No root tricks: both fail
// for root too.
TEST(MeshCache, AFolderThatCannotBeUsedOrWrittenIsDoneWithout) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-unusable");
  fs::create_directories(dir);
  std::ofstream(dir / "a-file") << "not a folder\n";
  const MeshRequest request = fractured_square();
  const TriangleMesh expected = generate_mesh(request);

  const CachedMesh no_folder = generate_or_reuse_mesh(request, dir / "a-file" / "cache");
  EXPECT_FALSE(no_folder.reused);
  EXPECT_FALSE(no_folder.stored);
  ASSERT_EQ(no_folder.warnings.size(), 1u);
  EXPECT_NE(no_folder.warnings[0].find("meshing without it"), std::string::npos) << no_folder.warnings[0];
  expect_same_mesh(no_folder.mesh, expected);

  const fs::path cache = dir / "cache";
  const CachedMesh probe = generate_or_reuse_mesh(request, cache);  // to learn the entry's name
  fs::remove(probe.file);
  fs::create_directories(fs::path(probe.file).concat(".partial"));
  const CachedMesh unwritten = generate_or_reuse_mesh(request, cache);
  EXPECT_FALSE(unwritten.reused);
  EXPECT_FALSE(unwritten.stored);
  ASSERT_EQ(unwritten.warnings.size(), 1u);
  EXPECT_NE(unwritten.warnings[0].find("not stored"), std::string::npos) << unwritten.warnings[0];
  EXPECT_FALSE(fs::exists(probe.file));
  expect_same_mesh(unwritten.mesh, expected);
  fs::remove_all(dir);
}

// Clearing the folder (a sweep's start) removes the cache's own files only, and follows no link.
TEST(MeshCache, ClearingRemovesOnlyTheCachesOwnFiles) {
  const fs::path dir = fresh_dir("hydrodda-mesh-cache-clear");
  const CachedMesh cached = generate_or_reuse_mesh(fractured_square(), dir);
  std::ofstream(dir / "notes.txt") << "mine\n";
  std::ofstream(dir / "0123456789ABCDEF.mesh") << "mine too: the cache names its files in lowercase\n";
  remove_cache_entries(dir);
  EXPECT_FALSE(fs::exists(cached.file));
  EXPECT_FALSE(fs::exists(fs::path(cached.file).replace_extension(".lock")));
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "0123456789ABCDEF.mesh"));
  remove_cache_entries(dir / "missing");  // nothing to clear
  const fs::path elsewhere = fresh_dir("hydrodda-mesh-cache-elsewhere");
  generate_or_reuse_mesh(fractured_square(), elsewhere);
  fs::create_directory_symlink(elsewhere, dir / "linked");
  EXPECT_THROW(remove_cache_entries(dir / "linked"), std::runtime_error);
  EXPECT_EQ(std::distance(fs::directory_iterator(elsewhere), fs::directory_iterator()), 2);
  fs::remove_all(dir);
  fs::remove_all(elsewhere);
}

}  // namespace
}  // namespace hydrodda::mesh
