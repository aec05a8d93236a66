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
#include "run/coupled_messages.hpp"
#include "run/model_building.hpp"
#include "run/no_equilibrium.hpp"
#include "run/permeability_cap.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_recorder.hpp"
#include "run/figures.hpp"
#include "run/fracture_output.hpp"
#include "run/resumed_run.hpp"
#include "run/run_summary.hpp"
#include "run/runs.hpp"
#include "run/scenario_fractures.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::run {

namespace {

// Whether a joint type that conducts by a law of its own reads each point by its own gap.
bool any_joint_read_by_point(const scenario::Scenario& s) {
  for (int t = 0; t < s.joint_type_count(); ++t)
    if (s.joint_type(t).hydraulic() && s.joint_type(t).hydraulic_opening == hydro::HydraulicOpening::local) return true;
  return false;
}

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
  std::vector<fractures::RefinedTip> added;
  std::vector<int> written_iterations;
};

// A round under way: its model and what records its passes.
struct Round {
  const RunContext& context;
  CoupledModel& model;
  CoupledRecorder& recorder;
};

// A run that ends unconverged or failed: `message` and `summary` get how far each region's
// answer moved over its last passes.
void add_last_passes(const Round& round, output::RunSummary& summary, std::string& message) {
  if (!summary.flow) return;
  if (const std::string moved =
          describe_last_passes(round.recorder.history_columns(), round.recorder.history_rows(),
                               round.model.loop().ramp_passes(), summary.flow->regions);
      !moved.empty())
    message += "; " + moved;
}

// The figures of the state the model is in, each with `status` on it ("" for a converged
// run): the fields of its last finished pass (none before the first), the passes' changes
// and the fractures' apertures.
void draw_round_figures(const Round& round, const std::string& status) {
  const scenario::Scenario& s = round.context.scenario;
  const coupling::StaggeredLoop& loop = round.model.loop();
  if (loop.has_flow())
    draw_figures(s, round.context.folder,
                 {round.model.mesh(), loop.flow(), loop.porosity().porosity, loop.permeability(),
                  round.model.block_polygons(), status, loop.iterations()});
  ConvergenceHistory convergence = read_convergence(round.recorder.history_rows(), s.coupling.tolerance);
  convergence.status = status;
  draw_convergence(s, round.context.folder, convergence);
  round.recorder.draw_bond_figure(status);
  if (loop.iterations() > 0)
    if (const fractures::FractureState* fractures = round.recorder.measured_fractures())
      draw_aperture_figure(s, round.context.folder, round.model.block_polygons(), *fractures,
                           {fmt::format("coupling iteration {}", loop.iterations()), status});
}

// A run that failed at pass `pass`: its summary (with how far each region's answer moved,
// when `with_range`) and its figures, of the last finished pass, each saying how it failed.
RunFailure fail_round(const Round& round, std::string message, bool with_range, int pass) {
  const int iterations = round.model.iterations();
  output::RunSummary summary;
  try {
    summary = round.recorder.summary();
  } catch (const std::exception& e) {  // the failure is still the news, with what is known
    message += fmt::format("; and no summary of coupling iteration {} could be made: {}", iterations, e.what());
    summary.title = round.context.scenario.title;
    summary.scenario = round.context.scenario.file.string();
    summary.iterations = iterations;
  }
  if (with_range) add_last_passes(round, summary, message);
  try {
    draw_round_figures(round, describe_failure_for_figures(pass, message));
  } catch (const std::exception& e) {
    spdlog::warn("the failed run's figures could not be drawn: {}", e.what());
  }
  return RunFailure(RunStatus::failed, std::move(message), std::move(summary));
}

