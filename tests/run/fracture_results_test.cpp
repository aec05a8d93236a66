// Results per fracture against the exact opening of two blocks moved by hand: a 2 m × 1 m
// domain cut by one vertical fracture at x = 1 m (aperture a0 between the blocks), the right
// block moved by an affine map, the left one left in place. The opening along the face is
// then a0 + u_x(right block at the face), exactly, and the meter's mean, largest value and open
// length are exact for an opening linear along the face (tolerances: round-off, 1e-15 m).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "geometry/block_network.hpp"
#include "run/fracture_results.hpp"

namespace geometry = hydrodda::geometry;
namespace run = hydrodda::run;
using geometry::Point;

namespace {

constexpr double kAperture = 1e-3;

run::FractureMeter two_block_meter() {
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  request.traces = {{{{1, 0}, {1, 1}}, {geometry::TraceSource::joint_set, 1, 3}}};
  request.aperture = kAperture;
  run::FractureLayout layout{request.traces, geometry::build_block_network(request)};
  return run::FractureMeter(std::move(layout), 0.1);
}

// The network's blocks with the right one (centroid x > 1) mapped by `move`.
std::vector<geometry::Polygon> moved(const run::FractureMeter& meter, const std::function<Point(Point)>& move) {
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  for (geometry::Polygon& b : blocks)
    if (geometry::centroid(b).x > 1.0)
      for (Point& p : b) p = move(p);
  return blocks;
}

TEST(FractureResults, TranslatedBlockOpensAndSlidesByItsDisplacement) {
  const run::FractureMeter meter = two_block_meter();
  ASSERT_EQ(meter.layout().network.blocks.size(), 2u);
  const double d = 2e-4, s = -3e-4;  // opening and sliding
  const auto blocks = moved(meter, [&](Point p) { return p + Point{d, s}; });
  const run::FractureState state = meter.measure(blocks, 0.0);
  ASSERT_EQ(state.fractures.size(), 1u);
  const run::FractureResult& r = state.fractures[0];
  EXPECT_EQ(r.id, 0);
  EXPECT_EQ(r.origin.source, geometry::TraceSource::joint_set);
  EXPECT_EQ(r.origin.set, 1);
  EXPECT_NEAR(r.length, 1.0, 1e-15);
  EXPECT_NEAR(r.open_length, 1.0, 1e-15);
  EXPECT_NEAR(r.mean_aperture, kAperture + d, 1e-15);
  EXPECT_NEAR(r.max_aperture, kAperture + d, 1e-15);
  EXPECT_NEAR(r.max_shear, std::abs(s), 1e-15);
  // Pieces at most 0.1 m long along the whole face, all open.
  EXPECT_EQ(state.pieces.size(), 10u);
  for (const run::FracturePiece& p : state.pieces) {
    EXPECT_TRUE(p.open);
    EXPECT_NEAR(p.aperture, kAperture + d, 1e-15);
  }
}

// u_x = β y on the right block: the gap a0 + β y closes at y* = −a0/β = 0.5 m, so
// open length = 0.5 m, mean aperture = ∫₀^½ (a0 + β y) dy / 1 m = a0/4, largest = a0. The
// right block's edge turns by θ = atan β, and the opening is taken along the two edges' mean
// normal: it is the gap × cos(θ/2) (5e-10 m less than the gap; round-off), and the shear the
// displacement βy × sin(θ/2), at most |β| θ/2 = 2e-6 m. The open length is exact: the gap
// vanishes at y*.
TEST(FractureResults, TiltedBlockClosesHalfTheFaceExactly) {
  const run::FractureMeter meter = two_block_meter();
  const double beta = -2.0 * kAperture;
  const auto blocks = moved(meter, [&](Point p) { return p + Point{beta * p.y, 0.0}; });
  const run::FractureState state = meter.measure(blocks, 0.0);
  ASSERT_EQ(state.fractures.size(), 1u);
  const run::FractureResult& r = state.fractures[0];
  const double theta = std::atan(std::abs(beta));
  EXPECT_NEAR(r.open_length, 0.5, 1e-12);
  EXPECT_NEAR(r.mean_aperture, kAperture / 4.0 * std::cos(theta / 2.0), 1e-15);
  EXPECT_NEAR(r.max_aperture, kAperture * std::cos(theta / 2.0), 1e-15);
  EXPECT_LE(r.max_shear, std::abs(beta) * std::sin(theta / 2.0) + 1e-15);
  // The pieces are cut where the face closes: every piece is wholly open (below y*) or closed.
  double open = 0.0, closed = 0.0;
  for (const run::FracturePiece& p : state.pieces) {
    const double length = geometry::distance(p.segment[0], p.segment[1]);
    const double top = std::max(p.segment[0].y, p.segment[1].y), bottom = std::min(p.segment[0].y, p.segment[1].y);
    if (p.open) {
      open += length;
      EXPECT_LE(top, 0.5 + 1e-12);
    } else {
      closed += length;
      EXPECT_GE(bottom, 0.5 - 1e-12);
    }
  }
  // Drawn on the midline, which leans by β/2: lengths grow by √(1 + β²/4) − 1 ≈ 5e-7.
  EXPECT_NEAR(open, 0.5, 1e-6);
  EXPECT_NEAR(closed, 0.5, 1e-6);
}

TEST(FractureResults, BlocksThatDoNotFitTheNetworkAreRefused) {
  const run::FractureMeter meter = two_block_meter();
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  blocks.pop_back();
  EXPECT_THROW(meter.measure(blocks, 0.0), std::invalid_argument);
}

}  // namespace
