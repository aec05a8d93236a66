#pragma once
// The run folder's record of bonds (docs/output.md, "Bonds"): each bond that broke as a new
// fracture in fractures.csv, and bonds.pvd with bonds_NNNN.vtu, every bonded face as a line
// with its state. A mechanics run records its breaks by DDA step and time (s), a coupled run by
// the coupling iteration (pass) whose DDA steps broke them, a coupled transient run by the time
// step whose iterations broke them and its end time (s).

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "output/pvd_series.hpp"
#include "output/run_folder.hpp"
#include "run/fracture_output.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// What a break is recorded at: the time (s) of the DDA step it broke in, the pass, the time
// step of a coupled transient run (its row at the step, at the step's end time in s), or the
// load of a breach search's step that held (its row at the step, at the load).
enum class BondClock { time, pass, time_step, load };

// fractures.csv's row of a bond's break recorded at `time`: its fracture id the bond's after the
// `trace_count` traces', its type the name of its joint type ("joint" for [joint]).
BrokenBondRow broken_bond_row(const scenario::Scenario& scenario, const dda::System& system,
                              const dda::BondBreak& bond_break, int trace_count, double time);

class BondOutput {
 public:
  // `trace_count`: the fractures the traces number, after which the broken bonds are numbered.
  // The bonds `system` holds broken and not among its breaks started broken (a tessellation's
  // cracks).
  BondOutput(const output::RunFolder& folder, const scenario::Scenario& scenario, const dda::System& system,
             int trace_count, BondClock clock = BondClock::time);

  // The bonds that broke since the last call, as rows of fractures.csv at step (or pass) `step`,
  // their `time` each break's own step's end (BondClock::time) or the pass's, `pass_time`
  // (BondClock::pass, which records the pass as when it broke; BondClock::time_step, the time
  // step's end, and BondClock::load, the step's load, which record that as when it broke); how many. Only breaks listed
  // here are written or drawn as broken: those of a step that failed never are.
  int add_breaks(long long step, const dda::System& system, FractureOutput& fractures, double pass_time = 0.0);
  // A resumed coupled run: the breaks `system` holds are those of its earlier passes,
  // `broken_per_pass[p]` of them in pass p + 1, in order (history.csv's broken_bonds); bonds.pvd
  // lists again the files of the passes `written` that are still there.
  void continue_from(const dda::System& system, std::span<const int> broken_per_pass, std::span<const int> written);
  // A resumed coupled transient run: `broken_per_step[k]` of the breaks `system` holds in time
  // step k (history.csv's broken_bonds, the row of t = 0 first), each broken at `step_times[k]`;
  // bonds.pvd lists again the files bonds_NNNN.vtu still there, at `written_times`[NNNN].
  void continue_in_time(const dda::System& system, std::span<const int> broken_per_step,
                        std::span<const double> step_times, std::span<const double> written_times);
  // bonds_NNNN.vtu, listed in bonds.pvd at `time`: each bond's face (the first sub-block's edge)
  // with `bond` (its id), `broken` (0 or 1), `mode` (0 intact, 1 tension, 2 shear) and
  // `broken_at` (the time it broke, or its pass; −1 intact or broken from the start).
  void write_series(int step, double time, const dda::System& system);
  // figures/cracks.* for each format output.figures asks for: the sub-blocks as they are, each
  // broken bond's face coloured by the time (or pass) it broke, intact ones thin and grey; bonds
  // broken in a step that failed are not drawn as broken, and the subtitle says how many.
  void draw_figure(const scenario::Scenario& scenario, const dda::System& system, const std::string& when) const;

 private:
  const output::RunFolder& folder_;
  BondClock clock_;
  std::vector<std::string> type_names_;  // per bond
  std::vector<char> broken_;             // per bond: broken from the start or in a listed break
  std::vector<double> broken_at_;        // per bond: when its listed break was (−1: none)
  std::vector<char> mode_;               // per bond: 0 intact or from the start, 1 tension, 2 shear
  int trace_count_ = 0;
  std::size_t listed_ = 0;  // breaks already in fractures.csv
  std::optional<output::PvdSeries> series_;

  // The first breaks `system` holds, `broken_per_group[g]` in group g (a pass or a time step),
  // marked broken at `when(g)`.
  template <class When>
  void list_earlier_breaks(const dda::System& system, std::span<const int> broken_per_group, When when);
};

}  // namespace hydrodda::run
