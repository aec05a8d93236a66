// A System's exported state, imported into a System built from the same definition, continues
// exactly as the original does after importing its own state: the state holds everything the
// steps read. Compared bit for bit (exact ==), as resumed runs must reproduce uninterrupted ones.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

// The incline with a point load, a prescribed displacement and a measured point, so that every
// kind of tracked point and contact record is part of the state.
ModelDefinition make_loaded_incline() {
  ModelDefinition m = testing::make_incline(30.0, 10.0, 0.0);
  const Polygon& block = m.blocks[1].polygon;
  m.point_loads.push_back({1, block[2], constant_force({1.0e3, 0.0})});
  m.measured_points.push_back({1, block[3]});
  return m;
}

void expect_same(const System& a, const System& b) {
  ASSERT_EQ(a.block_count(), b.block_count());
  EXPECT_EQ(a.time(), b.time());
  for (int k = 0; k < a.block_count(); ++k) {
    ASSERT_EQ(a.polygon(k).size(), b.polygon(k).size());
    for (std::size_t v = 0; v < a.polygon(k).size(); ++v) {
      EXPECT_EQ(a.polygon(k)[v].x, b.polygon(k)[v].x);
      EXPECT_EQ(a.polygon(k)[v].y, b.polygon(k)[v].y);
    }
    EXPECT_EQ(a.stress(k), b.stress(k));
    EXPECT_EQ(a.strain(k), b.strain(k));
    EXPECT_EQ(a.rotation(k), b.rotation(k));
    EXPECT_EQ(a.displacement(k).x, b.displacement(k).x);
  }
  const auto ma = a.measured_positions(), mb = b.measured_positions();
  ASSERT_EQ(ma.size(), mb.size());
  for (std::size_t i = 0; i < ma.size(); ++i) EXPECT_EQ(ma[i].x, mb[i].x);
  EXPECT_EQ(a.contacts().size(), b.contacts().size());
}

TEST(SystemState, ImportedIntoANewSystemContinuesBitForBit) {
  System original(make_loaded_incline());
  original.set_vertex_forces({{}, {{0.0, -10.0}, {0.0, -10.0}, {0.0, -10.0}, {0.0, -10.0}}});
  original.run_steps(40);
  const SystemState saved = original.export_state();
  ASSERT_FALSE(saved.contacts.empty());
  original.import_state(saved);  // what a run that writes checkpoints does at that point

  System resumed(make_loaded_incline());
  resumed.import_state(saved);
  expect_same(original, resumed);
  original.run_steps(60);
  resumed.run_steps(60);
  expect_same(original, resumed);
  EXPECT_GT(std::abs(original.displacement(1).x), 1e-3);  // it slid: the states compared move
}

TEST(SystemState, AStateOfAnotherModelIsRefusedAndChangesNothing) {
  System incline(make_loaded_incline());
  System wall(testing::make_brick_wall(2, 3));
  const SystemState before = incline.export_state();
  EXPECT_THROW(incline.import_state(wall.export_state()), std::invalid_argument);
  const SystemState after = incline.export_state();
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(after.blocks.size(), before.blocks.size());
}

}  // namespace
}  // namespace hydrodda::dda
