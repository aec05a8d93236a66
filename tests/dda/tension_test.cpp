// The tension cutoff (Settings::tension_cutoff): a closed contact carries at most T l of
// tension (T the joint's tensile strength, l the face length the contact carries) at the end
// of every accepted step, to 1e-9 of the largest normal force.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_brick_wall;
using testing::make_random_packing;
using testing::make_rectangle;

// The largest tension a closed contact reports, as a fraction of the largest normal force
// any contact reports (0 when none is in tension).
double find_tension_fraction(const System& system) {
  double largest = 0.0;
  double tension = 0.0;
  for (const ContactInfo& c : system.contacts()) {
    largest = std::max(largest, std::abs(c.normal_force));
    if (c.state != ContactState::open) tension = std::max(tension, -c.normal_force);
  }
  return largest > 0.0 ? tension / largest : 0.0;
}

// The contacts of the block's base (block 1's vertices on block 0's top edge).
std::vector<ContactInfo> find_base_contacts(const System& system) {
  std::vector<ContactInfo> out;
  for (const ContactInfo& c : system.contacts())
    if (c.key.block_i == 1 && c.key.block_j == 0) out.push_back(c);
  return out;
}

// A 1 m × 1 m block bonded to a fixed base by a joint of tensile strength T = 100 kPa, no
// gravity, static analysis, pulled up by a vertical load F shared by its two top vertices
// (so the base's two contacts, each carrying l = 0.5 m, pull with F/2 each). The bond holds
// while F < T L and breaks once F > T L, L = 1 m the base's length: the load rises by 0.1% of
// T L a step from 0.95 T L; below 0.99 T L both contacts stay closed and open by less than the
// penetration tolerance, and the first step at which they open has F within [T L, 1.01 T L]
// (never earlier: a closed contact holds exactly T l). Without the cutoff, the band of
// penalty × 1% of the penetration tolerance (5 kN here, 10% of T l) lets the bond hold to
// 1.1 T L.
TEST(Tension, ABondedBlockSeparatesAtTheJointsTensileStrength) {
  constexpr double kStrength = 1.0e5;  // Pa
  constexpr double kBreakingLoad = kStrength * 1.0;  // T L, N per metre
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.blocks.push_back({make_rectangle(-1.0, -1.0, 2.0, 0.0), 0, true});
  m.blocks.push_back({make_rectangle(0.0, 0.0, 1.0, 1.0), 0, false});
  m.joint = {30.0, 0.0, kStrength};
  m.settings.analysis = Analysis::static_;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1e-3;
  m.settings.tension_cutoff = true;
  System system(std::move(m));
  system.step();  // the contacts found touching, closed
  ASSERT_EQ(find_base_contacts(system).size(), 2u);
  double separated_at = -1.0;
  for (int k = 0; k <= 150 && separated_at < 0.0; ++k) {
    const double load = (0.95 + 1e-3 * k) * kBreakingLoad;
    std::vector<std::vector<Point>> forces(2);
    forces[1] = {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.5 * load}, {0.0, 0.5 * load}};
    system.set_vertex_forces(forces);
    system.step();
    const std::vector<ContactInfo> base = find_base_contacts(system);
    const bool open = std::any_of(base.begin(), base.end(), [](const ContactInfo& c) { return c.state == ContactState::open; });
    if (open) {
      separated_at = load;
      break;
    }
    for (const ContactInfo& c : base) {
      EXPECT_GE(c.normal_force, -0.5 * kStrength * (1.0 + 1e-6)) << "F = " << load;
      if (load < 0.99 * kBreakingLoad) {
        EXPECT_LT(-c.penetration, system.penetration_tolerance()) << "F = " << load;
      }
    }
  }
  ASSERT_GT(separated_at, 0.0) << "the bond never broke";
  EXPECT_GE(separated_at, kBreakingLoad);
  EXPECT_LE(separated_at, 1.01 * kBreakingLoad);
  // Once broken the block leaves the base.
  for (int k = 0; k < 20; ++k) system.step();
  EXPECT_GT(system.displacement(1).y, system.penetration_tolerance());
}

