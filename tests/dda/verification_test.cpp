// Verification of the DDA engine against analytic solutions (DESIGN.md §2.1). Each test
// states its formula and tolerance; tolerances are the and are not to be loosened.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <utility>

#include <omp.h>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_brick_wall;
using testing::make_incline;
using testing::make_random_packing;
using testing::make_rectangle;

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

// Runs to end_time and checks after every step that no closed contact penetrates deeper than
// the engine's stated tolerance (verification 6).
void run_checking_penetration(System& system, double end_time) {
  while (system.time() < end_time - 1e-12) {
    const StepReport r = system.run_until(std::min(end_time, system.time() + 1e-3));
    ASSERT_LE(r.max_penetration, system.penetration_tolerance()) << "t = " << r.time;
  }
}

struct SlideCase {
  double theta_deg;
  double phi_deg;
  double cohesion;
};

class SlidingBlock : public ::testing::TestWithParam<SlideCase> {};

// Block sliding down an incline, dynamic analysis. Along the slope
//   m a = m g sin θ − m g cos θ tan φ − c L   →   d(t) = ½ a t²,
// with m = ρ A (A = 1 m², L = 1 m the contact length). Tolerance 1% at t = 1 s.
TEST_P(SlidingBlock, MatchesAnalyticDisplacementWithinOnePercent) {
  const SlideCase c = GetParam();
  System system(make_incline(c.theta_deg, c.phi_deg, c.cohesion));
  run_checking_penetration(system, 1.0);
  const double theta = c.theta_deg * kPi / 180.0;
  const double phi = c.phi_deg * kPi / 180.0;
  const double a = kG * (std::sin(theta) - std::cos(theta) * std::tan(phi)) - c.cohesion * 1.0 / 2500.0;
  const double expected = 0.5 * a * 1.0 * 1.0;
  const Point u = system.displacement(1);
  EXPECT_NEAR(geometry::norm(u), expected, 0.01 * expected);
  EXPECT_LT(u.x, 0.0);  // downhill
}

INSTANTIATE_TEST_SUITE_P(Verification, SlidingBlock,
                         ::testing::Values(SlideCase{30.0, 20.0, 0.0}, SlideCase{40.0, 30.0, 0.0},
                                           SlideCase{25.0, 10.0, 0.0},
                                           SlideCase{30.0, 20.0, 1000.0}));

// φ > θ: friction holds the block; it moves less than 1e-4 of its 1 m size in 1 s.
TEST(Verification, BlockStaysPutWhenFrictionExceedsSlope) {
  System system(make_incline(20.0, 30.0, 0.0));
  run_checking_penetration(system, 1.0);
  EXPECT_LT(geometry::norm(system.displacement(1)), 1e-4 * 1.0);
}

// Free fall: d(t) = ½ g t², within 0.1% at t = 1 s.
TEST(Verification, FreeFallMatchesHalfGTSquared) {
  ModelDefinition m;
  m.materials = {Material{}};
  m.blocks.push_back({make_rectangle(0, 0, 1, 1), 0, false});
  m.settings.analysis = Analysis::dynamic;
  m.settings.max_displacement_ratio = 1.0;
  System system(std::move(m));
  system.run_until(1.0);
  EXPECT_NEAR(-system.displacement(0).y, 0.5 * kG, 1e-3 * 0.5 * kG);
  EXPECT_NEAR(system.displacement(0).x, 0.0, 1e-12);
}

// Ten 1 m blocks stacked on a fixed base, static: the mean vertical stress of a block is
// σyy = −ρ g × (depth of its centroid below the top), within 1%. With the default allowed step
// displacement (1% of half the 11 m height: a contact distance of 0.14 m) and with 30% of it,
// whose contact distance of 4.1 m reaches past four blocks: each corner then also lies within
// it of the far edges of the blocks beside it, which must not be taken for contacts.
TEST(Verification, StackedColumnCarriesRhoGDepth) {
  for (const double ratio : {0.01, 0.3}) {
    SCOPED_TRACE("max_displacement_ratio " + std::to_string(ratio));
    ModelDefinition m;
    m.materials = {Material{2500.0, 1.0e10, 0.25}};
    m.blocks.push_back({make_rectangle(-1, -1, 2, 0), 0, true});
    for (int k = 0; k < 10; ++k) m.blocks.push_back({make_rectangle(0, k, 1, k + 1), 0, false});
    m.settings.analysis = Analysis::static_;
    m.settings.time_step = 1e-2;
    m.settings.max_displacement_ratio = ratio;
    System system(std::move(m));
    for (int i = 0; i < 400; ++i) {
      const StepReport r = system.step();
      ASSERT_LE(r.max_penetration, system.penetration_tolerance());
    }
    for (int k = 0; k < 10; ++k) {
      const double depth = 10.0 - (k + 0.5);
      const double expected = -2500.0 * kG * depth;
      EXPECT_NEAR(system.stress(k + 1)[1], expected, 0.01 * std::abs(expected)) << "block " << k;
    }
  }
}

// A packing of 36 jittered blocks (edges 0.6–1.4 m) falling onto a fixed base with a contact
// distance of 2.7 m (30% of half its 7.2 m height, times 2.5), far past its blocks: every
// step settles and no closed contact penetrates deeper than the tolerance (verification 6)
// through its first 80 ms, in which the blocks meet the base and each other.
TEST(Verification, PackingWithAContactDistancePastItsBlocksSettles) {
  ModelDefinition m = make_random_packing(6);
  m.settings.max_displacement_ratio = 0.3;
  System system(std::move(m));
  run_checking_penetration(system, 0.08);
  int closed = 0;
  for (const ContactInfo& c : system.contacts()) closed += c.state != ContactState::open ? 1 : 0;
  EXPECT_GT(closed, 36);  // they have met: more closed contacts than blocks
}

