#include "run/run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "mesh/mesh_cache.hpp"
#include "output/item_list.hpp"
#include "output/run_folder.hpp"
#include "run/mesh_budget.hpp"
#include "run/model_building.hpp"
#include "run/runs.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::run {

namespace fs = std::filesystem;

namespace {

// A run that stopped before its end: summary.json says so (converged = false, status
// "interrupted", "no equilibrium" or "failed", what happened). `has_state`: the summary describes a state of the
// model, which is good only when every value in it is finite.
RunResult record_failure(const output::RunFolder& folder, RunStatus status, const std::string& what,
                         output::RunSummary summary, bool has_state = true) {
  summary.converged = false;
  summary.status = status == RunStatus::interrupted      ? "interrupted"
                   : status == RunStatus::no_equilibrium ? "no equilibrium"
                                                         : "failed";
  summary.message = what;
  const output::CheckedSummary checked = output::format_checked_summary(summary);
  try {
    folder.write("summary.json", checked.text);
    folder.sync();  // the verdict under its name through a power cut (docs/output.md, "Durability")
  } catch (const output::RunFolderError& e) {
    // Nowhere left to record the failure: the caller says both (once when they are the same).
    if (what == e.what()) throw;
    throw output::RunFolderError(fmt::format("{}; and the failure could not be recorded: {}", what, e.what()));
  }
  return {status, false, summary.iterations, what, summary, folder.path(), has_state && checked.non_finite.empty()};
}

// Results that overflowed (a conductivity of k ρ g / μ with μ = 1e-300) or came out NaN: the
// run failed, whatever its loop said, naming the first few values (all in non_finite.txt).
std::string describe_non_finite(const std::vector<std::string>& paths, const output::RunFolder& folder) {
  return fmt::format("{} result(s) not finite (overflow or 0/0; written as null in summary.json): {}", paths.size(),
                     output::list_items(paths, &folder, "non_finite.txt"));
}

// summary.json of a run that reached its end could not be written (a full disk): the result
// in memory is not turned into a failure's summary, and no summary.json claims one.
class SummaryNotWritten : public std::runtime_error {
 public:
  SummaryNotWritten(const std::string& message, output::RunSummary summary)
      : std::runtime_error(message), summary_(std::move(summary)) {}
  const output::RunSummary& summary() const { return summary_; }

 private:
  output::RunSummary summary_;
};

// The run's result, held in memory, that summary.json could not take: said, not recorded.
RunResult report_unwritten_summary(const SummaryNotWritten& e, RunKind kind, const fs::path& folder) {
  output::RunSummary summary = e.summary();
  summary.converged = false;
  summary.status = "failed";
  summary.message = fmt::format(
      "{}: the run's result ({}, {} iteration(s)) is not recorded; {}", e.what(),
      e.summary().converged ? "converged" : e.summary().status, e.summary().iterations,
      kind == RunKind::coupled
          ? fmt::format("its last state is in checkpoint.bin: make room, then `hydrodda run --resume {}` writes it",
                        folder.string())
          : "make room and run it again");
  return {RunStatus::failed, false, summary.iterations, summary.message, summary, folder};
}

RunResult run_in(const scenario::Scenario& s, const fs::path& directory, output::ExistingFolder policy,
                 const std::string& scenario_text, const output::RunCheckpoint* resume,
                 std::optional<int> stop_after, const Callbacks& callbacks,
                 const std::optional<fs::path>& mesh_cache = std::nullopt,
                 const output::TransientCheckpoint* resume_transient = nullptr,
                 const output::CoupledTransientCheckpoint* resume_coupled_transient = nullptr) {
  if (stop_after && kind_of(s) != RunKind::coupled)
    throw InputError("--stop-after: only coupled runs ([mechanics] and [flow]) stop after an iteration");
  std::error_code ec;
  const bool folder_is_new = !fs::exists(directory, ec);
  const output::RunFolder folder(directory, policy);
  // What summary.json holds once the run's result is written: a later failure (a figure that
  // cannot be drawn) does not replace it.
  std::optional<output::RunSummary> written;
  // The run writes its result before its figures and returns it: the same text is not written
  // (and flushed) twice.
  std::string written_text;
  const auto write_final_summary = [&folder, &written, &written_text](const output::RunSummary& summary) {
    output::CheckedSummary checked = output::format_checked_summary(summary);
    if (!checked.non_finite.empty())
      throw RunFailure(RunStatus::failed, describe_non_finite(checked.non_finite, folder), summary);
    if (written && checked.text == written_text) return;
    try {
      folder.write("summary.json", checked.text);
    } catch (const output::RunFolderError& e) {
      throw SummaryNotWritten(e.what(), summary);
    }
    written = summary;
    written_text = std::move(checked.text);
  };
  const RunContext context{s,          folder,     callbacks,           scenario_text,   resume,
                           stop_after, write_final_summary, mesh_cache, resume_transient, resume_coupled_transient};
  const bool resumed = resume || resume_transient || resume_coupled_transient;
  const RunKind kind = kind_of(s);
  if (const std::optional<std::string> capped = describe_capped_matrix(s)) spdlog::warn("{}", *capped);
  try {
    const output::RunSummary summary = kind == RunKind::coupled     ? run_coupled(context)
                                       : kind == RunKind::mechanics ? run_mechanics(context)
                                                                    : run_flow(context);
    write_final_summary(summary);
    folder.sync();  // the verdict under its name through a power cut (docs/output.md, "Durability")
    const RunStatus status = summary.status == "stopped" ? RunStatus::stopped : RunStatus::finished;
    return {status, summary.converged, summary.iterations, summary.message, summary, folder.path(), true};
  } catch (const scenario::ScenarioError&) {
    // Found while building the model: still bad input, and bad input leaves no run folder
    // behind. Nothing has been written by then; a folder this run made is removed.
    if (folder_is_new) fs::remove_all(directory, ec);
    throw;
  } catch (const SummaryNotWritten& e) {
    // An earlier run's summary.json (--overwrite) would be taken for this run's: removed. A
    // resumed run's is of the run it continues, and stays; so does anything not a file.
    if (!resumed && fs::is_regular_file(fs::symlink_status(folder.file("summary.json"), ec)))
      fs::remove(folder.file("summary.json"), ec);
    return report_unwritten_summary(e, kind, folder.path());
  } catch (const RunFailure& failure) {
    return record_failure(folder, failure.status(), failure.what(), failure.summary());
  } catch (const std::exception& e) {
    if (written)  // summary.json holds the run's result: a failure after it (a figure) leaves it be
      return {RunStatus::failed, false, written->iterations,
              fmt::format("{} (summary.json holds the run's result)", e.what()), *written, folder.path()};
    // A resumed run that could not take up its state (its model no longer fits the checkpoint)
    // has no result of its own: the folder's summary.json, of the run it continues, is kept.
    if (resumed)
      throw InputError(fmt::format("--resume {}: the run could not be continued: {}; its summary.json is left as it "
                                   "was",
                                   directory.string(), e.what()));
    // A failure before any result exists (meshing, a singular system): reported, never hidden.
    output::RunSummary summary;
    summary.title = s.title;
    summary.scenario = s.file.string();
    return record_failure(folder, RunStatus::failed, e.what(), summary, /*has_state=*/false);
  }
}

}  // namespace

