// A static run that cannot raise its load further (run/load_stall.hpp), told from one whose
// steps were cut and grew back, and from one whose load no longer rises.

#include "run/load_stall.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hydrodda::run {
namespace {

// A pressure rising 20 kPa a second on a boundary, time steps of 1 s. Below, cut tries that
// broke 5 bonds are a crack that runs: what tells a stall from none is then the steps alone.
scenario::MechanicsDefinition rising_pressure() {
  scenario::MechanicsDefinition m;
  m.time_step = 1.0;
  scenario::Traction t;
  t.boundary = "top";
  t.normal = numerics::TimeTable({0.0, 1000.0}, {0.0, -2.0e7});
  t.normal_end = t.normal;
  m.tractions.push_back(t);
  return m;
}

dda::StepReport kept(double start, double length, int cuts, int breaks = 0) {
  dda::StepReport r;
  r.time = start + length;
  r.time_step = length;
  r.retries = cuts;
  r.most_breaks_in_a_cut_try = breaks;
  return r;
}

// The Brazilian disc at D/40 past its peak: the times from which its steps were kept after
// failed tries, from 319 s (docs/studies/2026-11-30-brazilian-disc-past-the-band.md).
TEST(LoadStall, ShortStepsKeptAfterCutsThatAdvanceLessThanAStepAreAStall) {
  const scenario::MechanicsDefinition m = rising_pressure();
  LoadStallWatch watch(m);
  const std::vector<double> times{319.0,      319.09,     319.1305,   319.176062, 319.17883,
                                  319.179055, 319.179307, 319.17963,  319.179803, 319.180024, 319.180142};
  for (std::size_t i = 1; i < times.size(); ++i) {
    const bool stalled = watch.update(kept(times[i - 1], times[i] - times[i - 1], 2, i == 1 ? 448 : 60));
    EXPECT_EQ(stalled, i == times.size() - 1) << "step " << i;
  }
  const LoadStallWatch::Stall stall = watch.stall();
  EXPECT_DOUBLE_EQ(stall.from, 319.0);
  EXPECT_NEAR(stall.advanced, 0.180142, 1e-9);
  EXPECT_NEAR(stall.shortest, 0.000118, 1e-9);
  EXPECT_EQ(stall.cut, 10);
  EXPECT_EQ(stall.most_breaks, 448);
}

TEST(LoadStall, StepsThatGrowBackAfterACutAreNoStall) {
  const scenario::MechanicsDefinition m = rising_pressure();
  LoadStallWatch watch(m);
  // Cut to 0.3, then 0.45, 0.675 and whole steps without a cut.
  double t = 100.0;
  for (const auto& [length, cuts] : std::vector<std::pair<double, int>>{{0.3, 1}, {0.45, 0}, {0.675, 0}, {1.0, 0}}) {
    EXPECT_FALSE(watch.update(kept(t, length, cuts, 5)));
    t += length;
  }
  // Cut deep once, to 1e-3 of the step, then growing back by 1.5 a step: 18 short steps.
  for (double length = 1e-3; length < 1.0; t += length, length *= 1.5)
    EXPECT_FALSE(watch.update(kept(t, length, length == 1e-3 ? 5 : 0, 5))) << t;
  // Steps every one of them cut, but together longer than a time step: the load still rises.
  for (int i = 0; i < 20; ++i, t += 0.3) EXPECT_FALSE(watch.update(kept(t, 0.3, 1, 5))) << i;
}

// Short steps, half of them cut, whose cut tries broke no bond: a stall of the steps alone (a
// contact that chatters) is no load the rock cannot hold, and the run goes on as it would.
TEST(LoadStall, StepsHeldShortByTriesThatBreakNoBondAreNoStall) {
  const scenario::MechanicsDefinition m = rising_pressure();
  LoadStallWatch watch(m);
  double t = 612.0;
  for (int i = 0; i < 20; ++i, t += 0.01) EXPECT_FALSE(watch.update(kept(t, 0.01, i % 2, 0))) << i;
  // One bond at its strength holding them short (the D/10 disc at 612.8 s) is a stall: the bond
  // breaks at the state held, and the steps after it are a new window.
  bool stalled = false;
  for (int i = 0; i < 10; ++i, t += 0.01) stalled = watch.update(kept(t, 0.01, i % 2, 1));
  EXPECT_TRUE(stalled);
  watch.restart();
  EXPECT_FALSE(watch.update(kept(t, 0.01, 1, 1)));
  EXPECT_EQ(watch.stall().cut, 1);
}

TEST(LoadStall, StepsCutUnderALoadThatNoLongerChangesAreNoStall) {
  scenario::MechanicsDefinition m = rising_pressure();
  m.tractions[0].normal = numerics::TimeTable({0.0, 10.0}, {0.0, -2.0e7});  // held from 10 s
  m.tractions[0].normal_end = m.tractions[0].normal;
  LoadStallWatch watch(m);
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(watch.update(kept(20.0 + 0.01 * i, 0.01, 2, 5))) << i;
}

TEST(LoadStall, TheMessageNamesTheLastLoadHeldAndTheBondsBrokenAtStalls) {
  scenario::Scenario s;
  s.mechanics = rising_pressure();
  const LoadStallWatch::Stall broke{319.0, 0.179055, 0.000225, 10, 448};
  const std::string text = describe_load_stall(s, broke, 319.179055, "", {});
  EXPECT_NE(text.find("the load could not be raised past t = 319.179 s (mechanics.traction \"top\" normal = "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("its last 10 steps, 10 of them kept only after cuts, were short (to 0.000225 s at the "
                      "shortest) and together advanced the time from 319 s by 0.179 s, against "
                      "mechanics.time_step = 1 s; their cut tries broke up to 448 bonds in a try, none of them "
                      "still whole: the rock holds no more load, and t = 319.179 s is the largest load it held"),
            std::string::npos)
      << text;
  const std::string later = describe_load_stall(s, broke, 319.185, "top (0, -1.6e+06) N/m", {298, 319.180103});
  EXPECT_NE(later.find("; reactions top (0, -1.6e+06) N/m)"), std::string::npos) << later;
  EXPECT_NE(later.find("none of them still whole (298 broke where the load stalled before, from t = 319.18 s)"),
            std::string::npos)
      << later;
}

}  // namespace
}  // namespace hydrodda::run
