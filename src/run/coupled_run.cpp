#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <utility>

#include "coupling/convergence_diagnosis.hpp"
#include "run/coupled_model.hpp"
#include "run/figures.hpp"
#include "run/fracture_output.hpp"
#include "run/model_building.hpp"
#include "run/paraview_output.hpp"
#include "run/run_summary.hpp"
#include "run/runs.hpp"
#include "run/tip_refinement.hpp"
#include "output/csv_table.hpp"
#include "output/item_list.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::run {

namespace {

using output::CsvTable;

// The changes of every pass from history.csv's rows (columns iteration, time, head_change,
// displacement_change, ...), those of a resumed run's earlier passes included.
ConvergenceHistory read_convergence(const std::vector<std::vector<std::string>>& rows, double tolerance) {
  ConvergenceHistory h;
  h.tolerance = tolerance;
  for (const std::vector<std::string>& row : rows) {
    h.iteration.push_back(std::stod(row[0]));
    h.head_change.push_back(std::stod(row[2]));
    h.displacement_change.push_back(std::stod(row[3]));
  }
  return h;
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
  return report;
}

// "no mechanical equilibrium ...: blocks 12 (moved 2.91 m, size 1 m), ...", the farthest few
// (every one in `folder`'s escaping_blocks.txt when there are more).
std::string describe_escape(const std::vector<coupling::EscapingBlock>& escaping, int iteration,
                            const output::RunFolder& folder) {
  std::vector<std::string> named;
  for (const coupling::EscapingBlock& b : escaping)
    named.push_back(fmt::format("block {} (moved {:.3g} m, size {:.3g} m)", b.block, b.distance, b.size));
  const std::string blocks = output::list_items(named, &folder, "escaping_blocks.txt");
  return fmt::format(
      "no mechanical equilibrium under this load: at coupling iteration {}, {} block(s) have moved farther than "
      "their own size (the square root of their area) and the loop still moves them: {}; the fluid load exceeds "
      "what the blocks' weight, their contacts and the supports can hold",
      iteration, escaping.size(), blocks);
}

// "block 12 moved 0.159 m (ux 0.001 m, uy 0.159 m), ...": the farthest five since the start,
// which show where and which way the load moves the blocks of a loop that drifts or diverges.
std::string describe_farthest(const std::vector<geometry::Point>& displacements) {
  std::vector<int> order(displacements.size());
  for (std::size_t b = 0; b < order.size(); ++b) order[b] = static_cast<int>(b);
  const auto distance = [&](int b) { return std::hypot(displacements[b].x, displacements[b].y); };
  const std::size_t named = std::min<std::size_t>(order.size(), 5);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(named), order.end(),
                    [&](int a, int b) { return distance(a) > distance(b) || (distance(a) == distance(b) && a < b); });
  std::string text;
  for (std::size_t i = 0; i < named; ++i) {
    const int b = order[i];
    text += fmt::format("{}block {} moved {:.3g} m (ux {:.3g} m, uy {:.3g} m)", i == 0 ? "" : ", ", b, distance(b),
                        displacements[b].x, displacements[b].y);
  }
  return text;
}

// What a failed run's summary and figures hold: the last pass that finished, or nothing.
std::string describe_results_kept(int finished) {
  return finished > 0 ? fmt::format("summary.json and the figures hold coupling iteration {}, the last that finished",
                                    finished)
                      : "no coupling iteration finished: there are no results";
}

