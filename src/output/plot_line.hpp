#pragma once
// Line plots: convergence histories (changes on a log axis against iteration) and the
// responses of parameter sweeps, several series with a legend, horizontal reference lines
// (a tolerance, a baseline). PNG, SVG or PDF by file extension.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hydrodda::output {

struct LineSeries {
  std::string name;  // legend entry; unnamed series are left out of the legend
  std::vector<double> x, y;
  // Per point (empty: none): drawn as a hollow marker and left off the line, for a value that
  // is not a result, such as a sweep case that did not converge.
  std::vector<bool> open;
};

struct ReferenceLine {
  std::string name;  // written above the line at its right end
  double y = 0.0;
};

// A value known only as a range at one x, drawn as a capped vertical bar from low to high in
// its series' colour, on no line: an answer that still swung from pass to pass.
struct RangeBar {
  std::size_t series = 0;  // index into LinePlotSpec::series, for the colour
  double x = 0.0, low = 0.0, high = 0.0;
};

struct LinePlotSpec {
  std::string title;    // shrunk to fit the page when long
  std::string warning;  // in red under the title, e.g. "NOT CONVERGED"
  std::string x_label, y_label;
  bool x_log = false, y_log = false;
  // A quantity that cannot be negative (an opening): the y axis reaches below 0 only by a
  // margin for the markers, not by a unit about a single 0 (padded_range, plot_axes.hpp).
  bool y_at_least_zero = false;
  std::vector<LineSeries> series;
  std::vector<ReferenceLine> references;
  std::string open_label;  // the legend entry of the hollow markers, shown when some point is open
  std::vector<RangeBar> range_bars;
  std::string range_label;  // the legend entry of the range bars, shown when there is one
  // Points with no value (a sweep case that failed): a red cross at each x on the frame's
  // bottom edge, with the legend entry `marks_label` when there is one.
  std::vector<double> marks_x;
  std::string marks_label;
  double width = 460.0, height = 320.0;  // points
};

// On a log axis non-positive values are skipped (the line breaks there). Throws
// std::invalid_argument naming the path if a series' x and y (or a non-empty open) differ in length or nothing is
// plottable (crosses alone are: the y axis then spans 0 to 1), std::runtime_error naming the
// path if the file cannot be written.
void render_line_plot(const std::filesystem::path& path, const LinePlotSpec& spec);

}  // namespace hydrodda::output