std::optional<std::string> read_text_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

void clear_mesh_cache(const fs::path& folder) {
  try {
    mesh::remove_cache_entries(folder);
  } catch (const std::exception& e) {
    throw output::RunFolderError(fmt::format("cannot clear the mesh cache: {}", e.what()));
  }
}

RunKind kind_of(const scenario::Scenario& s) {
  return s.mechanics && s.flow ? RunKind::coupled : s.mechanics ? RunKind::mechanics : RunKind::flow;
}

RunResult run(const scenario::Scenario& scenario, const RunOptions& options, const Callbacks& callbacks) {
  std::optional<std::string> text = options.scenario_text;
  if (!text) text = read_text_file(scenario.file);
  if (!text) throw InputError(fmt::format("cannot read {}", scenario.file.string()));
  return run_in(scenario, options.folder,
                options.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse, *text,
                nullptr, options.stop_after, callbacks, options.mesh_cache);
}

RunResult resume(const ResumedRun& resumed, std::optional<int> stop_after, const Callbacks& callbacks) {
  // The folder's own files, continued.
  if (resumed.transient)
    return run_in(resumed.scenario, resumed.folder, output::ExistingFolder::Continue, resumed.scenario_text, nullptr,
                  stop_after, callbacks, std::nullopt, &*resumed.transient);
  if (resumed.coupled_transient)
    return run_in(resumed.scenario, resumed.folder, output::ExistingFolder::Continue, resumed.scenario_text, nullptr,
                  stop_after, callbacks, std::nullopt, nullptr, &*resumed.coupled_transient);
  return run_in(resumed.scenario, resumed.folder, output::ExistingFolder::Continue, resumed.scenario_text,
                &resumed.checkpoint, stop_after, callbacks);
}

std::string check_model(const scenario::Scenario& s) {
  if (const std::optional<std::string> capped = describe_capped_matrix(s)) spdlog::warn("{}", *capped);
  std::string geometry;
  if (s.geometry && !s.geometry->domain.empty()) {
    const ModelGeometry model = build_and_log_geometry(s);
    geometry = model.summary;
    if (s.mechanics) build_mechanics_model(s, blocks_of(s, model));
  } else if (s.mechanics) {
    build_mechanics_model(s, build_blocks(s));
  }
  if (s.flow && s.mesh && !s.mesh->file && s.geometry && !s.geometry->domain.empty()) {
    const std::string triangles = check_mesh_budget(s, make_mesh_request(s));
    geometry += (geometry.empty() ? "" : ", ") + std::string("mesh of ") + triangles;
  }
  if (s.mesh && s.mesh->file) {
    const mesh::TriangleMesh mesh = read_mesh_file(s);
    spdlog::debug("mesh.file: {} nodes, {} triangles", mesh.node_count(), mesh.triangle_count());
  }
  return geometry;
}

}  // namespace hydrodda::run
