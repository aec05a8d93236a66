// Transient flow-only runs through the real program, on the shipped verification scenarios:
// - transient_diffusion_1d.toml: a step in head at the end of a closed strip, against Carslaw &
//   Jaeger's series (1959, §3.3),
//     h − h0 = H [1 − Σ_{n≥0} 4/((2n+1)π) sin((2n+1)πx/(2L)) exp(−(2n+1)²π² c t/(4L²))],
//   c = k/(μ S), within 1% of the head change H at t = 20, 100, 300 and 1000 s;
// - transient_fracture_diffusion.toml: the same series along an open fracture between blocks
//   held still, whose gap stores by the water's compressibility, c = a²/(12 μ c_w), within 1% of
//   H at t = 2, 10, 20 and 50 ms;
// - transient_steady_limit.toml: run to 100 times its slowest decay time, the heads the steady
//   ones (piecewise linear through two materials in series, exact for P1) to 1e-8 m and the
//   flows those of the same scenario run steady, to 1e-8 of them.
// And what every transient run writes: one history row and one probe row per probe per step,
// the fields at the output times, a balance of boundary flows and storage to round-off.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <nlohmann/json.hpp>

#include "../cli/run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

struct TransientRun {
  nlohmann::json summary;
  std::vector<std::vector<std::string>> history, probes;
  std::string fluid_pvd;
};

