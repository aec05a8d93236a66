#pragma once
// What a coupled run's messages say of how it ended: a loop that drifts,
// a failed pass, how far the regions' answers still moved, steps cut short.

#include <cstddef>
#include <string>
#include <vector>

#include "coupling/pass_report.hpp"
#include "coupling/staggered_loop.hpp"
#include "dda/system.hpp"
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

// The blocks that moved most in the last pass, which decide the displacement norm: whether it
// is the whole model that still moves or a few pieces. "in the last pass block 593 (0.0171 m²,
// every bond broken) at (6.12, 4.31) moved 0.00116 m, ...; every other block at most 1.1e-05 m,
// and without these 2 the displacement change would be 0.0061". Names up to three, those that
// moved more than twice as far as the rest ("" when no pass before the last is known).
std::string describe_last_pass_movers(const coupling::StaggeredLoop::PassMotion& motion, const dda::System& system);

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
