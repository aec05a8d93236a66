#include "output/plot_axes.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace hydrodda::output {
namespace {

TEST(NiceTicks, StepsOfOneTwoFive) {
  EXPECT_EQ(nice_ticks(0.0, 5.0, 6), (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(nice_ticks(0.0, 20.0, 5), (std::vector<double>{0, 5, 10, 15, 20}));
  const auto t = nice_ticks(-0.03, 0.07, 5);
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(t[1] - t[0], 0.02, 1e-15);
}

// A count's bar (the pass a bond broke in, 1 to 3) is ticked at whole numbers where the nice
// ticks would put 1.5 and 2.5; over a wide range the nice step stands.
TEST(WholeNumberTicks, ACountIsTickedAtWholeNumbersOnly) {
  EXPECT_EQ(nice_ticks(1.0, 3.0, 6), (std::vector<double>{1, 1.5, 2, 2.5, 3}));
  EXPECT_EQ(whole_number_ticks(1.0, 3.0, 6), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(whole_number_ticks(0.0, 40.0, 6), (std::vector<double>{0, 10, 20, 30, 40}));
  EXPECT_EQ(whole_number_ticks(3.0, 47.0, 6), (std::vector<double>{10, 20, 30, 40}));
  EXPECT_EQ(whole_number_ticks(1.5, 2.5, 6), (std::vector<double>{2}));
  EXPECT_TRUE(whole_number_ticks(0.2, 0.8, 6).empty());
}

TEST(Viridis, EndsOfTheMap) {
  EXPECT_NEAR(viridis(0.0)[0], 0.267004, 1e-12);
  EXPECT_NEAR(viridis(1.0)[1], 0.906157, 1e-12);
  EXPECT_EQ(viridis(-1.0), viridis(0.0));
}

TEST(LogTicks, DecadesInsideTheRange) {
  EXPECT_EQ(log_ticks(1e-6, 1.0), (std::vector<double>{1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0}));
  // 21 decades: every third one, so at most 8 labels.
  EXPECT_EQ(log_ticks(1e-20, 10.0).size(), 8u);
  EXPECT_TRUE(log_ticks(-1.0, 10.0).empty());
  // Under a decade: 1, 2 and 5 times the powers of ten inside; fewer than two of those, the
  // linear ticks (steps of 1, 2 or 5 times a power of ten) inside the range.
  EXPECT_EQ(log_ticks(1.5, 30.0), (std::vector<double>{2.0, 5.0, 10.0, 20.0}));
  EXPECT_EQ(log_ticks(5.5, 9.9), (std::vector<double>{6.0, 7.0, 8.0, 9.0}));
}

TEST(FormatTick, DecimalsFollowTheStep) {
  EXPECT_EQ(format_tick(0.5, 0.5), "0.5");
  EXPECT_EQ(format_tick(10.0, 5.0), "10");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(1e-17, 0.1), "0.0");
}

// A log axis over a range under a decade falls back to linear ticks (1.6521, 1.6522, ...): their
// labels take the decimals of the step, where 6 significant digits printed "1.65217" at every
// tick of a breach curve that barely moved. Exact strings: the rule is formatting, not arithmetic.
TEST(LogTickLabels, EvenTicksOfANarrowRangeAreLabelledByTheirStep) {
  const std::vector<double> ticks = log_ticks(1.652165, 1.652175);
  ASSERT_GE(ticks.size(), 2u);
  const std::vector<std::string> labels = log_tick_labels(ticks);
  for (std::size_t i = 1; i < labels.size(); ++i) EXPECT_NE(labels[i], labels[i - 1]) << i;
  EXPECT_EQ(log_tick_labels({1.6521, 1.6522, 1.6523}), (std::vector<std::string>{"1.6521", "1.6522", "1.6523"}));
  // Decades stay empty (drawn as 10^e); the 1, 2, 5 ticks of a wider range keep their short form.
  EXPECT_EQ(log_tick_labels({0.2, 0.5, 1.0, 2.0}), (std::vector<std::string>{"0.2", "0.5", "", "2"}));
}

// Values that agree to 1e-6 of their size are one value (a breach curve's K_eff/K_m at every
// load, 1.6521680073 to 1.6521680123): the axis is drawn about it, not over its round-off.
TEST(FlatRange, ValuesAgreeingToAMillionthAreFlat) {
  EXPECT_TRUE(is_flat_range(1.6521680073837006, 1.6521680123449394));
  EXPECT_TRUE(is_flat_range(2.0, 2.0));
  EXPECT_FALSE(is_flat_range(2.4450, 2.4460));  // the 0.04% step of an opening flaw is drawn
  EXPECT_FALSE(is_flat_range(1.0, 1.0 + 2.0 * kFlatSpread));
}

// An axis's range: 4% of the span beyond the data each side; one value a unit about it; a
// quantity that cannot be negative only 4% of the top below 0. Exact arithmetic to 1e-12.
TEST(PaddedRange, AMarginEachSideAndNoNegativeUnitForAQuantityThatCannotBeNegative) {
  const auto expect_range = [](std::array<double, 2> got, double lo, double hi) {
    EXPECT_NEAR(got[0], lo, 1e-12);
    EXPECT_NEAR(got[1], hi, 1e-12);
  };
  expect_range(padded_range(0.0, 0.5, false), -0.02, 0.52);
  expect_range(padded_range(0.0, 0.0, false), -1.08, 1.08);  // ±1 at 0, then 4% of 2
  // Openings all 0 mm: 0 to 1.08, and below 0 only 4% of that.
  expect_range(padded_range(0.0, 0.0, false, true), -0.0432, 1.08);
  expect_range(padded_range(0.0, 0.5, false, true), -0.02, 0.52);  // the margin is under 4% of the top
  expect_range(padded_range(0.2, 0.4, false, true), 0.192, 0.408);
  expect_range(padded_range(-1.0, 1.0, false, true), -1.08, 1.08);  // data below 0: as without
  const std::array<double, 2> decade = padded_range(10.0, 10.0, true);  // a decade about 10
  EXPECT_NEAR(std::log10(decade[0]), 0.5 - 0.04, 1e-12);
  EXPECT_NEAR(std::log10(decade[1]), 1.5 + 0.04, 1e-12);
}

// One value in the middle of its range: ±10% of it (±1 at 0), or half a decade either side of
// its log10. Exact arithmetic to 1e-12 of the value.
TEST(OneValueRange, TheValueInTheMiddleOfAUnitAboutIt) {
  for (auto [value, half] : {std::pair{0.0, 1.0}, {3.0, 0.3}, {-2.472e7, 2.472e6}, {2.1281e7, 2.1281e6}}) {
    const std::array<double, 2> range = one_value_range(value, false);
    EXPECT_NEAR(range[0], value - half, 1e-12 * std::max(1.0, std::abs(value)));
    EXPECT_NEAR(range[1], value + half, 1e-12 * std::max(1.0, std::abs(value)));
  }
  const std::array<double, 2> decade = one_value_range(-17.0, true);  // permeability 1e-17 m²
  EXPECT_EQ(decade[0], -17.5);
  EXPECT_EQ(decade[1], -16.5);
}

}  // namespace
}  // namespace hydrodda::output
