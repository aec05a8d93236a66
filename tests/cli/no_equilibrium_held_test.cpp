// A run that ends "no equilibrium" tells the last state that held (run/no_equilibrium.hpp;
// docs/output.md, "A run that found no equilibrium"): the last DDA step after which no block
// was farther than its own size, the bonds broken by then and after, and summary.json's
// `last_held` saying the same. Exact identities between the message, summary.json and
// history.csv (no tolerance).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

#include "bond_record.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column_of;
using hydrodda::testing::edited_scenario;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

// The bar of bonded Voronoi sub-blocks in direct tension (bond_direct_tension.toml), its top
// traction rising to 1.01 MPa at 505 s and held there to its end, 520 s (a load held: no stall
// of a rising one, run/load_stall.hpp): it holds, no bond broken, to 1.0 MPa (step 500); the step after
// breaks 38 bonds across it (its cells zoned, a face's crack runs across the bar at the load
// that broke it) and its upper part, pulled on, flies off. The message names step 500 and the
// bonds broken after it, not the state the run ended in. (The message with bonds broken by the
// state held: NoEquilibrium.* in tests/run.)
TEST(NoEquilibriumHeld, ABondedBarPulledApartTellsTheBondsBrokenByTheLastStepThatHeld) {
  const fs::path original = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/bond_direct_tension.toml";
  const std::string name = "hydrodda-bar-pulled-apart-" + std::to_string(::getpid());
  const fs::path file = edited_scenario(original, name,
                                        {{"normal = [[0.0, 0.0], [1000.0, 2.0e6]]",
                                          "normal = [[0.0, 0.0], [505.0, 1.01e6], [1000.0, 1.01e6]]"}});
  const fs::path out = fs::temp_directory_path() / name;
  fs::remove_all(out);
  const auto result = run_program("-q run " + file.string() + " -o " + out.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 1) << result.output;
  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  ASSERT_EQ(summary["status"], "no equilibrium");
  ASSERT_TRUE(summary.contains("last_held")) << summary.dump();
  const auto& held = summary["last_held"];
  const int step = held["step"], kept = summary["iterations"];
  ASSERT_GT(step, 0);
  ASSERT_LT(step, kept);
  EXPECT_EQ(held["state"], "DDA step " + std::to_string(step));
  EXPECT_FALSE(held.contains("open_fractures")) << "no traces to measure";
  // history.csv: the bonds broken by the held step are its running total; the step after it
  // broke bonds (the bar parts there), and the rest broke after it.
  const auto history = read_csv(out / "history.csv");
  const std::size_t step_column = column_of(history[0], "step"), broken = column_of(history[0], "broken_bonds");
  const std::size_t total = column_of(history[0], "broken_bonds_total");
  int at_held = -1, next_broke = -1;
  for (std::size_t r = 1; r < history.size(); ++r) {
    if (std::stoi(history[r][step_column]) == step) at_held = std::stoi(history[r][total]);
    if (std::stoi(history[r][step_column]) == step + 1) next_broke = std::stoi(history[r][broken]);
  }
  ASSERT_GE(at_held, 0) << "no row of the step that held";
  EXPECT_EQ(held["broken_bonds"], at_held);
  EXPECT_GT(next_broke, 0) << "the bar parts in the step after the last that held";
  const int later = std::stoi(history.back()[total]) - at_held;
  ASSERT_GT(later, 0);
  const std::string bonds =
      at_held == 0 ? "no bond had broken (" + std::to_string(later) + " broke after it: fractures.csv's bond rows)"
                   : std::to_string(at_held) + " bonds had broken (fractures.csv's bond rows to then; " +
                         std::to_string(later) + " more after it)";
  const std::string message = summary["message"];
  EXPECT_NE(message.find("; in the last state that held (DDA step " + std::to_string(step) + ") " + bonds +
                         "; the load exceeds"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("(summary.json, history.csv and the figures are of DDA step " + std::to_string(kept) + ")"),
            std::string::npos)
      << message;
  fs::remove_all(out);
  fs::remove(file);
}

}  // namespace