class ElasticBlock : public ::testing::TestWithParam<Plane> {};

// A 1 m block on a fixed base (frictionless joint, so it expands freely sideways) under a
// top traction σ = −1 MPa, static: εy = σ / E′ with E′ = E (plane stress) or E/(1 − ν²)
// (plane strain), within 0.5%.
TEST_P(ElasticBlock, StrainIsStressOverEPrime) {
  const Plane plane = GetParam();
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  m.blocks.push_back({make_rectangle(-1, -1, 2, 0), 0, true});
  m.blocks.push_back({make_rectangle(0, 0, 1, 1), 0, false});
  m.joint = {0.0, 0.0, 0.0};
  m.tractions.push_back({1, 2, -1.0e6, -1.0e6, 0.0, 0.0});
  m.settings.analysis = Analysis::static_;
  m.settings.plane = plane;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1e-2;
  System system(std::move(m));
  for (int i = 0; i < 200; ++i) {
    const StepReport r = system.step();
    ASSERT_LE(r.max_penetration, system.penetration_tolerance());
  }
  const double nu = 0.25;
  const double e_prime = plane == Plane::stress ? 1.0e10 : 1.0e10 / (1 - nu * nu);
  const double expected = -1.0e6 / e_prime;
  EXPECT_NEAR(system.strain(1)[1], expected, 0.005 * std::abs(expected));
  EXPECT_NEAR(system.stress(1)[1], -1.0e6, 0.005 * 1.0e6);
}

INSTANTIATE_TEST_SUITE_P(Verification, ElasticBlock,
                         ::testing::Values(Plane::strain, Plane::stress));

// Every vertex of every block, x then y.
std::vector<double> vertex_coordinates(const System& system) {
  std::vector<double> coords;
  for (int b = 0; b < system.block_count(); ++b)
    for (Point p : system.polygon(b)) {
      coords.push_back(p.x);
      coords.push_back(p.y);
    }
  return coords;
}

// A 61-block brick wall run twice gives bitwise identical vertices.
TEST(Verification, BrickWallRunIsBitwiseReproducible) {
  const auto run = [] {
    System system(make_brick_wall(6, 10));
    system.run_steps(20);
    return vertex_coordinates(system);
  };
  const auto first = run();
  const auto second = run();
  ASSERT_GE(first.size(), 50u * 8u);
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
}

// A wall large enough (901 blocks: 2,600 block pairs, a factor of 15,000 blocks) that contact
// detection and the factor run in two parts side by side, and the loops over blocks and
// contacts in chunks over the threads, gives the same vertices to the last bit on one thread as
// on two, three or eight.
TEST(Verification, BrickWallRunIsTheSameOnOneThreadOrTwo) {
  const int threads_before = omp_get_max_threads();
  const auto run = [](int threads) {
    omp_set_num_threads(threads);
    System system(make_brick_wall(30, 30));
    system.run_steps(10);
    return vertex_coordinates(system);
  };
  const auto one = run(1);
  const auto two = run(2);
  const auto three = run(3);
  const auto eight = run(8);
  omp_set_num_threads(threads_before);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);
  for (const auto* more : {&three, &eight}) {
    ASSERT_EQ(one.size(), more->size());
    EXPECT_EQ(std::memcmp(one.data(), more->data(), one.size() * sizeof(double)), 0);
  }
}

// The contact lists kept from step to step (a skin of a fifth of the contact distance) give
// the same run, to the last bit of every vertex, as lists made afresh every step (no skin):
// a static wall whose blocks barely move (the lists kept throughout), a dynamic packing of 36
// jittered quadrilaterals falling onto a base and onto each other for 80 ms, and a block
// dropped onto a base (the lists made again as they fall).
TEST(Verification, KeptContactListsGiveTheSameRunAsFreshOnes) {
  // A block dropped from 0.3 m onto a base: it falls some nine times the lists' reach before
  // it touches, so only lists made again on the way down can find the contact.
  ModelDefinition drop;
  drop.materials = {Material{2500.0, 1.0e10, 0.25}};
  drop.joint = {30.0, 0.0, 0.0};
  drop.settings.analysis = Analysis::dynamic;
  drop.settings.time_step = 1.0e-3;
  drop.blocks.push_back({make_rectangle(-1.0, -1.0, 3.0, 0.0), 0, true});
  drop.blocks.push_back({make_rectangle(0.5, 0.3, 1.5, 1.3), 0, false});
  const auto run = [](ModelDefinition model, int steps, double skin) {
    model.settings.contact_skin = skin;
    System system(std::move(model));
    system.run_steps(steps);
    return vertex_coordinates(system);
  };
  for (const auto& [model, steps] :
       {std::pair{make_brick_wall(6, 10), 20}, std::pair{make_random_packing(6), 80}, std::pair{drop, 400}}) {
    const auto kept = run(model, steps, -1.0);
    const auto fresh = run(model, steps, 0.0);
    ASSERT_EQ(kept.size(), fresh.size());
    EXPECT_EQ(std::memcmp(kept.data(), fresh.data(), kept.size() * sizeof(double)), 0) << steps << " steps";
  }
  // The dropped block has met the base, not passed through it: after 0.4 s the y of its
  // bottom vertices (block 1, vertices 0 and 1: coordinates 9 and 11) lies between the base's
  // top (y = 0) and 2 cm above, where free fall (0.3 m − ½ g t²) would put them 0.48 m below.
  const auto dropped = run(drop, 400, -1.0);
  for (int k : {9, 11}) {
    EXPECT_GT(dropped[k], -1e-3);
    EXPECT_LT(dropped[k], 0.02);
  }
}

}  // namespace
}  // namespace hydrodda::dda
