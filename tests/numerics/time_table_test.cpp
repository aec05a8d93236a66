#include "numerics/time_table.hpp"

#include <gtest/gtest.h>

#include <array>

namespace hydrodda::numerics {
namespace {

// value(t) is the linear interpolant of the rows, held beyond them (time_table.hpp): exact
// identities, checked to 1e-15 relative.
TEST(TimeTable, InterpolatesLinearlyBetweenRowsAndHoldsBeyondThem) {
  const TimeTable head({0.0, 10.0, 30.0}, {100.0, 2500.0, 500.0});
  EXPECT_EQ(head.value(-5.0), 100.0);
  EXPECT_EQ(head.value(0.0), 100.0);
  EXPECT_NEAR(head.value(2.5), 100.0 + 0.25 * 2400.0, 1e-12);
  EXPECT_EQ(head.value(10.0), 2500.0);
  EXPECT_NEAR(head.value(25.0), 2500.0 - 0.75 * 2000.0, 1e-12);
  EXPECT_EQ(head.value(30.0), 500.0);
  EXPECT_EQ(head.value(1.0e9), 500.0);
  EXPECT_EQ(head.end_time(), 30.0);
}

TEST(TimeTable, AConstantIsItsNumberAtEveryTime) {
  const TimeTable c = 0.1 + 0.2;  // a number that is not exact in binary
  EXPECT_TRUE(c.is_constant());
  for (double t : {-1.0, 0.0, 1.0e30}) EXPECT_EQ(c.value(t), 0.1 + 0.2);
  const std::array<double, 2> force{3.0, -4.0};
  const TimeTable f = TimeTable::constant(force);
  EXPECT_EQ(f.columns(), 2u);
  EXPECT_EQ(f.value(7.0, 1), -4.0);
}

TEST(TimeTable, ColumnsShareTheirTimes) {
  const TimeTable force({0.0, 2.0}, {0.0, 10.0, 4.0, -6.0}, 2);
  EXPECT_NEAR(force.value(0.5, 0), 1.0, 1e-15);
  EXPECT_NEAR(force.value(0.5, 1), 6.0, 1e-15);
}

TEST(TimeTable, RefusesFewerThanTwoRowsTimesThatDoNotIncreaseAndRaggedRows) {
  EXPECT_THROW(TimeTable({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(TimeTable({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(TimeTable({2.0, 1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(TimeTable({0.0, 1.0}, {1.0, 2.0, 3.0}, 2), std::invalid_argument);
}

// A mix of two piecewise-linear paths is linear between the union of their times, so the table
// on that union equals a(t) + s (b(t) − a(t)) everywhere (to round-off, 1e-12).
TEST(TimeTable, MixesTwoPathsExactlyOnTheUnionOfTheirTimes) {
  const TimeTable a({0.0, 4.0}, {0.0, 8.0});
  const TimeTable b({1.0, 2.0, 3.0}, {5.0, -5.0, 5.0});
  const TimeTable c = TimeTable::between(a, b, 0.75);
  EXPECT_EQ(c.times(), (std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0}));
  for (double t = -1.0; t <= 5.0; t += 0.125) EXPECT_NEAR(c.value(t), 0.25 * a.value(t) + 0.75 * b.value(t), 1e-12) << t;
  const TimeTable k = TimeTable::between(TimeTable(2.0), TimeTable(6.0), 0.5);
  EXPECT_TRUE(k.is_constant());
  EXPECT_EQ(k.value(3.0), 4.0);
  const TimeTable mixed = TimeTable::between(TimeTable(2.0), a, 0.5);
  EXPECT_EQ(mixed.times(), a.times());
  EXPECT_EQ(mixed.value(2.0), 3.0);
}

}  // namespace
}  // namespace hydrodda::numerics
