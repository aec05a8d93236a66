#pragma once
// The kinds of run, as run() dispatches them: each builds its model from the scenario, runs it,
// and writes the run folder as it goes. They return the summary, which run() writes; one that reached
// its end writes it first itself (RunContext::write_summary), before drawing its figures.

#include <functional>
#include <filesystem>
#include <optional>
#include <string>

#include "fractures/fracture_results.hpp"
#include "output/checkpoint.hpp"
#include "output/run_folder.hpp"
#include "output/summary.hpp"
#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

struct RunContext {
  const scenario::Scenario& scenario;
  const output::RunFolder& folder;
  const Callbacks& callbacks;
  // The scenario's text as read: coupled runs save it as scenario.toml for resume.
  std::string scenario_text;
  // A coupled run continued from its checkpoint (resume), or none.
  const output::RunCheckpoint* resume = nullptr;
  // Coupled runs: stop after this coupling iteration, or run to the end.
  std::optional<int> stop_after;
  // Writes summary.json for a run that reached its end (throws RunFailure when a result is not
  // finite). Called before the figures are drawn, so that a run killed while drawing them
  // leaves a finished folder, not a converged checkpoint with no summary.
  std::function<void(const output::RunSummary&)> write_summary;
  // A folder of meshes shared with other runs (a sweep's), or none: mesh anew.
  std::optional<std::filesystem::path> mesh_cache;
  // A transient flow-only run continued from its checkpoint (resume), or none.
  const output::TransientCheckpoint* resume_transient = nullptr;
  // A coupled transient run continued from its checkpoint (resume), or none.
  const output::CoupledTransientCheckpoint* resume_coupled_transient = nullptr;

  void report(const ProgressReport& report) const {
    if (callbacks.progress) callbacks.progress(report);
  }
  bool stop_requested() const { return callbacks.stop_requested && callbacks.stop_requested(); }
};

// Callbacks::unstoppable_stage told for as long as it lives.
class UnstoppableStage {
 public:
  explicit UnstoppableStage(const Callbacks& callbacks) : tell_(callbacks.unstoppable_stage) {
    if (tell_) tell_(true);
  }
  ~UnstoppableStage() {
    if (tell_) tell_(false);
  }
  UnstoppableStage(const UnstoppableStage&) = delete;
  UnstoppableStage& operator=(const UnstoppableStage&) = delete;

 private:
  const std::function<void(bool)>& tell_;
};

// Callbacks::model_at_end told when it goes out of scope: declared after the model (and the
// fractures' results), so that it is told before they are destroyed, on every way out.
template <class Model>
class TellModelAtEnd {
 public:
  TellModelAtEnd(const Callbacks& callbacks, const Model& model, const std::optional<fractures::FractureState>& fractures)
      : tell_(&callbacks.model_at_end), model_(model), fractures_(fractures) {}
  ~TellModelAtEnd() {
    if (!tell_ || !*tell_) return;
    try {
      (*tell_)(ModelAtEnd{&model_, fractures_ ? &*fractures_ : nullptr});
    } catch (...) {
      // A front end's failure to read the fields must not turn a finished run into a crash.
    }
  }
  // Tells nothing after all: the run goes on in another model (a round of mesh.refine_tips).
  void dismiss() { tell_ = nullptr; }
  TellModelAtEnd(const TellModelAtEnd&) = delete;
  TellModelAtEnd& operator=(const TellModelAtEnd&) = delete;

 private:
  const std::function<void(const ModelAtEnd&)>* tell_;
  const Model& model_;
  const std::optional<fractures::FractureState>& fractures_;
};

// A run that stopped before its end: what failed or stopped it, and where. The summary holds
// the last good state and is written with converged = false.
class RunFailure : public std::runtime_error {
 public:
  RunFailure(RunStatus status, const std::string& message, output::RunSummary summary)
      : std::runtime_error(message), status_(status), summary_(std::move(summary)) {}
  RunStatus status() const { return status_; }  // interrupted or failed
  const output::RunSummary& summary() const { return summary_; }

 private:
  RunStatus status_;
  output::RunSummary summary_;
};

output::RunSummary run_mechanics(const RunContext& context);
output::RunSummary run_flow(const RunContext& context);
// The flow-only run of a scenario with [flow.transient] (transient_flow.hpp); run_flow hands it on.
output::RunSummary run_transient_flow(const RunContext& context);
output::RunSummary run_coupled(const RunContext& context);
// The coupled run of a scenario with [flow.transient] (coupled_transient.hpp); run_coupled hands it on.
output::RunSummary run_coupled_transient(const RunContext& context);

}  // namespace hydrodda::run
