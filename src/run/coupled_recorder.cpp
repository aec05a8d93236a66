#include "run/coupled_recorder.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <utility>

#include "run/coupled_messages.hpp"
#include "run/model_building.hpp"
#include "run/scenario_fractures.hpp"

#include "scenario/load_times.hpp"

namespace hydrodda::run {

namespace {

using output::CsvTable;

// history.csv's header: the pass's norms and fields, each boundary's flow, each region's flow
// and conductivity, then the loop's own measures.
std::vector<std::string> make_history_columns(const scenario::Scenario& s, bool bonded) {
  std::vector<std::string> columns{"iteration", "time", "head_change", "displacement_change",
                                   "largest_opening", "mean_porosity", "max_permeability"};
  for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) columns.push_back("flow_" + bc.name);
  for (const scenario::FlowRegion& r : s.flow->regions) {
    columns.push_back("region_flow_" + r.name);
    columns.push_back("region_conductivity_" + r.name);
  }
  columns.insert(columns.end(), {"head_change_two_passes", "relaxation", "load_factor", "contact_state_changes",
                                 "joint_crossings_switched", "fluid_load_change", "most_open_close_iterations",
                                 "step_cuts", "at_rest"});
  // A model with bonds: the bonds broken in the pass (none without, so that such a run's
  // history is as it was).
  if (bonded) columns.push_back("broken_bonds");
  // Loads over time: the load step each pass ran at and its time (none when every load is a
  // constant, so that such a run's history is as it was).
  if (!scenario::find_load_times(s).empty()) columns.insert(columns.end(), {"load_step", "load_time"});
  return columns;
}

ProgressReport report_pass(const coupling::PassReport& r) {
  ProgressReport report;
  report.kind = ProgressReport::Kind::coupling_pass;
  report.count = r.iteration;
  report.time = r.time;
  report.head_change = r.head_change;
  report.displacement_change = r.displacement_change;
  report.message = fmt::format("iteration {}: head change {:.2e}, displacement change {:.2e}", r.iteration,
                               r.head_change, r.displacement_change);
  // The first pass run again ramped (coupling::LoopSettings::ramp_if_moved): say why.
  if (r.moved_at_once > 0.0)
    report.message += fmt::format(" (the whole load at once moved the blocks {:.3g} m from their in-situ stress: "
                                  "the pass was run again with the load raised over its first passes, "
                                  "coupling.ramp_passes)",
                                  r.moved_at_once);
  return report;
}

// The largest opening of any fracture (fractures.csv's max_aperture), 0 when all are closed.
double find_largest_opening(const fractures::FractureState& state) {
  double largest = 0.0;
  for (const fractures::FractureResult& f : state.fractures) largest = std::max(largest, f.max_aperture);
  return largest;
}

}  // namespace

CoupledRecorder::CoupledRecorder(const RunContext& context, const CoupledModel& model,
                                 std::vector<fractures::RefinedTip> refined_tips,
                                 std::vector<output::InputFile> input_files)
    : context_(context),
      scenario_(context.scenario),
      model_(model),
      refined_tips_(std::move(refined_tips)),
      columns_(make_history_columns(context.scenario, model.mechanics().bond_count() > 0)),
      history_(columns_),
      measure_({"iteration", "time", "name", "x", "y", "ux", "uy"}),
      paraview_(context.folder, context.scenario.output.fields),
      meter_(make_fracture_meter(context.scenario)),
      joint_laws_(meter_ ? make_joint_aperture_laws(context.scenario, meter_->layout().traces)
                         : coupling::JointApertureLaws{}),
      flow_zones_(meter_ ? meter_->flow_zones(model.mesh()) : fractures::FractureMeter::FlowZones{}),
      fractures_(context.folder, /*with_flow=*/true, fracture_type_names(context.scenario)) {
  const scenario::Scenario& s = scenario_;
  checkpoint_.scenario_hash = output::hash_text(context.scenario_text);
  checkpoint_.scenario_file = std::filesystem::absolute(s.file).string();
  checkpoint_.input_files = std::move(input_files);
  cubic_law_ = s.flow->permeability_law == coupling::PermeabilityLaw::cubic;
  matrix_permeability_ = make_permeability_model(s).matrix_permeability();
  follow_tips_ = meter_ && s.mesh->refine_tips && fractures::current_round(refined_tips_) <= scenario::kRefineTipRounds;
  if (model.mechanics().bond_count() > 0) {
    fractures_.list_broken_bonds();
    bonds_.emplace(context.folder, s, model.mechanics(), static_cast<int>(fracture_type_names(s).size()),
                   BondClock::pass);
  }
}

