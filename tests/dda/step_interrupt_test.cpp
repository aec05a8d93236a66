// A step asked to stop between its open–close passes (System::set_interrupt_check): the check
// is asked once before each pass, and a true answer abandons the step, leaving the system
// exactly as the last finished step left it (no bond broken, the same blocks, time and time
// step), so that the step taken afterwards is the step an uninterrupted system takes.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {


constexpr double kStrength = 1.0e5;  // Pa, the bond's tensile strength T, on a face of L = 1 m

// A fixed base and a 1 m × 1 m sub-block bonded to it along their shared face, no gravity,
// static analysis: pulled up at its top corners by 1.5 T L (a static step takes the block some
// 0.88 of the way to its load: 1.3 T), the face breaks in the first pass of the step and its
// contacts open in a later one (a step of at least two passes).
ModelDefinition make_bonded_block() { return testing::make_bonded_block({30.0, 1.0e9, kStrength}); }

// Settled on its base (one step), then pulled up by 1.5 T L.
void settle_and_pull(System& system) {
  system.step();
  std::vector<std::vector<Point>> forces(2);
  forces[1].assign(4, {0.0, 0.0});
  forces[1][2] = forces[1][3] = {0.0, 0.75 * kStrength};
  system.set_vertex_forces(forces);
}

TEST(StepInterrupt, TheCheckIsAskedOnceBeforeEachPass) {
  System system(make_bonded_block());
  settle_and_pull(system);
  int asked = 0;
  system.set_interrupt_check([&] {
    ++asked;
    return false;
  });
  const StepReport report = system.step();
  ASSERT_EQ(report.retries, 0);
  EXPECT_GE(report.open_close_iterations, 2);
  EXPECT_EQ(asked, report.open_close_iterations);
  EXPECT_TRUE(system.is_bond_broken(0));
}

TEST(StepInterrupt, AnInterruptBeforeASecondPassLeavesTheSystemAsTheLastStepLeftIt) {
  System interrupted(make_bonded_block()), uninterrupted(make_bonded_block());
  settle_and_pull(interrupted);
  settle_and_pull(uninterrupted);
  const SystemState before = interrupted.export_state();
  int asked = 0;
  interrupted.set_interrupt_check([&] { return ++asked == 2; });  // before the step's second pass
  EXPECT_THROW(interrupted.step(), StepInterrupted);
  EXPECT_EQ(asked, 2);

  // The bond the first pass broke is whole again; blocks, time and time step as before.
  EXPECT_FALSE(interrupted.is_bond_broken(0));
  EXPECT_TRUE(interrupted.bond_breaks().empty());
  const SystemState after = interrupted.export_state();
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(after.time_step, before.time_step);
  ASSERT_EQ(after.blocks.size(), before.blocks.size());
  for (std::size_t b = 0; b < before.blocks.size(); ++b) {
    EXPECT_EQ(after.blocks[b].polygon, before.blocks[b].polygon) << "block " << b;
    EXPECT_EQ(after.blocks[b].stress, before.blocks[b].stress) << "block " << b;
  }
  ASSERT_EQ(after.contacts.size(), before.contacts.size());

  // Stepped again, unasked: the step of a system never interrupted. Its solver kept a factor
  // from the abandoned try, which changes the solution at the solver's tolerance (1e-12 of the
  // load) only: the displacements agree to 1e-9 of themselves.
  interrupted.set_interrupt_check({});
  interrupted.step();
  uninterrupted.step();
  EXPECT_TRUE(interrupted.is_bond_broken(0));
  ASSERT_EQ(interrupted.bond_breaks().size(), 1u);
  EXPECT_EQ(interrupted.bond_breaks().front().mode, BondFailure::tension);
  EXPECT_EQ(interrupted.time(), uninterrupted.time());
  const Point u = uninterrupted.displacement(1), v = interrupted.displacement(1);
  EXPECT_GT(std::abs(u.y), 0.0);
  EXPECT_NEAR(v.x, u.x, 1e-9 * std::abs(u.y));
  EXPECT_NEAR(v.y, u.y, 1e-9 * std::abs(u.y));
}

}  // namespace
}  // namespace hydrodda::dda
