#pragma once
// Why a staggered loop that ran out of passes did not converge: which norm stayed above the
// tolerance, how it behaved over the last passes, and what to try.

#include <string>
#include <string_view>
#include <vector>

namespace hydrodda::coupling {

enum class NonConvergence {
  still_converging,  // falling steadily, too slowly for the passes allowed
  oscillating,       // rising and falling by turns: the loop cycles between states
  drifting,          // neither falling nor alternating: the blocks keep moving
  diverging,         // rising
  erratic,           // jumping from pass to pass more than any steady trend explains
  too_few_passes,    // fewer than four passes: too few to tell
  never_at_rest,     // the blocks came to rest in none of the last passes (settling passes)
  not_counted,       // both norms under the tolerance at the last pass, which could not count
  at_threshold,      // settling between passes, kicked back each time joint crossings switch
};

struct ConvergenceDiagnosis {
  NonConvergence behaviour = NonConvergence::drifting;
  bool head_failed = false;
  bool displacement_failed = false;
  double rate = 1.0;       // the failed norm's mean factor per pass over the last passes
  int passes_needed = 0;   // still_converging: about how many more passes it needs
  int period = 0;          // oscillating: the passes after which the norm comes back (0: not found)
  std::string text;        // one sentence: the norm, the behaviour, what to try
};

// From the norms of every pass (history.csv's head_change, displacement_change and
// head_change_two_passes) and the tolerance. When neither norm is above the tolerance at the
// last pass (a pass that could not count: its steps were cut short, or its blocks were not at
// rest), their trend says nothing: not counted. Otherwise the failed norm is the larger of the
// two (relative to the tolerance) at the last pass; its last passes (up to ten, the first left out) are
// fitted by log c = a + k log r:
//   too few passes when fewer than three are fitted (a run of three passes or less);
//   oscillating when the norm cycles: its last p values rise and fall and each is within 10%
//   of the value p passes before, for a period p of 2 to 5 passes (two whole cycles fitted; a
//   fit over a window that is not a whole number of cycles reads as a fall or a rise);
//   oscillating also when it falls by less than 5% a pass and either the heads come back to those of
//   two passes before (the median of head_change_two_passes / head_change over those passes is
//   under 0.1: a swing between two states shows a steady change) or the norm rises and falls by
//   turns (its pass-to-pass changes alternate in sign at least 60% of the time);
//   diverging when r > 1.05; erratic when some fitted value lies more than a factor 2 from the
//   fitted trend (its rate then predicts nothing); drifting when r < 0.95 but log c lies nearer a line in log k than in
//   k with a slope above −2 (it falls only as a power of the pass k); still converging when
//   r < 0.95 otherwise; drifting otherwise.
// at threshold, in place of oscillating, erratic, diverging or drifting, when the passes' joint
// crossings and contact changes are known and, over the fitted passes, no contact changed state,
// some joint crossing switched between open and closed, every rise of the norm came in the pass
// after one that switched a crossing (the flow of pass k sees the blocks pass k − 1 left), and
// the norm did not grow through them (its least over their second half is at most its largest
// over the first): the loop settles while the crossings stand still and is kicked back when one
// switches. The hydraulic aperture jumps at a crossing's opening threshold, so a crossing that
// the heads open while it is shut and shut while it is open may leave the loop no fixed point.
// never at rest as above (kPassesNotAtRest);
// `loop` is the loop as run: the advice names an acceleration only to a loop that had none,
// settling passes only to a loop whose passes did not settle, a relaxation below the one it had,
// and the load ramp only to a loop whose load went on at once.
struct LoopAsRun {
  std::string_view acceleration = "none";  // coupling.acceleration: "none", "aitken", "anderson"
  double relaxation = 1.0;                 // coupling.relaxation
  bool settling = false;                   // coupling.settle
  int passes_not_at_rest = 0;              // the last passes in a row that ended with the blocks moving
  // history.csv's joint_crossings_switched and contact_state_changes, each the median over the
  // last passes (those the norms are fitted over; 0 without joint apertures).
  int crossings_switched = 0;
  int contacts_changed = 0;
  // Some joint type reads each point of a face by its own gap (`[joint] hydraulic_opening =
  // "local"`): joints that chatter are then told of "face", under which the wedges the blocks'
  // uniform strains leave open under compression no longer conduct.
  bool joints_by_point = false;
  // The whole fluid load went on at once in the first pass (coupling.ramp_passes = 1, the loop
  // unconverged in a steady run's first load step): a loop that swings, jumps or drifts is then
  // told to try the ramp too.
  bool sudden_load = false;
  // history.csv's largest_opening (m), one a pass; empty when not known.
  std::vector<double> largest_opening;
  // history.csv's joint_crossings_switched and contact_state_changes, one a pass (empty when
  // not known, or without joint apertures): the at-threshold rule reads them pass by pass.
  std::vector<int> crossings_by_pass;
  std::vector<int> contacts_by_pass;
};
// A loop that oscillates or jumps while a median of at least this many joint crossings switch
// between open and closed every pass is told that its joints chatter rather than sent to a
// relaxation or an acceleration of the heads: on the faulted seal (100–200 crossings a pass)
// none of them settles the loop (docs/studies/2026-11-29-loop-convergence.md); a loop on its
// way switches none after its first passes.
inline constexpr int kChatteringCrossings = 10;
// With settling passes, the blocks came to rest in none of the last kPassesNotAtRest passes
// (or in none of the passes after the first, when fewer were run): no pass reached the
// equilibrium of its fluid load, so the norms measure how far the blocks creep in a pass, not
// how far the loop is from a fixed point. Taken after "too few passes", before every other rule.
inline constexpr int kPassesNotAtRest = 5;
ConvergenceDiagnosis diagnose_non_convergence(const std::vector<double>& head_change,
                                              const std::vector<double>& displacement_change,
                                              const std::vector<double>& head_change_two_passes, double tolerance,
                                              const LoopAsRun& loop = {});

}  // namespace hydrodda::coupling
