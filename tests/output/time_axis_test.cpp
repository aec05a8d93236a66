// The unit of a time axis: the largest of s, min, h, days and years (365.25 days, the Julian
// year) of which the latest time plotted holds at least 2. Exact identities: each boundary is
// 2 units, a span just below it keeps the smaller unit.

#include "output/time_axis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace hydrodda::output {
namespace {

TEST(TimeUnit, EachUnitFromTwoOfItOn) {
  const double minute = 60.0, hour = 3600.0, day = 86400.0, year = 365.25 * day;
  const struct {
    double latest;
    std::string unit;
  } cases[] = {{0.0, "s"},
               {1.0, "s"},
               {std::nextafter(2.0 * minute, 0.0), "s"},
               {2.0 * minute, "min"},
               {std::nextafter(2.0 * hour, 0.0), "min"},
               {2.0 * hour, "h"},
               {std::nextafter(2.0 * day, 0.0), "h"},
               {2.0 * day, "days"},
               {std::nextafter(2.0 * year, 0.0), "days"},
               {2.0 * year, "years"},
               {2.0e8, "years"},
               {-1.0, "s"},
               {std::numeric_limits<double>::infinity(), "s"},
               {std::numeric_limits<double>::quiet_NaN(), "s"}};
  for (const auto& c : cases) EXPECT_EQ(time_unit_for(c.latest).name, c.unit) << c.latest << " s";
  EXPECT_EQ(time_unit_for(2.0 * year).seconds, 31557600.0);  // 365.25 × 86,400 s
  EXPECT_EQ(time_unit_for(2.0 * day).seconds, day);
}

TEST(TimeAxis, ThePlotIsPutInTheUnitOfItsLatestTime) {
  LinePlotSpec plot;
  plot.x_label = "time (s)";
  plot.series = {{"a", {0.0, 3.0 * 86400.0}, {1.0, 2.0}, {}}, {"b", {86400.0}, {5.0}, {}}};
  plot.range_bars = {{0, 43200.0, 1.0, 2.0}};
  plot.marks_x = {172800.0};
  put_time_axis(plot);
  EXPECT_EQ(plot.x_label, "time (days)");
  EXPECT_EQ(plot.series[0].x, (std::vector<double>{0.0, 3.0}));
  EXPECT_EQ(plot.series[1].x, (std::vector<double>{1.0}));
  EXPECT_EQ(plot.series[0].y, (std::vector<double>{1.0, 2.0}));  // the values untouched
  EXPECT_EQ(plot.range_bars[0].x, 0.5);
  EXPECT_EQ(plot.marks_x, (std::vector<double>{2.0}));
}

TEST(TimeAxis, SecondsStayAsTheyAre) {
  LinePlotSpec plot;
  plot.series = {{"a", {0.1, 100.0}, {1.0, 2.0}, {}}};
  put_time_axis(plot);
  EXPECT_EQ(plot.x_label, "time (s)");
  EXPECT_EQ(plot.series[0].x, (std::vector<double>{0.1, 100.0}));
}

}  // namespace
}  // namespace hydrodda::output
