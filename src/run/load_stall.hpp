#pragma once
// A static run whose load rises in time and that cannot raise it further. Past the largest load
// the rock holds (a disc splitting under a rising pressure), every try of the next step breaks
// bonds, runs their crack on in its open–close passes and fails to settle, and is cut; a cut
// short enough is kept (its load barely above the last, its bonds whole), and the next, longer,
// fails again. The times kept approach a limit as a series that converges, and the run would
// creep towards it for as long as it is left. At such a stall, the bonds the last breaking try
// broke break at the state held (dda::System::break_bonds_of_last_cut_try), and the run goes on
// from there: the crack runs on through the steps that follow, as under a load held. A stall
// whose tries break no bond still whole ends the run at the last load held, with no equilibrium.

#include <deque>
#include <string>

#include "dda/system.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A stall: the last kStalledSteps kept steps, each shorter than `mechanics.time_step`, together
// advanced the time by less than one time step while the loads changed, at least half of them
// were kept only after a cut (tries that lengthened the step failed again), and a cut try of
// theirs broke bonds. A step cut once grows back by 1.5 a step (0.3, 0.45, 0.675 then the
// whole, past one time step in three); one cut deep grows back in steps that are short but not cut.
inline constexpr int kStalledSteps = 10;

class LoadStallWatch {
 public:
  explicit LoadStallWatch(const scenario::MechanicsDefinition& mechanics) : mechanics_(mechanics) {}

  // After each kept step of a static run; true once the last kStalledSteps were a stall.
  bool update(const dda::StepReport& step);
  // After a stall's bonds are broken: the steps from here on are a new window.
  void restart() { window_.clear(); }

  // The stalled steps: the time they started from, how far they advanced it, their shortest
  // length, how many were cut, and the most bonds a cut try of theirs broke.
  struct Stall {
    double from = 0.0;
    double advanced = 0.0;
    double shortest = 0.0;
    int cut = 0;
    int most_breaks = 0;
  };
  Stall stall() const;

 private:
  const scenario::MechanicsDefinition& mechanics_;
  std::deque<dda::StepReport> window_;  // the last kept steps, each short, under changing loads
};

// The bonds broken at a run's stalls: how many, and the time of the first stall (s).
struct StallBreaks {
  int bonds = 0;
  double first = 0.0;
};

// The message of a run ended by a stall at time `t` (the last load held): the loads then (as
// the scenario spells them), how the steps stalled, and the bonds broken at earlier stalls.
// `reactions`: the prescribed displacements' at t, as history.csv names them ("" without any).
std::string describe_load_stall(const scenario::Scenario& s, const LoadStallWatch::Stall& stall, double t,
                                const std::string& reactions, const StallBreaks& broken);

}  // namespace hydrodda::run
