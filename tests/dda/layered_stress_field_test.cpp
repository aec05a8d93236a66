// A layered stress field (dda::StressField with knots): piecewise linear in y, and the share of
// a face's force each end takes integrated exactly across its knots. Reference: hand
// integration of ∫ σ(s) N_p(s) ds, σ piecewise linear, N_p = 1 − s/L (below); round-off
// tolerance 1e-12.

#include <gtest/gtest.h>

#include "dda/definitions.hpp"
#include "dda/initial_stress.hpp"

namespace {

using hydrodda::dda::Point;
using hydrodda::dda::StressField;

// σxx: −3 at y = 0, −1 at y = 1, 0 at y = 2; σyy twice that; τxy 0.
StressField two_layers() {
  StressField field;
  field.knots = {{0.0, {-3.0, -6.0, 0.0}}, {1.0, {-1.0, -2.0, 0.0}}, {2.0, {0.0, 0.0, 0.0}}};
  return field;
}

TEST(LayeredStressField, IsLinearBetweenKnotsAndAlongTheEndPiecesBeyond) {
  const StressField field = two_layers();
  EXPECT_NEAR(field.at(0.5)[0], -2.0, 1e-12);
  EXPECT_NEAR(field.at(1.0)[1], -2.0, 1e-12);
  EXPECT_NEAR(field.at(1.5)[1], -1.0, 1e-12);
  EXPECT_NEAR(field.at(-1.0)[0], -5.0, 1e-12);  // the lower piece's slope, 2 per m
  EXPECT_NEAR(field.at(3.0)[0], 1.0, 1e-12);    // the upper piece's, 1 per m
}

TEST(LayeredStressField, AFaceAcrossAKnotTakesItsExactShares) {
  // A vertical face p = (0, 0) → q = (0, 2), outward normal +x: traction (σxx, τxy).
  // p's share ∫_0^2 σxx(s)(1 − s/2) ds: ∫_0^1 (−3 + 2s)(1 − s/2) ds = −19/12 and
  // ∫_1^2 (s − 2)(1 − s/2) ds = −1/6, so −7/4; the whole force ∫ σxx ds = −2 − 1/2, so q's is −3/4.
  const StressField field = two_layers();
  const Point p{0.0, 0.0}, q{0.0, 2.0}, n{1.0, 0.0};
  const Point at_p = hydrodda::dda::compute_face_load(field, p, q, n);
  const Point at_q = hydrodda::dda::compute_face_load(field, q, p, n);
  EXPECT_NEAR(at_p.x, -7.0 / 4.0, 1e-12);
  EXPECT_NEAR(at_q.x, -3.0 / 4.0, 1e-12);
  EXPECT_NEAR(at_p.y, 0.0, 1e-12);
}

TEST(LayeredStressField, AFaceWithinOneLayerTakesTheLinearShares) {
  // Within [0, 1] the field is linear: L (2 t(p) + t(q)) / 6 = (2 (−3) + (−1)) / 6 = −7/6.
  const StressField field = two_layers();
  const Point share = hydrodda::dda::compute_face_load(field, {0.0, 0.0}, {0.0, 1.0}, {1.0, 0.0});
  EXPECT_NEAR(share.x, -7.0 / 6.0, 1e-12);
}

}  // namespace
