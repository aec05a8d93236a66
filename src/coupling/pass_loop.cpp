#include "coupling/pass_loop.hpp"

namespace hydrodda::coupling {

LoopResult run_passes(PassRunner& runner, const LoopLimits& limits, PassObserver& observer) {
  LoopResult result;
  while (runner.iterations() < limits.max_passes) {
    // The stop request first: an interrupt at the pass a run was to stop after is an interrupt.
    if (observer.stop_requested()) {
      result.end = LoopEnd::stop_requested;
      return result;
    }
    if (limits.stop_after && runner.iterations() >= *limits.stop_after) {
      result.end = LoopEnd::stopped_after;
      return result;
    }
    result.last_pass = runner.run_pass();
    ++result.passes_run;
    observer.after_pass(*result.last_pass);
    const PassReport& pass = *result.last_pass;
    // Divergence before convergence: a change that grew tenfold is news even when under the
    // tolerance.
    if (pass.diverging) {
      result.end = LoopEnd::diverging;
      return result;
    }
    if (!pass.escaping.empty()) {
      result.end = LoopEnd::escaping;
      return result;
    }
    if (pass.converged) {
      result.end = LoopEnd::converged;
      return result;
    }
  }
  result.end = LoopEnd::max_passes;
  return result;
}

}  // namespace hydrodda::coupling
