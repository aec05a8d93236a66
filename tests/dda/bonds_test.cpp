// Bonds (BlockDefinition::edge_bonds, dda/bonds.cpp): a bonded face holds while its normal
// traction is under the tensile strength T and its shear under c + σn tan φ, breaks at those
// strengths (the exact cutoff, to round-off, whatever Settings::tension_cutoff says), and then
// holds no tension and no cohesion.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_bonded_block;

constexpr double kStrength = 1.0e5;  // Pa, T (or c), on faces of L = 1 m

// Loads block 1 by `force` shared by the two vertices given (its corners 0..3 from the lower left).
void load_block(System& system, Point force, int v0, int v1) {
  std::vector<std::vector<Point>> forces(2);
  forces[1].assign(4, {0.0, 0.0});
  forces[1][static_cast<std::size_t>(v0)] = 0.5 * force;
  forces[1][static_cast<std::size_t>(v1)] = 0.5 * force;
  system.set_vertex_forces(forces);
}

// Raises the load by 0.1% of `breaking` a step from 0.95 of it until the bond breaks; the load
// it broke at (−1: never). `direction` the load's unit direction.
double find_breaking_load(System& system, double breaking, Point direction, int v0, int v1) {
  for (int k = 0; k <= 150; ++k) {
    const double load = (0.95 + 1e-3 * k) * breaking;
    load_block(system, load * direction, v0, v1);
    system.step();
    if (system.is_bond_broken(0)) return load;
  }
  return -1.0;
}

// Direct tension: the block pulled up by F at its top corners. The face breaks at F = T L,
// L = 1 m: within [T L, 1.01 T L] (the load's step is 0.1%), never before, with the default
// setting of the tension cutoff (off), whose hysteresis band would let a plain joint hold to
// 1.1 T L here (tension_test.cpp). Broken, it is recorded as a tension break in the step it
// broke, and the block leaves the base: no tension is left.
TEST(Bonds, ABondedFaceBreaksInTensionAtItsStrengthNotBefore) {
  System system(make_bonded_block({30.0, 1.0e9, kStrength}));
  ASSERT_EQ(system.bond_count(), 1);
  system.step();  // the face's contacts found touching: locked
  const double broke_at = find_breaking_load(system, kStrength * 1.0, {0.0, 1.0}, 2, 3);
  ASSERT_GT(broke_at, 0.0) << "the bond never broke";
  EXPECT_GE(broke_at, kStrength * 1.0);
  EXPECT_LE(broke_at, 1.01 * kStrength);
  ASSERT_EQ(system.bond_breaks().size(), 1u);
  const BondBreak& b = system.bond_breaks().front();
  EXPECT_EQ(b.mode, BondFailure::tension);
  EXPECT_DOUBLE_EQ(b.time, system.time());
  EXPECT_NEAR(b.from.y, 0.0, 1e-9);  // the base's top edge
  EXPECT_NEAR(b.to.y, 0.0, 1e-9);
  for (int k = 0; k < 20; ++k) system.step();
  EXPECT_GT(system.displacement(1).y, system.penetration_tolerance());
}

// Direct shear: the block pushed along the face by F at its top corners, so that it carries
// the shear stress τxy = F/L (its moment goes to the base's contacts; σyy stays 0), the bond's
// cohesion c and φ = 30°: it breaks at F = c L within [c L, 1.01 c L], never before, as a
// shear break. Broken, the face holds by friction only, less than F: the block moves on (by
// more than 10× the penetration tolerance in 20 steps; locked, it would not move).
TEST(Bonds, ABondedFaceBreaksInShearAtItsCohesionNotBefore) {
  System system(make_bonded_block({30.0, kStrength, 1.0e9}));
  system.step();
  const double broke_at = find_breaking_load(system, kStrength * 1.0, {1.0, 0.0}, 2, 3);
  ASSERT_GT(broke_at, 0.0) << "the bond never broke";
  EXPECT_GE(broke_at, kStrength * 1.0);
  EXPECT_LE(broke_at, 1.01 * kStrength);
  ASSERT_EQ(system.bond_breaks().size(), 1u);
  EXPECT_EQ(system.bond_breaks().front().mode, BondFailure::shear);
  const double before = system.displacement(1).x;
  for (int k = 0; k < 20; ++k) system.step();
  EXPECT_GT(system.displacement(1).x - before, 10.0 * system.penetration_tolerance());
}

// The bonded face holds under 0.9 T L and breaks under 1.1 T L; the break survives export
// and import into a system built afresh (a checkpoint's round trip).
// A zone face (edge_bonds −2 − k: a face within a zoned Voronoi cell) is locked as a bond's and
// never breaks: the face of the direct tension case above, pulled by 1.5 T L for 20 steps, holds
// the block to its base (its centroid rises by less than its whole stretch, 1.5 T L / E = 15 µm,
// under E = 10 GPa; on a bond, which breaks, by more than ten times that), and the system has
// no bond.
TEST(Bonds, AZoneFaceHoldsPastAnyStrengthAndIsNoBond) {
  const auto pulled = [](bool zone) {
    ModelDefinition model = make_bonded_block({30.0, 1.0e9, kStrength});
    if (zone) {
      model.blocks[0].edge_bonds = {-1, -1, -2, -1};
      model.blocks[1].edge_bonds = {-2, -1, -1, -1};
    }
    System system(model);
    EXPECT_EQ(system.bond_count(), zone ? 0 : 1);
    system.step();
    load_block(system, {0.0, 1.5 * kStrength}, 2, 3);
    for (int k = 0; k < 20; ++k) system.step();
    EXPECT_EQ(system.bond_breaks().size(), zone ? 0u : 1u);
    return system.displacement(1).y;
  };
  const double stretch = 1.5 * kStrength * 1.0 / 1.0e10;  // m
  const double held = pulled(true);
  const double freed = pulled(false);
  EXPECT_GT(held, 0.0);
  EXPECT_LT(held, stretch) << "held " << held << " m";      // measured 6.4 µm
  EXPECT_GT(freed, 10.0 * stretch) << "freed " << freed << " m";  // measured 0.6 mm
}

TEST(Bonds, BrokenBondsCarryThroughExportAndImport) {
  System system(make_bonded_block({30.0, 1.0e9, kStrength}));
  system.step();
  load_block(system, {0.0, 0.9 * kStrength}, 2, 3);
  system.step();
  EXPECT_FALSE(system.is_bond_broken(0));
  load_block(system, {0.0, 1.1 * kStrength}, 2, 3);
  system.step();
  ASSERT_TRUE(system.is_bond_broken(0));
  System copy(make_bonded_block({30.0, 1.0e9, kStrength}));
  EXPECT_FALSE(copy.is_bond_broken(0));
  copy.import_state(system.export_state());
  EXPECT_TRUE(copy.is_bond_broken(0));
  ASSERT_EQ(copy.bond_breaks().size(), 1u);
  EXPECT_EQ(copy.bond_breaks().front().mode, BondFailure::tension);
}

TEST(Bonds, ABondOnOneFaceOnlyIsRefused) {
  ModelDefinition m = make_bonded_block({30.0, 0.0, kStrength});
  m.blocks[0].edge_bonds = {-1, -1, -1, -1};
  EXPECT_THROW(System{std::move(m)}, std::invalid_argument);
  ModelDefinition twice = make_bonded_block({30.0, 0.0, kStrength});
  twice.blocks[1].edge_bonds = {0, 0, -1, -1};
  EXPECT_THROW(System{std::move(twice)}, std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::dda
