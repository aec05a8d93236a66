#pragma once
// What `hydrodda breach` writes into its folder, step by step (docs/breach.md): breach.csv,
// steps/step_NNN.json, the ParaView series of the held states (time = the load), fractures.csv
// (each held state's fractures, and a model with bonds' breaks as bond rows, as a run writes
// them), and at the end breach.json, the curves and the figures of the last state that held
// (figures/cracks.* of a model with bonds).

#include <optional>
#include <string>
#include <vector>

#include "breach/coupled_stepper.hpp"
#include "breach/load_search.hpp"
#include "output/csv_table.hpp"
#include "output/run_folder.hpp"
#include "run/bond_output.hpp"
#include "run/fracture_output.hpp"
#include "run/paraview_output.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::breach {

// What a state that held measured, as breach.csv and the curves hold it.
struct HeldState {
  double load = 0.0;
  bool beyond_limit = false;
  bool unsettled = false;  // held, unsettled: its K_eff/K_m is `ranges`, not `conductivity`
  std::vector<std::optional<double>> conductivity;  // K_eff/K_m per flow region (none when unsettled)
  std::vector<std::optional<ValueRange>> ranges;    // per flow region, over the last passes when unsettled
  double largest_opening = 0.0;                     // m, over the fractures
  std::vector<int> open_fractures;                  // ids
  std::optional<double> limit_value;
  std::vector<int> broken_bonds;  // the bonds its step broke, in the order they broke (a model with bonds)
  int broken_bonds_total = 0;     // broken along the path up to it (not the cracks broken from the start)
};

class BreachFiles {
 public:
  // `mechanics`: the model's blocks as built (their bonds, if any, the cracks broken from the start).
  BreachFiles(const output::RunFolder& folder, const scenario::Scenario& scenario, std::string key,
              std::optional<Limit> limit, const dda::System& mechanics);

  void write_scenario(const std::string& text) const;
  // A step's row (breach.csv written again), and for a state that held its summary and fields.
  // `kept`: the search goes on from its state (it holds), so its bonds' breaks are recorded.
  void add_step(const SearchStep& step, const CoupledStepper& stepper, bool kept);
  // The figures of the last state that held (the model at it), and last_held.json.
  void write_last_held(double load, const CoupledStepper& stepper);
  // breach.json and the curves.
  void finish(const SearchResult& result, const std::string& verdict, const SearchSettings& settings);
  // Of the states that held unsettled, the widest spread of a region's K_eff/K_m ((largest −
  // least) / largest) and its load; none when no state held unsettled.
  std::optional<UnsettledSpread> worst_unsettled_spread() const;

 private:
  HeldState measure(const SearchStep& step, const output::RunSummary& summary,
                    const std::vector<std::optional<ValueRange>>& ranges) const;
  std::vector<std::string> row_of(const SearchStep& step, const std::optional<HeldState>& held) const;
  void draw_curves(const std::string& format) const;
  // fractures.csv's rows of a state that held (its bonds' breaks first) and bonds_NNNN.vtu.
  void record_fractures(const SearchStep& step, const CoupledStepper& stepper, bool kept, HeldState& held);

  const output::RunFolder& folder_;
  const scenario::Scenario& scenario_;
  std::string key_;
  std::optional<Limit> limit_;
  std::vector<std::string> regions_;
  output::CsvTable table_;
  run::ParaviewOutput paraview_;
  run::FractureOutput fractures_;
  std::optional<run::BondOutput> bonds_;  // a model with bonds: its breaks, by the step that held
  int bonds_listed_ = 0;                  // the breaks recorded so far (those of steps that held)
  std::vector<SearchStep> steps_;
  std::vector<HeldState> held_;  // in the order tried
};

}  // namespace hydrodda::breach
