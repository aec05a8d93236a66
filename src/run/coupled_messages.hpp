#pragma once
// What a coupled run's messages say of how it ended: a loop that drifts,
// a failed pass, how far the regions' answers still moved, steps cut short.

#include <cstddef>
#include <string>
#include <vector>

#include "coupling/pass_report.hpp"
#include "geometry/point.hpp"
#include "output/run_folder.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Passes of an unconverged run over which its regions' answers are ranged.
constexpr std::size_t kRangePasses = 10;

// "block 12 moved 0.159 m (ux 0.001 m, uy 0.159 m), ...": the farthest five since the start,
// which show where and which way the load moves the blocks of a loop that drifts or diverges.
std::string describe_farthest(const std::vector<geometry::Point>& displacements);

// What a failed run's summary and figures hold: the last pass that finished, or nothing.
std::string describe_results_kept(int finished);

// A failed run's status line on its figures: "failed at pass 6: " and what failed, the
// message's first clause after "coupling iteration 6 failed: ".
std::string describe_failure_for_figures(int pass, const std::string& message);

// Sets each region's range of K_eff/K_m over the last passes (up to kRangePasses) of a run that
// did not converge, from history.csv's rows (`columns` its header): how far its answer still
// moved, and so what it is worth. Only passes after the first `ramp_passes` count: a pass
// solves its flow on the blocks the pass before left, so the first pass's flow is that of the
// blocks as built, under no fluid load at all, and the ramp's under part of it: no answer to
// the load asked. "K_eff/K_m of region 'seal' ranged from 4.98 to 5.56 (11%) ...", or ""
// without a region or such a pass.
std::string describe_last_passes(const std::vector<std::string>& columns,
                                 const std::vector<std::vector<std::string>>& rows, int ramp_passes,
                                 std::vector<output::RegionSummary>& regions);

// Why a pass whose norms are under the tolerance may still be short of equilibrium.
std::string describe_cut_steps(double shortest, double full);

}  // namespace hydrodda::run
