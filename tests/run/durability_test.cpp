// How much of a run folder a run flushes to the disk (docs/output.md, "Durability"): only
// what a resume reads and the verdict, and the folder's entries once at the end; the fields,
// tables and figures are renamed into place without a flush. Counts exact (fsync calls made
// through output::AtomicFile and RunFolder::sync).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "output/atomic_file.hpp"
#include "run/run.hpp"
#include "scenario/reader.hpp"

namespace hydrodda {
namespace {

namespace fs = std::filesystem;

// benchmarks/startup.py's run: one block on a fixed base, 5 static steps.
constexpr const char* kOneBlock = R"(title = "one block on a base"
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[[geometry.block]]
vertices = [[-1.0, -1.0], [2.0, -1.0], [2.0, 0.0], [-1.0, 0.0]]
fixed = true
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint]
friction_angle = 30.0
[mechanics]
analysis = "static"
gravity = [0.0, -9.81]
time_step = 1.0e-3
steps = 5
)";

// A mechanics run writes summary.json before its figures and flushes it, and not again after
// them (the same text), then flushes the folder once: 2 fsync calls, where flushing every file
// made one per file (11: the .vtu and .pvd of two output steps, history.csv, summary.json
// twice).
TEST(Durability, AOneBlockRunFlushesItsVerdictAndItsFolderOnly) {
  const fs::path folder = fs::temp_directory_path() / ("hydrodda-durability-run-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  const scenario::Scenario s = scenario::parse_scenario(kOneBlock, folder.string() + ".toml");
  const long long before = output::disk_flushes();
  const run::RunResult result = run::run(s, {folder, false, std::nullopt, std::string(kOneBlock)}, {});
  ASSERT_EQ(result.status, run::RunStatus::finished) << result.message;
  EXPECT_EQ(output::disk_flushes() - before, 2);
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    files += entry.is_regular_file();
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << entry.path();
  }
  EXPECT_GE(files, 8);  // summary.json, history.csv, two .pvd, four .vtu
  fs::remove_all(folder);
}

}  // namespace
}  // namespace hydrodda
