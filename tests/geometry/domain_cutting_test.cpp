#include "geometry/domain_cutting.hpp"

#include <gtest/gtest.h>

namespace hydrodda::geometry {
namespace {

const Polygon kUnitSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

double total_area(const std::vector<Polygon>& blocks) {
  double a = 0.0;
  for (const Polygon& b : blocks) a += signed_area(b);
  return a;
}

TEST(CutDomain, CrossMakesFourQuarters) {
  const CutResult r = cut_domain(kUnitSquare, {{{0.5, -0.2}, {0.5, 1.2}}, {{0.0, 0.5}, {1.0, 0.5}}}, {});
  ASSERT_EQ(r.blocks.size(), 4u);
  for (const Polygon& b : r.blocks) EXPECT_NEAR(signed_area(b), 0.25, 1e-15);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.used_traces.size(), 4u);  // each trace split in two at the crossing
}

TEST(CutDomain, SixBlockModelOfThePaperScenario) {
  // The shipped six-block reconstruction: two through-going traces and two ending on the
  // near-vertical one. Six blocks whose areas add up to the domain's (1e-12 relative).
  const Polygon domain{{0, 0}, {5, 0}, {5, 5}, {0, 5}};
  const std::vector<Segment2> fractures{{{0.0, 2.1}, {5.0, 2.9}},
                                        {{2.4, 0.0}, {2.0, 5.0}},
                                        {{2.088, 3.9}, {5.0, 4.3}},
                                        {{0.0, 0.9}, {2.296, 1.3}}};
  const CutResult r = cut_domain(domain, fractures, {});
  EXPECT_EQ(r.blocks.size(), 6u);
  EXPECT_NEAR(total_area(r.blocks), 25.0, 25.0 * 1e-12);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(CutDomain, DanglingPiecesAreDroppedWithAWarning) {
  // A trace from the left side ending mid-block cuts nothing: one block, one warning.
  const CutResult r = cut_domain(kUnitSquare, {{{0.0, 0.5}, {0.6, 0.5}}}, {});
  EXPECT_EQ(r.blocks.size(), 1u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("fracture 0"), std::string::npos);
  // A trace that crosses a through-going one and stops: the crossing part stays, the stub goes.
  const CutResult t = cut_domain(kUnitSquare, {{{0.5, 0.0}, {0.5, 1.0}}, {{0.0, 0.3}, {0.8, 0.3}}}, {});
  EXPECT_EQ(t.blocks.size(), 3u);
  EXPECT_EQ(t.warnings.size(), 1u);
  EXPECT_NEAR(total_area(t.blocks), 1.0, 1e-15);
}

TEST(CutDomain, WeldedRegionsStayWhole) {
  // A 3 × 1 layer welded at both ends, cut by a vertical trace in the middle and a horizontal
  // one along its length. Inside the welded ends the horizontal trace is ignored; what is left
  // of it runs from the vertical trace into welded material, separates nothing, and is dropped.
  const Polygon layer{{0, 0}, {3, 0}, {3, 1}, {0, 1}};
  const std::vector<Polygon> welded{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{2, 0}, {3, 0}, {3, 1}, {2, 1}}};
  const CutResult r = cut_domain(layer, {{{0.0, 0.5}, {3.0, 0.5}}, {{1.5, 0.0}, {1.5, 1.0}}}, welded);
  EXPECT_EQ(r.blocks.size(), 2u);
  EXPECT_NEAR(total_area(r.blocks), 3.0, 1e-14);
  EXPECT_EQ(r.warnings.size(), 1u);
}

TEST(ShrinkBlocks, OpensTheApertureAndKeepsBoundaryFaces) {
  // A cross in the unit square, aperture w: the open area is 2w − w² exactly, and every block
  // keeps its faces on the domain boundary.
  const double w = 0.01;
  const CutResult r = cut_domain(kUnitSquare, {{{0.5, 0.0}, {0.5, 1.0}}, {{0.0, 0.5}, {1.0, 0.5}}}, {});
  const auto shrunk = shrink_blocks(r.blocks, kUnitSquare, w);
  EXPECT_NEAR(1.0 - total_area(shrunk), 2 * w - w * w, 1e-15);
  for (const Polygon& b : shrunk) {
    const Box box = bounding_box(b);
    EXPECT_TRUE(box.lo.x == 0.0 || box.hi.x == 1.0);
    EXPECT_TRUE(box.lo.y == 0.0 || box.hi.y == 1.0);
    EXPECT_NEAR(box.width(), 0.5 - w / 2, 1e-15);
  }
  EXPECT_THROW(shrink_blocks(r.blocks, kUnitSquare, 1.2), std::runtime_error);
}

}  // namespace
}  // namespace hydrodda::geometry
