// The wedge tips a round of mesh.refine_tips leaves to the next (fractures/tip_refinement.hpp,
// with the radius run/scenario_fractures.hpp gives).

#include "fractures/tip_refinement.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <vector>

#include "run/scenario_fractures.hpp"

namespace hydrodda::run {
namespace {

// A tip of s* = `length` at (x, y) in an element `element` across.
fractures::WedgeTipElement tip_in(double x, double y, double length, double element) {
  fractures::WedgeTipElement e;
  e.tip.point = {x, y};
  e.tip.length = length;
  e.element_size = element;
  return e;
}

// Every tip whose element is over s*/2 gets a point of size s*/4 and the default radius
// (mesh.size − size) / 0.2; a resolved one none; when the least resolved (first) is resolved,
// nothing is refined.
TEST(TipRefinement, EveryUnresolvedTipGetsAPointAtAQuarterOfItsLength) {
  scenario::MeshDefinition mesh;
  mesh.size = 0.15;
  const std::vector<fractures::WedgeTipElement> tips{tip_in(5.0, 1.0, 0.002, 0.004), tip_in(6.0, 0.0, 0.004, 0.0015),
                                                     tip_in(4.0, 0.0, 0.001, 0.0006)};
  const std::vector<fractures::RefinedTip> added = fractures::tips_to_refine(tips, 2, default_refine_radius(mesh));
  ASSERT_EQ(added.size(), 2u);
  EXPECT_EQ(added[0].x, 5.0);
  EXPECT_DOUBLE_EQ(added[0].size, 0.0005);
  EXPECT_DOUBLE_EQ(added[0].radius, (0.15 - 0.0005) / 0.2);
  EXPECT_EQ(added[0].round, 2);
  EXPECT_EQ(added[1].x, 4.0);
  EXPECT_DOUBLE_EQ(added[1].size, 0.00025);
  EXPECT_TRUE(fractures::tips_to_refine(std::vector<fractures::WedgeTipElement>{tip_in(6.0, 0.0, 0.004, 0.002)}, 1,
                                        default_refine_radius(mesh)).empty());
  EXPECT_EQ(fractures::current_round({}), 1);
  EXPECT_EQ(fractures::current_round(added), 3);
}

// Over a round's last passes, the same tip found again a little away (closer than 4 × the
// smaller size, its s*) is one point: the newest pass's place, the finer size. A tip farther
// than that is another point. The newest pass's tips come first.
TEST(TipRefinement, ATipFoundOverSeveralPassesIsOnePointAtItsFinestSize) {
  std::deque<fractures::PassTips> passes;
  passes.push_back({41, {{5.0, 1.0, 0.0004, 0.7, 2}, {9.0, 0.0, 0.001, 0.7, 2}, {9.01, 0.0, 0.001, 0.7, 2}}});
  passes.push_back({42, {}});
  passes.push_back({43, {{5.0012, 1.0, 0.0005, 0.7, 2}}});
  passes.push_back({44, {{9.0039, 0.0, 0.001, 0.7, 2}, {9.0041, 0.0, 0.001, 0.7, 2}}});
  const std::vector<fractures::RefinedTip> merged = fractures::merge_tips(passes);
  ASSERT_EQ(merged.size(), 3u);
  // Pass 44's first; its second, 0.2 mm away, is the same tip (s* = 4 mm), and so is pass 41's
  // at x = 9.0, 3.9 mm away.
  EXPECT_EQ(merged[0].x, 9.0039);
  EXPECT_DOUBLE_EQ(merged[0].size, 0.001);
  // Pass 43's, which pass 41's 1.2 mm away (under 4 × 0.0004) joins with its finer size.
  EXPECT_EQ(merged[1].x, 5.0012);
  EXPECT_DOUBLE_EQ(merged[1].size, 0.0004);
  // Pass 41's at x = 9.01, 6.1 mm from 9.0039: another tip.
  EXPECT_EQ(merged[2].x, 9.01);
  EXPECT_TRUE(fractures::merge_tips({}).empty());
}

// The checkpoint's numbers read back to the same tips and passes, a pass without tips kept (the
// window of the last passes is the same after a resume).
TEST(TipRefinement, TipsReadBackFromACheckpointsNumbers) {
  const std::vector<fractures::RefinedTip> refined{{8.0, 1.0073446173275367, 4.5e-4, 0.7477, 1},
                                                {11.9958, 1.0034, 5.5e-3, 0.72, 2}};
  const std::vector<fractures::RefinedTip> back = fractures::read_refined_tips(fractures::write_refined_tips(refined));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].y, 1.0073446173275367);
  EXPECT_EQ(back[1].round, 2);
  std::deque<fractures::PassTips> passes;
  passes.push_back({7, refined});
  passes.push_back({8, {}});
  passes.push_back({9, {refined[0]}});
  const std::deque<fractures::PassTips> read = fractures::read_recent_tips(fractures::write_recent_tips(passes));
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read[0].iteration, 7);
  EXPECT_EQ(read[0].tips.size(), 2u);
  EXPECT_EQ(read[1].iteration, 8);
  EXPECT_TRUE(read[1].tips.empty());
  EXPECT_EQ(read[2].tips[0].size, 4.5e-4);
}

}  // namespace
}  // namespace hydrodda::run
