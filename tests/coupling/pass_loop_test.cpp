// The loop over coupling passes (coupling/pass_loop.hpp): where it stops and whom it tells,
// on a stand-in runner whose passes report what the test scripts.

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "coupling/pass_loop.hpp"

namespace hydrodda::coupling {
namespace {

// Passes that report what `script` says of pass k (1-based); unscripted passes change a little.
class ScriptedPasses final : public PassRunner {
 public:
  explicit ScriptedPasses(std::function<void(PassReport&)> script = {}, int finished = 0)
      : script_(std::move(script)), finished_(finished) {}
  PassReport run_pass() override {
    PassReport report;
    report.iteration = finished_ + 1;
    report.head_change = report.displacement_change = 0.5;
    if (script_) script_(report);
    finished_ = report.iteration;
    return report;
  }
  int iterations() const override { return finished_; }

 private:
  std::function<void(PassReport&)> script_;
  int finished_ = 0;
};

// Counts what the loop tells it; asks to stop before pass `stop_before` (0: never).
class CountingObserver final : public PassObserver {
 public:
  explicit CountingObserver(int stop_before = 0) : stop_before_(stop_before) {}
  bool stop_requested() override {
    ++stop_checks;
    return stop_before_ > 0 && static_cast<int>(seen.size()) + 1 >= stop_before_;
  }
  void after_pass(const PassReport& report) override { seen.push_back(report.iteration); }
  std::vector<int> seen;
  int stop_checks = 0;

 private:
  int stop_before_;
};

LoopLimits up_to(int max_passes) { return {max_passes, std::nullopt}; }

TEST(PassLoop, StopsAtMaxPassesTellingTheObserverOncePerPass) {
  ScriptedPasses passes;
  CountingObserver observer;
  const LoopResult result = run_passes(passes, up_to(7), observer);
  EXPECT_EQ(result.end, LoopEnd::max_passes);
  EXPECT_EQ(result.passes_run, 7);
  EXPECT_EQ(observer.seen, (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(observer.stop_checks, 7);  // before each pass, none after the last
  ASSERT_TRUE(result.last_pass.has_value());
  EXPECT_EQ(result.last_pass->iteration, 7);
}

TEST(PassLoop, StopsOnTheFirstConvergedPass) {
  ScriptedPasses passes([](PassReport& r) { r.converged = r.iteration == 3; });
  CountingObserver observer;
  const LoopResult result = run_passes(passes, up_to(10), observer);
  EXPECT_EQ(result.end, LoopEnd::converged);
  EXPECT_EQ(observer.seen, (std::vector<int>{1, 2, 3}));  // the converged pass is told too
}

TEST(PassLoop, StopsOnADivergingPassEvenUnderTheTolerance) {
  ScriptedPasses passes([](PassReport& r) {
    r.diverging = r.iteration == 4;
    r.converged = r.iteration == 4;
  });
  CountingObserver observer;
  const LoopResult result = run_passes(passes, up_to(10), observer);
  EXPECT_EQ(result.end, LoopEnd::diverging);
  EXPECT_EQ(result.last_pass->iteration, 4);
  EXPECT_EQ(observer.seen.size(), 4U);
}

TEST(PassLoop, StopsWhenBlocksEscape) {
  ScriptedPasses passes([](PassReport& r) {
    if (r.iteration == 2) r.escaping.push_back({5, 3.0, 1.0});
  });
  CountingObserver observer;
  const LoopResult result = run_passes(passes, up_to(10), observer);
  EXPECT_EQ(result.end, LoopEnd::escaping);
  ASSERT_EQ(result.last_pass->escaping.size(), 1U);
  EXPECT_EQ(result.last_pass->escaping[0].block, 5);
}

TEST(PassLoop, AnObserversStopRequestEndsItBeforeTheNextPass) {
  ScriptedPasses passes;
  CountingObserver observer(/*stop_before=*/3);
  const LoopResult result = run_passes(passes, up_to(10), observer);
  EXPECT_EQ(result.end, LoopEnd::stop_requested);
  EXPECT_EQ(result.passes_run, 2);
  EXPECT_EQ(passes.iterations(), 2);
}

// A stop request is asked before stop_after is looked at: an interrupt at that pass is one.
TEST(PassLoop, StopsAfterTheAskedPassAndAStopRequestComesFirst) {
  ScriptedPasses passes;
  CountingObserver observer;
  LoopResult result = run_passes(passes, {.max_passes = 10, .stop_after = 2}, observer);
  EXPECT_EQ(result.end, LoopEnd::stopped_after);
  EXPECT_EQ(observer.seen, (std::vector<int>{1, 2}));
  EXPECT_EQ(observer.stop_checks, 3);

  CountingObserver stopping(/*stop_before=*/1);
  ScriptedPasses more;
  result = run_passes(more, {.max_passes = 10, .stop_after = 0}, stopping);
  EXPECT_EQ(result.end, LoopEnd::stop_requested);
}

// A resumed loop counts its limits from its first pass ever, and one at its limit runs none
// and asks nothing.
TEST(PassLoop, AResumedLoopCountsThePassesItHadAlready) {
  ScriptedPasses resumed({}, /*finished=*/4);
  CountingObserver observer;
  LoopResult result = run_passes(resumed, up_to(6), observer);
  EXPECT_EQ(result.end, LoopEnd::max_passes);
  EXPECT_EQ(observer.seen, (std::vector<int>{5, 6}));

  CountingObserver idle;
  result = run_passes(resumed, {.max_passes = 6, .stop_after = 6}, idle);
  EXPECT_EQ(result.end, LoopEnd::max_passes);
  EXPECT_EQ(result.passes_run, 0);
  EXPECT_FALSE(result.last_pass.has_value());
  EXPECT_EQ(idle.stop_checks, 0);
}

TEST(PassLoop, APassThatThrowsEndsTheLoopWithItsException) {
  ScriptedPasses passes([](PassReport& r) {
    if (r.iteration == 2) throw std::runtime_error("DDA step 3 of 100 failed");
  });
  CountingObserver observer;
  EXPECT_THROW(run_passes(passes, up_to(10), observer), std::runtime_error);
  EXPECT_EQ(observer.seen, (std::vector<int>{1}));
}

}  // namespace
}  // namespace hydrodda::coupling
