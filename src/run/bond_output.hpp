#pragma once
// The run folder's record of bonds (docs/output.md, "Bonds"): each bond that broke as a new
// fracture in fractures.csv, and bonds.pvd with bonds_NNNN.vtu, every bonded face as a line
// with its state.

#include <optional>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "output/pvd_series.hpp"
#include "output/run_folder.hpp"
#include "run/fracture_output.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

class BondOutput {
 public:
  // `trace_count`: the fractures the traces number, after which the broken bonds are numbered.
  BondOutput(const output::RunFolder& folder, const scenario::Scenario& scenario, const dda::System& system,
             int trace_count);

  // The bonds that broke since the last call, as rows of fractures.csv at step `step`; how many.
  int add_breaks(long long step, const dda::System& system, FractureOutput& fractures);
  // bonds_NNNN.vtu, listed in bonds.pvd at `time`: each bond's face (the first sub-block's edge)
  // with `bond` (its id), `broken` (0 or 1), `mode` (0 intact, 1 tension, 2 shear) and
  // `broken_at` (the time it broke; −1 intact).
  void write_series(int step, double time, const dda::System& system);
  // figures/cracks.* for each format output.figures asks for: the sub-blocks as they are, each
  // broken bond's face coloured by the time it broke, intact ones thin and grey.
  void draw_figure(const scenario::Scenario& scenario, const dda::System& system, const std::string& when) const;

 private:
  const output::RunFolder& folder_;
  std::vector<std::string> type_names_;  // per bond
  int trace_count_ = 0;
  std::size_t listed_ = 0;  // breaks already in fractures.csv
  std::optional<output::PvdSeries> series_;
};

}  // namespace hydrodda::run
