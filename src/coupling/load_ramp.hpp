#pragma once
// The fluid load's ramp over a steady run's first passes (coupling.ramp_passes, coupling.ramp):
// pass k of n applies the load at r_k = min(1, k / n) of the way from where the ramp starts.
//   whole:        F_k = r_k F(p)                        (from no fluid load at all)
//   overpressure: F_k = F(p_s) + r_k (F(p) − F(p_s))    (from still water, p_s)
// F(p) the fluid forces of the pass's pressure p on the blocks as they are (faces (1 − α) p,
// inside −α ∇p: linear in p), p_s the still water's (hydro::DarcySolver::still_water_pressure),
// so that the overpressure ramp is the load of the pressure p_s + r_k (p − p_s): the water that
// floats a block keeps floating it while the excess over it rises. Under the overpressure
// convention with a head boundary the lowest, p_s = 0 and the two ramps are one.

#include <vector>

#include "geometry/point.hpp"

namespace hydrodda::coupling {

enum class RampedLoad { whole, overpressure };

// r_k = min(1, k / n) for pass k ≥ 1 of a ramp over n ≥ 1 passes.
double ramp_factor(int pass, int ramp_passes);

// Per block, per vertex: `forces` (the full load F(p)) becomes F_s + r (F − F_s), F_s
// `still` (F(p_s)); with `still` empty, r F (the whole load ramped). Throws
// std::invalid_argument when `still` is given and its shape is not that of `forces`.
void ramp_fluid_forces(std::vector<std::vector<geometry::Point>>& forces,
                       const std::vector<std::vector<geometry::Point>>& still, double factor);

}  // namespace hydrodda::coupling
