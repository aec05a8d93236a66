// A coupled run's record of its broken bonds (docs/output.md, "Bonds"), read back from its run
// folder: history.csv's broken_bonds of each row (a pass, or a time step) against fractures.csv's
// bond rows of that row. Exact identities, no tolerance.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace hydrodda::testing {

inline std::size_t column_of(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

struct BreaksRecorded {
  int total = 0;         // bonds broken, each listed once
  int rows_breaking = 0;  // history rows (passes or steps) that broke any
};

// history.csv's broken_bonds of each row (`row_key`: "iteration" for a steady run's passes,
// "step" for a transient run's time steps) is the number of fractures.csv's bond rows whose
// `step` is that row's, their `time` the row's; every bond listed once.
inline BreaksRecorded expect_breaks_recorded(const std::filesystem::path& folder, const std::string& row_key) {
  const auto history = read_csv(folder / "history.csv");
  const std::size_t row = column_of(history[0], row_key), time = column_of(history[0], "time");
  const std::size_t broken = column_of(history[0], "broken_bonds");
  const auto fractures = read_csv(folder / "fractures.csv");
  const std::size_t step = column_of(fractures[0], "step"), row_time = column_of(fractures[0], "time");
  const std::size_t origin = column_of(fractures[0], "origin"), number = column_of(fractures[0], "number");
  std::map<std::string, int> bond_rows;
  std::map<std::string, std::string> time_of_row;
  std::set<std::string> bonds;
  for (std::size_t r = 1; r < fractures.size(); ++r) {
    if (fractures[r][origin] != "bond") continue;
    ++bond_rows[fractures[r][step]];
    time_of_row[fractures[r][step]] = fractures[r][row_time];
    EXPECT_TRUE(bonds.insert(fractures[r][number]).second) << "bond " << fractures[r][number] << " listed twice";
  }
  BreaksRecorded recorded;
  for (std::size_t r = 1; r < history.size(); ++r) {
    const std::string& key = history[r][row];
    const int in_row = std::stoi(history[r][broken]);
    EXPECT_EQ(in_row, bond_rows[key]) << row_key << " " << key;
    if (in_row > 0) {
      EXPECT_EQ(time_of_row[key], history[r][time]) << row_key << " " << key;
      ++recorded.rows_breaking;
    }
    recorded.total += in_row;
  }
  EXPECT_EQ(recorded.total, static_cast<int>(bonds.size()));
  return recorded;
}

// The bond rows of a pass or time step in a run folder's fractures.csv, as text.
inline std::vector<std::vector<std::string>> bond_rows_of(const std::filesystem::path& folder, const std::string& step) {
  const auto fractures = read_csv(folder / "fractures.csv");
  std::vector<std::vector<std::string>> rows;
  for (std::size_t r = 1; r < fractures.size(); ++r)
    if (fractures[r][column_of(fractures[0], "origin")] == "bond" && fractures[r][0] == step) rows.push_back(fractures[r]);
  return rows;
}

}  // namespace hydrodda::testing
