// The Brazilian disc through the program, on scenarios/verification/brazilian_disc.toml: a disc
// of diameter D = 1 m (t = 1 m, plane stress) of bonded triangle sub-blocks of D/20, squeezed
// between flats 2b = 0.1 m wide by a pressure q rising in time, its bonds of tensile strength
// T = 1 MPa (cohesion 20 MPa).
// Reference: an elastic disc under diametral loads P carries the tension
//   σx = 2 P / (π D t)
// across its loaded diameter (Hertz; Timoshenko & Goodier 1951, §41; (sin 2α / α − 1) = 0.987
// of it at the centre for loads spread over arcs 2α, Hondros 1959), its largest tension. No
// face can reach T before σx does, and faces across that diameter reach it with it; the
// Brazilian test reads the tensile strength as σt = 2 P / (π D t) at the load that cracks it.
// Tolerance: the first bond breaks, in tension, on a face within D/10 of the loaded diameter,
// at σt within 10% of T (the load rises 0.13% a step; measured 1.052 T: the faces nearest the
// diameter are not quite square to σx), none before; every bond broken by 1.15 T (18 MPa) is
// a tension break within D/10 of that diameter (measured 3).
// Not verified: the disc's peak load. The breaks stay scattered along the diameter as the load
// rises, and the disc does not split at the first one (docs/dda.md, "Bonds").

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "../cli/run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::edited_scenario;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

constexpr double kStrength = 1.0e6;   // T (Pa)
constexpr double kDiameter = 1.0;     // D (m), thickness 1 m
constexpr double kFlatWidth = 0.1;    // 2b (m)

// The pressure on the top flat at time t: 0 to 12 MPa over 100 s, then 20 kPa a second.
double pressure_at(double t) { return t <= 100.0 ? 1.2e5 * t : 1.2e7 + 2.0e4 * (t - 100.0); }

double brazilian_strength(double t) {
  const double load = pressure_at(t) * kFlatWidth;  // P (N per metre of thickness)
  return 2.0 * load / (std::numbers::pi * kDiameter);
}

std::size_t column_of(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(BrazilianDisc, TheFirstBondBreaksOnTheLoadedDiameterWhenTheBrazilianTensionReachesItsStrength) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/brazilian_disc.toml";
  const fs::path out = fs::temp_directory_path() / ("hydrodda-brazilian-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = run_program("run " + scenario.string() + " -o " + out.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto fractures = read_csv(out / "fractures.csv");
  ASSERT_GE(fractures.size(), 2u) << "no bond broke";
  const std::vector<std::string>& header = fractures.front();
  for (std::size_t r = 1; r < fractures.size(); ++r) {
    const std::vector<std::string>& row = fractures[r];
    EXPECT_EQ(row[column_of(header, "origin")], "bond");
    EXPECT_EQ(row[column_of(header, "mode")], "tension") << "row " << r;
    const double mid_x = 0.5 * (std::stod(row[column_of(header, "x1")]) + std::stod(row[column_of(header, "x2")]));
    EXPECT_LT(std::abs(mid_x), 0.1 * kDiameter) << "row " << r;
  }
  const double first = std::stod(fractures[1][column_of(header, "time")]);
  EXPECT_NEAR(brazilian_strength(first) / kStrength, 1.0, 0.10) << "first break at t = " << first;
  const auto history = read_csv(out / "history.csv");
  const std::size_t t_column = column_of(history.front(), "time");
  const std::size_t total = column_of(history.front(), "broken_bonds_total");
  for (std::size_t r = 1; r < history.size(); ++r)
    if (std::stod(history[r][t_column]) < first - 1e-9) EXPECT_EQ(history[r][total], "0") << "row " << r;
  fs::remove_all(out);
}

// Past the disc's peak, a cascade of breaks: at D/10 the loaded disc broke 35 bonds by 725 s
// (1.56 T), and in the step after, an open-close pass that opened contacts of a sub-block freed
// of its bonds moved it 28 m at its inertia (2M/Δt², the only stiffness left to it); the
// Lagrangian passes then grew the closed contacts' multipliers without bound (λ ← λ + p d,
// 10^4 times a pass) until they overflowed, and the solver, handed loads that were not finite,
// ended the run "numerically singular". The matrix was not singular: such a try is now cut and
// retried at a shorter step, as any try whose forces do not settle (dda::System::step). The
// disc steps on past 725 s and breaks more bonds (40 by 800 s); the run ends at its end time
// (exit 0), not failed.
TEST(BrazilianDisc, ACascadeOfBreaksPastThePeakCutsTheStepInsteadOfFailingTheRun) {
  const fs::path scenario = edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/brazilian_disc.toml",
      "brazilian-cascade-" + std::to_string(::getpid()),
      {{"size = 0.05", "size = 0.1"},
       {"end_time = 400.0", "end_time = 810.0"},
       {"[400.0, -1.8e7]]", "[400.0, -1.8e7], [1000.0, -3.0e7]]"}});
  const fs::path out = fs::temp_directory_path() / ("hydrodda-brazilian-cascade-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = run_program("-q run " + scenario.string() + " -o " + out.string() + " --threads 1");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["status"], "ok") << summary.dump();
  EXPECT_EQ(summary["iterations"], 810);
  const auto history = read_csv(out / "history.csv");
  const std::size_t total = column_of(history.front(), "broken_bonds_total");
  EXPECT_GT(std::stoi(history.back()[total]), 35) << "the cascade past 725 s";
  fs::remove_all(out);
  fs::remove(scenario);
}

}  // namespace
