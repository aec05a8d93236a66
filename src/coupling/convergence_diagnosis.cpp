#include "coupling/convergence_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "numerics/distinct_digits.hpp"

namespace hydrodda::coupling {

namespace {

std::string format_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", x);
  return text;
}

// The least-squares line log c = a + b x through (x_i, log c_i): its slope b (0 when the x
// do not spread), the residual sum of squares about it, and the largest residual |log c_i − a
// − b x_i| (how far, as a log factor, the worst value lies from the fitted geometric trend).
struct LogLine {
  double slope = 0.0;
  double misfit = 0.0;
  double largest_miss = 0.0;
};

LogLine fit_log_line(const std::vector<double>& x, const std::vector<double>& c) {
  const double n = static_cast<double>(c.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double y = std::log(std::max(c[i], 1e-300));
    sx += x[i];
    sy += y;
    sxx += x[i] * x[i];
    sxy += x[i] * y;
    syy += y * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (!(denominator > 0)) return {};
  const double b = (n * sxy - sx * sy) / denominator, a = (sy - b * sx) / n;
  double largest_miss = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    largest_miss = std::max(largest_miss, std::abs(std::log(std::max(c[i], 1e-300)) - a - b * x[i]));
  return {b, std::max(0.0, syy - a * sy - b * sxy), largest_miss};
}

// The pass numbers of c's values, the first being `first_pass`.
std::vector<double> passes_of(const std::vector<double>& c, std::size_t first_pass) {
  std::vector<double> k;
  for (std::size_t i = 0; i < c.size(); ++i) k.push_back(static_cast<double>(first_pass + i));
  return k;
}

// The least-squares slope of log c against the pass, as a factor per pass.
double rate_per_pass(const std::vector<double>& c) { return std::exp(fit_log_line(passes_of(c, 0), c).slope); }

// Whether that geometric trend explains c: every value lies within a factor 2 of it. A norm that
// jumps by more (0.21, 0.03, 0.21, 0.03, 0.02) has a fitted rate that predicts nothing.
bool follows_its_trend(const std::vector<double>& c) {
  return fit_log_line(passes_of(c, 0), c).largest_miss <= std::log(2.0);
}

// Whether c falls as a power of the pass rather than geometrically: log c is nearer a line in
// log k than in k, with a slope above −2 (k the pass number from the run's start, `first_pass`
// that of c's first value). A block pushed the same way by the same step every pass has a change
// relative to its displacement of 1/k: it never converges, though its fitted rate falls.
bool falls_as_a_power(const std::vector<double>& c, std::size_t first_pass) {
  if (c.size() < 4) return false;
  const std::vector<double> k = passes_of(c, first_pass);
  std::vector<double> log_k;
  for (double pass : k) log_k.push_back(std::log(pass));
  const LogLine power = fit_log_line(log_k, c);
  return power.misfit < fit_log_line(k, c).misfit && power.slope > -2.0;
}

// The share of successive pass-to-pass changes of c that change sign.
double alternation(const std::vector<double>& c) {
  int turns = 0, pairs = 0;
  for (std::size_t i = 2; i < c.size(); ++i) {
    const double before = c[i - 1] - c[i - 2], after = c[i] - c[i - 1];
    ++pairs;
    turns += before * after < 0 ? 1 : 0;
  }
  return pairs > 0 ? static_cast<double>(turns) / pairs : 0.0;
}

// The least period p in 2..5 after which the last values of c come back: the last p values
// rise and fall (a cycle, not a steady decay or growth) and each is within 10% of the value p
// passes before it. 0 when there is none, or fewer than two cycles to compare.
int cycle_period(const std::vector<double>& c) {
  const std::size_t n = c.size();
  for (std::size_t p = 2; p <= 5 && 2 * p <= n; ++p) {
    bool rises = false, falls = false, returns = true;
    for (std::size_t i = n - p; i < n; ++i) {
      rises = rises || c[i] > c[i - 1];
      falls = falls || c[i] < c[i - 1];
      returns = returns && std::abs(c[i] - c[i - p]) <= 0.1 * std::max(c[i], c[i - p]);
    }
    if (rises && falls && returns) return static_cast<int>(p);
  }
  return 0;
}

// The relaxation to try next: 0.5, or half of one already at 0.5 or below.
std::string smaller_relaxation(double relaxation) {
  return "coupling.relaxation = " + format_number(relaxation > 0.5 ? 0.5 : 0.5 * relaxation);
}

// What to try when the loop swings or jumps between states rather than settling: an
// acceleration if it had none, else a smaller relaxation or more steps, and that a jacking joint
// may have no steady state.
std::string chattering_joints(const LoopAsRun& loop) {
  return "the joints open and shut from pass to pass (a median of " + std::to_string(loop.crossings_switched) +
         " of their crossings with fluid elements switched between open and closed, and " +
         std::to_string(loop.contacts_changed) +
         " contacts changed state, a pass): a relaxation or acceleration of the heads seldom settles such a loop "
         "(none did on the faulted seal of docs/studies/2026-11-29-loop-convergence.md; Aitken's did on the "
         "untuned seal of docs/studies/2026-11-30-untuned-seal-fixed-point.md from a fresh start at 0.86 and 0.93 "
         "of its lift-off, not at 0.97 nor along its loading path), and its answer holds only to how far it moved "
         "over these passes" +
         std::string(loop.joints_by_point
                         ? "; its joints are read point by point (joint.hydraulic_opening = \"local\"): where the rock's "
                           "stress holds them shut, try \"face\", under which a face that carries a force is closed along "
                           "its length and the wedges the blocks' uniform strains leave open no longer conduct (it settled "
                           "the faulted seal and the untuned seal: docs/coupling.md, \"Joint hydraulic apertures\")"
                         : "");
}

std::string unsettled_advice(const LoopAsRun& loop) {
  if (loop.crossings_switched >= kChatteringCrossings) return chattering_joints(loop);
  if (loop.acceleration == "none")
    return "try coupling.acceleration = \"anderson\" (or \"aitken\"), or " + smaller_relaxation(loop.relaxation);
  return "the " + std::string(loop.acceleration) + " acceleration did not settle it: " +
         (loop.relaxation < 1.0 ? "with coupling.relaxation = " + format_number(loop.relaxation) + " too; " : "") +
         "try " + smaller_relaxation(loop.relaxation) +
         ", or more mechanics.steps per pass; a "
         "joint that jacks open and shut from pass to pass (history.csv's largest_opening) may have no steady "
         "state under this load";
}

// Whether the loop's rises come from joint crossings at their opening threshold (the
// at-threshold rule of convergence_diagnosis.hpp) over the fitted passes first..n − 1 of the
// failed norm c: no contact changed state in them, a crossing switched in some, every rise
// c_k > c_{k−1} follows a pass k − 1 that switched one, and the norm's least over the second
// half is at most its largest over the first (not growing). The cycles this reads are those of
// the untuned seal near its breach (docs/studies/2026-11-30-untuned-seal-fixed-point.md).
struct Threshold {
  bool holds = false;
  int fewest = 0, most = 0;  // crossings switched a pass, over the fitted passes
};
Threshold crossings_at_threshold(const std::vector<double>& c, std::size_t first, const LoopAsRun& loop) {
  const std::vector<int>& crossings = loop.crossings_by_pass;
  const std::vector<int>& contacts = loop.contacts_by_pass;
  if (crossings.size() != c.size() || contacts.size() != c.size() || c.size() - first < 4) return {};
  Threshold t{false, crossings[first], crossings[first]};
  for (std::size_t k = first; k < c.size(); ++k) {
    if (contacts[k] > 0) return {};
    t.fewest = std::min(t.fewest, crossings[k]);
    t.most = std::max(t.most, crossings[k]);
    if (k > first && c[k] > c[k - 1] && crossings[k - 1] == 0) return {};
  }
  const std::size_t middle = first + (c.size() - first) / 2;
  const double early_high = *std::max_element(c.begin() + static_cast<std::ptrdiff_t>(first),
                                              c.begin() + static_cast<std::ptrdiff_t>(middle));
  const double late_low = *std::min_element(c.begin() + static_cast<std::ptrdiff_t>(middle), c.end());
  t.holds = t.most > 0 && late_low <= early_high;
  return t;
}

// What a loop kicked back by crossings at their threshold is worth, and what may still help.
std::string describe_threshold(const Threshold& t, const std::vector<double>& last, const std::string& norms,
                               const std::string& name, const LoopAsRun& loop) {
  const auto [low, high] = std::minmax_element(last.begin(), last.end());
  return norms + " stayed above the tolerance: the " + name + " change (between " + format_number(*low) + " and " +
         format_number(*high) + " over the last " + std::to_string(last.size()) +
         " passes) rose only after passes in which joint crossings with fluid elements switched between open and "
         "closed (" + std::to_string(t.fewest) + " to " + std::to_string(t.most) +
         " a pass), while no contact changed state: crossings at their opening threshold, which the heads shut "
         "while they are open and open while they are shut, their hydraulic aperture jumping there, so that the "
         "loop may have no fixed point at this tolerance; a smaller relaxation does not remove the jump" +
         (loop.acceleration == "none"
              ? std::string(", coupling.acceleration = \"aitken\" may land on a state where none sits at its "
                            "threshold, or may not")
              : std::string()) +
         " (docs/studies/2026-11-30-untuned-seal-fixed-point.md), and the answer holds only to how far it moved over "
         "these passes";
}

// A loop that swings, jumps or drifts after the whole fluid load went on at once: its first pass
// threw the blocks from the state as built, and the joints that pass opened may chatter from
// then on. Raised over three passes instead, the load met the layered faulted seal's blocks near
// an equilibrium under part of it, and its loop settled in 7-9 passes at 0.92-1.00 of its
// jacking head, where the sudden load's swung or drifted for 30
// (docs/studies/2026-11-29-default-ramp.md). The ramp scales the whole fluid load, the water
// that floats a layer too, and friction keeps each path's state: said, not hidden.
std::string ramp_advice(const LoopAsRun& loop) {
  if (!loop.sudden_load) return "";
  return "; the whole fluid load went on at once in the first pass (coupling.ramp_passes = 1): try "
         "coupling.ramp_passes = 3, which raises it over three passes (its excess over still water: coupling.ramp) "
         "so that the blocks meet it from near an equilibrium under part of it (friction may then hold them in "
         "another state, and a layer the overpressure holds up may sink under part of it: docs/coupling.md, "
         "\"Relaxation, acceleration and the load ramp\")";
}

// Whether the widest opening went up and down over the last passes rather than one way: it
// ended less than a third of the way it travelled from where it began (net < path / 3 over the
// last 10 passes, the first pass left out). A drift whose openings wander so comes to rest each
// pass about one state, not farther on: the layered faulted seal at 0.95 H* at once, its widest
// opening 0.406–0.414 mm over its last 10 passes (docs/studies/2026-11-29-default-ramp.md).
struct Wander {
  bool wanders = false;
  double low = 0.0, high = 0.0;
  int passes = 0;
};
Wander opening_wander(const std::vector<double>& opening) {
  if (opening.size() < 5) return {};
  const std::size_t first = std::max<std::size_t>(1, opening.size() > 10 ? opening.size() - 10 : 1);
  double path = 0.0;
  for (std::size_t k = first + 1; k < opening.size(); ++k) path += std::abs(opening[k] - opening[k - 1]);
  const double net = std::abs(opening.back() - opening[first]);
  const auto [low, high] = std::minmax_element(opening.begin() + static_cast<std::ptrdiff_t>(first), opening.end());
  return {path > 0.0 && net < path / 3.0, *low, *high, static_cast<int>(opening.size() - first)};
}

// "0.2629 mm and 0.2631 mm": to 3 figures, or as many more as tell the two apart; openings that
// wander by a few per cent differ at 3.
std::string format_millimetre_range(double low, double high) {
  const std::array<std::string, 2> ends = numerics::format_apart(low * 1e3, high * 1e3, 3);
  return ends[0] + " mm and " + ends[1] + " mm";
}

// What a drift's blocks do, by the passes' widest openings when known.
std::string drifting_blocks(const LoopAsRun& loop) {
  if (!loop.settling)
    return "the blocks keep moving from pass to pass; try coupling.settle = true (each pass steps on until the "
           "blocks are at rest) or more mechanics.steps per pass, or check that the fluid load leaves the blocks an "
           "equilibrium";
  if (const Wander w = opening_wander(loop.largest_opening); w.wanders)
    return "the blocks come to rest every pass, about one state rather than farther on (history.csv's "
           "largest_opening went up and down between " + format_millimetre_range(w.low, w.high) + " over the last " +
           std::to_string(w.passes) + " passes)";
  return "the blocks keep moving from pass to pass, each pass coming to rest a little farther on; check that the "
         "fluid load leaves the blocks an equilibrium (history.csv's largest_opening shows a joint that keeps opening)";
}

// Blocks that no pass brought to rest: no pass's fluid load has an equilibrium where they are.
std::string describe_never_at_rest(int passes, const std::string& name, const std::string& level) {
  return "the blocks came to rest in none of the last " + std::to_string(passes) +
         " passes (each ran its mechanics.steps and its settling steps with them still moving; the " + name +
         " change near " + level +
         "): under each pass's fluid load they have no equilibrium, and the loop has not reached the state where the "
         "load that moves them falls away (blocks lifted by a seepage past the critical gradient float only where the "
         "load falls as they rise; a jacked joint holds only where its pressure falls as it opens). The state written "
         "is the last pass's, with the blocks still moving; an acceleration of the heads does not see where the blocks "
         "are: follow them in measure.csv and history.csv's largest_opening";
}

}  // namespace

// The median over the passes from `first` of two_back / change: small when the heads keep
// returning to those of two passes before.
double return_ratio(const std::vector<double>& change, const std::vector<double>& two_back, std::size_t first) {
  std::vector<double> ratios;
  for (std::size_t k = std::max<std::size_t>(first, 2); k < change.size(); ++k)
    if (change[k] > 0) ratios.push_back(two_back[k] / change[k]);
  if (ratios.size() < 3) return 1.0;
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2), ratios.end());
  return ratios[ratios.size() / 2];
}

