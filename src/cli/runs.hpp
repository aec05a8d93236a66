#pragma once
// The kinds of run: each builds its engines from the scenario, runs them, and writes the run
// folder as it goes. They return the summary; run_command writes it.

#include <optional>
#include <string>

#include "cli/progress.hpp"
#include "output/checkpoint.hpp"
#include "output/run_folder.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::cli {

struct RunContext {
  const scenario::Scenario& scenario;
  const output::RunFolder& folder;
  Progress& progress;
  // The scenario's text as read: coupled runs save it as scenario.toml for --resume.
  std::string scenario_text;
  // A coupled run continued from its checkpoint (run --resume), or none.
  const output::RunCheckpoint* resume = nullptr;
  // Coupled runs: stop after this coupling iteration (run --stop-after), or run to the end.
  std::optional<int> stop_after;
};

// A run that stopped before its end: what failed and where. The summary holds the last good
// state and is written with converged = false.
class RunFailure : public std::runtime_error {
 public:
  RunFailure(const std::string& message, output::RunSummary summary)
      : std::runtime_error(message), summary_(std::move(summary)) {}
  const output::RunSummary& summary() const { return summary_; }

 private:
  output::RunSummary summary_;
};

output::RunSummary run_mechanics(const RunContext& context);
output::RunSummary run_flow(const RunContext& context);
output::RunSummary run_coupled(const RunContext& context);

}  // namespace hydrodda::cli
