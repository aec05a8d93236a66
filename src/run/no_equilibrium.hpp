#pragma once
// The breach named as such: a load under which no mechanical equilibrium exists (a layer lifts
// off its base, blocks are thrown) ends a run with RunStatus::no_equilibrium ("no equilibrium"
// in summary.json, exit 1), whose message names the load that drives it (the scenario's keys
// and values), the blocks that escape (ids and centroids), and the fractures open and the bonds
// broken at the last state that held (summary.json's `last_held`); summary.json, history.csv
// and the figures are of the last state that finished.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "coupling/pass_report.hpp"
#include "dda/system.hpp"
#include "fractures/fracture_results.hpp"
#include "geometry/polygon.hpp"
#include "output/run_folder.hpp"
#include "output/summary.hpp"
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
// "and"), then mechanics.traction and mechanics.load entries. "gravity alone" without any. A
// table is named by the highest value it reaches, or, given `time` (a run in time), by its value
// then, the highest then first.
std::string describe_driving_load(const scenario::Scenario& s, std::optional<double> time = std::nullopt);

// The last state that held: the last DDA step (or coupling iteration) after which no block was
// farther than its own size, and what it held of the fractures: those open then (measured
// over the scenario's traces; none to measure: `fractures_known` false) and, on a model with
// bonds, how many had broken by then (the cracks broken from the start not counted).
struct HeldState {
  std::string name = "the blocks as built";  // "DDA step 28", "coupling iteration 3"
  long long step = 0;                         // the step or pass; 0: the blocks as built
  bool fractures_known = false;
  std::vector<int> open_fractures;
  std::optional<int> broken_bonds;            // a model with bonds
  int broken_bonds_later = 0;                 // broken after it, by the state the run kept
};

// summary.json's `last_held`, as the message tells it.
output::LastHeldSummary summarise_held_state(const HeldState& held);

// The ids of the fractures open (over at least 9/10 of their length) in `state`; none measured
// (a scenario without traces) is not known.
void take_open_fractures(const fractures::FractureState& state, HeldState& held);

// "no mechanical equilibrium under <load>: 2 block(s) moved farther than their own size ...:
// block 3 at (1.5, 2.4) (moved 1.2 m, size 1 m), ...; in the last state that held (<held>)
// fractures 2, 5 were open and 14 bonds had broken, 3 more after it; ... (summary.json, history.csv and the
// figures are of <kept>)". `kept`: the state the run folder holds, the last that finished.
// Long lists name five and go whole to escaping_blocks.txt in `folder` (none: a model stepped
// by hand, which writes no file; the line says how many more). `load_time`: a run in time names
// its loads' values then, "under <load> (the loads at t = 5 s)".
std::string describe_no_equilibrium(const scenario::Scenario& s, std::span<const EscapedBlock> blocks,
                                    const HeldState& held, const std::string& kept, const output::RunFolder* folder,
                                    std::optional<double> load_time = std::nullopt);

}  // namespace hydrodda::run
