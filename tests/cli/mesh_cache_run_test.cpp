// A sweep's cases share one mesh when their geometry and mesh settings are the same: one mesh
// in DIR/mesh-cache for a sweep over heads, and a case run from it gives the same results,
// byte for byte, as the same case meshed anew; a case that changes a mesh key meshes anew.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::fresh_dir;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;

int count_meshes(const fs::path& folder) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(folder)) n += entry.path().extension() == ".mesh";
  return n;
}

}  // namespace

TEST(MeshCacheRun, ASweepOverHeadsMeshesOnceAndTheCachedMeshGivesTheSameResults) {
  const auto folder = fresh_dir("hydrodda-mesh-cache-sweep");
  const fs::path& out = folder.path;
  const fs::path plain = out / "plain", again = out / "again";
  // The still-water column, coupled: three cases, two at a time (the second waits for the
  // first's mesh or reads it).
  const auto sweep = run_program("sweep " + (kSource / "scenarios/verification/coupled_hydrostatic_column.toml").string() +
                                 " --set flow.boundary[1].head=3,3.5,4 --jobs 2 -o " + out.string());
  ASSERT_EQ(sweep.exit_code, 0) << sweep.output;
  EXPECT_EQ(count_meshes(out / "mesh-cache"), 1);

  // The last case meshed anew, without the cache: every result file the same.
  const fs::path case_file = out / "case_002" / "scenario.toml";
  const auto fresh = run_program("run " + case_file.string() + " -o " + plain.string());
  ASSERT_EQ(fresh.exit_code, 0) << fresh.output;
  EXPECT_EQ(fresh.output.find("mesh: read from"), std::string::npos) << fresh.output;
  fs::remove(out / "case_002" / "run.log");  // the sweep's log of the case, not a result
  expect_same_results(out / "case_002", plain);

  // From the cache, said so, and again the same.
  const auto cached = run_program("run " + case_file.string() + " -o " + again.string() + " --mesh-cache " +
                                  (out / "mesh-cache").string());
  ASSERT_EQ(cached.exit_code, 0) << cached.output;
  EXPECT_NE(cached.output.find("mesh: read from"), std::string::npos) << cached.output;
  expect_same_results(again, plain);
}

TEST(MeshCacheRun, AChangedMeshKeyMeshesAnew) {
  const auto folder = fresh_dir("hydrodda-mesh-cache-keys");
  const fs::path& out = folder.path;
  // Two mesh sizes, and for each two heads: two meshes, each made once.
  const auto sweep = run_program("sweep " + (kSource / "scenarios/verification/coupled_hydrostatic_column.toml").string() +
                                 " --set mesh.size=0.1,0.08 --set flow.boundary[1].head=3,3.5 --jobs 2 -o " + out.string());
  ASSERT_EQ(sweep.exit_code, 0) << sweep.output;
  EXPECT_EQ(count_meshes(out / "mesh-cache"), 2);
  // The scenario as shipped (mesh.size = 0.1): its mesh is there.
  const fs::path column = kSource / "scenarios/verification/coupled_hydrostatic_column.toml";
  const auto same = run_program("run " + column.string() + " -o " + (out / "same").string() + " --mesh-cache " +
                                (out / "mesh-cache").string());
  ASSERT_EQ(same.exit_code, 0) << same.output;
  EXPECT_NE(same.output.find("mesh: read from"), std::string::npos) << same.output;
  // mesh.fracture_size changed: a key of its own, meshed and stored beside the others.
  std::string text = hydrodda::testing::read_file(column);
  const std::string from = "fracture_size = 0.02";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "fracture_size = 0.03");
  const fs::path changed = out / "changed.toml";
  std::ofstream(changed) << text;
  const auto other = run_program("run " + changed.string() + " -o " + (out / "changed").string() + " --mesh-cache " +
                                 (out / "mesh-cache").string());
  ASSERT_EQ(other.exit_code, 0) << other.output;
  EXPECT_NE(other.output.find("mesh: made and stored in"), std::string::npos) << other.output;
  EXPECT_EQ(count_meshes(out / "mesh-cache"), 3);
}

// A cache that cannot be made (a file where its folder should be: no write permission is
// needed to show it, so it holds for root too) costs the run its meshing, not the run: a
// warning says so, and the results are those of a run without the cache.
TEST(MeshCacheRun, ACacheThatCannotBeMadeWarnsAndTheRunGoesOn) {
  const auto folder = fresh_dir("hydrodda-mesh-cache-unusable");
  const fs::path& out = folder.path;
  fs::create_directories(out);
  std::ofstream(out / "a-file") << "not a folder\n";
  const fs::path scenario = kSource / "scenarios/verification/coupled_hydrostatic_column.toml";
  const auto cached = run_program("run " + scenario.string() + " -o " + (out / "cached").string() +
                                  " --mesh-cache " + (out / "a-file" / "cache").string());
  ASSERT_EQ(cached.exit_code, 0) << cached.output;
  EXPECT_NE(cached.output.find("warning: mesh: the mesh cache '" + (out / "a-file" / "cache").string() +
                               "' cannot be used"),
            std::string::npos)
      << cached.output;
  EXPECT_NE(cached.output.find("meshing without it"), std::string::npos) << cached.output;
  const auto plain = run_program("run " + scenario.string() + " -o " + (out / "plain").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  expect_same_results(out / "cached", out / "plain");
}

// sweep --overwrite starts with no mesh of an earlier sweep, and removes nothing else: a file
// of the user's in DIR/mesh-cache/ is kept.
TEST(MeshCacheRun, ASweepOverwritingItsFolderKeepsAUsersFileInTheMeshCache) {
  const auto folder = fresh_dir("hydrodda-mesh-cache-overwrite");
  const fs::path& out = folder.path;
  const std::string sweep = "sweep " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                            " --set flow.boundary[0].head=3 -o " + out.string();
  const auto first = run_program(sweep);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_EQ(count_meshes(out / "mesh-cache"), 1);
  std::ofstream(out / "mesh-cache" / "notes.txt") << "mine\n";
  const auto again = run_program(sweep + " --overwrite");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(hydrodda::testing::read_file(out / "mesh-cache" / "notes.txt"), "mine\n");
  EXPECT_EQ(count_meshes(out / "mesh-cache"), 1);
  // Made again, not read: the earlier sweep's mesh was removed.
  EXPECT_EQ(hydrodda::testing::read_file(out / "case_000" / "run.log").find("mesh: read from"), std::string::npos);
}
