#pragma once
// Reading a run folder's files in command-line tests: a temporary folder removed at the end,
// a CSV column by name, and what tests/output/check_vtu.py prints of a .vtu (VTK's reader).

#include <array>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

namespace hydrodda::testing {

// A fresh folder in the temporary directory, removed when the test ends.
struct TemporaryFolder {
  std::filesystem::path path;
  explicit TemporaryFolder(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path); }
};

// A TemporaryFolder whose name carries the process id, so that two suites running at once
// (`make test` beside `make asan`) never share one.
inline TemporaryFolder fresh_dir(const std::string& name) {
  return TemporaryFolder(name + "-" + std::to_string(::getpid()));
}

// The index of a CSV header's column; a test failure when there is none.
inline int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// One .vtu as check_vtu.py prints it: points, cells (type and nodes), and the cell arrays'
// shapes (" COMPONENTS TUPLES") and first components by tuple.
struct VtuDump {
  int cells = -1;
  std::map<int, std::array<double, 3>> points;
  std::map<int, std::pair<int, std::vector<int>>> cell_nodes;  // type, nodes
  std::map<std::string, std::string> cell_shapes;
  std::map<std::string, std::map<int, double>> cell_values;
};

inline VtuDump parse_vtu_dump(const std::string& text) {
  VtuDump dump;
  std::stringstream lines(text);
  std::string line, word, name;
  while (std::getline(lines, line)) {
    std::stringstream words(line);
    words >> word;
    if (word == "cells") words >> dump.cells;
    if (word == "point") {
      int i = 0;
      words >> i;
      words >> dump.points[i][0] >> dump.points[i][1] >> dump.points[i][2];
    }
    if (word == "cell") {
      int i = 0, type = 0;
      words >> i >> type;
      auto& [cell_type, nodes] = dump.cell_nodes[i];
      cell_type = type;
      for (int node = 0; words >> node;) nodes.push_back(node);
    }
    if (word == "cell_array") {
      words >> name;
      std::getline(words, dump.cell_shapes[name]);
    }
    if (word == "cell_value") {
      int tuple = 0, component = 0;
      double value = 0.0;
      words >> name >> tuple >> component >> value;
      if (component == 0) dump.cell_values[name][tuple] = value;
    }
  }
  return dump;
}

}  // namespace hydrodda::testing
