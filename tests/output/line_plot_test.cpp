#include "output/plot_line.hpp"

#include <gtest/gtest.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace hydrodda::output {
namespace {

namespace fs = std::filesystem;

std::string read_head(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  return s.substr(0, static_cast<std::size_t>(in.gcount()));
}

LinePlotSpec make_convergence_spec() {
  LinePlotSpec spec;
  spec.title = "Coupling convergence";
  spec.x_label = "coupling iteration";
  spec.y_label = "relative change";
  spec.y_log = true;
  LineSeries head{"head", {}, {}, {}}, displacement{"displacement", {}, {}, {}};
  for (int i = 1; i <= 12; ++i) {
    head.x.push_back(i);
    head.y.push_back(std::pow(0.35, i));
    displacement.x.push_back(i);
    displacement.y.push_back(2.0 * std::pow(0.5, i));
  }
  spec.series = {head, displacement};
  spec.references = {{"tolerance", 1e-4}};
  return spec;
}

class LinePlot : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("hydrodda-line-plot-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(LinePlot, ConvergenceHistoryInEachFormat) {
  const LinePlotSpec spec = make_convergence_spec();
  render_line_plot(dir / "c.png", spec);
  EXPECT_EQ(read_head(dir / "c.png", 8), std::string("\x89PNG\r\n\x1a\n", 8));
  render_line_plot(dir / "c.pdf", spec);
  EXPECT_EQ(read_head(dir / "c.pdf", 5), "%PDF-");
  render_line_plot(dir / "c.svg", spec);
  // The SVG is well-formed XML with an <svg> root.
  boost::property_tree::ptree tree;
  ASSERT_NO_THROW(boost::property_tree::read_xml((dir / "c.svg").string(), tree));
  EXPECT_EQ(tree.count("svg"), 1u);
  EXPECT_FALSE(fs::exists(dir / "c.svg.tmp"));
}

TEST_F(LinePlot, LinearAxesAndOneSeriesPerValue) {
  LinePlotSpec spec;
  spec.x_label = "head differential (m)";
  spec.y_label = "K / K matrix";
  for (double load : {5.0, 10.0}) {
    LineSeries s{"load " + std::to_string(static_cast<int>(load)), {}, {}, {}};
    for (double dh = 5.0; dh <= 20.0; dh += 5.0) {
      s.x.push_back(dh);
      s.y.push_back(1.0 + 0.02 * dh * dh / load);
    }
    spec.series.push_back(s);
  }
  spec.references = {{"unfractured", 1.0}};
  render_line_plot(dir / "s.png", spec);
  EXPECT_EQ(read_head(dir / "s.png", 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(LinePlot, BadInputIsRejected) {
  LinePlotSpec spec;
  spec.series = {LineSeries{"bad", {1, 2}, {1}, {}}};
  EXPECT_THROW(render_line_plot(dir / "a.png", spec), std::invalid_argument);
  // Only non-positive values on a log axis: nothing to plot.
  spec.series = {LineSeries{"zero", {1, 2}, {0, -1}, {}}};
  spec.y_log = true;
  EXPECT_THROW(render_line_plot(dir / "b.png", spec), std::invalid_argument);
  // An open flag for each point, or none.
  spec.y_log = false;
  spec.series = {LineSeries{"open", {1, 2}, {1, 2}, {true}}};
  EXPECT_THROW(render_line_plot(dir / "d.png", spec), std::invalid_argument);
  spec.series = {LineSeries{"ok", {1, 2}, {1, 2}, {}}};
  EXPECT_THROW(render_line_plot(dir / "c.jpg", spec), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "a.png"));
  EXPECT_FALSE(fs::exists(dir / "d.png"));
}

}  // namespace
}  // namespace hydrodda::output
