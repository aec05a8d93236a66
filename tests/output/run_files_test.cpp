#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "output/atomic_file.hpp"
#include "output/csv_table.hpp"
#include "output/item_list.hpp"
#include "output/run_folder.hpp"
#include "output/summary.hpp"

namespace hydrodda::output {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  return dir;
}

TEST(AtomicFile, ReplacesWholeAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("hydrodda-atomic");
  fs::create_directories(dir);
  write_file_atomically(dir / "a.txt", "first\n");
  write_file_atomically(dir / "a.txt", "second\n");
  EXPECT_EQ(read_all(dir / "a.txt"), "second\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  EXPECT_THROW(write_file_atomically(dir / "missing" / "b.txt", "x"), std::runtime_error);
  fs::remove_all(dir);
}

// Durability (docs/output.md): a durable file is flushed to the disk (one fsync) before its
// rename, an atomic one only renamed; both end whole under their name with no temporary left.
TEST(AtomicFile, OnlyADurableFileIsFlushedBeforeItsRename) {
  const fs::path dir = fresh_dir("hydrodda-durability");
  fs::create_directories(dir);
  long long before = disk_flushes();
  write_file_atomically(dir / "kept.txt", "durable\n", Durability::durable);
  EXPECT_EQ(disk_flushes() - before, 1);
  before = disk_flushes();
  write_file_atomically(dir / "field.txt", "atomic\n", Durability::atomic);
  EXPECT_EQ(disk_flushes() - before, 0);
  EXPECT_EQ(read_all(dir / "kept.txt"), "durable\n");
  EXPECT_EQ(read_all(dir / "field.txt"), "atomic\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
  fs::remove_all(dir);
}

// A run folder flushes what a resume reads (checkpoint.bin, scenario.toml) and the verdict
// (summary.json) before renaming them, nothing else; sync() flushes the folder's entries once,
// and says which folder it could not flush.
TEST(RunFolder, FlushesOnlyWhatAResumeReadsAndTheVerdict) {
  const fs::path dir = fresh_dir("hydrodda-run-folder-durability");
  const RunFolder folder(dir, ExistingFolder::Refuse);
  for (const char* name : {"checkpoint.bin", "scenario.toml", "summary.json"}) {
    EXPECT_EQ(RunFolder::durability_of(name), Durability::durable) << name;
    const long long before = disk_flushes();
    folder.write(name, "x");
    EXPECT_EQ(disk_flushes() - before, 1) << name;
  }
  for (const char* name : {"history.csv", "fluid_0001.vtu", "fluid.pvd", "fractures.csv", "sweep.csv"}) {
    EXPECT_EQ(RunFolder::durability_of(name), Durability::atomic) << name;
    const long long before = disk_flushes();
    folder.write(name, "x");
    EXPECT_EQ(disk_flushes() - before, 0) << name;
    EXPECT_EQ(read_all(dir / name), "x");
  }
  const long long before = disk_flushes();
  folder.sync();
  EXPECT_EQ(disk_flushes() - before, 1);
  fs::remove_all(dir);
  try {
    folder.sync();
    ADD_FAILURE() << "a folder removed was flushed";
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot flush " + dir.string()), std::string::npos) << e.what();
  }
}

TEST(RunFolder, CreatesOnDemandAndRefusesOccupiedFolders) {
  const fs::path dir = fresh_dir("hydrodda-folder") / "nested" / "run";
  {
    RunFolder folder(dir, ExistingFolder::Refuse);
    EXPECT_TRUE(fs::is_directory(dir));
    folder.write("summary.json", "{}\n");
    EXPECT_TRUE(fs::is_directory(folder.figures()));
  }
  EXPECT_THROW(RunFolder(dir, ExistingFolder::Refuse), RunFolderError);
  std::ofstream(dir / "mine.txt") << "keep";
  RunFolder again(dir, ExistingFolder::Overwrite);
  again.write("summary.json", "{\"new\": true}\n");
  EXPECT_EQ(read_all(dir / "mine.txt"), "keep");
  EXPECT_EQ(read_all(dir / "summary.json"), "{\"new\": true}\n");
  fs::remove_all(dir.parent_path().parent_path());
}

// The current folder, named as "." (what Python's Path("") is), "" or as the folder that holds
// it: --overwrite there would replace the user's own scenario.toml, so it is refused, and the
// file is kept. Without --overwrite an empty current folder is a run folder like any other.
TEST(RunFolder, OverwriteRefusesTheCurrentFolderAndTheFoldersAboveIt) {
  const fs::path dir = fresh_dir("hydrodda-folder-current");
  fs::create_directories(dir / "work");
  std::ofstream(dir / "work" / "scenario.toml") << "title = \"mine\"\n";
  const fs::path before = fs::current_path();
  fs::current_path(dir / "work");
  EXPECT_THROW(RunFolder(".", ExistingFolder::Overwrite), RunFolderError);
  EXPECT_THROW(RunFolder("", ExistingFolder::Overwrite), RunFolderError);
  EXPECT_THROW(RunFolder(dir / "work", ExistingFolder::Overwrite), RunFolderError);
  EXPECT_THROW(RunFolder("..", ExistingFolder::Overwrite), RunFolderError);
  try {
    RunFolder(".", ExistingFolder::Overwrite);
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("current folder"), std::string::npos) << e.what();
  }
  RunFolder below("out", ExistingFolder::Overwrite);  // a folder of its own is fine
  below.write("scenario.toml", "title = \"run\"\n");
  fs::current_path(before);
  EXPECT_EQ(read_all(dir / "work" / "scenario.toml"), "title = \"mine\"\n");
  EXPECT_EQ(read_all(dir / "work" / "out" / "scenario.toml"), "title = \"run\"\n");
  fs::remove_all(dir);
}

// A figures/ (or round_N/) that is a symbolic link would take the run's files outside its
// folder, over whatever is there: refused, and nothing outside is touched.
TEST(RunFolder, NoSymbolicLinkLeadsTheRunOutOfItsFolder) {
  const fs::path dir = fresh_dir("hydrodda-folder-links");
  const fs::path outside = dir / "outside", run = dir / "run";
  fs::create_directories(outside);
  fs::create_directories(run);
  std::ofstream(outside / "heads.png") << "the user's own picture";
  fs::create_directory_symlink(outside, run / "figures");
  EXPECT_THROW(RunFolder(run, ExistingFolder::Overwrite), RunFolderError);

  // Made after the folder was taken: figures() refuses it too, as does any subfolder.
  fs::remove(run / "figures");
  const RunFolder folder(run, ExistingFolder::Overwrite);
  fs::create_directory_symlink(outside, run / "figures");
  fs::create_directory_symlink(outside, run / "round_1");
  EXPECT_THROW(folder.figures(), RunFolderError);
  EXPECT_THROW(folder.subfolder("round_1"), RunFolderError);
  std::ofstream(run / "round_2") << "a file";
  EXPECT_THROW(folder.subfolder("round_2"), RunFolderError);
  EXPECT_TRUE(fs::is_directory(folder.subfolder("round_3")));
  EXPECT_EQ(read_all(outside / "heads.png"), "the user's own picture");
  EXPECT_EQ(std::distance(fs::directory_iterator(outside), fs::directory_iterator{}), 1);
  fs::remove_all(dir);
}

// HYDRODDA_TEST_FULL_DISK=NAME, the tests' stand-in for a full disk: a write of a file so named
// fails as on one (ENOSPC) and leaves the file as it was; other files are written.
TEST(AtomicFile, TheFullDiskHookFailsWritesOfTheNamedFileOnly) {
  const fs::path dir = fresh_dir("hydrodda-atomic-full");
  fs::create_directories(dir);
  write_file_atomically(dir / "summary.json", "before\n");
  ::setenv("HYDRODDA_TEST_FULL_DISK", "summary.json", 1);
  try {
    write_file_atomically(dir / "summary.json", "after\n");
    ADD_FAILURE() << "the write went through";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::strerror(ENOSPC)), std::string::npos) << e.what();
  }
  write_file_atomically(dir / "history.csv", "written\n");
  ::unsetenv("HYDRODDA_TEST_FULL_DISK");
  EXPECT_EQ(read_all(dir / "summary.json"), "before\n");
  EXPECT_EQ(read_all(dir / "history.csv"), "written\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
  fs::remove_all(dir);
}

