// A step's try whose augmented Lagrangian passes run out at a step so short that the blocks'
// inertia outweighs the penalty (src/dda/lagrangian_limits.cpp): a closed contact standing off
// its edge opens, one at the penetration tolerance itself is held rather than the step cut
// until it fails, and one the inertia slows is pushed out by stiffer normal springs.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_rectangle;

constexpr double kTolerance = 1e-6;

// The error of a step that fails as it should, after the time step fell below any use; empty
// (and the test failed) if the step held.
std::string error_of_failed_step(System& system) {
  try {
    system.step();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("time step fell below any use"), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "the step should have failed";
  return {};
}

// A 1 m block `upper` (ρ 2500, E 10 GPa: the default penalty 5e11 N/m) over a fixed base whose
// top is edge 2, (4, 0) to (−1, 0), under gravity, with Coulomb friction of 30° and no cohesion.
ModelDefinition block_over_base(Polygon upper) {
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.blocks.push_back({make_rectangle(-1, -1, 4, 0), 0, true});
  m.blocks.push_back({std::move(upper), 0, false});
  m.joint = {30.0, 0.0, 0.0};
  m.settings.analysis = Analysis::static_;
  m.settings.time_step = 1e-2;
  m.settings.penetration_tolerance = kTolerance;
  return m;
}

// A 1 m block (ρ 2500, E 10 GPa: the default penalty 5e11 N/m) with its base `lift` m over a
// fixed base (lift < 0: overlapping it), under gravity; its base corners' contacts with the
// base's top (edge 2, (4, 0) to (−1, 0)) closed, each pushing with `multiplier` N/m, and the
// step the next one starts from `time_step` s.
System make_block_on_closed_contacts(double lift, double multiplier, double time_step) {
  System system(block_over_base(make_rectangle(1, lift, 2, 1 + lift)));
  SystemState state = system.export_state();
  state.time_step = time_step;
  state.contacts.clear();
  for (int vertex : {0, 1}) {
    ContactRecord r;
    r.state = ContactState::locked;
    r.multiplier = multiplier;
    r.normal_force = multiplier;
    r.reference_ratio = vertex == 0 ? 0.6 : 0.4;  // the corner's place along the edge from (4, 0)
    state.contacts.push_back({ContactKey{1, vertex, 0, 2}, r});
  }
  system.import_state(state);
  return system;
}

// A block held 2 µm (twice the tolerance) off the base with its corners' contacts closed and
// pushing it off with 1e9 N/m each, from a geometry it has left, at a 1e-6 s step: its
// inertia 2M/Δt² (5e15 N/m) outweighs the penalty ten-thousandfold, so a Lagrangian pass,
// lowering each multiplier by p × 2 µm = 1e6 N/m, hardly moves it, and the 30 + 60 passes of
// a try lower the multipliers by under a tenth. The contacts touch nothing: the step opens
// them (Shi's open rule) and goes on at its time step, the block falling ½ g Δt² (to 1e-9 of
// it: round-off on a 1 m block). Without the rule the step was cut 40 times and failed.
TEST(LagrangianLimits, AClosedContactStandingOffItsEdgeOpens) {
  const double dt = 1e-6;
  System system = make_block_on_closed_contacts(2 * kTolerance, 1e9, dt);
  StepReport report;
  ASSERT_NO_THROW(report = system.step());
  EXPECT_EQ(report.retries, 0);
  EXPECT_EQ(report.time_step, dt);
  EXPECT_EQ(report.contacts, 0);
  for (const ContactInfo& c : system.contacts()) EXPECT_EQ(c.state, ContactState::open);
  const double fall = 0.5 * 9.81 * dt * dt;
  EXPECT_NEAR(system.displacement(1).y, -fall, 1e-9 * fall + 1e-15);
}

// A block resting 1e-9 of the tolerance past it (where the last step's update, its rotations
// exact and its penetrations linear, can leave a contact), its corners' contacts closed and
// carrying none of its weight, at a 1e-10 s step (2M/Δt² = 5e23 N/m): the 30 + 60 passes of a
// try raise each multiplier by p × 1e-6 m each, moving the block by 1e-16 m, less than the
// 1e-15 m it lies past the tolerance, and a shorter step moves it less. The step holds the
// overlap (its weight pushes it on by ½ g Δt² = 5e-20 m, under 1e-6 of the tolerance), at its
// time step, and the steps after it, growing by half each, push it back within the tolerance
// once they are long enough to move the block. Without the rule the step was cut 40 times and
// failed.
TEST(LagrangianLimits, AContactAtTheToleranceItselfIsHeldAndThenPushedBack) {
  const double dt = 1e-10;
  const double start = kTolerance * (1 + 1e-9);
  System system = make_block_on_closed_contacts(-start, 0.0, dt);
  StepReport first;
  ASSERT_NO_THROW(first = system.step());
  EXPECT_EQ(first.retries, 0);
  EXPECT_EQ(first.time_step, dt);
  EXPECT_EQ(first.contacts, 2);
  EXPECT_GT(first.max_penetration, kTolerance) << "held where it was: no pass can move it";
  EXPECT_LE(first.max_penetration, start + 1e-6 * kTolerance);
  StepReport last = first;
  int steps = 1;
  for (; steps < 100 && last.max_penetration > kTolerance; ++steps) ASSERT_NO_THROW(last = system.step());
  EXPECT_LE(last.max_penetration, kTolerance) << "after " << steps << " steps";
  EXPECT_EQ(last.contacts, 2);
}

// An overlap deeper than twice the tolerance is no contact at the tolerance: a step that
// cannot push it out (the same block 3 µm into the base at 1e-10 s) is cut until it fails, as
// before, and the error names the contact.
TEST(LagrangianLimits, ADeeperOverlapThatNoPassCanMoveStillFailsTheStep) {
  System system = make_block_on_closed_contacts(-3 * kTolerance, 0.0, 1e-10);
  const std::string what = error_of_failed_step(system);
  EXPECT_NE(what.find("of block 1 against edge 2 of block 0"), std::string::npos) << what;
  EXPECT_NE(what.find("overlaps it by 3e-06 m"), std::string::npos) << what;
}

// The block 20 µm into the base (twenty times the tolerance) at a step of 3e-6 s, where its
// inertia 2M/Δt² = 5.6e14 N/m is 1,100 times the penalty p = 5e11 N/m: a Lagrangian pass
// leaves nearly all of the overlap, and a try's 30 passes and the next try's 60 leave it past
// the tolerance (no mixing: the block's inertia, not the blocks about it, holds the overlap).
// The step used to be cut there, which only slows its passes further. Its third try, with the
// normal springs stiffened to 10 × 2M/Δt² capped at 100 p = 5e13 N/m, settles in a few passes,
// at the step's own length, the base's corners within the tolerance (the block lifted 4.8 µm
// and compressed by the rest). Measured: 96 passes in all (src/dda/lagrangian_limits.cpp,
// "A short step's normal springs").
TEST(LagrangianLimits, AStepWhosePassesTheBlocksInertiaSlowsStiffensItsNormalSpringsRatherThanBeingCut) {
  const double dt = 3e-6;
  System system = make_block_on_closed_contacts(-20 * kTolerance, 0.0, dt);
  StepReport report;
  ASSERT_NO_THROW(report = system.step());
  EXPECT_EQ(report.retries, 2) << "the try at 30 passes and the one at 60 before it";
  EXPECT_EQ(report.time_step, dt) << "not cut";
  EXPECT_EQ(report.contacts, 2);
  EXPECT_LE(report.max_penetration, kTolerance);
  EXPECT_LE(report.lagrangian_iterations, 30 + 60 + 10) << "a few passes in the third try";
  EXPECT_GT(system.displacement(1).y, 0.0);
}

// The same block tilted: its corner 0 1e-9 of the tolerance past it, held there as above, and
// its corner 1 standing 1e-8 m off the base, its contact locked with 2e5 N/m of normal force and
// a shear of 1e5 N/m (its spring stretched 2e-7 m along the edge), at a 1e-10 s step: the
// tessellated seal's failed step in small (docs/studies/2026-11-30-a-seal-not-tuned.md). No pass
// moves the block, and each of a pass's 30 Lagrangian updates λ ← λ + p d lowered corner 1's
// multiplier by p × 1e-8 m = 5e3 N/m: 1.95e5 N/m at the start (its strength 1.1e5 N/m holds the
// shear), 4.5e4 after the first pass (2.6e4 N/m of strength: it slid), −1.05e5 after the second
// (pulling: it opened), a contact within the tolerance let go by updates that moved nothing.
// Allowed one pass in which a contact changes a second time, every try ended so, whatever its
// time step, and the step failed. The stalled passes' updates of the contacts within the
// tolerance are taken back: the step holds at its time step, corner 1 locked with the force it
// started with (to the 1e-6 of it that the block's motion changes it by), corner 0 held.
TEST(LagrangianLimits, AStalledTryLeavesTheMultipliersOfContactsWithinTheToleranceAsTheyWere) {
  const double gap = 1e-8;
  const double overlap = kTolerance * (1 + 1e-9);
  const double dt = 1e-10;
  ModelDefinition m =
      block_over_base(Polygon{{1, -overlap}, {2, gap}, {2, 1 + gap}, {1, 1 - overlap}});
  m.settings.max_open_close_iterations = 1;
  System system(std::move(m));
  SystemState state = system.export_state();
  state.time_step = dt;
  state.contacts.clear();
  ContactRecord held;
  held.state = ContactState::locked;
  held.reference_ratio = 0.6;  // corner 0's place along edge 2, (4, 0) to (−1, 0)
  state.contacts.push_back({ContactKey{1, 0, 0, 2}, held});
  ContactRecord standing_off = held;
  standing_off.multiplier = standing_off.normal_force = 2e5;
  standing_off.reference_ratio = 0.4 + 2e-7 / 5.0;  // corner 1's place, its reference 2e-7 m along
  state.contacts.push_back({ContactKey{1, 1, 0, 2}, standing_off});
  system.import_state(state);
  StepReport report;
  ASSERT_NO_THROW(report = system.step());
  EXPECT_EQ(report.retries, 0);
  EXPECT_EQ(report.time_step, dt);
  EXPECT_EQ(report.contacts, 2);
  const double start_force = 2e5 - 5e11 * gap;
  for (const ContactInfo& c : system.contacts()) {
    EXPECT_EQ(c.state, ContactState::locked) << "vertex " << c.key.vertex;
    if (c.key.vertex == 1) EXPECT_NEAR(c.normal_force, start_force, 1e-6 * start_force);
  }
}

// A step whose contact states never settle names the contacts that changed state in its last
// pass. A block resting on the base, its corner 1's contact sliding in +x along the base's
// top edge, its spring's shear 2e-7 m the other way (its reference point moved 2e-7 m along
// the edge), carrying 1e5 N/m of normal force, at a 1e-10 s step: the first pass locks it (a
// clear reversal: past the hysteresis band of 1e-7 m, ten times the usual as every pass of a
// try allowed one pass without progress counts as chattering), the second slides it the other
// way (p × 2e-7 m = 1e5 N/m of shear against 5.8e4 N/m of strength): a second change, which
// with max_open_close_iterations = 1 ends the try, at any time step, as nothing moves. The error
// names corner 1, its two states in the last pass and its penetrations (without this: no
// contact at all).
TEST(LagrangianLimits, AStepWhoseContactStatesNeverSettleNamesTheContactsThatChanged) {
  ModelDefinition m = block_over_base(make_rectangle(1, 0, 2, 1));
  m.settings.max_open_close_iterations = 1;
  System system(std::move(m));
  SystemState state = system.export_state();
  state.time_step = 1e-10;
  state.contacts.clear();
  ContactRecord locked;
  locked.state = ContactState::locked;
  locked.multiplier = locked.normal_force = 1e5;
  locked.reference_ratio = 0.6;  // corner 0's place along edge 2, (4, 0) to (−1, 0)
  state.contacts.push_back({ContactKey{1, 0, 0, 2}, locked});
  ContactRecord sliding = locked;
  sliding.state = ContactState::sliding;
  sliding.slide_sign = 1;
  sliding.reference_ratio = 0.4 + 2e-7 / 5.0;  // its shear (p1 − p0)·t = −2e-7 m, t = (−1, 0)
  state.contacts.push_back({ContactKey{1, 1, 0, 2}, sliding});
  system.import_state(state);
  const std::string what = error_of_failed_step(system);
  EXPECT_NE(what.find("the open-close iteration did not settle the contact states: 1 contact changed state in its "
                      "last pass (pass 2), 1 of them changing back or on: vertex 1 of block 1 against edge 2 of "
                      "block 0 at (2, 0), locked to sliding, penetration "),
            std::string::npos) << what;
}

}  // namespace
}  // namespace hydrodda::dda