// With T = 0, no closed contact reports tension beyond round-off (1e-9 of the largest
// contact force) at the end of any step: a packing of 10 × 10 irregular blocks falling onto
// a base and settling (dynamic, 150 steps of 1 ms), and a 10 × 10 brick wall (static, 30
// steps).
TEST(Tension, NoClosedContactPullsInASettlingPacking) {
  ModelDefinition m = make_random_packing(10);
  m.settings.tension_cutoff = true;
  System system(std::move(m));
  for (int k = 0; k < 150; ++k) {
    system.step();
    ASSERT_LE(find_tension_fraction(system), 1e-9) << "step " << k << ", t = " << system.time();
  }
}

TEST(Tension, NoClosedContactPullsInABrickWall) {
  ModelDefinition m = make_brick_wall(10, 10);
  m.settings.tension_cutoff = true;
  System system(std::move(m));
  for (int k = 0; k < 30; ++k) {
    system.step();
    ASSERT_LE(find_tension_fraction(system), 1e-9) << "step " << k;
  }
}

// The cutoff's first step on a brick wall is a cascade: every touching contact starts locked,
// the solve leaves a quarter of them pulling (the 20 × 20 wall: the joints that carry next to
// no load), the pass opens them, and the next solve leaves a few of the rest pulling, and so
// on, each contact opening once. A pass that changes only contacts that had kept their state
// in this step is progress, not a failure to settle: with room for 4 unsettled passes the
// step runs its whole cascade (more than 4 passes) at its full time step, uncut (before, it
// was cut to 0.3 Δt and began the same cascade again), and ends with no closed contact pulling.
TEST(Tension, AWallsFirstStepOpensItsJointsWithoutBeingCut) {
  ModelDefinition m = make_brick_wall(20, 20);
  m.settings.tension_cutoff = true;
  m.settings.max_open_close_iterations = 4;
  const double full_step = m.settings.time_step;
  System system(std::move(m));
  const StepReport first = system.step();
  EXPECT_GT(first.open_close_iterations, 4);
  EXPECT_EQ(first.retries, 0);
  EXPECT_EQ(first.time_step, full_step);
  EXPECT_LE(find_tension_fraction(system), 1e-9);
}

// A 20 × 20 wall settling under its weight (static steps of 1 ms: it sinks some 5 µm a step)
// brings many of the joints its first step opened back within the hysteresis band of
// touching: a contact the cutoff released closes again only by penetrating past the
// penetration tolerance, in a later step as in its own (ContactRecord::released), since
// within the tolerance it is touching as closely as the step resolves a closed one. Before,
// the mark lasted one step: 126 contacts of this wall closed again in its steps 2–10 (and
// most opened again a pass or two later), where now none does; and no closed contact pulls.
TEST(Tension, AWallsReleasedJointsDoNotCloseAgainAsItSettles) {
  ModelDefinition m = make_brick_wall(20, 20);
  m.settings.tension_cutoff = true;
  System system(std::move(m));
  system.step();
  std::vector<ContactInfo> before = system.contacts();
  int released = 0;
  for (const ContactInfo& c : before) released += c.state == ContactState::open && c.penetration > -1e-9 ? 1 : 0;
  ASSERT_GT(released, 100) << "the first step opens the joints that carry no load";
  int closed_again = 0;
  for (int k = 2; k <= 10; ++k) {
    system.step();
    const std::vector<ContactInfo> after = system.contacts();
    for (const ContactInfo& c : after) {
      const auto was = std::lower_bound(before.begin(), before.end(), c.key,
                                        [](const ContactInfo& a, const ContactKey& key) { return a.key < key; });
      if (was != before.end() && was->key == c.key && was->state == ContactState::open && c.state != ContactState::open)
        ++closed_again;
    }
    ASSERT_LE(find_tension_fraction(system), 1e-9) << "step " << k;
    before = after;
  }
  EXPECT_EQ(closed_again, 0);
}

}  // namespace
}  // namespace hydrodda::dda