// A line lists a few items; the full list goes to a file in the run folder that it names.
TEST(ItemList, AFewInTheLineAndAllInAFileItNames) {
  const fs::path dir = fresh_dir("hydrodda-item-list");
  const RunFolder folder(dir, ExistingFolder::Refuse);
  std::vector<std::string> tables;
  for (int i = 0; i < 100; ++i) tables.push_back("[[mesh.refine]] point = [" + std::to_string(i) + ", 0]");
  const std::string line = list_items(tables, &folder, "tables.toml", "; ");
  EXPECT_EQ(line, "[[mesh.refine]] point = [0, 0]; [[mesh.refine]] point = [1, 0]; [[mesh.refine]] point = [2, 0]; "
                  "[[mesh.refine]] point = [3, 0]; [[mesh.refine]] point = [4, 0] and 95 more (all 100 in " +
                      (dir / "tables.toml").string() + ")");
  std::string all;
  for (const std::string& t : tables) all += t + "\n";
  EXPECT_EQ(read_all(dir / "tables.toml"), all);
  // A few are all in the line, and no file is written; without a folder the line counts the rest.
  const std::vector<std::string> few(tables.begin(), tables.begin() + kListedItems);
  EXPECT_EQ(list_items(few, &folder, "few.txt").find(" more"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "few.txt"));
  const std::string bare = list_items(tables, nullptr, "tables.toml");
  EXPECT_TRUE(bare.ends_with("[4, 0] and 95 more")) << bare;
  fs::remove_all(dir);
}

