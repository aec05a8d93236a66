// The per-fracture files of a coupled run, through the real program: one fracture from the
// inflow to the outflow boundary (tests/cli/scenarios/single_fracture_flow.toml), whose flow in
// fractures.csv must equal the top's outflow in history.csv every pass (an exact identity of
// the P1 solution, docs/output.md: round-off, 1e-9 relative), whose blocks are held so its
// aperture stays near the initial 0.1 mm, and whose fractures.pvd VTK's own reader reads back
// (python3-vtk9 through tests/output/check_vtu.py).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "result_files.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

const fs::path kScenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/single_fracture_flow.toml";

struct Folder : hydrodda::testing::TemporaryFolder {
  explicit Folder(const std::string& name)
      : TemporaryFolder("hydrodda-fractures-" + name + "-" + std::to_string(::getpid())) {}
};

TEST(FractureOutput, FlowAlongTheFractureIsTheBoundaryFlow) {
  Folder out("flow");
  const auto result = run_program("-q run " + kScenario.string() + " -o " + out.path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const auto history = read_csv(out.path / "history.csv");
  const auto fractures = read_csv(out.path / "fractures.csv");
  ASSERT_GE(history.size(), 2u);
  ASSERT_EQ(fractures.size(), history.size());  // one fracture: one row per pass
  const auto& header = fractures[0];
  EXPECT_EQ(header, (std::vector<std::string>{"step", "time", "fracture", "origin", "set", "number", "length",
                                              "open_length", "open", "mean_aperture", "max_aperture",
                                              "hydraulic_aperture", "normal_stress", "max_shear", "tip_opening_angle",
                                              "flow", "type", "open_share"}));
  const int top = column(history[0], "flow_top");
  for (std::size_t k = 1; k < fractures.size(); ++k) {
    const auto& row = fractures[k];
    EXPECT_EQ(row[0], history[k][0]);
    EXPECT_EQ(row[2], "0");
    EXPECT_EQ(row[3], "listed");
    EXPECT_EQ(std::stod(row[6]), 2.0);  // the face runs the domain's height
    // Q_f = (1/L) Σ (q_e · t) A_e over every element = the outflow through the top.
    const double flow = std::stod(row[column(header, "flow")]);
    const double outflow = std::stod(history[k][top]);
    EXPECT_GT(outflow, 0.0);
    EXPECT_NEAR(flow, outflow, 1e-9 * outflow) << "pass " << row[0];
    // Blocks held at their bottom corners stay near the 0.1 mm they were cut with; the face is open.
    EXPECT_NEAR(std::stod(row[column(header, "mean_aperture")]), 1e-4, 1e-5);
    EXPECT_EQ(row[column(header, "open")], "1");
    EXPECT_NEAR(std::stod(row[column(header, "open_length")]), 2.0, 1e-12);
    EXPECT_EQ(std::stod(row[column(header, "open_share")]), 1.0);
  }
  EXPECT_TRUE(fs::exists(out.path / "figures" / "apertures.png"));

  // fractures.pvd, read back: one data set per fluid data set, lines along the fracture whose
  // lengths add up to its 2 m, the documented arrays one tuple per line.
  if (std::system("/usr/bin/python3 -c 'import vtkmodules.vtkIOXML' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 is not installed: the ParaView files cannot be read back";
  const std::string check = "/usr/bin/python3 " + (fs::path(HYDRODDA_SOURCE_DIR) / "tests/output/check_vtu.py").string();
  const auto count_datasets = [](const std::string& text) {
    int n = 0;
    std::stringstream lines(text);
    for (std::string line; std::getline(lines, line);) n += line.rfind("dataset ", 0) == 0;
    return n;
  };
  const auto series = run_command(check + " " + (out.path / "fractures.pvd").string());
  ASSERT_EQ(series.exit_code, 0) << series.output.substr(0, 2000);
  const auto fluid = run_command(check + " " + (out.path / "fluid.pvd").string());
  EXPECT_EQ(count_datasets(series.output), count_datasets(fluid.output));
  EXPECT_GE(count_datasets(series.output), 1);

  std::string last;
  for (const auto& entry : fs::directory_iterator(out.path))
    if (entry.path().filename().string().rfind("fractures_", 0) == 0) last = std::max(last, entry.path().string());
  const auto read = run_command(check + " " + last);
  ASSERT_EQ(read.exit_code, 0);
  const hydrodda::testing::VtuDump dump = hydrodda::testing::parse_vtu_dump(read.output);
  const int cells = dump.cells;
  ASSERT_GT(cells, 0);
  for (const char* array : {"fracture", "aperture", "shear", "open", "flow"})
    EXPECT_EQ(dump.cell_shapes.at(array), " 1 " + std::to_string(cells)) << array;
  double length = 0.0;
  for (const auto& [cell, shape] : dump.cell_nodes) {
    const auto& [type, nodes] = shape;
    EXPECT_EQ(type, 3);  // VTK_LINE
    ASSERT_EQ(nodes.size(), 2u);
    const auto a = dump.points.at(nodes[0]), b = dump.points.at(nodes[1]);
    length += std::hypot(b[0] - a[0], b[1] - a[1]);
    EXPECT_EQ(dump.cell_values.at("open").at(cell), 1.0);
    EXPECT_NEAR(dump.cell_values.at("aperture").at(cell), 1e-4, 1e-5);
  }
  // The midline of blocks that settle under their weight by about ρ g H² / (2 E) = 5e-6 m.
  EXPECT_NEAR(length, 2.0, 1e-5);
  EXPECT_LT(length, 2.0);
}

}  // namespace