TransientRun run_and_read(const fs::path& scenario, const std::string& name) {
  const fs::path out = fs::temp_directory_path() / ("hydrodda-transient-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = run_program("run " + scenario.string() + " -o " + out.string() + " --threads 1");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  TransientRun run;
  std::ifstream in(out / "summary.json");
  run.summary = in ? nlohmann::json::parse(in) : nlohmann::json::object();
  run.history = read_csv(out / "history.csv");
  run.probes = read_csv(out / "probes.csv");
  std::ifstream pvd(out / "fluid.pvd");
  run.fluid_pvd.assign(std::istreambuf_iterator<char>(pvd), {});
  fs::remove_all(out);
  return run;
}

fs::path shipped(const std::string& name) {
  return fs::path(HYDRODDA_SOURCE_DIR) / "scenarios" / "verification" / (name + ".toml");
}

double series_head_change(double x, double t, double c, double length) {
  double sum = 0.0;
  for (int n = 0; n < 2000; ++n) {
    const double m = 2.0 * n + 1.0;
    sum += 4.0 / (m * std::numbers::pi) * std::sin(m * std::numbers::pi * x / (2.0 * length)) *
           std::exp(-m * m * std::numbers::pi * std::numbers::pi * c * t / (4.0 * length * length));
  }
  return 1.0 - sum;
}

TEST(TransientFlowRun, OneDimensionalDiffusionFollowsCarslawAndJaegersSeries) {
  const TransientRun run = run_and_read(shipped("transient_diffusion_1d"), "diffusion");
  // c = k/(μ S) = 1e-13/(1e-3 × 1e-9) = 0.1 m²/s; L = 10 m; h0 = 10 m, H = 1 m.
  const std::map<std::string, double> x{{"x1", 1.0}, {"x2.5", 2.5}, {"x5", 5.0}, {"x10", 10.0}};
  int checked = 0;
  for (std::size_t r = 1; r < run.probes.size(); ++r) {
    const double t = std::stod(run.probes[r][0]);
    if (t != 20.0 && t != 100.0 && t != 300.0 && t != 1000.0) continue;
    const double head = std::stod(run.probes[r][2]);
    EXPECT_NEAR(head - 10.0, series_head_change(x.at(run.probes[r][1]), t, 0.1, 10.0), 0.01)
        << run.probes[r][1] << " at t = " << t;
    ++checked;
  }
  EXPECT_EQ(checked, 16);  // four probes at four times
  EXPECT_EQ(run.summary["time"].get<double>(), 1000.0);
  EXPECT_TRUE(run.summary["converged"].get<bool>());
  // The boundary's inflow is what the strip stores, to round-off.
  const double inflow = -run.summary["flow"]["boundaries"]["left"].get<double>();
  EXPECT_GT(inflow, 0.0);
  EXPECT_NEAR(run.summary["flow"]["storage_rate"].get<double>(), inflow, 1e-10 * inflow);
  EXPECT_LE(run.summary["flow"]["balance"].get<double>(), 1e-10);
  // One history row per step and the initial state; one probe row per probe per row of history.
  const int steps = run.summary["iterations"].get<int>();
  EXPECT_EQ(run.history.size(), static_cast<std::size_t>(steps) + 2);  // header, t = 0, each step
  EXPECT_EQ(run.probes.size(), 4 * (static_cast<std::size_t>(steps) + 1) + 1);
  EXPECT_EQ(run.history[0][0], "step");
  EXPECT_EQ(run.probes[0], (std::vector<std::string>{"time", "name", "head", "pressure"}));
  // The fields at t = 0 and the four output times, by their real times.
  for (const std::string t : {"\"0\"", "\"20\"", "\"100\"", "\"300\"", "\"1000\""})
    EXPECT_NE(run.fluid_pvd.find("timestep=" + t), std::string::npos) << t << "\n" << run.fluid_pvd;
}

TEST(TransientFlowRun, DiffusionAlongAnOpenFractureFollowsTheSeriesWithTheGapsStorage) {
  const TransientRun run = run_and_read(shipped("transient_fracture_diffusion"), "fracture");
  // a = 1e-4 m, μ = 1e-3 Pa s, c_w = 4.5e-10 1/Pa: c = a²/(12 μ c_w) = 1851.85 m²/s; L = 10 m; H = 1 m.
  const double c = 1e-8 / (12.0 * 1e-3 * 4.5e-10);
  const std::map<std::string, double> x{{"x1", 1.0}, {"x2.5", 2.5}, {"x5", 5.0}, {"x10", 10.0}};
  int checked = 0;
  for (std::size_t r = 1; r < run.probes.size(); ++r) {
    const double t = std::stod(run.probes[r][0]);
    const bool wanted = std::abs(t - 0.002) < 1e-12 || std::abs(t - 0.01) < 1e-12 || std::abs(t - 0.02) < 1e-12 ||
                        std::abs(t - 0.05) < 1e-12;
    if (!wanted) continue;
    EXPECT_NEAR(std::stod(run.probes[r][2]), series_head_change(x.at(run.probes[r][1]), t, c, 10.0), 0.01)
        << run.probes[r][1] << " at t = " << t;
    ++checked;
  }
  EXPECT_EQ(checked, 16);
  EXPECT_LE(run.summary["flow"]["balance"].get<double>(), 1e-10);
}

TEST(TransientFlowRun, RunLongEnoughItReachesTheSteadyHeadsAndFlows) {
  const TransientRun run = run_and_read(shipped("transient_steady_limit"), "steady_limit");
  // Sandstone 4 m (k = 4e-13) then mudstone 6 m (k = 1e-13), K = k ρ g / μ, h 1 → 0:
  // q = 1 / (4/K_s + 6/K_m); h = 1 − q x/K_s for x ≤ 4, q (10 − x)/K_m beyond.
  const double factor = 1000.0 * 9.81 / 1e-3, ks = 4e-13 * factor, km = 1e-13 * factor;
  const double q = 1.0 / (4.0 / ks + 6.0 / km);
  const auto steady = [&](double x) { return x <= 4.0 ? 1.0 - q * x / ks : q * (10.0 - x) / km; };
  const std::map<std::string, double> x{{"x2", 2.0}, {"x4", 4.0}, {"x7", 7.0}};
  const std::size_t last = run.probes.size() - 3;
  ASSERT_GE(last, 1u);
  for (std::size_t r = last; r < run.probes.size(); ++r) {
    EXPECT_EQ(std::stod(run.probes[r][0]), 4000.0);
    EXPECT_NEAR(std::stod(run.probes[r][2]), steady(x.at(run.probes[r][1])), 1e-8) << run.probes[r][1];
  }
  EXPECT_NEAR(run.summary["flow"]["boundaries"]["left"].get<double>(), -q, 1e-8 * q);
  EXPECT_NEAR(run.summary["flow"]["boundaries"]["right"].get<double>(), q, 1e-8 * q);
  // The same scenario run steady: the file cut before its [flow.transient]. Its probes, one row
  // each with no time, and its flows are the transient run's at its end.
  std::ifstream in(shipped("transient_steady_limit"));
  std::string text(std::istreambuf_iterator<char>(in), {});
  text.erase(text.find("[flow.transient]"));
  const fs::path steady_file = fs::temp_directory_path() / ("transient_steady_limit_steady-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(steady_file) << text;
  const TransientRun steady_run = run_and_read(steady_file, "steady");
  fs::remove(steady_file);
  ASSERT_EQ(steady_run.probes.size(), 4u);
  for (std::size_t p = 1; p < 4; ++p) {
    EXPECT_EQ(steady_run.probes[p][0], "");  // a steady run has no time
    EXPECT_EQ(steady_run.probes[p][1], run.probes[last + p - 1][1]);
    EXPECT_NEAR(std::stod(run.probes[last + p - 1][2]), std::stod(steady_run.probes[p][2]), 1e-8);
  }
  for (const std::string b : {"left", "right"})
    EXPECT_NEAR(run.summary["flow"]["boundaries"][b].get<double>(),
                steady_run.summary["flow"]["boundaries"][b].get<double>(), 1e-8 * q);
  EXPECT_FALSE(steady_run.summary.contains("time"));
}

}  // namespace
