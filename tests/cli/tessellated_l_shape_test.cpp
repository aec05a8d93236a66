// An L-shaped domain (one block with a reflex corner) tessellated into bonded sub-blocks
// (geometry.tessellate, docs/scenario.md), on a roller base under its own weight: `check`
// accepts it, and three static steps run with no bond broken, the sub-blocks holding the
// weight as the continuum does. The identity: from div σ + b = 0, ∫ σ_ij dA = ∮ t_i x_j ds +
// ∫ b_i x_j dA; on a base at y = 0 with its other sides free and b = (0, −ρ g),
// ∫ σ_yy dA = −ρ g A ȳ and ∫ σ_xx dA = 0 (a roller carries no shear). The L: A = 9 m²,
// ȳ = (6 · 0.75 + 3 · 2.25)/9 = 1.25 m, so ∫ σ_yy dA = −2500 · 9.81 · 9 · 1.25 = −275,906.25 N
// per metre. Tolerance 1e-4 of it: the sum over sub-blocks of σ · area counts the contact
// forces between them at their deformed places (displacements ~1e-5 m of 3 m).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

std::string l_shape(const std::string& kind) {
  return R"(title = "an L in sub-blocks"
[geometry]
domain = [[0.0, 0.0], [4.0, 0.0], [4.0, 1.5], [2.0, 1.5], [2.0, 3.0], [0.0, 3.0]]
[[geometry.tessellate]]
size = 0.5
kind = ")" + kind + R"("
joint = "bond"
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint.bond]
tensile_strength = 1.0e6
cohesion = 1.0e6
fracture_energy = 10.0
[mechanics]
analysis = "static"
gravity = [0.0, -9.81]
time_step = 1.0
steps = 3
[[mechanics.roller]]
boundary = "bottom"
)";
}

TEST(TessellatedLShape, ChecksAndHoldsItsWeightOnBondedSubBlocks) {
  for (const std::string kind : {"voronoi", "triangles"}) {
    SCOPED_TRACE(kind);
    const fs::path folder = fs::temp_directory_path() / ("hydrodda-l-shape-" + kind + "-" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "l.toml") << l_shape(kind);
    const auto checked = run_program("check " + (folder / "l.toml").string());
    EXPECT_EQ(checked.exit_code, 0) << checked.output;
    EXPECT_NE(checked.output.find("1 of them tessellated into"), std::string::npos) << checked.output;
    const auto ran = run_program("-q run " + (folder / "l.toml").string() + " -o " + (folder / "out").string() + " --threads 1");
    ASSERT_EQ(ran.exit_code, 0) << ran.output;
    std::ifstream in(folder / "out/summary.json");
    const nlohmann::json summary = in ? nlohmann::json::parse(in) : nlohmann::json::object();
    ASSERT_TRUE(summary.contains("blocks"));
    EXPECT_GT(summary["blocks"].size(), 20u);
    double sxx = 0.0, syy = 0.0;
    for (const auto& block : summary["blocks"]) {
      sxx += block["stress"][0].get<double>() * block["area"].get<double>();
      syy += block["stress"][1].get<double>() * block["area"].get<double>();
    }
    const double weight_moment = -2500.0 * 9.81 * 9.0 * 1.25;
    EXPECT_NEAR(syy, weight_moment, 1e-4 * std::abs(weight_moment));
    EXPECT_NEAR(sxx, 0.0, 1e-4 * std::abs(weight_moment));
    std::ifstream history(folder / "out/history.csv");
    std::string line, last;
    int rows = -1;  // the header
    while (std::getline(history, line)) {
      ++rows;
      last = line;
    }
    EXPECT_EQ(rows, 3);
    EXPECT_EQ(last.substr(last.rfind(',') + 1), "0") << "bonds broken: " << last;
    fs::remove_all(folder);
  }
}

}  // namespace
