#pragma once
// Aitken's Δ² relaxation of a fixed-point iteration x = G(x), for vectors (Irons & Tuck 1969;
// Küttler & Wall 2008, Comput. Mech. 43, eq. 44): x ← x + ω (G(x) − x), ω following the last
// two updates r = G(x) − x:
//   ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖²,  clipped to [kMinRelaxation, 1]
// (the secant estimate of the step that would land on the fixed point along r). An iteration
// whose updates flip sign pass after pass (cycling between two states) gets ω near 1/2 and
// settles; one whose updates keep their direction keeps ω near 1.

#include <span>

namespace hydrodda::numerics {

// The smallest ω Aitken's rule gives: a loop is never frozen in place.
inline constexpr double kMinAitkenRelaxation = 0.05;

// ω_k from ω_{k−1} (`relaxation`) and the last two updates, of one size; ω_{k−1} itself when
// the two updates are the same (nothing to take a secant from).
double aitken_relaxation(double relaxation, std::span<const double> previous_update, std::span<const double> update);

}  // namespace hydrodda::numerics
