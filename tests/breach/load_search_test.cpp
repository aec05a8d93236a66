// The breach search against a stand-in model whose breach load is known exactly: it holds at
// every load up to a threshold and not beyond, and remembers which state each step started from.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "breach/load_search.hpp"

namespace hb = hydrodda::breach;

namespace {

// Holds at loads ≤ threshold. Each try starts from the kept state, which must be the largest
// load that held so far (a loading path never starts a step from a state it has abandoned).
class ThresholdStepper final : public hb::LoadStepper {
 public:
  explicit ThresholdStepper(double threshold, hb::StepStatus beyond = hb::StepStatus::no_equilibrium)
      : threshold_(threshold), beyond_(beyond) {}
  hb::StepResult try_load(double load) override {
    started_from.push_back(kept_);
    last_ = load;
    if (interrupt_at && tried.size() == static_cast<std::size_t>(*interrupt_at)) return {hb::StepStatus::interrupted, 0, ""};
    tried.push_back(load);
    if (load <= threshold_) return {hb::StepStatus::held, 2, ""};
    return {beyond_, 5, "beyond the threshold"};
  }
  void keep_state() override { kept_ = last_; }

  std::vector<double> tried;
  std::vector<std::optional<double>> started_from;
  std::optional<int> interrupt_at;

 private:
  double threshold_;
  hb::StepStatus beyond_;
  std::optional<double> kept_;
  double last_ = 0.0;
};

}  // namespace

TEST(LoadSearch, BracketsTheThresholdWithinTheTolerance) {
  ThresholdStepper model(23.5);
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = 40.0, .steps = 8, .tolerance = 1e-3}, model);
  ASSERT_TRUE(r.held && r.broken);
  EXPECT_LE(*r.held, 23.5);
  EXPECT_GT(*r.broken, 23.5);
  EXPECT_LE(*r.broken - *r.held, 1e-3 * *r.broken);
  EXPECT_TRUE(r.narrowed);
  EXPECT_EQ(r.broken_status, hb::StepStatus::no_equilibrium);
  // Steps 0, 5, ..., 25 (25 breaks), then bisections of [20, 25].
  EXPECT_EQ(std::vector<double>(model.tried.begin(), model.tried.begin() + 6),
            (std::vector<double>{0.0, 5.0, 10.0, 15.0, 20.0, 25.0}));
  EXPECT_EQ(model.tried[6], 22.5);
  EXPECT_EQ(r.steps.size(), model.tried.size());
  EXPECT_FALSE(r.steps[5].bisection);
  EXPECT_TRUE(r.steps[6].bisection);
}

TEST(LoadSearch, EveryStepStartsFromTheLargestLoadThatHeldBeforeIt) {
  ThresholdStepper model(7.3);
  hb::search_breach({.from = 1.0, .to = 10.0, .steps = 3, .tolerance = 1e-2}, model);
  std::optional<double> largest_held;
  for (std::size_t i = 0; i < model.tried.size(); ++i) {
    EXPECT_EQ(model.started_from[i], largest_held) << "step " << i;
    if (model.tried[i] <= 7.3) largest_held = model.tried[i];
  }
}

TEST(LoadSearch, ADecreasingLoadIsSearchedTheSameWay) {
  // A traction made more tensile: from −10 MPa towards 0, holding while below −2.5 MPa (the
  // stand-in holds at loads ≤ threshold, so the path runs downwards from a breaking load).
  class Below final : public hb::LoadStepper {
   public:
    hb::StepResult try_load(double load) override {
      return load >= -2.5e6 ? hb::StepResult{hb::StepStatus::held, 1, ""}
                            : hb::StepResult{hb::StepStatus::not_converged, 3, "no"};
    }
    void keep_state() override {}
  } model;
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = -1e7, .steps = 4, .tolerance = 1e-3}, model);
  ASSERT_TRUE(r.held && r.broken);
  EXPECT_GE(*r.held, -2.5e6);
  EXPECT_LT(*r.broken, -2.5e6);
  EXPECT_LE(std::abs(*r.broken - *r.held), 1e-3 * std::abs(*r.broken));
}

TEST(LoadSearch, SaysWhenEveryStepHeld) {
  ThresholdStepper model(100.0);
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = 10.0, .steps = 5}, model);
  EXPECT_EQ(r.held, 10.0);
  EXPECT_FALSE(r.broken);
  EXPECT_EQ(model.tried.size(), 6u);
  EXPECT_EQ(model.tried.back(), 10.0);  // the last step lands on `to` exactly
}

TEST(LoadSearch, SaysWhenTheFirstLoadDidNotHold) {
  ThresholdStepper model(-1.0, hb::StepStatus::failed);
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = 10.0, .steps = 5}, model);
  EXPECT_FALSE(r.held);
  EXPECT_EQ(r.broken, 0.0);
  EXPECT_EQ(r.broken_status, hb::StepStatus::failed);
  EXPECT_EQ(model.tried.size(), 1u);  // nothing to bisect against
}

TEST(LoadSearch, AnInterruptEndsTheSearchWhereItIs) {
  ThresholdStepper model(23.5);
  model.interrupt_at = 7;
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = 40.0, .steps = 8, .tolerance = 1e-6}, model);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(model.tried.size(), 7u);
  EXPECT_EQ(r.steps.size(), 8u);
  EXPECT_EQ(r.steps.back().result.status, hb::StepStatus::interrupted);
  EXPECT_FALSE(r.narrowed);
}

