// Mandel's problem through the real program on scenarios/verification/mandel.toml
// (docs/coupling.md, "Coupled transient runs"): the quarter of a rectangle squeezed between rigid
// frictionless plates, twenty strips of blocks under a stiff plate, drained at x = a. Reference:
// Mandel's series (mandel_series.hpp; Abousleiman et al. 1996, Cheng & Detournay 1988).
// Tolerances: the pressure at x = 0, 0.25, 0.5, 0.75 and 0.9 m at t* = c t/a² = 0.01, 0.05, 0.1
// and 0.5 within 2% of p0 (measured 1.52% at worst, at x = 0.9 m at t* = 0.01, where the
// pressure falls by half over the last two strips); the first step's (0.5 s) within 1% of p0 of
// the series' (measured 0.39% at worst); the Mandel–Cryer rise, the centre's highest pressure
// less its first step's, within 2% of p0 of the series' 1.0839 p0 − 1.0081 p0 (measured 0.6%).
// docs/studies/2026-11-29-mandel-first-attempt.md, "The strips under a frictionless plate".

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "coupled_runs.hpp"
#include "mandel_series.hpp"

using namespace hydrodda::testing::coupled;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;
using namespace hydrodda::testing::mandel;

namespace {

TEST(CoupledTransientVerification, StripsUnderAFrictionlessPlateFollowMandelsSeriesAndItsCryerRise) {
  const fs::path out = fs::temp_directory_path() / "hydrodda-mandel";
  fs::remove_all(out);
  const auto result = run_program("run " + (kVerification / "mandel.toml").string() + " -o " + out.string() +
                                  " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  nlohmann::json summary;
  if (std::ifstream in(out / "summary.json"); in) summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["converged"], true) << summary.dump();
  EXPECT_DOUBLE_EQ(summary["time"].get<double>(), 1000.0);
  const auto probes = read_csv(out / "probes.csv");
  fs::remove_all(out);

  const std::map<std::string, double> at{{"centre", 0.0}, {"x0.25", 0.25}, {"x0.5", 0.5}, {"x0.75", 0.75}, {"x0.9", 0.9}};
  int compared = 0, first = 0;
  double centre_first = 0.0, centre_highest = 0.0;
  for (std::size_t r = 1; r < probes.size(); ++r) {
    const double t = std::stod(probes[r][0]);
    const std::string& name = probes[r][1];
    const double p = std::stod(probes[r][3]);
    if (name == "centre" && t > 0.0) centre_highest = std::max(centre_highest, p);
    if (t == 0.5) {
      EXPECT_NEAR(p, series_pressure(at.at(name), t), 0.01 * kP0) << name << ": undrained at the first step";
      if (name == "centre") centre_first = p;
      ++first;
    }
    if (t != 9.33 && t != 46.67 && t != 93.3 && t != 466.7) continue;
    EXPECT_NEAR(p, series_pressure(at.at(name), t), 0.02 * kP0) << name << " at t = " << t;
    ++compared;
  }
  EXPECT_EQ(compared, 20);
  EXPECT_EQ(first, 5);
  // The series' highest at the centre: 1.0839 p0 at t = 61.5 s (t* = 0.066), as scripts/mandel_error.py,
  // a sum of its own, finds it.
  double series_highest = 0.0;
  for (double t = 0.5; t < 300.0; t += 0.5) series_highest = std::max(series_highest, series_pressure(0.0, t));
  EXPECT_NEAR(series_highest / kP0, 1.0839, 1e-4);
  EXPECT_NEAR(centre_highest - centre_first, series_highest - series_pressure(0.0, 0.5), 0.02 * kP0);
}

}  // namespace