TEST(CsvTable, FullPrecisionAndQuoting) {
  CsvTable table({"name", "value"});
  table.add_row({"a,b", CsvTable::cell(0.1)});
  table.add_row({"say \"hi\"", CsvTable::cell(1LL)});
  EXPECT_EQ(table.text(), "name,value\n\"a,b\",0.10000000000000001\n\"say \"\"hi\"\"\",1\n");
  EXPECT_EQ(table.rows(), 2u);
  EXPECT_THROW(table.add_row({"only one"}), std::logic_error);
  // The printed value reads back to the same double, bit for bit.
  EXPECT_EQ(std::stod(CsvTable::cell(1.0 / 3.0)), 1.0 / 3.0);
}

TEST(Summary, HoldsTheContractKeys) {
  RunSummary s;
  s.title = "t";
  s.converged = true;
  s.iterations = 7;
  s.blocks.push_back({3, {1.0, 2.0}, {0.1, -0.2}, 0.01, {-1.0, -2.0, 0.5}, 4.0});
  s.measures.push_back({"A", {2.5, 4.0}, {0.0, -1e-3}});
  RegionSummary core;
  core.name = "core";
  core.flow = 1.5e-6;
  core.effective_conductivity = 2e-7;
  s.flow = FlowSummary{{{"left", -1.5e-6}, {"right", 1.5e-6}}, 1e-14, {core}};
  s.timings.push_back({"flow", 0.25});
  const auto j = nlohmann::json::parse(format_summary(s));
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["iterations"], 7);
  EXPECT_EQ(j["blocks"][0]["id"], 3);
  EXPECT_EQ(j["blocks"][0]["stress"][2], 0.5);
  EXPECT_EQ(j["measure"]["A"]["displacement"][1], -1e-3);
  EXPECT_EQ(j["flow"]["boundaries"]["left"], -1.5e-6);
  EXPECT_EQ(j["flow"]["balance"], 1e-14);
  EXPECT_EQ(j["flow"]["regions"]["core"]["effective_conductivity"], 2e-7);
  EXPECT_TRUE(j["flow"]["regions"]["core"]["matrix_conductivity"].is_null());  // not measured: null, not 0
  EXPECT_FALSE(j["flow"]["regions"]["core"].contains("last_passes"));  // a converged run's
  EXPECT_EQ(j["timings"]["flow"], 0.25);
  // An unconverged run's regions say how far K_eff/K_m moved over its last passes.
  s.flow->regions[0].last_passes = RegionSummary::PassRange{10, 4.965, 5.355};
  const auto unconverged = nlohmann::json::parse(format_summary(s));
  EXPECT_EQ(unconverged["flow"]["regions"]["core"]["last_passes"]["passes"], 10);
  EXPECT_EQ(unconverged["flow"]["regions"]["core"]["last_passes"]["least"], 4.965);
  EXPECT_EQ(unconverged["flow"]["regions"]["core"]["last_passes"]["largest"], 5.355);
}

}  // namespace
}  // namespace hydrodda::output