TEST(LoadSearch, StopsBisectingAfterItsLimitAndSaysTheBracketIsWide) {
  ThresholdStepper model(0.3);
  const hb::SearchResult r =
      hb::search_breach({.from = 0.0, .to = 1.0, .steps = 1, .tolerance = 1e-9, .max_bisections = 3}, model);
  EXPECT_EQ(model.tried.size(), 5u);  // 0, 1 and three bisections
  EXPECT_FALSE(r.narrowed);
  EXPECT_EQ(r.held, 0.25);
  EXPECT_EQ(r.broken, 0.375);
}

TEST(LoadSearch, RefusesSettingsThatCannotBeSearched) {
  ThresholdStepper model(1.0);
  EXPECT_THROW(hb::search_breach({.from = 1.0, .to = 1.0}, model), std::invalid_argument);
  EXPECT_THROW(hb::search_breach({.from = 0.0, .to = 1.0, .steps = 0}, model), std::invalid_argument);
  EXPECT_THROW(hb::search_breach({.from = 0.0, .to = 1.0, .steps = 2, .tolerance = 0.0}, model), std::invalid_argument);
  EXPECT_THROW(hb::search_breach({.from = 0.0, .to = NAN}, model), std::invalid_argument);
  EXPECT_TRUE(model.tried.empty());
}

TEST(LoadSearch, NamesEachStatusAsBreachCsvWritesIt) {
  EXPECT_EQ(hb::status_name(hb::StepStatus::held), "held");
  EXPECT_EQ(hb::status_name(hb::StepStatus::held_unsettled), "held, unsettled");
  EXPECT_EQ(hb::status_name(hb::StepStatus::beyond_limit), "beyond limit");
  EXPECT_EQ(hb::status_name(hb::StepStatus::not_converged), "not converged");
  EXPECT_EQ(hb::status_name(hb::StepStatus::not_at_rest), "not at rest");
  EXPECT_EQ(hb::status_name(hb::StepStatus::no_equilibrium), "no equilibrium");
  EXPECT_EQ(hb::status_name(hb::StepStatus::failed), "failed");
  EXPECT_EQ(hb::status_name(hb::StepStatus::interrupted), "interrupted");
}

namespace {

// Three ranges of load, as a seal meets them: converged up to `settled`, at rest but swinging
// (held, unsettled) up to `lifts`, no equilibrium beyond. Records which state each try started
// from, as ThresholdStepper does.
class SwingingStepper final : public hb::LoadStepper {
 public:
  SwingingStepper(double settled, double lifts) : settled_(settled), lifts_(lifts) {}
  hb::StepResult try_load(double load) override {
    started_from.push_back(kept_);
    last_ = load;
    tried.push_back(load);
    if (load <= settled_) return {hb::StepStatus::held, 4, ""};
    if (load <= lifts_) return {hb::StepStatus::held_unsettled, 30, "swings"};
    return {hb::StepStatus::no_equilibrium, 7, "blocks escape"};
  }
  void keep_state() override { kept_ = last_; }

  std::vector<double> tried;
  std::vector<std::optional<double>> started_from;

 private:
  double settled_, lifts_;
  std::optional<double> kept_;
  double last_ = 0.0;
};

}  // namespace

TEST(LoadSearch, AStepThatHeldUnsettledHoldsByDefaultAndTheBracketIsTheMechanicalBreach) {
  SwingingStepper model(9.0, 23.5);
  const hb::SearchResult r = hb::search_breach({.from = 0.0, .to = 40.0, .steps = 8, .tolerance = 1e-3}, model);
  ASSERT_TRUE(r.held && r.broken);
  EXPECT_LE(*r.held, 23.5);
  EXPECT_GT(*r.broken, 23.5);
  EXPECT_LE(*r.broken - *r.held, 1e-3 * *r.broken);
  EXPECT_EQ(r.broken_status, hb::StepStatus::no_equilibrium);
  // Unsettled: steps 10, 15, 20 and every bisection below 23.5 (each counted once).
  int unsettled = 0;
  for (const hb::SearchStep& s : r.steps) unsettled += s.result.status == hb::StepStatus::held_unsettled;
  EXPECT_EQ(r.unsettled_held, unsettled);
  EXPECT_GE(r.unsettled_held, 3);
}

TEST(LoadSearch, AfterAnUnsettledStepTheNextStartsFromItsState) {
  SwingingStepper model(9.0, 23.5);
  hb::search_breach({.from = 0.0, .to = 40.0, .steps = 8, .tolerance = 1e-2}, model);
  std::optional<double> largest_held;
  for (std::size_t i = 0; i < model.tried.size(); ++i) {
    EXPECT_EQ(model.started_from[i], largest_held) << "step " << i;
    if (model.tried[i] <= 23.5) largest_held = model.tried[i];  // held or held unsettled: kept
  }
}

TEST(LoadSearch, ConvergedOnlyCountsAnUnsettledStepAsTheBreach) {
  SwingingStepper model(9.0, 23.5);
  const hb::SearchResult r = hb::search_breach(
      {.from = 0.0, .to = 40.0, .steps = 8, .tolerance = 1e-3, .converged_only = true}, model);
  ASSERT_TRUE(r.held && r.broken);
  EXPECT_LE(*r.held, 9.0);
  EXPECT_GT(*r.broken, 9.0);
  EXPECT_LE(*r.broken - *r.held, 1e-3 * *r.broken);
  EXPECT_EQ(r.broken_status, hb::StepStatus::held_unsettled);
  EXPECT_EQ(r.unsettled_held, 0);
  // 0, 5, 10 (unsettled: the breach), then bisections of [5, 10].
  ASSERT_GE(model.tried.size(), 4u);
  EXPECT_EQ(model.tried[2], 10.0);
  EXPECT_EQ(model.tried[3], 7.5);
  EXPECT_TRUE(r.steps[3].bisection);
}
