// A joint with no friction and no cohesion carries no shear: its contacts slide from the moment
// they close (System::closed_state), never held by a locked spring.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_incline;

// A block on a frictionless incline of 1° (dynamic, no cohesion) slides from rest at
// g sin θ: |d| = ½ g sin θ t² (exact for a constant acceleration; 1e-3 relative for the
// contacts' penalty and the steps' landing). A locked spring would hold it: its shear
// m g sin θ ≈ 430 N/m stretches it far less than its shear band.
TEST(FrictionlessContact, ABlockOnAFrictionlessInclineSlidesFromRestAtGSinTheta) {
  System system(make_incline(1.0, 0.0, 0.0));
  system.run_steps(1);
  for (const ContactInfo& c : system.contacts())
    if (c.state != ContactState::open) EXPECT_EQ(c.state, ContactState::sliding);
  system.run_until(1.0);
  const double expected = 0.5 * 9.81 * std::sin(std::numbers::pi / 180.0);
  EXPECT_NEAR(geometry::norm(system.displacement(1)), expected, 1e-3 * expected);
}

// In a static analysis each step starts from rest, so a free block under a constant force F
// moves d = F Δt²/(2 m) a step (the inertia term 2M/Δt² of the step's equations): on the
// frictionless incline N steps move it N · ½ g sin θ Δt² (1e-3 relative), a few tenths of a
// micrometre a step. A locked spring holds any shear that stretches it by less than its shear
// band, and the reference point of a locked contact stays put from step to step: the block
// would not move.
TEST(FrictionlessContact, AStaticStepMovesTheBlockAsIfTheInclineWereNotThere) {
  ModelDefinition m = make_incline(1.0, 0.0, 0.0);
  m.settings.analysis = Analysis::static_;
  System system(std::move(m));
  const int steps = 100;
  system.run_steps(steps);
  const double dt = system.time() / steps;
  const double theta = std::numbers::pi / 180.0;
  const double expected = steps * 0.5 * 9.81 * std::sin(theta) * dt * dt;
  // Along the slope: across it the block sinks by its contacts' penetration, N/p.
  const Point d = system.displacement(1);
  EXPECT_NEAR(-(d.x * std::cos(theta) + d.y * std::sin(theta)), expected, 1e-3 * expected);
}

// The same block with cohesion (c l > m g sin θ) is held: the rule is the joint's strength,
// not the friction angle alone.
TEST(FrictionlessContact, CohesionWithoutFrictionStillHoldsTheBlock) {
  System system(make_incline(1.0, 0.0, 1.0e4));
  system.run_until(1.0);
  EXPECT_LT(geometry::norm(system.displacement(1)), 1e-6);
}

}  // namespace
}  // namespace hydrodda::dda