void CoupledRecorder::start() {
  context_.folder.write("scenario.toml", context_.scenario_text);
  hold(0);
}

void CoupledRecorder::hold(int iteration) {
  held_ = HeldState{};
  held_.step = iteration;
  if (iteration > 0) held_.name = fmt::format("coupling iteration {}", iteration);
  if (bonds_) held_.broken_bonds = static_cast<int>(model_.mechanics().bond_breaks().size());
  if (!meter_) return;
  if (iteration == 0) {  // the blocks as built, which no pass has measured
    const dda::System& system = model_.mechanics();
    take_open_fractures(meter_->measure(model_.block_polygons(), system.penetration_tolerance(), system.contacts(),
                                        joint_laws_),
                        held_);
  } else if (fracture_state_) {
    take_open_fractures(*fracture_state_, held_);
  }
}

void CoupledRecorder::resume_from(const output::RunCheckpoint& saved, CoupledModel& model) {
  model.import_state({saved.mechanics, saved.coupling});
  checkpoint_.history = saved.history;
  checkpoint_.measure = saved.measure;
  for (const std::vector<std::string>& row : saved.measure) measure_.add_row(row);
  checkpoint_.written_iterations = saved.written_iterations;
  for (const std::vector<std::string>& row : saved.history) history_.add_row(row);
  paraview_.list_written(saved.written_iterations);
  const int iterations = model.loop().iterations();
  if (bonds_) {
    const auto column = static_cast<std::size_t>(
        std::find(columns_.begin(), columns_.end(), "broken_bonds") - columns_.begin());
    std::vector<int> broken_per_pass;
    for (const std::vector<std::string>& row : saved.history) broken_per_pass.push_back(std::stoi(row.at(column)));
    bonds_->continue_from(model.mechanics(), broken_per_pass, saved.written_iterations);
  }
  if (meter_ || bonds_)
    fractures_.continue_from(iterations,
                             scenario_.output.fields.fractures ? saved.written_iterations : std::vector<int>{});
  // The fractures as the last pass left them: a run resumed after its last pass (to write its
  // summary) measures no pass of its own.
  if (meter_ && iterations > 0) measure_fractures();
  hold(iterations);  // the run went on from it: it held
  spdlog::info("resuming after coupling iteration {}", iterations);
  last_written_ = checkpoint_.written_iterations.empty() ? 0 : checkpoint_.written_iterations.back();
  // A run resumed after its last pass (its summary was not written) only writes it.
  converged_ = saved.converged;
  recent_ = fractures::read_recent_tips(saved.recent_tips);
  // The load step of the last pass, from its history row (load_step's column).
  if (model.has_load_tables() && !saved.history.empty()) {
    const std::size_t column = columns_.size() - 2;
    model.start_load_step(std::stoi(saved.history.back().at(column)));
  }
}

int CoupledRecorder::passes_before_load_step() const {
  if (!model_.has_load_tables()) return 0;
  const std::size_t column = columns_.size() - 2;
  int passes = 0;
  for (const std::vector<std::string>& row : checkpoint_.history)
    if (std::stoi(row.at(column)) < model_.load_step()) ++passes;
  return passes;
}

void CoupledRecorder::after_pass(const coupling::PassReport& r) {
  if (meter_) measure_fractures();
  // The bonds broken in the pass's DDA steps, recorded at the pass (before its fractures' rows,
  // as a mechanics run's step).
  if (bonds_) broken_in_pass_ = bonds_->add_breaks(r.iteration, model_.mechanics(), fractures_, r.time);
  add_history_row(r);
  add_measures(r);
  if (meter_) fractures_.add_rows(r.iteration, r.time, *fracture_state_);
  if (r.escaping.empty()) hold(r.iteration);
  if (follow_tips_) follow_tips(r);
  context_.report(report_pass(r));
  log_pass(r);
  last_pass_cut_short_ = !r.full_time_step;
  last_pass_moving_ = !r.at_rest;
  shortest_time_step_ = r.shortest_time_step;
  converged_ = r.converged;
  // The first pass, every `every`-th, and the last (write_last_fields if not here).
  if (r.iteration == 1 || r.iteration % scenario_.output.every == 0 || converged_ || r.diverging ||
      !r.escaping.empty()) {
    write_fields(r.iteration);
    last_written_ = r.iteration;
  }
  save_checkpoint();
}

