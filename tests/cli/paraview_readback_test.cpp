// A coupled run's ParaView series opened by ParaView itself: pvbatch (Debian packages paraview
// and python3-paraview) runs tests/output/check_paraview.py, which reads fluid.pvd, blocks.pvd,
// contacts.pvd and fractures.pvd with ParaView's PVDReader and checks them against summary.json and the
// scenario's still water (every head 3 m, pressure ρ_w g (h − z)). Skipped only when pvbatch is
// not installed; scripts/install-deps.sh installs it.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

TEST(ParaviewReadback, CoupledRunSeriesOpenInParaView) {
  // pvbatch reads files without a display (only rendering needs one, or xvfb-run).
  if (run_command("command -v pvbatch").exit_code != 0) {
    GTEST_SKIP() << "pvbatch is not installed (Debian packages paraview, python3-paraview): "
                    "the ParaView files were not opened in ParaView";
  }
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/coupled_hydrostatic_column.toml";
  const fs::path out = fs::temp_directory_path() / "hydrodda-paraview-readback";
  fs::remove_all(out);
  const auto run = run_program("run " + scenario.string() + " -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;

  const std::string check = (fs::path(HYDRODDA_SOURCE_DIR) / "tests/output/check_paraview.py").string();
  const double head = 3.0, rho_g = 1000.0 * 9.81;  // the scenario's boundary heads and fluid
  const auto read = run_command("pvbatch " + check + " " + out.string() + " " + std::to_string(head) + " " +
                                std::to_string(rho_g));
  EXPECT_EQ(read.exit_code, 0) << read.output;
  for (const char* fact : {"fluid times", "point arrays head pressure",
                           "cell arrays permeability porosity flux region", "heads and hydrostatic pressures as given",
                           "blocks times", "cell arrays block displacement rotation stress area", "blocks as summary.json",
                           "contacts times", "contacts consistent", "\nok"})
    EXPECT_NE(read.output.find(fact), std::string::npos) << fact << " not in:\n" << read.output;
  fs::remove_all(out);
}

}  // namespace
