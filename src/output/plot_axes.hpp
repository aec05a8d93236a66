#pragma once
// Axis ticks and the colour map shared by every figure (field maps and line plots).

#include <array>
#include <string>
#include <vector>

namespace hydrodda::output {

// "Nice" step near (hi - lo) / count: 1, 2, 5 or 10 × 10^k, the smallest at or above it.
// Heckbert, "Nice numbers for graph labels", Graphics Gems (1990).
double nice_step(double lo, double hi, int count);

// "Nice" tick values covering [lo, hi] with about `count` ticks (1, 2, 5 × 10^k steps).
std::vector<double> nice_ticks(double lo, double hi, int count);

// The same for a count (passes, steps): whole numbers only, the step at least 1.
std::vector<double> whole_number_ticks(double lo, double hi, int count);

// Ticks of a log10 axis over [lo, hi] (both > 0): the decades inside, every n-th when there
// are many, so at most about 8 are labelled; 1, 2 and 5 times them when fewer than two
// decades lie inside, or the linear nice_ticks where those give fewer than two.
std::vector<double> log_ticks(double lo, double hi);

// A linear tick's label with as few decimals as the step between ticks needs.
std::string format_tick(double value, double step);

// The labels of log_ticks: empty for a power of ten (drawn as 10^e); the others with as many
// decimals as the least gap between neighbouring ticks needs, so that the linear ticks of a
// narrow range (1.6521, 1.6522, ...) never print alike, as 6 significant digits would.
std::vector<std::string> log_tick_labels(const std::vector<double>& ticks);

// Values over [lo, hi] that agree to kFlatSpread of the larger's size: one value and its
// round-off, which an axis drawn over them alone would magnify into a slope.
inline constexpr double kFlatSpread = 1e-6;
bool is_flat_range(double lo, double hi);

// The range a line plot's axis spans for data over [lo, hi]: a margin of 4% of the span (of its
// decades on a log axis) on each side, so that markers at the ends are not cut by the frame; one
// value gets a unit about it (a decade on a log axis; ±10% of it, or ±1 at 0, on a linear one).
// `at_least_zero` (a linear quantity that cannot be negative, data ≥ 0): below 0 the margin is
// 4% of the top, not a unit, so that an opening of 0 mm is not drawn on an axis down to −1 mm.
std::array<double, 2> padded_range(double lo, double hi, bool log_axis, bool at_least_zero = false);

// The range an axis or a colour bar gives one value, with the value in its middle: half a decade
// either side on a log axis (the value and the range as log10), ±10% of it (±1 at 0) on a linear one.
std::array<double, 2> one_value_range(double value, bool log_axis);

// Viridis colour map, t in [0, 1] → RGB in [0, 1].
std::array<double, 3> viridis(double t);

}  // namespace hydrodda::output
