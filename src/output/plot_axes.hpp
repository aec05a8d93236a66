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

// Ticks of a log10 axis over [lo, hi] (both > 0): the decades inside, every n-th when there
// are many, so at most about 8 are labelled; 1, 2 and 5 times them when fewer than two
// decades lie inside, or the linear nice_ticks where those give fewer than two.
std::vector<double> log_ticks(double lo, double hi);

// A linear tick's label with as few decimals as the step between ticks needs.
std::string format_tick(double value, double step);

// Viridis colour map, t in [0, 1] → RGB in [0, 1].
std::array<double, 3> viridis(double t);

}  // namespace hydrodda::output