void CoupledRecorder::add_history_row(const coupling::PassReport& r) {
  // The fractures' widest opening as fractures.csv measures it; without fracture traces, the
  // widest gap of an open contact between blocks.
  const double largest_opening = meter_ ? find_largest_opening(*fracture_state_) : r.largest_opening;
  std::vector<std::string> row{CsvTable::cell(static_cast<long long>(r.iteration)), CsvTable::cell(r.time),
                               CsvTable::cell(r.head_change), CsvTable::cell(r.displacement_change),
                               CsvTable::cell(largest_opening), CsvTable::cell(r.mean_porosity),
                               CsvTable::cell(r.max_permeability)};
  for (const scenario::FlowBoundaryCondition& bc : scenario_.flow->boundaries)
    row.push_back(CsvTable::cell(model_.loop().flow().boundary_flow(bc.name)));
  // A region that holds no element has empty cells (summary.json's warning says why).
  for (const std::optional<output::RegionSummary>& region : model_.region_flows()) {
    row.push_back(region ? CsvTable::cell(region->flow) : "");
    row.push_back(region && region->effective_conductivity ? CsvTable::cell(*region->effective_conductivity) : "");
  }
  row.insert(row.end(), {CsvTable::cell(r.head_change_two_passes), CsvTable::cell(r.relaxation),
                         CsvTable::cell(r.load_factor), CsvTable::cell(static_cast<long long>(r.contact_state_changes)),
                         CsvTable::cell(static_cast<long long>(r.joint_crossings_switched)),
                         CsvTable::cell(r.fluid_load_change),
                         CsvTable::cell(static_cast<long long>(r.most_open_close_iterations)),
                         CsvTable::cell(static_cast<long long>(r.step_cuts)),
                         CsvTable::cell(static_cast<long long>(r.at_rest ? 1 : 0))});
  if (bonds_) row.push_back(CsvTable::cell(static_cast<long long>(broken_in_pass_)));
  if (model_.has_load_tables())
    row.insert(row.end(), {CsvTable::cell(static_cast<long long>(model_.load_step())), CsvTable::cell(model_.load_time())});
  history_.add_row(row);
  checkpoint_.history.push_back(row);
  context_.folder.write("history.csv", history_.text());
}

void CoupledRecorder::add_measures(const coupling::PassReport& r) {
  const std::vector<scenario::MeasurePoint>& measures = scenario_.mechanics->measures;
  const auto positions = model_.mechanics().measured_positions();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const geometry::Point p0 = measures[i].point;
    std::vector<std::string> measured{CsvTable::cell(static_cast<long long>(r.iteration)), CsvTable::cell(r.time),
                                      measures[i].name, CsvTable::cell(positions[i].x),
                                      CsvTable::cell(positions[i].y), CsvTable::cell(positions[i].x - p0.x),
                                      CsvTable::cell(positions[i].y - p0.y)};
    measure_.add_row(measured);
    checkpoint_.measure.push_back(std::move(measured));
  }
  if (!measures.empty()) context_.folder.write("measure.csv", measure_.text());
}

void CoupledRecorder::follow_tips(const coupling::PassReport& r) {
  const std::vector<fractures::WedgeTipElement> tips = find_tip_elements();
  recent_.push_back({r.iteration, fractures::tips_to_refine(tips, fractures::current_round(refined_tips_),
                                                            default_refine_radius(*scenario_.mesh))});
  if (recent_.size() > fractures::kTipPasses) recent_.pop_front();
}

void CoupledRecorder::log_pass(const coupling::PassReport& r) const {
  const coupling::StaggeredLoop& loop = model_.loop();
  spdlog::debug(
      "iteration {}: head change {:.3e}, displacement change {:.3e}; porosity {:.3f} s, flow {:.3f} s ({}, {} CG "
      "iterations, {} elements corrected), mechanics {:.3f} s",
      r.iteration, r.head_change, r.displacement_change, r.porosity_seconds, r.flow_seconds,
      loop.flow().factorised ? "factored afresh" : "on the kept factor", loop.flow().cg_iterations,
      loop.flow().corrected_elements, r.mechanics_seconds);
  if (scenario_.coupling.settle)
    spdlog::debug("iteration {}: {} more DDA steps to rest{}", r.iteration, r.settling_steps,
                  r.at_rest ? "" : ", and the blocks still move");
  if (!r.at_rest && r.drifting_block >= 0)
    spdlog::warn("coupling iteration {}: the blocks still moved after the pass's DDA steps and {} more to "
                 "settle (coupling.settle), block {} moving freely, not slowing, and at its steps' rate landing "
                 "only after the settle steps left, so the pass stopped there; the pass does not count as converged",
                 r.iteration, r.settling_steps, r.drifting_block);
  else if (!r.at_rest)
    spdlog::warn("coupling iteration {}: the blocks still moved after the pass's DDA steps and {} more to "
                 "settle (coupling.settle); the pass does not count as converged",
                 r.iteration, r.settling_steps);
  if (r.groups_moved > 0)
    spdlog::info("coupling iteration {}: {} group(s) of blocks meeting nothing moved on to where the secant of "
                 "their net load vanishes, the farthest by {:.3g} m (docs/coupling.md, \"A group that floats\")",
                 r.iteration, r.groups_moved, r.longest_group_shift);
  if (r.under_tolerance && !r.full_time_step)
    spdlog::warn("coupling iteration {}: {}; the pass does not count as converged", r.iteration,
                 describe_cut_steps(r.shortest_time_step, scenario_.mechanics->time_step));
}

