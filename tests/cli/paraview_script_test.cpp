// examples/paraview/render_run.py, the script docs/paraview.md shows, run as a user runs it,
// `pvbatch render_run.py RUN_FOLDER FIELD OUT.png` on an X server of its own, on a small
// coupled run. Checks that it draws the fluid, blocks and fractures series at the run's last
// coupling iteration and writes a PNG of the size it asks for. Skipped, saying why, when pvbatch or Xvfb is
// not installed (Debian packages paraview, python3-paraview, xvfb, xauth).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

TEST(ParaviewScript, RendersARunFolderHeadless) {
  for (const char* tool : {"pvbatch", "Xvfb"})
    if (run_command(std::string("command -v ") + tool).exit_code != 0)
      GTEST_SKIP() << tool << " is not installed (Debian packages paraview, python3-paraview, xvfb, xauth): "
                   << "examples/paraview/render_run.py was not run";
  const fs::path source(HYDRODDA_SOURCE_DIR);
  const fs::path out = fs::temp_directory_path() / "hydrodda-paraview-script";
  fs::remove_all(out);
  const auto run = run_program("run " + (source / "scenarios/verification/coupled_hydrostatic_column.toml").string() +
                               " -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  const int iterations = summary.at("iterations").get<int>();

  const fs::path png = out / "pressure.png";
  // The X server is started here rather than by xvfb-run -a, which guesses a free display from
  // lock files without taking one (two suites' servers met on one display, the client failing
  // with "bad X server connection"). Xvfb -displayfd takes a free display itself and writes
  // its number once it accepts connections: the script starts then. -noreset: pvbatch
  // connects once early and again to render, and a server that resets as the first
  // connection closes refused the second.
  const std::string draw =
      "bash -c 'exec 3< <(exec Xvfb -displayfd 1 -noreset -screen 0 1280x1024x24 -nolisten tcp 2> \"$0/xvfb.log\"); "
      "xvfb=$!; "
      "if ! read -r display <&3; then echo \"Xvfb failed to start:\"; cat \"$0/xvfb.log\"; exit 90; fi; "
      "DISPLAY=:$display pvbatch \"$@\"; status=$?; kill $xvfb; exit $status' " +
      out.string() + " " + (source / "examples/paraview/render_run.py").string() + " " + out.string() +
      " pressure " + png.string();
  const auto drawn = run_command(draw);
  ASSERT_EQ(drawn.exit_code, 0) << drawn.output;
  EXPECT_NE(drawn.output.find("drew fluid, blocks, fractures at time " + std::to_string(iterations) +
                              ", coloured by pressure"),
            std::string::npos)
      << drawn.output;
  // A PNG of 1200 × 800: the signature, then the IHDR chunk's width and height (big-endian).
  std::ifstream in(png, std::ios::binary);
  ASSERT_TRUE(in) << png;
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(header) + 1, 3), "PNG");
  const auto be32 = [&](int at) { return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3]; };
  EXPECT_EQ(be32(16), 1200);
  EXPECT_EQ(be32(20), 800);
  fs::remove_all(out);
}

}  // namespace
