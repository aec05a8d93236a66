#pragma once
// The wedge tips a coupled run refines its fluid mesh around (mesh.refine_tips; docs/coupling.md,
// "Refined by the run"): which tips a round leaves to the next, and how a checkpoint holds them
// (run/scenario_fractures.hpp makes them [[mesh.refine]] points).

#include <cstddef>
#include <deque>
#include <functional>
#include <span>
#include <vector>

#include "fractures/fracture_results.hpp"
#include "fractures/refined_tip.hpp"

namespace hydrodda::fractures {

// The round a run with these tips refined is in: 1 on the scenario's own mesh, one more for
// each round that added tips.
int current_round(const std::vector<RefinedTip>& tips);

// A point at s*/4 of every tip the mesh does not resolve (find_wedge_tip_elements: least
// resolved first), of the radius `refine_radius` gives for its size (mesh.refine's default),
// found in `round`; none when the least resolved is resolved.
std::vector<RefinedTip> tips_to_refine(std::span<const WedgeTipElement> tips, int round,
                                       const std::function<double(double size)>& refine_radius);
// A round that does not converge stops in one of the states it swings between, and the tips
// unresolved in that one state hang on the pass it stopped at (the cubic Fig. 9 flexure at
// 20 m refined other tips after each acceleration). Such a round refines the tips of its last
// kTipPasses passes.
inline constexpr std::size_t kTipPasses = 10;
struct PassTips {
  int iteration = 0;
  std::vector<RefinedTip> tips;  // tips_to_refine of that pass
};

// One point per tip over the passes (oldest first), the newest pass's first. A tip within
// 4 × the smaller size (the smaller s*) of a point already taken is that point's, which keeps
// the finer size: the element there is then at most size + 0.2 × 4 size = 0.45 s* across (the
// size grows by a fifth of the distance), resolving either.
std::vector<RefinedTip> merge_tips(const std::deque<PassTips>& passes);

// As a checkpoint holds them (output::RunCheckpoint::refined_tips, five numbers a tip:
// x, y, size, radius, round; recent_tips, each pass as its iteration, its tip count and five
// numbers a tip, a pass with none kept too) and back.
std::vector<double> write_refined_tips(const std::vector<RefinedTip>& tips);
std::vector<RefinedTip> read_refined_tips(const std::vector<double>& numbers);
std::vector<double> write_recent_tips(const std::deque<PassTips>& passes);
std::deque<PassTips> read_recent_tips(const std::vector<double>& numbers);

}  // namespace hydrodda::fractures
