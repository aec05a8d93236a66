// `hydrodda check FILE --figure PATH` through the real program: the preview is drawn where asked,
// at the page size of the domain's shape; a scenario that check refuses, a folder, a path in a
// folder that does not exist and an unknown format are refused with exit 2 and nothing drawn.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

const fs::path kSeal = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/jointed_seal.toml";

struct Folder {
  fs::path path;
  explicit Folder(const std::string& name) : path(fs::temp_directory_path() / ("hydrodda-check-figure-" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
};

// The width and height a PNG's IHDR chunk gives (0, 0 when it is no PNG).
std::pair<int, int> png_size(const fs::path& png) {
  std::ifstream in(png, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if (std::string(reinterpret_cast<char*>(header) + 1, 3) != "PNG") return {0, 0};
  const auto be32 = [&](int at) { return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3]; };
  return {be32(16), be32(20)};
}

TEST(CheckFigure, DrawsThePreviewOfTheJointedSeal) {
  const Folder f("seal");
  const fs::path png = f.path / "seal.png";
  const auto result = run_program("check " + kSeal.string() + " --figure " + png.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("preview drawn: " + png.string()), std::string::npos) << result.output;
  // The 20 m × 6 m seal: the widest page, 820 × 298 points, at twice that in pixels
  // (tests/output/preview_figure_test.cpp checks the same sizes and the colours).
  EXPECT_EQ(png_size(png), (std::pair{1640, 596}));
  const fs::path pdf = f.path / "seal.pdf";
  ASSERT_EQ(run_program("check " + kSeal.string() + " --figure " + pdf.string()).exit_code, 0);
  EXPECT_GT(fs::file_size(pdf), 1000u);
}

TEST(CheckFigure, RefusesABadScenarioAFolderAMissingFolderAndAnUnknownFormatDrawingNothing) {
  const Folder f("refused");
  // A scenario check refuses: its errors, exit 2, no figure.
  const fs::path bad = f.path / "bad.toml";
  std::ofstream(bad) << "[geometry]\ndomain = [[0.0, 0.0], [1.0, 0.0]]\n";
  const fs::path png = f.path / "bad.png";
  const auto refused = run_program("check " + bad.string() + " --figure " + png.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_FALSE(fs::exists(png));
  for (const auto& [target, words] : {std::pair{f.path.string(), std::string("is a folder")},
                                      std::pair{(f.path / "no/such/folder/p.png").string(), std::string("does not exist")},
                                      std::pair{(f.path / "p.jpg").string(), std::string(".png, .svg or .pdf")}}) {
    const auto result = run_program("check " + kSeal.string() + " --figure " + target);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(words), std::string::npos) << result.output;
  }
  EXPECT_FALSE(fs::exists(f.path / "p.jpg"));
  EXPECT_EQ(std::distance(fs::directory_iterator(f.path), fs::directory_iterator{}), 1);  // bad.toml only
}

}  // namespace