// A load under which no equilibrium exists: the blocks that escape, where they are at the last
// finished pass (which the summary, history and figures describe), and the fractures open and
// bonds broken at the last pass that held, under the load the scenario drives the blocks with.
RunFailure no_equilibrium_round(const Round& round, const std::vector<coupling::EscapingBlock>& escaping) {
  const int kept = round.model.iterations();
  HeldState held = round.recorder.held_state();
  if (held.broken_bonds)
    held.broken_bonds_later = static_cast<int>(round.model.mechanics().bond_breaks().size()) - *held.broken_bonds;
  std::string message = describe_no_equilibrium(
      round.context.scenario, locate_escaping_blocks(escaping, round.model.block_polygons()), held,
      kept > 0 ? fmt::format("coupling iteration {}", kept) : "the blocks as built", &round.context.folder);
  output::RunSummary summary = round.recorder.summary();
  summary.last_held = summarise_held_state(held);
  try {
    draw_round_figures(round, describe_status_for_figures(fmt::format("no equilibrium after pass {}", kept), message));
  } catch (const std::exception& e) {
    spdlog::warn("the figures of the run without equilibrium could not be drawn: {}", e.what());
  }
  return RunFailure(RunStatus::no_equilibrium, std::move(message), std::move(summary));
}

// A run interrupted after its last finished pass: its summary, and its figures saying so.
RunFailure interrupt_round(const Round& round, std::string message) {
  output::RunSummary summary = round.recorder.summary();
  try {
    draw_round_figures(round,
                       describe_status_for_figures(fmt::format("interrupted after pass {}", round.model.iterations()), ""));
  } catch (const std::exception& e) {
    spdlog::warn("the interrupted run's figures could not be drawn: {}", e.what());
  }
  return RunFailure(RunStatus::interrupted, std::move(message), std::move(summary));
}

// Why the loop ended, when that ends the run before its summary: an interrupt, a loop that
// diverges, blocks that escape (thrown as RunFailure).
void end_on_loop_failure(const Round& round, const coupling::LoopResult& result) {
  const int iterations = round.model.iterations();
  if (result.end == coupling::LoopEnd::stop_requested)
    throw interrupt_round(round, fmt::format("interrupted after coupling iteration {}", iterations));
  if (result.end == coupling::LoopEnd::diverging) {
    const coupling::PassReport& r = *result.last_pass;
    throw fail_round(round,
                     fmt::format("the coupling loop diverges: its change grew {} passes in a row, to a head change "
                                 "of {:.3e} and a displacement change of {:.3e} at coupling iteration {}",
                                 r.growing_passes, r.head_change, r.displacement_change, r.iteration),
                     true, r.iteration);
  }
  if (result.end == coupling::LoopEnd::escaping) throw no_equilibrium_round(round, result.last_pass->escaping);
}

// The load steps from the one the model is at (docs/scenario.md, "Loads over time"): each
// step's passes until they converge, then the next step's, until the last step converges or
// the loop ends otherwise; coupling.max_iterations bounds each step's passes. One step when
// every load is a constant. A round resumed after its last pass runs none.
coupling::LoopResult run_load_steps(const Round& round) {
  const scenario::Scenario& s = round.context.scenario;
  CoupledModel& model = round.model;
  coupling::LoopResult result;
  result.end = coupling::LoopEnd::converged;
  bool step_converged = round.recorder.converged();
  while (!step_converged || model.load_step() < model.load_steps()) {
    if (step_converged) {
      // A run to stop after this pass stops in the step it finished, so that its summary and
      // checkpoint are of that step; resumed, it starts the next.
      if (round.context.stop_after && model.iterations() >= *round.context.stop_after) {
        result.end = coupling::LoopEnd::stopped_after;
        return result;
      }
      model.start_load_step(model.load_step() + 1);
      spdlog::info("load step {} of {}: the loads at t = {:g}", model.load_step(), model.load_steps(), model.load_time());
    }
    const int passes_before = round.recorder.passes_before_load_step();
    result = model.run({passes_before + s.coupling.max_iterations, round.context.stop_after}, round.recorder);
    if (result.end != coupling::LoopEnd::converged) return result;
    step_converged = true;
  }
  return result;
}