// A failed run's status line on its figures: "failed at pass 6: " and what failed, the
// message's first clause after "coupling iteration 6 failed: ".
std::string describe_failure_for_figures(int pass, const std::string& message) {
  const std::string prefix = fmt::format("coupling iteration {} failed: ", pass);
  return describe_status_for_figures(fmt::format("failed at pass {}", pass),
                                     message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
}

// The largest opening of any fracture (fractures.csv's max_aperture), 0 when all are closed.
double find_largest_opening(const FractureState& state) {
  double largest = 0.0;
  for (const FractureResult& f : state.fractures) largest = std::max(largest, f.max_aperture);
  return largest;
}

// Passes of an unconverged run over which its regions' answers are ranged.
constexpr std::size_t kRangePasses = 10;

// Sets each region's range of K_eff/K_m over the last passes (up to kRangePasses) of a run that
// did not converge, from history.csv's rows (`columns` its header): how far its answer still
// moved, and so what it is worth. Only passes after the first `ramp_passes` count: a pass
// solves its flow on the blocks the pass before left, so the first pass's flow is that of the
// blocks as built, under no fluid load at all, and the ramp's under part of it: no answer to
// the load asked. "K_eff/K_m of region 'seal' ranged from 4.98 to 5.56 (11%) ...", or ""
// without a region or such a pass.
std::string describe_last_passes(const std::vector<std::string>& columns,
                                 const std::vector<std::vector<std::string>>& rows, int ramp_passes,
                                 std::vector<output::RegionSummary>& regions) {
  const std::size_t loaded = rows.size() > static_cast<std::size_t>(ramp_passes) ? rows.size() - ramp_passes : 0;
  const std::size_t passes = std::min(kRangePasses, loaded);
  if (passes == 0) return {};
  std::string text;
  for (output::RegionSummary& r : regions) {
    const auto column = std::find(columns.begin(), columns.end(), "region_conductivity_" + r.name);
    if (column == columns.end() || !(r.matrix_conductivity.value_or(0.0) > 0.0)) continue;
    const auto at = static_cast<std::size_t>(column - columns.begin());
    output::RegionSummary::PassRange range{static_cast<int>(passes), std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity()};
    for (std::size_t k = rows.size() - passes; k < rows.size(); ++k) {
      if (at >= rows[k].size() || rows[k][at].empty()) continue;  // a region that held no element
      const double normalised = std::stod(rows[k][at]) / *r.matrix_conductivity;
      range.least = std::min(range.least, normalised);
      range.largest = std::max(range.largest, normalised);
    }
    if (!(range.least <= range.largest)) continue;  // no value in those passes
    r.last_passes = range;
    // A region whose answer did not move (its permeability fixed) is no news in the message.
    const double spread = (range.largest - range.least) / std::abs(*r.normalised_conductivity);
    if (!(spread > 1e-9)) continue;
    text += fmt::format("{}K_eff/K_m of region '{}' ranged from {:.4g} to {:.4g} ({}%)", text.empty() ? "" : ", ",
                        r.name, range.least, range.largest,
                        spread >= 0.1 ? fmt::format("{:.0f}", 100.0 * spread) : fmt::format("{:.2g}", 100.0 * spread));
  }
  return text.empty() ? text : fmt::format("over the last {} passes {}", passes, text);
}

// Why a pass whose norms are under the tolerance may still be short of equilibrium.
std::string describe_cut_steps(double shortest, double full) {
  return fmt::format(
      "its DDA steps were cut short (to {:.3g} s at the shortest, against mechanics.time_step = {:g} s) and its last "
      "one had not grown back: steps cut short move the blocks little however far they are from equilibrium, so a "
      "small change proves nothing. The contacts did not settle at the full step (their states or their forces): "
      "look for blocks thinner than the contact distance (set by mechanics.max_displacement_ratio), or give more "
      "mechanics.steps so that the step can grow back",
      shortest, full);
}

// Moves what a round wrote into the folder round_N/ beside it, where the next round's files
// would otherwise mix with them: the tables and the ParaView series of the iterations it wrote.
// Its checkpoint is removed: the next round starts from the blocks as built, not from it.
void move_round_files(const output::RunFolder& folder, int round, const std::vector<int>& written_iterations) {
  namespace fs = std::filesystem;
  const fs::path into = folder.subfolder(fmt::format("round_{}", round));
  std::vector<std::string> names{"history.csv", "measure.csv", "fractures.csv",
                                 "fluid.pvd",   "blocks.pvd",  "contacts.pvd", "fractures.pvd"};
  for (int i : written_iterations)
    for (const char* series : {"fluid", "blocks", "contacts", "fractures"}) names.push_back(fmt::format("{}_{:04d}.vtu", series, i));
  for (const std::string& name : names)
    if (fs::exists(folder.file(name))) fs::rename(folder.file(name), into / name);
  fs::remove(folder.file("checkpoint.bin"));
}

// How a round ended: with the run's summary, or with the tips to mesh again around.
struct RoundEnd {
  std::optional<output::RunSummary> summary;
  std::vector<output::RefinedTip> added;
  std::vector<int> written_iterations;
};

// One round of a coupled run: the whole run on the scenario's mesh refined around
// `refined_tips` as well, continued from `resume` when given. With mesh.refine_tips, a round
// that ends with wedge tips its mesh does not resolve returns them instead of a summary.
RoundEnd run_round(const RunContext& context, const output::RunCheckpoint* resume,
                   const std::vector<output::RefinedTip>& refined_tips) {
  const scenario::Scenario& s = context.scenario;
  // The first round (or a resumed one) may end at once while it meshes: nothing of it is
  // written yet. A later round has earlier rounds' files to keep, and is stopped once it has
  // meshed and written its start (below), so that it can be resumed.
  const bool later_round = !resume && !refined_tips.empty();
  // The files the scenario names, hashed as the model is built from them: a resumed run refuses
  // to start from any that changed since.
  std::vector<output::InputFile> input_files = resume ? resume->input_files : hash_input_files(s);
  std::optional<UnstoppableStage> building;
  if (!later_round) building.emplace(context.callbacks);
  CoupledModel model(s, context.mesh_cache, refine_points(refined_tips));
  building.reset();
  model.set_stop_request(context.callbacks.stop_requested);
  const mesh::TriangleMesh& mesh = model.mesh();
  const dda::System& system = model.mechanics();
  const coupling::StaggeredLoop& loop = model.loop();

  std::vector<std::string> columns{"iteration", "time", "head_change", "displacement_change",
                                   "largest_opening", "mean_porosity", "max_permeability"};
  for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) columns.push_back("flow_" + bc.name);
  for (const scenario::FlowRegion& r : s.flow->regions) {
    columns.push_back("region_flow_" + r.name);
    columns.push_back("region_conductivity_" + r.name);
  }
  columns.insert(columns.end(), {"head_change_two_passes", "relaxation", "load_factor"});
  CsvTable history(columns);
  const std::vector<scenario::MeasurePoint>& measures = s.mechanics->measures;
  CsvTable measure({"iteration", "time", "name", "x", "y", "ux", "uy"});

  // What a checkpoint holds besides the engines' states; restored first when resuming.
  output::RunCheckpoint checkpoint;
  checkpoint.scenario_hash = output::hash_text(context.scenario_text);
  checkpoint.scenario_file = std::filesystem::absolute(s.file).string();
  checkpoint.input_files = std::move(input_files);
  ParaviewOutput paraview(context.folder, s.output.fields);
  const std::optional<FractureMeter> meter = make_fracture_meter(s);
  const hydro::JointApertureLaw joint_law = make_joint_aperture_law(s);
  const FractureMeter::FlowZones flow_zones = meter ? meter->flow_zones(mesh) : FractureMeter::FlowZones{};
  FractureOutput fractures(context.folder, /*with_flow=*/true);
  std::optional<FractureState> fracture_state;  // of the last finished pass
  TellModelAtEnd tell_model_at_end(context.callbacks, model, fracture_state);
  const auto measure_fractures = [&] {
    fracture_state = meter->measure(model.block_polygons(), system.penetration_tolerance(), system.contacts(), joint_law);
    meter->add_flow(*fracture_state, flow_zones, mesh, loop.flow());
  };
  if (resume) {
    const output::RunCheckpoint& saved = *resume;
    model.import_state({saved.mechanics, saved.coupling});
    checkpoint.history = saved.history;
    checkpoint.measure = saved.measure;
    for (const std::vector<std::string>& row : saved.measure) measure.add_row(row);
    checkpoint.written_iterations = saved.written_iterations;
    for (const std::vector<std::string>& row : saved.history) history.add_row(row);
    paraview.list_written(saved.written_iterations);
    if (meter) fractures.continue_from(loop.iterations(), s.output.fields.fractures ? saved.written_iterations : std::vector<int>{});
    // The fractures as the last pass left them: a run resumed after its last pass (to write its
    // summary) measures no pass of its own.
    if (meter && loop.iterations() > 0) measure_fractures();
    spdlog::info("resuming after coupling iteration {}", loop.iterations());
  } else {
    context.folder.write("scenario.toml", context.scenario_text);
  }

  const auto write_fields = [&](int iteration) {
    paraview.write_fluid(iteration, iteration, mesh, loop.flow(), loop.porosity().porosity, loop.permeability());
    paraview.write_blocks(iteration, iteration, system);
    if (meter && s.output.fields.fractures) {
      if (!fracture_state) measure_fractures();
      fractures.write_series(iteration, iteration, *fracture_state);
    }
    checkpoint.written_iterations.push_back(iteration);
  };
  int last_written = checkpoint.written_iterations.empty() ? 0 : checkpoint.written_iterations.back();
  // A run resumed after its last pass (its summary was not written) only writes it.
  bool converged = resume && resume->converged;
  bool last_pass_cut_short = false;  // its last DDA step was cut short (PassReport::full_time_step)
  bool last_pass_moving = false;     // its blocks still moved after the settle steps (PassReport::at_rest)
  double shortest_time_step = 0.0;   // of the last pass
  bool stopped = false;  // by stop_after
  // The cubic law's wedge tips (docs/coupling.md, "Wedge tips").
  const bool cubic_law = s.flow->permeability_law == coupling::PermeabilityLaw::cubic;
  const double matrix_permeability = make_permeability_model(s).matrix_permeability();
  // The fluid mesh's triangle finder for the tips' elements, made when first needed.
  std::optional<mesh::PointLocator> locator;
  const auto tip_locator = [&]() -> const mesh::PointLocator& {
    if (!locator) locator.emplace(mesh);
    return *locator;
  };
  // mesh.refine_tips: whether this round may end with tips to refine, and the unresolved tips of
  // its last passes (in the checkpoint, so that a resumed round refines the same).
  const bool follow_tips = meter && s.mesh->refine_tips && current_round(refined_tips) <= scenario::kRefineTipRounds;
  std::deque<PassTips> recent;
  if (resume) recent = read_recent_tips(resume->recent_tips);
  const auto current_summary = [&] {
    output::RunSummary summary = model.summary();
    summary.timings = model.timings();
    if (fracture_state) {
      summary.fractures = summarise_fractures(*fracture_state);
      summary.fractures->refined_tips = refined_tips;
      if (s.mesh->refine_tips) summary.fractures->rounds = current_round(refined_tips);
      const std::optional<WedgeTip> tip =
          cubic_law ? find_sharpest_wedge_tip(*fracture_state, matrix_permeability, joint_law) : std::nullopt;
      if (tip) {
        summary.fractures->tip_length = tip->length;
        summary.fractures->tip_length_id = tip->fracture;
        if (const auto element = find_wedge_tip_element(*tip, mesh, tip_locator(), meter->layout().traces))
          summary.fractures->tip_element_size = element->element_size;
      }
    }
    return summary;
  };
  // A run that ends unconverged or failed: `message` and `summary` get how far each region's
  // answer moved over its last passes.
  const auto add_last_passes = [&](output::RunSummary& summary, std::string& message) {
    if (!summary.flow) return;
    if (const std::string moved =
            describe_last_passes(columns, checkpoint.history, s.coupling.ramp_passes, summary.flow->regions);
        !moved.empty())
      message += "; " + moved;
  };
  // The figures of the state the model is in, each with `status` on it ("" for a converged
  // run): the fields of its last finished pass (none before the first), the passes' changes
  // and the fractures' apertures.
  const auto draw_run_figures = [&](const std::string& status) {
    if (loop.has_flow())
      draw_figures(s, context.folder,
                   {mesh, loop.flow(), loop.porosity().porosity, loop.permeability(), model.block_polygons(), status,
                    loop.iterations()});
    ConvergenceHistory convergence = read_convergence(checkpoint.history, s.coupling.tolerance);
    convergence.status = status;
    draw_convergence(s, context.folder, convergence);
    if (meter && loop.iterations() > 0) {
      if (!fracture_state) measure_fractures();
      draw_aperture_figure(s, context.folder, model.block_polygons(), *fracture_state,
                           {fmt::format("coupling iteration {}", loop.iterations()), status});
    }
  };
  // A run that failed at pass `pass`: its summary (with how far each region's answer moved,
  // when `with_range`) and its figures, of the last finished pass, each saying how it failed.
  const auto failure = [&](std::string message, bool with_range, int pass) {
    output::RunSummary summary;
    try {
      summary = current_summary();
    } catch (const std::exception& e) {  // the failure is still the news, with what is known
      message += fmt::format("; and no summary of coupling iteration {} could be made: {}", loop.iterations(), e.what());
      summary.title = s.title;
      summary.scenario = s.file.string();
      summary.iterations = loop.iterations();
    }
    if (with_range) add_last_passes(summary, message);
    try {
      draw_run_figures(describe_failure_for_figures(pass, message));
    } catch (const std::exception& e) {
      spdlog::warn("the failed run's figures could not be drawn: {}", e.what());
    }
    return RunFailure(RunStatus::failed, std::move(message), std::move(summary));
  };
  // A run interrupted after its last finished pass: its summary, and its figures saying so.
  const auto interrupted = [&](std::string message) {
    output::RunSummary summary = current_summary();
    try {
      draw_run_figures(describe_status_for_figures(fmt::format("interrupted after pass {}", loop.iterations()), ""));
    } catch (const std::exception& e) {
      spdlog::warn("the interrupted run's figures could not be drawn: {}", e.what());
    }
    return RunFailure(RunStatus::interrupted, std::move(message), std::move(summary));
  };
  // After every finished pass: the checkpoint of the state the model continues from
  // (CoupledModel::run_pass), which a resumed run continues from too.
  const auto save_checkpoint = [&] {
    checkpoint.converged = converged;
    checkpoint.refined_tips = write_refined_tips(refined_tips);
    checkpoint.recent_tips = write_recent_tips(recent);
    const CoupledState state = model.export_state();
    context.folder.write_with("checkpoint.bin", [&](output::AtomicFile& file) {
      output::write_checkpoint(file, checkpoint, state.mechanics, state.coupling);
    });
  };
  // A later round's start is a checkpoint too (the blocks as built, no pass yet): a run stopped
  // before its first pass ends resumes on this round's mesh, not from the round before.
  if (later_round) save_checkpoint();
  try {
    for (int k = loop.iterations(); k < s.coupling.max_iterations && !converged; ++k) {
      if (context.stop_requested())
        throw interrupted(fmt::format("interrupted after coupling iteration {}", loop.iterations()));
      if (context.stop_after && loop.iterations() >= *context.stop_after) {
        stopped = true;
        break;
      }
      const coupling::PassReport r = model.run_pass();
      if (meter) measure_fractures();
      // The fractures' widest opening as fractures.csv measures it; without fracture traces,
      // the widest gap of an open contact between blocks.
      const double largest_opening = meter ? find_largest_opening(*fracture_state) : r.largest_opening;
      std::vector<std::string> row{CsvTable::cell(static_cast<long long>(r.iteration)), CsvTable::cell(r.time),
                                   CsvTable::cell(r.head_change), CsvTable::cell(r.displacement_change),
                                   CsvTable::cell(largest_opening), CsvTable::cell(r.mean_porosity),
                                   CsvTable::cell(r.max_permeability)};
      for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries)
        row.push_back(CsvTable::cell(loop.flow().boundary_flow(bc.name)));
      // A region that holds no element has empty cells (summary.json's warning says why).
      for (const std::optional<output::RegionSummary>& region : model.region_flows()) {
        row.push_back(region ? CsvTable::cell(region->flow) : "");
        row.push_back(region && region->effective_conductivity ? CsvTable::cell(*region->effective_conductivity) : "");
      }
      row.insert(row.end(), {CsvTable::cell(r.head_change_two_passes), CsvTable::cell(r.relaxation),
                             CsvTable::cell(r.load_factor)});
      history.add_row(row);
      checkpoint.history.push_back(row);
      context.folder.write("history.csv", history.text());
      const auto positions = system.measured_positions();
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const geometry::Point p0 = measures[i].point;
        std::vector<std::string> measured{CsvTable::cell(static_cast<long long>(r.iteration)), CsvTable::cell(r.time),
                                          measures[i].name, CsvTable::cell(positions[i].x),
                                          CsvTable::cell(positions[i].y), CsvTable::cell(positions[i].x - p0.x),
                                          CsvTable::cell(positions[i].y - p0.y)};
        measure.add_row(measured);
        checkpoint.measure.push_back(std::move(measured));
      }
      if (!measures.empty()) context.folder.write("measure.csv", measure.text());
      if (meter) fractures.add_rows(r.iteration, r.time, *fracture_state);
      if (follow_tips) {
        const std::vector<WedgeTipElement> tips = find_wedge_tip_elements(
            *fracture_state, matrix_permeability, joint_law, mesh, tip_locator(), meter->layout().traces);
        recent.push_back({r.iteration, tips_to_refine(tips, s.mesh->size, current_round(refined_tips))});
        if (recent.size() > kTipPasses) recent.pop_front();
      }
      context.report(report_pass(r));
      spdlog::debug(
          "iteration {}: head change {:.3e}, displacement change {:.3e}; porosity {:.3f} s, flow {:.3f} s ({}, {} CG "
          "iterations, {} elements corrected), mechanics {:.3f} s",
          r.iteration, r.head_change, r.displacement_change, r.porosity_seconds, r.flow_seconds,
          loop.flow().factorised ? "factored afresh" : "on the kept factor", loop.flow().cg_iterations,
          loop.flow().corrected_elements, r.mechanics_seconds);
      if (s.coupling.settle)
        spdlog::debug("iteration {}: {} more DDA steps to rest{}", r.iteration, r.settling_steps,
                      r.at_rest ? "" : ", and the blocks still move");
      if (!r.at_rest)
        spdlog::warn("coupling iteration {}: the blocks still moved after the pass's DDA steps and {} more to "
                     "settle (coupling.settle); the pass does not count as converged",
                     r.iteration, r.settling_steps);
      last_pass_cut_short = !r.full_time_step;
      last_pass_moving = !r.at_rest;
      shortest_time_step = r.shortest_time_step;
      if (r.under_tolerance && !r.full_time_step)
        spdlog::warn("coupling iteration {}: {}; the pass does not count as converged", r.iteration,
                     describe_cut_steps(r.shortest_time_step, s.mechanics->time_step));
      converged = r.converged;
      // The first pass, every `every`-th, and the last (written below if not here).
      if (r.iteration == 1 || r.iteration % s.output.every == 0 || converged || r.diverging || !r.escaping.empty()) {
        write_fields(r.iteration);
        last_written = r.iteration;
      }
      save_checkpoint();
      if (r.diverging) {
        throw failure(fmt::format("the coupling loop diverges: its change grew {} passes in a row, to a head change "
                                  "of {:.3e} and a displacement change of {:.3e} at coupling iteration {}",
                                  r.growing_passes, r.head_change, r.displacement_change, r.iteration),
                      true, r.iteration);
      }
      if (!r.escaping.empty()) throw failure(describe_escape(r.escaping, r.iteration, context.folder), false, r.iteration);
    }
    // The last state's fields, unless the run is to be continued (it writes them at its end).
    if (!stopped && loop.iterations() > 0 && last_written != loop.iterations()) {
      write_fields(loop.iterations());
      save_checkpoint();
    }
  } catch (const RunFailure&) {
    throw;
  } catch (const coupling::PassInterrupted& e) {
    // The model is back at the last finished pass, the state the run folder and the checkpoint
    // hold (before the first pass: the blocks as built), so that summary.json describes it.
    throw interrupted(
        fmt::format("interrupted: {}; the results are those of coupling iteration {}", e.what(), loop.iterations()));
  } catch (const std::exception& e) {
    // A DDA step that fails while blocks fly off is the escape, not the step, to report.
    const std::vector<coupling::EscapingBlock> escaping = loop.blocks_beyond_their_size();
    const int failed = loop.iterations() + 1;
    // Back to the last finished pass, which the summary, the figures and the checkpoint then
    // describe alike (its heads, fields and blocks), not the pass that failed half-way.
    model.abandon_pass();
    throw failure(fmt::format("coupling iteration {} failed: {}{}; {}", failed, e.what(),
                              escaping.empty() ? "" : "; " + describe_escape(escaping, failed, context.folder),
                              describe_results_kept(loop.iterations())),
                  true, failed);
  }
  if (stopped) {
    output::RunSummary summary = current_summary();
    summary.status = "stopped";
    summary.message = fmt::format("stopped after coupling iteration {} (--stop-after)", loop.iterations());
    return {summary, {}, {}};
  }
  if (const std::string unreached = describe_unreached_displacement(s, system); !unreached.empty())
    throw failure(unreached, false, loop.iterations());
  // A round that ends with wedge tips its mesh does not resolve ends there: the next meshes again
  // around them (mesh.refine_tips), while rounds remain. So does one that did not converge: its
  // unresolved tips may be why (the symmetric flexure's bed joint, docs/coupling.md).
  if (follow_tips && loop.iterations() > 0) {
    std::vector<output::RefinedTip> added =
        converged ? (recent.empty() ? std::vector<output::RefinedTip>{} : recent.back().tips) : merge_tips(recent);
    if (!added.empty()) {
      spdlog::info(
          "round {}: {} in {} coupling iterations, with {} wedge tip(s) in fluid elements wider than s*/2{} (the "
          "first at ({:.4g}, {:.4g}), s* = {:.2g} m): running again on a mesh refined to s*/4 around them "
          "(mesh.refine_tips; this round's files are in round_{}/)",
          current_round(refined_tips), converged ? "converged" : "did not converge", loop.iterations(), added.size(),
          converged ? "" : fmt::format(" over its last {} passes", recent.size()), added.front().x, added.front().y,
          4.0 * added.front().size, current_round(refined_tips));
      tell_model_at_end.dismiss();
      return {std::nullopt, std::move(added), checkpoint.written_iterations};
    }
  }
  ConvergenceHistory convergence = read_convergence(checkpoint.history, s.coupling.tolerance);
  output::RunSummary summary = current_summary();
  summary.converged = converged;
  // Round-off beyond the mesh edge (blocks resting on it) is no excursion: warn only past the
  // DDA's penetration tolerance, the precision block positions are held to.
  if (summary.outside_mesh && summary.outside_mesh->blocks > 0 &&
      summary.outside_mesh->largest_distance > system.penetration_tolerance())
    spdlog::warn("{} block(s) reach outside the fluid mesh, block {} farthest, by {:.3g} m: their parts outside "
                 "take the pressure of the mesh boundary there",
                 summary.outside_mesh->blocks, summary.outside_mesh->block, summary.outside_mesh->largest_distance);
  // The cubic law's answer depends on the mesh where the elements at a wedge tip are wider than
  // its exchange length (docs/coupling.md, "Wedge tips").
  if (meter && cubic_law && s.mesh) {
    if (!fracture_state) measure_fractures();
    const std::vector<WedgeTipElement> tips = find_wedge_tip_elements(
        *fracture_state, matrix_permeability, joint_law, mesh, tip_locator(), meter->layout().traces);
    if (const auto text = describe_unresolved_wedge_tips(tips, *s.mesh, &context.folder))
      spdlog::warn("{}{}",
                   s.mesh->refine_tips
                       ? fmt::format("after {} round(s) of mesh.refine_tips (at most {}), ", current_round(refined_tips) - 1,
                                     scenario::kRefineTipRounds)
                       : "",
                   *text);
  }
  if (!converged) {
    std::vector<double> two_passes;  // history.csv's third column from the end
    for (const std::vector<std::string>& row : checkpoint.history) two_passes.push_back(std::stod(row[row.size() - 3]));
    const coupling::ConvergenceDiagnosis why =
        coupling::diagnose_non_convergence(convergence.head_change, convergence.displacement_change, two_passes,
                                           s.coupling.tolerance,
                                           {.acceleration = scenario::spell(s.coupling.acceleration),
                                            .relaxation = s.coupling.relaxation,
                                            .settling = s.coupling.settle});
    summary.message = fmt::format("the coupling loop did not converge in {} iterations (tolerance {:g}): {}",
                                  s.coupling.max_iterations, s.coupling.tolerance, why.text);
    if (why.behaviour == coupling::NonConvergence::drifting || why.behaviour == coupling::NonConvergence::diverging)
      summary.message += "; farthest from where they started: " + describe_farthest(loop.block_displacements());
    if (last_pass_cut_short)
      summary.message += "; in the last pass " + describe_cut_steps(shortest_time_step, s.mechanics->time_step);
    if (last_pass_moving)
      summary.message += "; in the last pass the blocks still moved after its DDA steps and the settle steps "
                         "(coupling.settle)";
    add_last_passes(summary, summary.message);
    spdlog::warn("{}", summary.message);
  }
  context.write_summary(summary);  // the run's result is on disk before the figures are drawn
  draw_run_figures(converged ? "" : fmt::format("not converged after {} passes", loop.iterations()));
  return {summary, {}, {}};
}

}  // namespace

output::RunSummary run_coupled(const RunContext& context) {
  // A resumed run takes up the round it stopped in, on the mesh of the tips refined before it.
  std::vector<output::RefinedTip> refined_tips;
  if (context.resume) refined_tips = read_refined_tips(context.resume->refined_tips);
  const output::RunCheckpoint* resume = context.resume;
  for (;;) {
    RoundEnd end = run_round(context, resume, refined_tips);
    if (end.summary) return std::move(*end.summary);
    move_round_files(context.folder, current_round(refined_tips), end.written_iterations);
    refined_tips.insert(refined_tips.end(), end.added.begin(), end.added.end());
    resume = nullptr;
  }
}

}  // namespace hydrodda::run
