#pragma once
// The unit of a figure's time axis: the run's times are seconds (and stay so in every CSV
// table), but an axis running to 2e8 s reads better in years. One rule for every figure
// against time, so that they all agree.

#include <string>

#include "output/plot_line.hpp"

namespace hydrodda::output {

struct TimeUnit {
  std::string name;      // "s", "min", "h", "days", "years"
  double seconds = 1.0;  // its length; a year is 365.25 days (the Julian year)
};

// The largest unit of which `latest` seconds (the latest time plotted) hold at least 2, so that
// the axis runs from 0 past 2 of them: s below 2 min, then min below 2 h, h below 2 days,
// days below 2 years, years from there. Not a finite number, or ≤ 0: seconds.
TimeUnit time_unit_for(double latest);

// Puts a plot drawn against time in seconds into the unit of its latest time: each series'
// x, the range bars' and the crosses' x divided by the unit, x_label "time (<unit>)".
void put_time_axis(LinePlotSpec& plot);

}  // namespace hydrodda::output