// The round's passes, each recorded, until the loop ends (a round resumed after its last pass
// runs none). Returns whether it stopped after --stop-after's pass; throws RunFailure when
// interrupted or failed, the model back at its last finished pass.
bool run_passes(const Round& round) {
  try {
    const coupling::LoopResult result = run_load_steps(round);
    end_on_loop_failure(round, result);
    const bool stopped = result.end == coupling::LoopEnd::stopped_after;
    // The last state's fields, unless the run is to be continued (it writes them at its end).
    if (!stopped) round.recorder.write_last_fields();
    return stopped;
  } catch (const RunFailure&) {
    throw;
  } catch (const coupling::PassInterrupted& e) {
    // The model is back at the last finished pass, the state the run folder and the checkpoint
    // hold (before the first pass: the blocks as built), so that summary.json describes it.
    throw interrupt_round(round, fmt::format("interrupted: {}; the results are those of coupling iteration {}",
                                             e.what(), round.model.iterations()));
  } catch (const std::exception& e) {
    // A DDA step or a flow solve that fails while blocks fly off is the breach, not the step
    // (cut to nothing) or the solve (of a layer lifted metres off its base), to report.
    const std::vector<coupling::EscapingBlock> escaping = round.model.loop().blocks_beyond_their_size();
    const int failed = round.model.iterations() + 1;
    // Back to the last finished pass, which the summary, the figures and the checkpoint then
    // describe alike (its heads, fields and blocks), not the pass that failed half-way.
    round.model.abandon_pass();
    if (!escaping.empty()) {
      spdlog::debug("coupling iteration {} failed as blocks escaped: {}", failed, e.what());
      throw no_equilibrium_round(round, escaping);
    }
    throw fail_round(round,
                     fmt::format("coupling iteration {} failed: {}; {}", failed, e.what(),
                                 describe_results_kept(round.model.iterations())),
                     true, failed);
  }
}

// A round that ends with wedge tips its mesh does not resolve ends there: the next meshes again
// around them (mesh.refine_tips), while rounds remain. So does one that did not converge: its
// unresolved tips may be why (the symmetric flexure's bed joint, docs/coupling.md). The tips
// to refine, none when the run ends with this round.
std::vector<fractures::RefinedTip> find_tips_for_next_round(const Round& round) {
  const CoupledRecorder& recorder = round.recorder;
  if (!recorder.follows_tips() || round.model.iterations() == 0) return {};
  const std::deque<fractures::PassTips>& recent = recorder.recent_tips();
  const bool converged = recorder.converged();
  std::vector<fractures::RefinedTip> added =
      converged ? (recent.empty() ? std::vector<fractures::RefinedTip>{} : recent.back().tips) : fractures::merge_tips(recent);
  if (!added.empty()) {
    const int round_number = fractures::current_round(recorder.refined_tips());
    spdlog::info(
        "round {}: {} in {} coupling iterations, with {} wedge tip(s) in fluid elements wider than s*/2{} (the "
        "first at ({:.4g}, {:.4g}), s* = {:.2g} m): running again on a mesh refined to s*/4 around them "
        "(mesh.refine_tips; this round's files are in round_{}/)",
        round_number, converged ? "converged" : "did not converge", round.model.iterations(), added.size(),
        converged ? "" : fmt::format(" over its last {} passes", recent.size()), added.front().x, added.front().y,
        4.0 * added.front().size, round_number);
  }
  return added;
}

// The warnings of a round at its end: blocks outside the fluid mesh, wedge tips the mesh does
// not resolve.
void warn_at_end(const Round& round, const output::RunSummary& summary) {
  const scenario::Scenario& s = round.context.scenario;
  // Round-off beyond the mesh edge (blocks resting on it) is no excursion: warn only past the
  // DDA's penetration tolerance, the precision block positions are held to.
  if (summary.outside_mesh && summary.outside_mesh->blocks > 0 &&
      summary.outside_mesh->largest_distance > round.model.mechanics().penetration_tolerance())
    spdlog::warn("{} block(s) reach outside the fluid mesh, block {} farthest, by {:.3g} m: their parts outside "
                 "take the pressure of the mesh boundary there",
                 summary.outside_mesh->blocks, summary.outside_mesh->block, summary.outside_mesh->largest_distance);
  const std::vector<int> capped_elements =
      capped_by_the_law(round.model.loop().capped_elements(), find_fixed_permeability(s, round.model.mesh()));
  if (const auto capped = describe_capped_fractures(capped_elements, round.model.mesh(),
                                                    round.recorder.element_fractures(),
                                                    s.flow->fracture_permeability_cap, &round.context.folder))
    spdlog::warn("at coupling iteration {}, {}", round.model.iterations(), *capped);
  // The cubic law's answer depends on the mesh where the elements at a wedge tip are wider than
  // its exchange length (docs/coupling.md, "Wedge tips").
  if (!round.recorder.cubic_law() || !s.mesh) return;
  const std::vector<fractures::WedgeTipElement> tips = round.recorder.find_tip_elements();  // none without traces
  if (const auto text = describe_unresolved_wedge_tips(tips, *s.mesh, &round.context.folder))
    spdlog::warn("{}{}",
                 s.mesh->refine_tips
                     ? fmt::format("after {} round(s) of mesh.refine_tips (at most {}), ",
                                   fractures::current_round(round.recorder.refined_tips()) - 1, scenario::kRefineTipRounds)
                     : "",
                 *text);
}

