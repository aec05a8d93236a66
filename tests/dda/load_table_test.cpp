// Loads given as (time, value) tables: an elastic block follows its traction's path step by
// step, and a held load time reads every table there (numerics/time_table.hpp).

#include <gtest/gtest.h>

#include <cmath>

#include "dda/selection.hpp"
#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_rectangle;

constexpr double kYoung = 1.0e10, kPoisson = 0.25;

// A 1 m block on rollers at its left and bottom, free at its right, under a normal traction
// p(t) on its top: σyy = p(t), σxx = 0, so in plane strain εy = (1 − ν²) p / E (Hooke's law).
// Its density is 1e-3 kg/m³ and gravity off, so that the step's inertia term (2M/Δt², 2e-9 of
// the elastic stiffness at Δt = 0.01 s) leaves each step's end in equilibrium with the load of
// that time: the strain follows the table to 1e-7 of its largest value.
ModelDefinition make_block_under_table(const numerics::TimeTable& top) {
  ModelDefinition m;
  m.materials = {Material{1.0e-3, kYoung, kPoisson}};
  m.blocks.push_back({make_rectangle(0, 0, 1, 1), 0, false});
  for (auto [a, b] : {std::pair{Point{0, 0}, Point{0, 1}}, std::pair{Point{0, 0}, Point{1, 0}}}) {
    auto rollers = make_rollers_on_segment(m.blocks, a, b, 1e-9, std::nullopt);
    m.rollers.insert(m.rollers.end(), rollers.begin(), rollers.end());
  }
  m.tractions = make_tractions_on_segment(m.blocks, {0, 1}, {1, 1}, 1e-9, top, top, 0.0, 0.0);
  m.settings.analysis = Analysis::static_;
  m.settings.plane = Plane::strain;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 0.01;
  return m;
}

TEST(LoadTable, ABlockStrainsAsItsTractionTableSaysAtEveryStep) {
  // Up to 1 MPa of compression in 1 s, held, then up to 3 MPa and back to 2 MPa.
  const numerics::TimeTable top({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, -1.0e6, -1.0e6, -3.0e6, -2.0e6});
  System system(make_block_under_table(top));
  const double compliance = (1 - kPoisson * kPoisson) / kYoung;
  const double tolerance = 1e-7 * 3.0e6 * compliance;
  for (int step = 1; step <= 500; ++step) {
    system.step();
    const double t = system.time();
    ASSERT_NEAR(system.strain(0)[1], compliance * top.value(t), tolerance) << "t = " << t;
    ASSERT_NEAR(system.stress(0)[1], top.value(t), 1e-7 * 3.0e6) << "t = " << t;
  }
  EXPECT_NEAR(system.time(), 5.0, 1e-9);
}

TEST(LoadTable, AHeldLoadTimeReadsEveryTableThereWhateverTheStepsTime) {
  const numerics::TimeTable top({0.0, 10.0}, {0.0, -2.0e6});
  System system(make_block_under_table(top));
  system.hold_load_time(2.5);
  for (int step = 0; step < 20; ++step) system.step();
  const double compliance = (1 - kPoisson * kPoisson) / kYoung;
  EXPECT_NEAR(system.strain(0)[1], compliance * -0.5e6, 1e-7 * 0.5e6 * compliance);
}

// A point load's table of two columns (fx, fy) at the centroid of the same block, pushing it
// into its rollers: the left ones react with −fx at x − x_c = −½ m, the bottom ones with −fy
// at y − y_c = −½ m, and a DDA block's uniform stress balances that virial, A σ = Σ F (x − x_c):
// σxx = fx (x_c − x_left) / A and σyy = fy (y_c − y_bottom) / A, ½ m of arm on the 1 m² block as
// built. The block's strain (up to 2e-4 here) moves its faces, and DDA adds each step's stress
// on that step's geometry, so the identity is taken on the block as it stands and holds to the
// order of the strain's change of the arms over the path: 1e-5 of the largest load.
TEST(LoadTable, APointLoadFollowsItsTableColumnByColumn) {
  ModelDefinition m = make_block_under_table(0.0);
  m.tractions.clear();
  const numerics::TimeTable force({0.0, 1.0, 2.0}, {0.0, 0.0, -4.0e6, -1.0e6, -4.0e6, -3.0e6}, 2);
  m.point_loads.push_back({0, {0.5, 0.5}, force});
  System system(std::move(m));
  for (int step = 1; step <= 300; ++step) {
    system.step();
    const double t = system.time();
    // The arms on the block as it stands: its strain (up to 2e-4) moves its faces.
    const Polygon& p = system.polygon(0);
    const Point c = system.centroid(0);
    const double area = system.area(0);
    ASSERT_NEAR(system.stress(0)[0], force.value(t, 0) * (c.x - p[0].x) / area, 1e-5 * 4.0e6) << "t = " << t;
    ASSERT_NEAR(system.stress(0)[1], force.value(t, 1) * (c.y - p[0].y) / area, 1e-5 * 4.0e6) << "t = " << t;
  }
}

}  // namespace
}  // namespace hydrodda::dda
