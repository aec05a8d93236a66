#include "output/plot_axes.hpp"

#include <gtest/gtest.h>

namespace hydrodda::output {
namespace {

TEST(NiceTicks, StepsOfOneTwoFive) {
  EXPECT_EQ(nice_ticks(0.0, 5.0, 6), (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(nice_ticks(0.0, 20.0, 5), (std::vector<double>{0, 5, 10, 15, 20}));
  const auto t = nice_ticks(-0.03, 0.07, 5);
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(t[1] - t[0], 0.02, 1e-15);
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

}  // namespace
}  // namespace hydrodda::output
