#pragma once
// Running the shipped coupled verification scenarios through the real program and reading back
// what they wrote: summary.json, history.csv and the last pass's contacts, blocks and fluid
// .vtu files; the interface forces of a block column; the P1 pressure of a fluid_NNNN.vtu.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/run_program.hpp"
#include "../output/appended_arrays.hpp"

namespace hydrodda::testing::coupled {

namespace fs = std::filesystem;

inline const fs::path kVerification = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification";
inline constexpr double kG = 9.81;         // gravity of both the mechanics ([0, -9.81]) and the flow model
inline constexpr double kRhoWater = 1000.0;
inline constexpr double kRhoRock = 2500.0;

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `text` with every `from` replaced by `to`; `count` is how many there were.
inline std::string replace_all(std::string text, const std::string& from, const std::string& to, int& count) {
  count = 0;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
    ++count;
  }
  return text;
}

struct RunResult {
  nlohmann::json summary = nlohmann::json::object();
  std::vector<std::vector<std::string>> history;  // history.csv, header first
  std::string contacts;                           // the last pass's contacts_NNNN.vtu
  std::string blocks;                             // the last pass's blocks_NNNN.vtu
  std::string fluid;                              // the last pass's fluid_NNNN.vtu
  std::vector<std::vector<std::string>> fractures;  // fractures.csv, header first (none: empty)
};

// The normal force each interface of a block column carries, from a contacts_NNNN.vtu: the
// interface at y = k m lies between blocks k - 1 and k. With `locked`, every contact must be
// locked.
inline std::array<double, 3> sum_interface_forces(const std::string& contacts, bool locked) {
  const auto state = read_vtu_array(contacts, "state");
  const auto normal = read_vtu_array(contacts, "normal_force");
  const auto block_i = read_vtu_array(contacts, "block_i");
  const auto block_j = read_vtu_array(contacts, "block_j");
  EXPECT_FALSE(state.empty());
  std::array<double, 3> force{0.0, 0.0, 0.0};
  if (normal.size() != state.size() || block_i.size() != state.size() || block_j.size() != state.size()) {
    ADD_FAILURE() << "contacts_NNNN.vtu: arrays of different lengths";
    return force;
  }
  for (std::size_t c = 0; c < state.size(); ++c) {
    if (locked) {
      EXPECT_EQ(state[c], 2.0) << "contact " << c << " must stay locked";
    }
    EXPECT_EQ(std::abs(block_i[c] - block_j[c]), 1.0) << "contact " << c << " joins neighbours";
    force[static_cast<int>(std::max(block_i[c], block_j[c])) % 3] += normal[c];
  }
  return force;
}

// Runs a scenario file into a fresh temporary folder named `name`; exit code `exit_code`
// expected (0: the run went to its end; 1: it failed, e.g. on blocks thrown off).
inline RunResult run_and_read(const fs::path& scenario, const std::string& name, int exit_code = 0) {
  const fs::path out = fs::temp_directory_path() / ("hydrodda-coupled-verification-" + name);
  fs::remove_all(out);
  const auto result = run_program("run " + scenario.string() + " -o " + out.string());
  EXPECT_EQ(result.exit_code, exit_code) << result.output;
  RunResult r;
  if (std::ifstream in(out / "summary.json"); in) r.summary = nlohmann::json::parse(in);
  r.history = read_csv(out / "history.csv");
  if (fs::exists(out / "fractures.csv")) r.fractures = read_csv(out / "fractures.csv");
  if (r.summary.contains("iterations")) {
    char number[16];
    std::snprintf(number, sizeof number, "_%04d.vtu", r.summary["iterations"].get<int>());
    r.contacts = hydrodda::testing::read_file_bytes(out / ("contacts" + std::string(number)));
    r.blocks = hydrodda::testing::read_file_bytes(out / ("blocks" + std::string(number)));
    r.fluid = hydrodda::testing::read_file_bytes(out / ("fluid" + std::string(number)));
  }
  fs::remove_all(out);
  return r;
}

// Runs a scenario given as text (a shipped file with some values replaced) in a folder named
// `name`, through a temporary scenario file.
inline RunResult run_text_and_read(const std::string& scenario, const std::string& name, int exit_code = 0) {
  const fs::path file = fs::temp_directory_path() / ("hydrodda-coupled-verification-" + name + ".toml");
  std::ofstream(file) << scenario;
  RunResult r = run_and_read(file, name, exit_code);
  fs::remove(file);
  return r;
}

// The points of a .vtu file (x, y of each; z dropped).
inline std::vector<std::array<double, 2>> read_vtu_points(const std::string& vtu) {
  const std::vector<double> xyz = read_vtu_array(vtu, "Points");
  std::vector<std::array<double, 2>> points;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) points.push_back({xyz[i], xyz[i + 1]});
  return points;
}

// The P1 field of a fluid_NNNN.vtu's nodal pressure, evaluated by a search over its triangles.
class PressureField {
 public:
  explicit PressureField(const std::string& vtu)
      : points_(read_vtu_points(vtu)), pressure_(read_vtu_array(vtu, "pressure")) {
    const std::vector<std::int64_t> connectivity = hydrodda::testing::read_vtu_int64_array(vtu, "connectivity");
    for (std::size_t i = 0; i + 2 < connectivity.size(); i += 3)
      triangles_.push_back({static_cast<int>(connectivity[i]), static_cast<int>(connectivity[i + 1]),
                            static_cast<int>(connectivity[i + 2])});
  }
  bool empty() const { return triangles_.empty() || pressure_.size() != points_.size(); }
  // The pressure at (x, y), or NaN outside the mesh.
  double at(double x, double y) const {
    for (const auto& t : triangles_) {
      const auto& a = points_[t[0]];
      const auto& b = points_[t[1]];
      const auto& c = points_[t[2]];
      const auto orient = [](const std::array<double, 2>& p, const std::array<double, 2>& q, double px, double py) {
        return (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0]);
      };
      const double whole = orient(a, b, c[0], c[1]);
      const double wa = orient(b, c, x, y) / whole, wb = orient(c, a, x, y) / whole, wc = orient(a, b, x, y) / whole;
      if (std::min({wa, wb, wc}) >= -1e-9) return wa * pressure_[t[0]] + wb * pressure_[t[1]] + wc * pressure_[t[2]];
    }
    return NAN;
  }

 private:
  std::vector<std::array<double, 2>> points_;
  std::vector<double> pressure_;
  std::vector<std::array<int, 3>> triangles_;
};

inline int column_of(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

}  // namespace hydrodda::testing::coupled
