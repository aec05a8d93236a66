#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "output/atomic_file.hpp"
#include "output/csv_table.hpp"
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
