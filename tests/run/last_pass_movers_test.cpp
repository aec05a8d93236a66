// The message of a loop that did not converge names the blocks that moved most in its last
// pass, which decide the displacement norm (coupling::displacement_change): a few pieces far
// ahead of the rest (a sub-block loose in its crack, every bond broken, resting elsewhere each
// pass), or the whole model still moving. Exact: the text is compared whole; the norm without
// the named blocks is the identity max |Δu| / max(max |u|, ℓ) over the others.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dda/system.hpp"
#include "run/coupled_messages.hpp"

namespace hydrodda::run {
namespace {

// Block 0 a unit square bonded along x = 1 to block 1, a triangle of 0.5 m², by bond 0, broken;
// blocks 2 and 3 unit squares of their own.
dda::System make_blocks() {
  dda::ModelDefinition m;
  m.materials = {dda::Material{2500.0, 1.0e10, 0.25}};
  dda::BlockDefinition square{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}, 0, false};
  square.edge_bonds = {-1, 0, -1, -1};
  dda::BlockDefinition triangle{{{1.0, 0.0}, {2.0, 0.0}, {1.0, 1.0}}, 0, false};
  triangle.edge_bonds = {-1, -1, 0};
  const dda::BlockDefinition right{{{3.0, 0.0}, {4.0, 0.0}, {4.0, 1.0}, {3.0, 1.0}}, 0, false};
  const dda::BlockDefinition far_right{{{5.0, 0.0}, {6.0, 0.0}, {6.0, 1.0}, {5.0, 1.0}}, 0, false};
  m.blocks = {square, triangle, right, far_right};
  m.joint_types = {dda::Joint{25.0, 6.0e6, 2.0e6}};
  m.broken_bonds = {0};
  m.settings.time_step = 1e-3;
  return dda::System(m);
}

TEST(LastPassMovers, AFewPiecesFarAheadOfTheRestAreNamedWithTheNormWithoutThem) {
  const dda::System system = make_blocks();
  coupling::StaggeredLoop::PassMotion motion;
  motion.before = {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
  motion.after = {{1.0e-5, 0.0}, {0.0, 3.0e-3}, {0.0, -4.0e-3}, {2.0e-5, 0.0}};
  motion.reference_length = 0.01;
  // Without blocks 2 and 1: 2e-5 m over max(2e-5 m, ℓ = 0.01 m) = 0.002.
  EXPECT_EQ(describe_last_pass_movers(motion, system),
            "in the last pass block 2 (1 m²) at (3.5, 0.5) moved 0.004 m, block 1 (0.5 m², every bond broken) "
            "at (1.333, 0.3333) moved 0.003 m; every other block at most 2e-05 m, and without these 2 the "
            "displacement change would be 0.002");
}

TEST(LastPassMovers, AWholeModelStillMovingNamesItsLeaderAndTheRestBesideIt) {
  const dda::System system = make_blocks();
  coupling::StaggeredLoop::PassMotion motion;
  motion.before = {{0.0, 1.0e-3}, {0.0, 1.0e-3}, {0.0, 1.0e-3}, {0.0, 1.0e-3}};
  motion.after = {{0.0, 2.0e-3}, {0.0, 1.9e-3}, {0.0, 1.8e-3}, {0.0, 1.7e-3}};
  motion.reference_length = 0.01;
  EXPECT_EQ(describe_last_pass_movers(motion, system),
            "in the last pass block 0 (1 m², every bond broken) at (0.5, 0.5) moved 0.001 m; every other block "
            "at most 0.0009 m");
}

TEST(LastPassMovers, WithoutAPassBeforeTheLastNothingIsSaid) {
  const dda::System system = make_blocks();
  coupling::StaggeredLoop::PassMotion motion;
  motion.after = {{0.0, 2.0e-3}, {0.0, 1.9e-3}, {0.0, 1.8e-3}, {0.0, 1.7e-3}};
  EXPECT_EQ(describe_last_pass_movers(motion, system), "");
}

}  // namespace
}  // namespace hydrodda::run
