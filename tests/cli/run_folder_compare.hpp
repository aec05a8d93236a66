#pragma once
// Comparing two run folders byte for byte, for the resume and determinism tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace hydrodda::testing {

namespace fs = std::filesystem;

inline std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// summary.json without `timings` (wall-clock seconds, different in every run).
inline nlohmann::json read_summary_without_timings(const fs::path& folder) {
  nlohmann::json summary = nlohmann::json::parse(read_file(folder / "summary.json"));
  summary.erase("timings");
  return summary;
}

// Every file of the two folders (its subfolders apart) is the same, byte for byte; summary.json,
// where there is one, apart from its timings, parsed so that the comparison names the field.
inline void expect_same_results(const fs::path& a, const fs::path& b) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(a))
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  for (const auto& entry : fs::directory_iterator(b)) {
    if (entry.is_regular_file()) {
      EXPECT_TRUE(fs::exists(a / entry.path().filename())) << entry.path();
    }
  }
  ASSERT_GT(names.size(), 5u);
  for (const std::string& name : names) {
    if (name == "summary.json") continue;  // holds timings; checkpoint.bin holds none
    ASSERT_TRUE(fs::exists(b / name)) << name;
    EXPECT_TRUE(read_file(a / name) == read_file(b / name)) << name << " differs";
  }
  if (fs::exists(a / "summary.json")) {
    EXPECT_EQ(read_summary_without_timings(a), read_summary_without_timings(b));
  }
}

}  // namespace hydrodda::testing