ConvergenceDiagnosis diagnose_non_convergence(const std::vector<double>& head_change,
                                              const std::vector<double>& displacement_change,
                                              const std::vector<double>& head_change_two_passes, double tolerance,
                                              const LoopAsRun& loop) {
  if (head_change.empty() || head_change.size() != displacement_change.size() ||
      head_change.size() != head_change_two_passes.size())
    throw std::invalid_argument("convergence diagnosis: one head and one displacement change per pass are needed");
  ConvergenceDiagnosis d;
  d.head_failed = head_change.back() >= tolerance;
  d.displacement_failed = displacement_change.back() >= tolerance;
  const bool head_worse = head_change.back() / tolerance >= displacement_change.back() / tolerance;
  const std::vector<double>& all = head_worse ? head_change : displacement_change;
  const std::size_t first = std::max<std::size_t>(1, all.size() > 10 ? all.size() - 10 : 1);
  const std::size_t first_index = std::min(first, all.size() - 1);
  const std::size_t first_pass = first_index + 1;  // passes count from 1
  std::vector<double> last(all.begin() + static_cast<std::ptrdiff_t>(first_index), all.end());
  d.rate = rate_per_pass(last);
  d.period = cycle_period(last);
  const bool two_states = return_ratio(head_change, head_change_two_passes, first) < 0.1;
  const bool swinging = two_states || alternation(last) >= 0.6;
  if (!d.head_failed && !d.displacement_failed) d.behaviour = NonConvergence::not_counted;
  else if (head_change.size() < 4) d.behaviour = NonConvergence::too_few_passes;
  else if (loop.settling && loop.passes_not_at_rest >= std::min<int>(kPassesNotAtRest, head_change.size() - 1))
    d.behaviour = NonConvergence::never_at_rest;
  else if (d.period > 0) d.behaviour = NonConvergence::oscillating;
  else if (last.size() >= 4 && swinging && d.rate > 0.95) d.behaviour = NonConvergence::oscillating;
  else if (d.rate > 1.05) d.behaviour = NonConvergence::diverging;
  else if (last.size() >= 4 && !follows_its_trend(last)) d.behaviour = NonConvergence::erratic;
  else if (d.rate < 0.95 && falls_as_a_power(last, first_pass)) d.behaviour = NonConvergence::drifting;
  else if (d.rate < 0.95) d.behaviour = NonConvergence::still_converging;
  else d.behaviour = NonConvergence::drifting;
  const Threshold threshold = crossings_at_threshold(all, first_index, loop);
  const bool unsettled = d.behaviour == NonConvergence::oscillating || d.behaviour == NonConvergence::erratic ||
                         d.behaviour == NonConvergence::diverging || d.behaviour == NonConvergence::drifting;
  if (unsettled && threshold.holds) d.behaviour = NonConvergence::at_threshold;

  const bool accelerated = loop.acceleration != "none";
  std::string norms = d.head_failed && d.displacement_failed ? "the head and displacement changes"
                      : d.head_failed                        ? "the head change"
                                                             : "the displacement change";
  const std::string name = head_worse ? "head" : "displacement";
  const std::string level = format_number(all.back());
  switch (d.behaviour) {
    case NonConvergence::not_counted:
      // The run says why the pass could not count (steps cut short, blocks not at rest).
      d.text = "both changes were under the tolerance at the last pass (the head change at " +
               format_number(head_change.back()) + ", the displacement change at " +
               format_number(displacement_change.back()) + "), but that pass could not count";
      break;
    case NonConvergence::too_few_passes:
      d.text = norms + " stayed above the tolerance after " + std::to_string(head_change.size()) +
               " passes, too few to tell how the loop goes (the " + name + " change at " + level +
               "): raise coupling.max_iterations";
      break;
    case NonConvergence::never_at_rest:
      d.text = describe_never_at_rest(loop.passes_not_at_rest, name, level);
      break;
    case NonConvergence::oscillating:
      // Two states only where the heads come back to those of two passes before; a norm that
      // rises and falls by turns may come back every third pass or not at all.
      d.text = norms + " stayed above the tolerance: the loop oscillates (the " + name + " change near " + level +
               (d.period > 2   ? ", coming back to the same values every " + std::to_string(d.period) + " passes"
                : two_states   ? std::string(", the blocks swinging between two states pass after pass; the state "
                                             "written is the last pass's, one of the two")
                : d.period == 2 ? std::string(", coming back to the same values every 2 passes")
                                : std::string(", rising and falling by turns")) +
               "); " + unsettled_advice(loop) + ramp_advice(loop);
      break;
    case NonConvergence::erratic: {
      const auto [low, high] = std::minmax_element(last.begin(), last.end());
      d.text = norms + " stayed above the tolerance: the " + name + " change jumps from pass to pass (between " +
               format_number(*low) + " and " + format_number(*high) + " over the last " +
               std::to_string(last.size()) +
               " passes, at " + level + "), with no steady trend, so no number of passes can be told; " +
               unsettled_advice(loop) + ramp_advice(loop);
      break;
    }
    case NonConvergence::diverging:
      d.text = norms + " stayed above the tolerance: the " + name + " change diverges (×" + format_number(d.rate) +
               " a pass, to " + level + "); try coupling.ramp_passes = 5 and coupling.relaxation = 0.3; if it still "
               "grows, the fluid load may exceed what the blocks' supports and contacts can hold";
      break;
    case NonConvergence::still_converging: {
      d.passes_needed = static_cast<int>(std::ceil(std::log(tolerance / all.back()) / std::log(d.rate)));
      d.text = norms + " stayed above the tolerance: the " + name + " change still falls (×" +
               format_number(d.rate) + " a pass, at " + level + "); about " + std::to_string(d.passes_needed) +
               " more passes would reach it: raise coupling.max_iterations" +
               (accelerated ? std::string() : std::string(", or try coupling.acceleration = \"anderson\""));
      break;
    }
    case NonConvergence::at_threshold:
      d.text = describe_threshold(threshold, last, norms, name, loop) + ramp_advice(loop);
      break;
    case NonConvergence::drifting:
      d.text = norms + " stayed above the tolerance: the " + name + " change drifts (" +
               (d.rate < 0.95 ? "at " + level + ", falling only as a power of the passes, not geometrically"
                              : "near " + level + ", neither falling nor alternating") +
               "): " + drifting_blocks(loop) +
               (loop.crossings_switched >= kChatteringCrossings ? "; " + chattering_joints(loop) : std::string()) +
               ramp_advice(loop);
      break;
  }
  return d;
}

}  // namespace hydrodda::coupling
