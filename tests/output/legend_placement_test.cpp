// Where a line plot's legend goes (output/legend_placement.hpp): the corner whose box hides the
// fewest data points, the first of them on a tie, and the raised y axis that leaves a band
// above the data when every corner hides some. Exact arithmetic but for the log axis's power
// (checked to 1e-12 relative).

#include "output/legend_placement.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace hydrodda::output {
namespace {

// A 400 × 300 frame at (50, 20), a legend of 100 × 40 set 8 in.
const PageBox kFrame{50.0, 20.0, 400.0, 300.0};

TEST(LegendPlacement, TheCornersAreTheFramesInnerCornersInTheOrderTried) {
  const std::array<PageBox, 4> c = legend_corners(kFrame, 100.0, 40.0, 8.0);
  EXPECT_EQ(c[0].x, 342.0);  // top right: 50 + 400 − 100 − 8
  EXPECT_EQ(c[0].y, 28.0);
  EXPECT_EQ(c[1].x, 58.0);  // top left
  EXPECT_EQ(c[1].y, 28.0);
  EXPECT_EQ(c[2].x, 342.0);  // bottom right: 20 + 300 − 40 − 8
  EXPECT_EQ(c[2].y, 272.0);
  EXPECT_EQ(c[3].x, 58.0);
  EXPECT_EQ(c[3].y, 272.0);
  EXPECT_EQ(c[3].w, 100.0);
  EXPECT_EQ(c[3].h, 40.0);
}

TEST(LegendPlacement, TheCornerThatHidesTheFewestPointsIsChosen) {
  const std::array<PageBox, 4> c = legend_corners(kFrame, 100.0, 40.0, 8.0);
  // Two points under the top right corner's box, one under each bottom one, none top left.
  const std::vector<std::array<double, 2>> points{{400.0, 40.0}, {440.0, 60.0}, {400.0, 300.0}, {100.0, 300.0}};
  const LegendCorner chosen = choose_legend_corner(c, points, 4.0);
  EXPECT_EQ(chosen.corner, 1u);
  EXPECT_EQ(chosen.hidden, 0u);
  // A point 3 below the top left box's bottom edge (28 + 40) lies within its margin of 4.
  const std::vector<std::array<double, 2>> everywhere{{400.0, 40.0}, {100.0, 71.0}, {400.0, 300.0}, {100.0, 300.0}};
  const LegendCorner tie = choose_legend_corner(c, everywhere, 4.0);
  EXPECT_EQ(tie.corner, 0u);  // each hides one: the first tried
  EXPECT_EQ(tie.hidden, 1u);
  EXPECT_EQ(choose_legend_corner(c, everywhere, 2.0).corner, 1u);  // 3 beyond a margin of 2
}

TEST(LegendPlacement, ARaisedAxisPutsTheDataTopAtTheBandsFoot) {
  // Linear: 0 + 10 / (1 − 0.2) = 12.5, where 10 lies 0.8 of the way up.
  EXPECT_EQ(raise_axis_top(0.0, 10.0, 0.2, false), 12.5);
  EXPECT_EQ(raise_axis_top(-5.0, 5.0, 0.5, false), 15.0);
  // Log: log10(100 / 1) / log10(hi / 1) = 0.75, hi = 10^(8/3).
  const double hi = raise_axis_top(1.0, 100.0, 0.25, true);
  EXPECT_NEAR(hi, std::pow(10.0, 8.0 / 3.0), 1e-12 * hi);
  EXPECT_NEAR(std::log10(100.0) / std::log10(hi), 0.75, 1e-12);
}

}  // namespace
}  // namespace hydrodda::output
