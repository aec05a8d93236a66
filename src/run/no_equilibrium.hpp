#pragma once
// The breach named as such: a load under which no mechanical equilibrium exists (a layer lifts
// off its base, blocks are thrown) ends a run with RunStatus::no_equilibrium ("no equilibrium"
// in summary.json, exit 1), whose message names the load that drives it (the scenario's keys
// and values), the blocks that escape (ids and centroids) and the fractures open at the last
// state that held; summary.json, history.csv and the figures are of that state.

#include <span>
#include <string>
#include <vector>

#include "coupling/pass_report.hpp"
#include "dda/system.hpp"
#include "geometry/polygon.hpp"
#include "output/run_folder.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A block that escapes, where it is now.
struct EscapedBlock {
  coupling::EscapingBlock escape;
  geometry::Point centroid;
};

// The blocks of a DDA system farther from where they were built than their own size (the
// square root of their area), farthest first: in a static analysis, blocks in equilibrium move
// by their strains and by sliding to a new seat, not by their whole size.
std::vector<coupling::EscapingBlock> find_escaping_blocks(const dda::System& system);

// The escaping blocks with their centroids (`blocks`: every block's polygon now, by id).
std::vector<EscapedBlock> locate_escaping_blocks(std::span<const coupling::EscapingBlock> escaping,
                                                 std::span<const geometry::Polygon> blocks);

// The loads a scenario drives its blocks with, as its keys spell them: the flow boundaries
// that fix a head or pressure, the highest first ('flow.boundary "bottom" pressure =
// 2.16e+07 Pa, against "top" pressure = 6e+06 Pa'; several at the highest value joined by
// "and"), then mechanics.traction and mechanics.load entries. "gravity alone" without any.
std::string describe_driving_load(const scenario::Scenario& s);

// "no mechanical equilibrium under <load>: 2 block(s) moved farther than their own size ...:
// block 3 at (1.5, 2.4) (moved 1.2 m, size 1 m), ...; the last state that held (<held>) has
// fractures 2, 5 open; ...". `open_fractures`: ids open then (none known: `fractures_known`
// false). Long lists name five and go whole to escaping_blocks.txt in `folder`.
std::string describe_no_equilibrium(const scenario::Scenario& s, std::span<const EscapedBlock> blocks,
                                    const std::string& held, std::span<const int> open_fractures,
                                    bool fractures_known, const output::RunFolder& folder);

}  // namespace hydrodda::run