void CoupledRecorder::write_fields(int iteration) {
  const coupling::StaggeredLoop& loop = model_.loop();
  paraview_.write_fluid(iteration, iteration, model_.mesh(), loop.flow(), loop.porosity().porosity,
                        loop.permeability());
  paraview_.write_blocks(iteration, iteration, model_.mechanics());
  if (bonds_) bonds_->write_series(iteration, iteration, model_.mechanics());
  if (meter_ && scenario_.output.fields.fractures) {
    if (!fracture_state_) measure_fractures();
    fractures_.write_series(iteration, iteration, *fracture_state_);
  }
  checkpoint_.written_iterations.push_back(iteration);
}

void CoupledRecorder::write_last_fields() {
  const int iterations = model_.loop().iterations();
  if (iterations == 0 || last_written_ == iterations) return;
  write_fields(iterations);
  save_checkpoint();
}

void CoupledRecorder::save_checkpoint() {
  checkpoint_.converged = converged_;
  checkpoint_.refined_tips = fractures::write_refined_tips(refined_tips_);
  checkpoint_.recent_tips = fractures::write_recent_tips(recent_);
  const CoupledState state = model_.export_state();
  context_.folder.write_with("checkpoint.bin", [&](output::AtomicFile& file) {
    output::write_checkpoint(file, checkpoint_, state.mechanics, state.coupling);
  });
}

void CoupledRecorder::measure_fractures() {
  const dda::System& system = model_.mechanics();
  fracture_state_ =
      meter_->measure(model_.block_polygons(), system.penetration_tolerance(), system.contacts(), joint_laws_);
  meter_->add_flow(*fracture_state_, flow_zones_, model_.mesh(), model_.loop().flow());
}

const fractures::FractureState* CoupledRecorder::measured_fractures() {
  if (!meter_) return nullptr;
  if (!fracture_state_) measure_fractures();
  return &*fracture_state_;
}

std::vector<fractures::WedgeTipElement> CoupledRecorder::find_tip_elements() {
  const fractures::FractureState* state = measured_fractures();
  if (!state) return {};
  return fractures::find_wedge_tip_elements(*state, matrix_permeability_, joint_laws_, model_.mesh(), tip_locator(),
                                 meter_->layout().traces);
}

const mesh::PointLocator& CoupledRecorder::tip_locator() {
  if (!locator_) locator_.emplace(model_.mesh());
  return *locator_;
}

void CoupledRecorder::draw_bond_figure(const std::string& status) const {
  if (!bonds_) return;
  const std::string when = fmt::format("coupling iteration {}", model_.loop().iterations());
  bonds_->draw_figure(scenario_, model_.mechanics(), status.empty() ? when : when + ", " + status);
}

output::RunSummary CoupledRecorder::summary() {
  output::RunSummary summary = model_.summary();
  summary.timings = model_.timings();
  if (fracture_state_) {
    summary.fractures = summarise_fractures(*fracture_state_, fracture_type_names(scenario_));
    summary.fractures->refined_tips = refined_tips_;
    if (scenario_.mesh->refine_tips) summary.fractures->rounds = fractures::current_round(refined_tips_);
    const std::optional<fractures::WedgeTip> tip =
        cubic_law_ ? fractures::find_sharpest_wedge_tip(*fracture_state_, matrix_permeability_, joint_laws_) : std::nullopt;
    if (tip) {
      summary.fractures->tip_length = tip->length;
      summary.fractures->tip_length_id = tip->fracture;
      if (const auto element = fractures::find_wedge_tip_element(*tip, model_.mesh(), tip_locator(), meter_->layout().traces))
        summary.fractures->tip_element_size = element->element_size;
    }
  }
  return summary;
}

}  // namespace hydrodda::run
