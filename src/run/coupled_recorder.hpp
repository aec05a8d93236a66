#pragma once
// What a coupled run writes of each pass, as the staggered loop's observer: history.csv's row,
// measure.csv's rows, fractures.csv's rows (with the bonds broken in the pass), the ParaView fields of the first pass, every
// output.every-th and the last, the checkpoint after every pass, and the wedge tips a round of
// mesh.refine_tips leaves to the next. Also what the end of a round reads of them: the
// history's rows, the fractures as the last pass left them, the summary of the model now.

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "coupling/pass_loop.hpp"
#include "fractures/fracture_results.hpp"
#include "fractures/tip_refinement.hpp"
#include "coupling/joint_aperture_laws.hpp"
#include "mesh/point_locator.hpp"
#include "output/checkpoint.hpp"
#include "output/csv_table.hpp"
#include "output/summary.hpp"
#include "run/bond_output.hpp"
#include "run/coupled_model.hpp"
#include "run/fracture_output.hpp"
#include "run/no_equilibrium.hpp"
#include "run/paraview_output.hpp"
#include "run/runs.hpp"

namespace hydrodda::run {

class CoupledRecorder final : public coupling::PassObserver {
 public:
  // A round of `model` on the scenario's mesh refined around `refined_tips`; `input_files` the
  // files the scenario names with their hashes, for the checkpoint. Writes nothing yet.
  CoupledRecorder(const RunContext& context, const CoupledModel& model, std::vector<fractures::RefinedTip> refined_tips,
                  std::vector<output::InputFile> input_files);
  CoupledRecorder(const CoupledRecorder&) = delete;
  CoupledRecorder& operator=(const CoupledRecorder&) = delete;

  // A new run: the scenario's text as scenario.toml.
  void start();
  // A run continued from `saved`: the model takes up its state, and the tables, series and
  // tips go on from its rows and files. Logs where it resumes.
  void resume_from(const output::RunCheckpoint& saved, CoupledModel& model);

  bool stop_requested() override { return context_.stop_requested(); }
  void after_pass(const coupling::PassReport& report) override;

  // The last pass's fields unless they are written already (a run that ended between its
  // output steps), with the checkpoint after them.
  void write_last_fields();
  // checkpoint.bin: the state the model continues from (CoupledModel::run_pass), which a
  // resumed run continues from too.
  void save_checkpoint();

  // Whether the last pass converged (a run resumed after its last pass: whether it had).
  bool converged() const { return converged_; }
  // The passes finished before the current load step's first (CoupledModel::load_step), from
  // the history's load_step column; 0 without load tables.
  int passes_before_load_step() const;
  // history.csv's header and rows, a resumed run's earlier passes included.
  const std::vector<std::string>& history_columns() const { return columns_; }
  const std::vector<std::vector<std::string>>& history_rows() const { return checkpoint_.history; }
  // The files of the ParaView series written so far (by iteration).
  const std::vector<int>& written_iterations() const { return checkpoint_.written_iterations; }
  // Of the last pass: its last DDA step was cut short, its blocks still moved after the settle
  // steps, and its shortest DDA step.
  bool last_pass_cut_short() const { return last_pass_cut_short_; }
  bool last_pass_moving() const { return last_pass_moving_; }
  double shortest_time_step() const { return shortest_time_step_; }

  // The fractures as the model's blocks are now (measured when not yet), or null for a
  // scenario that lists its blocks.
  const fractures::FractureState* measured_fractures();
  // The last state that held: the last pass after which no block was farther than its own size
  // (before the first: the blocks as built; resumed: the pass it resumed after), its open
  // fractures and the bonds broken by then.
  const HeldState& held_state() const { return held_; }
  // The fractures of the last finished pass, once measured (what the front end is shown).
  const std::optional<fractures::FractureState>& fracture_state() const { return fracture_state_; }
  // The cubic law's wedge tips in the fluid elements, the least resolved first (none without
  // fracture traces).
  std::vector<fractures::WedgeTipElement> find_tip_elements();
  // mesh.refine_tips: whether this round may end with tips to refine, and the tips unresolved
  // over its last passes (fractures::PassTips, newest last).
  bool follows_tips() const { return follow_tips_; }
  const std::deque<fractures::PassTips>& recent_tips() const { return recent_; }
  bool cubic_law() const { return cubic_law_; }
  // Per fluid element: the fracture whose flow zone holds it, or -1 (FractureMeter::flow_zones);
  // empty without fracture traces.
  const std::vector<int>& element_fractures() const { return flow_zones_.fracture; }
  const std::vector<fractures::RefinedTip>& refined_tips() const { return refined_tips_; }

  // summary.json of the model now: its blocks, flow, timings and fractures.
  output::RunSummary summary();
  // figures/cracks.* of a model with bonds (none without): its breaks listed so far, by pass,
  // `status` beside the pass (BondOutput::draw_figure).
  void draw_bond_figure(const std::string& status) const;

 private:
  void measure_fractures();
  void hold(int iteration);
  void add_history_row(const coupling::PassReport& r);
  void add_measures(const coupling::PassReport& r);
  void follow_tips(const coupling::PassReport& r);
  void log_pass(const coupling::PassReport& r) const;
  void write_fields(int iteration);
  const mesh::PointLocator& tip_locator();

  const RunContext& context_;
  const scenario::Scenario& scenario_;
  const CoupledModel& model_;
  std::vector<fractures::RefinedTip> refined_tips_;
  std::vector<std::string> columns_;
  output::CsvTable history_;
  output::CsvTable measure_;
  // What a checkpoint holds besides the engines' states; restored first when resuming.
  output::RunCheckpoint checkpoint_;
  ParaviewOutput paraview_;
  std::optional<fractures::FractureMeter> meter_;
  coupling::JointApertureLaws joint_laws_;  // by fracture id, the meter's
  fractures::FractureMeter::FlowZones flow_zones_;
  FractureOutput fractures_;
  std::optional<BondOutput> bonds_;  // a model with bonds: its breaks, by the pass they broke in
  std::optional<fractures::FractureState> fracture_state_;  // of the last finished pass
  HeldState held_;
  int last_written_ = 0;
  int broken_in_pass_ = 0;  // bonds broken in the last pass (history.csv's broken_bonds)
  bool converged_ = false;
  bool last_pass_cut_short_ = false;  // its last DDA step was cut short (PassReport::full_time_step)
  bool last_pass_moving_ = false;     // its blocks still moved after the settle steps (PassReport::at_rest)
  double shortest_time_step_ = 0.0;   // of the last pass
  // The cubic law's wedge tips (docs/coupling.md, "Wedge tips").
  bool cubic_law_ = false;
  double matrix_permeability_ = 0.0;
  // The fluid mesh's triangle finder for the tips' elements, made when first needed.
  std::optional<mesh::PointLocator> locator_;
  bool follow_tips_ = false;
  std::deque<fractures::PassTips> recent_;  // in the checkpoint, so that a resumed round refines the same
};

}  // namespace hydrodda::run
