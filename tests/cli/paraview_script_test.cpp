// examples/paraview/render_run.py, the script docs/paraview.md shows, run as a user runs it:
// `xvfb-run -a pvbatch render_run.py RUN_FOLDER FIELD OUT.png` on a small coupled run. Checks
// that it draws the fluid, blocks and fractures series at the run's last coupling iteration
// and writes a PNG of the size it asks for. Skipped, saying why, when pvbatch or xvfb-run is
// not installed (Debian packages paraview, python3-paraview, xvfb, xauth).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

TEST(ParaviewScript, RendersARunFolderHeadless) {
  for (const char* tool : {"pvbatch", "xvfb-run"})
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
  // xvfb-run -a picks its display by looking for lock files, without taking one: X servers
  // started at the same moment (another suite on the host) pick the same display, and all but
  // one client then fail to connect (3 of 6 started 0.3 s apart, measured); it was also seen
  // once in a whole suite with no other X server running. Either way the X server failed, not
  // the script: it is tried again, up to three times, and only for those messages. The search
  // starts from a display of this process's own (-n), so that two suites seldom meet at all.
  const std::string draw = "xvfb-run -a -n " + std::to_string(100 + ::getpid() % 800) + " pvbatch " +
                           (source / "examples/paraview/render_run.py").string() + " " + out.string() +
                           " pressure " + png.string();
  const auto x_server_failed = [](const std::string& output) {
    return output.find("bad X server connection") != std::string::npos ||
           output.find("Xvfb failed to start") != std::string::npos;
  };
  auto drawn = run_command(draw);
  for (int retry = 0; retry < 2 && drawn.exit_code != 0 && x_server_failed(drawn.output); ++retry)
    drawn = run_command(draw);
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
