#include "output/time_axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hydrodda::output {

TimeUnit time_unit_for(double latest) {
  constexpr double day = 86400.0;
  static const std::array<TimeUnit, 5> units{{{"s", 1.0},
                                              {"min", 60.0},
                                              {"h", 3600.0},
                                              {"days", day},
                                              {"years", 365.25 * day}}};
  TimeUnit chosen = units[0];
  if (!std::isfinite(latest)) return chosen;
  for (const TimeUnit& unit : units)
    if (latest >= 2.0 * unit.seconds) chosen = unit;
  return chosen;
}

void put_time_axis(LinePlotSpec& plot) {
  double latest = 0.0;
  for (const LineSeries& s : plot.series)
    for (double x : s.x)
      if (std::isfinite(x)) latest = std::max(latest, std::abs(x));
  for (const RangeBar& bar : plot.range_bars) latest = std::max(latest, std::abs(bar.x));
  for (double x : plot.marks_x) latest = std::max(latest, std::abs(x));
  const TimeUnit unit = time_unit_for(latest);
  plot.x_label = "time (" + unit.name + ")";
  if (unit.seconds == 1.0) return;  // seconds: the values as they are, to the last bit
  for (LineSeries& s : plot.series)
    for (double& x : s.x) x /= unit.seconds;
  for (RangeBar& bar : plot.range_bars) bar.x /= unit.seconds;
  for (double& x : plot.marks_x) x /= unit.seconds;
}

}  // namespace hydrodda::output