// Why a loop that did not converge did not: its behaviour over the passes (drifting, swinging,
// ...), where the blocks went, and what the last pass left undone.
std::string describe_non_convergence(const Round& round) {
  const scenario::Scenario& s = round.context.scenario;
  const CoupledRecorder& recorder = round.recorder;
  const ConvergenceHistory convergence = read_convergence(recorder.history_rows(), s.coupling.tolerance);
  const std::vector<std::string>& columns = recorder.history_columns();
  const auto column = [&](std::string_view name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  // The median of a count column over the passes the diagnosis fits (the last ten, the first pass left out).
  const auto median_of_last = [&](std::string_view name) {
    const std::vector<std::vector<std::string>>& rows = recorder.history_rows();
    std::vector<long long> values;
    for (std::size_t i = std::max<std::size_t>(1, rows.size() > 10 ? rows.size() - 10 : 1); i < rows.size(); ++i)
      values.push_back(std::stoll(rows[i].at(column(name))));
    if (values.empty()) return 0;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
    return static_cast<int>(values[values.size() / 2]);
  };
  const std::size_t two_passes_column = column("head_change_two_passes"), at_rest_column = column("at_rest");
  const std::size_t opening_column = column("largest_opening");
  std::vector<double> two_passes;  // history.csv's head_change_two_passes
  std::vector<double> largest_opening;
  std::vector<int> crossings, contacts;  // history.csv's joint_crossings_switched, contact_state_changes
  const std::size_t crossings_column = column("joint_crossings_switched");
  const std::size_t contacts_column = column("contact_state_changes");
  int passes_not_at_rest = 0;      // the last passes in a row whose at_rest is 0
  for (const std::vector<std::string>& row : recorder.history_rows()) {
    two_passes.push_back(std::stod(row.at(two_passes_column)));
    largest_opening.push_back(std::stod(row.at(opening_column)));
    crossings.push_back(std::stoi(row.at(crossings_column)));
    contacts.push_back(std::stoi(row.at(contacts_column)));
    passes_not_at_rest = row.at(at_rest_column) == "0" ? passes_not_at_rest + 1 : 0;
  }
  const coupling::ConvergenceDiagnosis why =
      coupling::diagnose_non_convergence(convergence.head_change, convergence.displacement_change, two_passes,
                                         s.coupling.tolerance,
                                         {.acceleration = scenario::spell(s.coupling.acceleration),
                                          .relaxation = s.coupling.relaxation,
                                          .settling = s.coupling.settle,
                                          .passes_not_at_rest = passes_not_at_rest,
                                          .crossings_switched = median_of_last("joint_crossings_switched"),
                                          .contacts_changed = median_of_last("contact_state_changes"),
                                          .joints_by_point = any_joint_read_by_point(s),
                                          .sudden_load = round.model.loop().ramp_passes() == 1 && round.model.load_step() == 1,
                                          .largest_opening = std::move(largest_opening),
                                          .crossings_by_pass = std::move(crossings),
                                          .contacts_by_pass = std::move(contacts)});
  std::string message = fmt::format("the coupling loop did not converge in {} iterations (tolerance {:g}): {}",
                                    s.coupling.max_iterations, s.coupling.tolerance, why.text);
  const bool never_at_rest = why.behaviour == coupling::NonConvergence::never_at_rest;
  if (why.behaviour == coupling::NonConvergence::drifting || why.behaviour == coupling::NonConvergence::diverging ||
      never_at_rest)
    message += "; farthest from where they started: " + describe_farthest(round.model.loop().block_displacements());
  // Whether the displacement norm is the whole model's or a few loose pieces'.
  if (!convergence.displacement_change.empty() && convergence.displacement_change.back() >= s.coupling.tolerance)
    if (const std::string movers =
            describe_last_pass_movers(round.model.loop().last_pass_motion(), round.model.mechanics());
        !movers.empty())
      message += "; " + movers;
  if (recorder.last_pass_cut_short())
    message += "; in the last pass " + describe_cut_steps(recorder.shortest_time_step(), s.mechanics->time_step);
  if (recorder.last_pass_moving() && !never_at_rest)  // else the diagnosis said so
    message += "; in the last pass the blocks still moved after its DDA steps and the settle steps "
               "(coupling.settle)";
  return message;
}

// summary.json of a round that reached its end, with its warnings and, unconverged, why.
output::RunSummary summarise_round(const Round& round) {
  output::RunSummary summary = round.recorder.summary();
  summary.converged = round.recorder.converged();
  warn_at_end(round, summary);
  if (!summary.converged) {
    summary.message = describe_non_convergence(round);
    // With loads over time, the step that did not converge ended the run: say which.
    if (round.model.has_load_tables())
      summary.message = fmt::format("load step {} of {} (the loads at t = {:g}): {}", round.model.load_step(),
                                    round.model.load_steps(), round.model.load_time(), summary.message);
    add_last_passes(round, summary, summary.message);
    spdlog::warn("{}", summary.message);
  }
  return summary;
}

// One round of a coupled run: the whole run on the scenario's mesh refined around
// `refined_tips` as well, continued from `resume` when given. With mesh.refine_tips, a round
// that ends with wedge tips its mesh does not resolve returns them instead of a summary.
RoundEnd run_round(const RunContext& context, const output::RunCheckpoint* resume,
                   const std::vector<fractures::RefinedTip>& refined_tips) {
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
  CoupledRecorder recorder(context, model, refined_tips, std::move(input_files));
  TellModelAtEnd tell_model_at_end(context.callbacks, model, recorder.fracture_state());
  if (resume) recorder.resume_from(*resume, model);
  else recorder.start();
  const Round round{context, model, recorder};
  // A later round's start is a checkpoint too (the blocks as built, no pass yet): a run stopped
  // before its first pass ends resumes on this round's mesh, not from the round before.
  if (later_round) recorder.save_checkpoint();

  if (run_passes(round)) {
    output::RunSummary summary = recorder.summary();
    summary.status = "stopped";
    summary.message = fmt::format("stopped after coupling iteration {} (--stop-after)", model.iterations());
    return {summary, {}, {}};
  }
  if (const std::string unreached = describe_unreached_displacement(s, model.mechanics()); !unreached.empty())
    throw fail_round(round, unreached, false, model.iterations());
  if (std::vector<fractures::RefinedTip> added = find_tips_for_next_round(round); !added.empty()) {
    tell_model_at_end.dismiss();
    return {std::nullopt, std::move(added), recorder.written_iterations()};
  }
  const output::RunSummary summary = summarise_round(round);
  context.write_summary(summary);  // the run's result is on disk before the figures are drawn
  // An unconverged run's figures show its last pass; one whose blocks were still moving says so.
  draw_round_figures(round, summary.converged             ? ""
                            : recorder.last_pass_moving() ? fmt::format("not converged after {} passes, the blocks "
                                                                        "still moving", model.iterations())
                                                          : fmt::format("not converged after {} passes", model.iterations()));
  return {summary, {}, {}};
}

}  // namespace

output::RunSummary run_coupled(const RunContext& context) {
  if (context.scenario.flow->transient) return run_coupled_transient(context);
  // A resumed run takes up the round it stopped in, on the mesh of the tips refined before it.
  std::vector<fractures::RefinedTip> refined_tips;
  if (context.resume) refined_tips = fractures::read_refined_tips(context.resume->refined_tips);
  const output::RunCheckpoint* resume = context.resume;
  for (;;) {
    RoundEnd end = run_round(context, resume, refined_tips);
    if (end.summary) return std::move(*end.summary);
    move_round_files(context.folder, fractures::current_round(refined_tips), end.written_iterations);
    refined_tips.insert(refined_tips.end(), end.added.begin(), end.added.end());
    resume = nullptr;
  }
}

}  // namespace hydrodda::run
