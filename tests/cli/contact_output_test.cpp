// The contacts of a mechanics run in ParaView's files, read back with VTK's own reader
// (python3-paraview's or python3-vtk9's, through tests/output/check_vtu.py): one contact data
// set per block data set, the documented arrays, and forces that carry the column's weight.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>
#include <sstream>

#include "result_files.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

TEST(ContactOutput, StackedColumnContactsCarryTheWeight) {
  if (std::system("/usr/bin/python3 -c 'import vtkmodules.vtkIOXML' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3 cannot import vtk (python3-paraview or python3-vtk9): the ParaView files cannot be read back";
  const fs::path out = fs::temp_directory_path() / ("hydrodda-contacts-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto run =
      run_program("-q run " + (fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/stacked_column.toml").string() +
                  " -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;

  // As many contact data sets as block data sets, at the same times.
  const std::string check = (fs::path(HYDRODDA_SOURCE_DIR) / "tests/output/check_vtu.py").string();
  const auto datasets = [](const std::string& text) {
    std::vector<std::string> times;
    std::stringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
      if (line.rfind("dataset ", 0) == 0) times.push_back(line.substr(8, line.find(' ', 8) - 8));
    return times;
  };
  const auto contacts = run_command("/usr/bin/python3 " + check + " " + (out / "contacts.pvd").string());
  ASSERT_EQ(contacts.exit_code, 0) << contacts.output.substr(0, 2000);
  const auto blocks = run_command("/usr/bin/python3 " + check + " " + (out / "blocks.pvd").string());
  ASSERT_EQ(blocks.exit_code, 0);
  EXPECT_EQ(datasets(contacts.output), datasets(blocks.output));

  // The last step's contacts: every array one tuple per contact (a line cell).
  std::string last;
  for (const auto& entry : fs::directory_iterator(out))
    if (entry.path().filename().string().rfind("contacts_", 0) == 0) last = std::max(last, entry.path().string());
  const auto read = run_command("/usr/bin/python3 " + check + " " + last);
  ASSERT_EQ(read.exit_code, 0);
  const hydrodda::testing::VtuDump dump = hydrodda::testing::parse_vtu_dump(read.output);
  const int cells = dump.cells;
  auto arrays = dump.cell_values;
  auto shapes = dump.cell_shapes;
  ASSERT_GT(cells, 0);
  for (const char* array : {"state", "normal_force", "penetration", "aperture", "block_i", "block_j"})
    EXPECT_EQ(shapes[array], " 1 " + std::to_string(cells)) << array;

  // Forces between block pairs: in equilibrium the contacts under block k carry the weight of
  // the blocks above them, ρ g × (11 − k) m² per metre (blocks 1..10 of 1 m², the base is 0).
  // The augmented Lagrangian leaves a residual far below 1e-5 of it.
  std::map<std::pair<int, int>, double> force_between;
  for (int c = 0; c < cells; ++c) {
    const double state = arrays["state"][c];
    EXPECT_TRUE(state == 0.0 || state == 1.0 || state == 2.0) << state;
    EXPECT_EQ(arrays["aperture"][c], std::max(0.0, -arrays["penetration"][c]));
    if (state == 0.0) continue;
    const int i = static_cast<int>(arrays["block_i"][c]), j = static_cast<int>(arrays["block_j"][c]);
    force_between[{std::min(i, j), std::max(i, j)}] += arrays["normal_force"][c];
  }
  for (int k = 1; k <= 10; ++k) {
    const double weight = 2500.0 * 9.81 * (11 - k);
    EXPECT_NEAR(force_between[std::make_pair(k - 1, k)], weight, 1e-5 * weight) << "under block " << k;
  }
  fs::remove_all(out);
}

}  // namespace
