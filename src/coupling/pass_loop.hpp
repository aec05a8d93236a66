#pragma once
// The bounded loop over coupling passes (OpenGeoSys's staggered scheme, DESIGN.md §2.3):
//   for each pass, until a limit:
//     stop requested?  → interrupted        (asked before every pass)
//     stop_after hit?  → stopped
//     run the pass (its convergence, divergence and escape are measured by the pass itself)
//     tell the observer (history, fields, checkpoint, ...)
//     diverging? blocks escaping? converged?  → end
//   max_passes passes finished → max_passes
// What a pass runs and what is recorded after it are not the loop's: the runner (the staggered
// loop itself, or a stand-in) runs passes, and the observer records them. A pass that throws
// ends the loop with its exception; the runner's abandon_pass() is the caller's to call.

#include <optional>

#include "coupling/pass_report.hpp"

namespace hydrodda::coupling {

struct LoopLimits {
  int max_passes = 100;           // counted from the first pass ever (a resumed loop's included)
  std::optional<int> stop_after;  // end once this many passes have finished (a run to resume)
};

// Called by the loop between passes. `after_pass` is where a run records the pass, and where
// a later physics (bond breakage) changes the model before the next pass.
class PassObserver {
 public:
  virtual ~PassObserver() = default;
  // Asked before every pass, first: true ends the loop (LoopEnd::stop_requested).
  virtual bool stop_requested() { return false; }
  // After every finished pass, with what it measured.
  virtual void after_pass(const PassReport& report) = 0;
};

// What the loop drives: one pass at a time, and how many have finished.
class PassRunner {
 public:
  virtual PassReport run_pass() = 0;
  virtual int iterations() const = 0;

 protected:
  ~PassRunner() = default;
};

enum class LoopEnd {
  converged,       // the last pass converged
  max_passes,      // LoopLimits::max_passes finished without convergence
  stopped_after,   // LoopLimits::stop_after passes finished
  stop_requested,  // PassObserver::stop_requested
  diverging,       // the last pass's change grew too long (PassReport::diverging)
  escaping,        // the last pass left blocks beyond their size (PassReport::escaping)
};

struct LoopResult {
  LoopEnd end = LoopEnd::max_passes;
  int passes_run = 0;                 // by this call
  std::optional<PassReport> last_pass;  // of this call; none when it ran none
};

// Runs passes of `runner` within `limits`, telling `observer` after each.
LoopResult run_passes(PassRunner& runner, const LoopLimits& limits, PassObserver& observer);

}  // namespace hydrodda::coupling
