#pragma once
// What a breach step's coupling passes did, pass by pass: whether each one's blocks came to rest
// at the full time step, and each flow region's K_eff/K_m after it. From it a step that did not
// converge is told apart (docs/breach.md, "What holds"):
//   - its blocks came to rest in each of its last passes: the model holds mechanically, its
//     loop swings; the answer is the range of K_eff/K_m over those passes (held, unsettled);
//   - its blocks came to rest in none of kPassesNotAtRest passes in a row, the last of them
//     moving at the full time step or stalled on DDA steps cut short that no longer move them:
//     they reached no state of rest (not at rest), and the step ends there. A pass whose steps
//     were cut short but still moved the blocks past the loop's tolerance is on its way through
//     the chatter that cut them: the step goes on (docs/breach.md, "What holds").

#include <optional>
#include <string>
#include <vector>

namespace hydrodda::breach {

// Passes in a row whose blocks did not come to rest after which a step ends `not at rest`
// (as the loop's own diagnosis, coupling::kPassesNotAtRest).
inline constexpr int kPassesNotAtRest = 5;
// Passes over which an unsettled step's blocks must have rested and its K_eff/K_m is ranged (as
// a run's summary ranges an unconverged answer, run::kRangePasses).
inline constexpr int kUnsettledPasses = 10;

struct ValueRange {
  double least = 0.0, largest = 0.0;
  // (largest − least) / largest: how far the answer still moved, 0 when it did not.
  double spread() const { return largest != 0.0 ? (largest - least) / largest : 0.0; }
};

// Of a search's steps that held unsettled, the widest spread of a region's K_eff/K_m over its
// last passes, the region and the load.
struct UnsettledSpread {
  double spread = 0.0, load = 0.0;
  std::string region;
};

class PassTrail {
 public:
  // One pass: whether its blocks passed the at-rest test after its settling steps, whether its
  // last DDA step ran at the full time step (a step cut short moves the blocks little however
  // far they are from rest, so its at-rest test proves nothing), whether it moved the blocks
  // by more than the loop's tolerance (its displacement change), and each region's K_eff/K_m
  // after it (none where a region has no value).
  void add(bool at_rest, bool full_time_step, bool moved, std::vector<std::optional<double>> conductivity);
  void clear() { passes_.clear(); }
  int passes() const { return static_cast<int>(passes_.size()); }

  // The last passes in a row whose blocks failed the at-rest test.
  int passes_not_at_rest() const;
  // Whether the last pass ended on a DDA step cut short and still moved the blocks by more than
  // the loop's tolerance: getting through what cut its steps, neither resting nor stalled.
  bool getting_through() const;
  // Whether the blocks came to rest, at the full time step, in each of the last min(n, passes())
  // passes (false with none).
  bool rested_in_last(int n) const;
  // Of the last min(n, passes()) passes, how many ended on a DDA step cut short.
  int passes_cut_short(int n) const;
  // Per region, the least and largest K_eff/K_m over the last min(n, passes()) passes; none for
  // a region with no value in them.
  std::vector<std::optional<ValueRange>> ranges_over_last(int n) const;

 private:
  struct Pass {
    bool at_rest = false, full_time_step = false, moved = false;
    std::vector<std::optional<double>> conductivity;
  };
  std::vector<Pass> passes_;
};

}  // namespace hydrodda::breach
