// Joint types per face: a contact takes the Mohr–Coulomb strengths of the joint type of the
// edge its vertex touches (dda::BlockDefinition::edge_joints, dda::ModelDefinition::joint_types).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

// The incline of test_models.hpp (a 1 m block on a fixed slope at θ), its joint type 0 of
// φ = 45° (which would hold the block), the slope's top edge and the block's base of type
// `base` and the block's other three edges of type `side`. Types 1 and 2: φ = 20° and 45°.
ModelDefinition make_typed_incline(double theta_deg, int base, int side) {
  ModelDefinition m = testing::make_incline(theta_deg, 45.0, 0.0);
  m.joint_types = {Joint{20.0, 0.0, 0.0}, Joint{45.0, 0.0, 0.0}};
  m.blocks[0].edge_joints = {0, 0, base, 0};         // the slope: bottom, right, top, left
  m.blocks[1].edge_joints = {base, side, side, side};  // the block: base, right, top, left
  return m;
}

void run_to(System& system, double end_time) {
  while (system.time() < end_time - 1e-12) system.run_until(std::min(end_time, system.time() + 1e-3));
}

// A base of φ = 20° on a 30° slope: m a = m g (sin θ − cos θ tan φ), d(1 s) = ½ a, within 1% as
// the engine's sliding-block verification; the sides' 45° and the default's 45° play no part.
TEST(JointTypes, ABlockSlidesByTheFrictionOfItsBasesType) {
  System system(make_typed_incline(30.0, /*base=*/1, /*side=*/2));
  run_to(system, 1.0);
  const double theta = 30.0 * kPi / 180.0, phi = 20.0 * kPi / 180.0;
  const double expected = 0.5 * kG * (std::sin(theta) - std::cos(theta) * std::tan(phi));
  EXPECT_NEAR(std::hypot(system.displacement(1).x, system.displacement(1).y), expected, 0.01 * expected);
}

// The same block with its base of φ = 45° and its sides of 20°: it holds (moves less than 1e-4
// of its 1 m size in 1 s).
TEST(JointTypes, ABlockOnABaseOfHigherFrictionHoldsWhateverItsSides) {
  System system(make_typed_incline(30.0, /*base=*/2, /*side=*/1));
  run_to(system, 1.0);
  EXPECT_LT(std::hypot(system.displacement(1).x, system.displacement(1).y), 1e-4);
}

TEST(JointTypes, ABadTypeIndexOrCountIsRefused) {
  ModelDefinition m = make_typed_incline(30.0, 1, 2);
  m.blocks[1].edge_joints = {1, 2, 3, 0};
  EXPECT_THROW(System{m}, std::invalid_argument);
  m.blocks[1].edge_joints = {1, 2};
  EXPECT_THROW(System{m}, std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::dda
